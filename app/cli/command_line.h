// The one command line (CLI11): every command is a subcommand of `glint` that declares its options,
// bound to its own settings, and the function that runs it. Mistakes are reported the same way for
// all of them: "glint COMMAND: message" on stderr, exit code 2.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <string>

namespace glint {

// Adds the subcommand `name` (its `summary` is its line in `glint --help`); `run` is called once
// its options parsed, and what it returns is the exit code.
CLI::App* addCommand(CLI::App& glint, const std::string& name, const std::string& summary, std::function<int()> run);

// A check of an option's value worded the Glint way: `what` is what the option needs ("a number
// from 1 to 1000": shown in --help); a value `accepts` refuses gives "--frames needs a number from
// 1 to 1000 (got 0)", and so does a missing value.
CLI::Validator needs(const std::string& what, std::function<bool(const std::string& value)> accepts);

// A whole number in [low, high].
CLI::Validator needsWholeNumber(const std::string& what, int low, int high);

// WIDTHxHEIGHT into `width` and `height`, each in [low, high].
CLI::Option* addPixelSize(CLI::App& command, int& width, int& height, int low, int high, const std::string& description);

// --allow-outside-references, for a command that opens files: those files may then name files
// outside their own folder (core/util/reference_confinement.h), for this run.
void addOutsideReferencesFlag(CLI::App& command);

// A refusal found while taking an option's value (an option function): printed as it is.
[[noreturn]] void refuse(const std::string& message);

// A command that could not do its work: "glint COMMAND: message" on stderr ("glint: message" for
// glint itself, an empty `command`); returns `exitCode`.
int commandFailed(const std::string& command, const std::string& message, int exitCode = 2);

// A mistake in a command's arguments found after parsing, reported as parsing reports one:
// "glint COMMAND: message" and where the options are listed; returns 2, the exit code.
int usageError(const std::string& command, const std::string& message);

// Parses the arguments and runs the command chosen; returns its exit code. With no command, `glint`
// itself parsed; `chosen` is then false and the caller runs the editor.
int runCommandLine(CLI::App& glint, int argc, char** argv, bool& chosen);

}  // namespace glint
