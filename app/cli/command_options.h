// Option parsing for subcommands: each command declares its options (spellings, the value they
// take, what to do with it) and gets back its positional arguments or the first mistake.
// Usage texts and what the options mean stay with each command.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "util/diagnostic.h"

namespace glint {

struct CommandOption {
    std::vector<std::string> names;  // e.g. {"-o", "--out"}
    std::string valueName;           // empty: a flag; else what follows it, for "--out needs DIR"
    // Takes the value (empty for a flag); returns an error message, or "" when accepted.
    std::function<std::string(const std::string& value)> apply;
};

struct ParsedArguments {
    bool help = false;                     // -h or --help was given
    std::vector<std::string> positionals;  // what is not an option (at most one)
};

// An option's `apply` that takes a whole number in [low, high] into `out`, or refuses it with
// `message`. `out` must outlive the parse.
std::function<std::string(const std::string& value)> wholeNumberOption(int& out, int low, int high, std::string message);

// An option's `apply` that takes WIDTHxHEIGHT, each in [low, high], into `width` and `height`, or
// refuses it with `message`. Both must outlive the parse.
std::function<std::string(const std::string& value)> pixelSizeOption(int& width, int& height, int low, int high, std::string message);

// Walks `arguments`; an unknown option, a missing value, a refused one, or more than one
// positional argument ("one `positionalName` at a time") is an error.
Result<ParsedArguments> parseCommandOptions(const std::vector<std::string>& arguments, const std::vector<CommandOption>& options,
                                            const std::string& positionalName);

}  // namespace glint
