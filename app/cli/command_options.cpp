// Option parsing for subcommands (see command_options.h).
#include "cli/command_options.h"

#include <algorithm>
#include <regex>

namespace glint {

std::function<std::string(const std::string& value)> wholeNumberOption(int& out, int low, int high, std::string message) {
    return [&out, low, high, message = std::move(message)](const std::string& value) {
        if (!std::regex_match(value, std::regex("[0-9]{1,5}")) || std::stoi(value) < low || std::stoi(value) > high) return message;
        out = std::stoi(value);
        return std::string();
    };
}

std::function<std::string(const std::string& value)> pixelSizeOption(int& width, int& height, int low, int high, std::string message) {
    return [&width, &height, low, high, message = std::move(message)](const std::string& value) {
        static const std::regex sizePattern(R"(([0-9]{1,5})x([0-9]{1,5}))");
        std::smatch match;
        if (!std::regex_match(value, match, sizePattern)) return message;
        const int parsedWidth = std::stoi(match[1]), parsedHeight = std::stoi(match[2]);
        if (parsedWidth < low || parsedHeight < low || parsedWidth > high || parsedHeight > high) return message;
        width = parsedWidth, height = parsedHeight;
        return std::string();
    };
}

Result<ParsedArguments> parseCommandOptions(const std::vector<std::string>& arguments, const std::vector<CommandOption>& options,
                                            const std::string& positionalName) {
    ParsedArguments parsed;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        if (argument == "-h" || argument == "--help") {
            parsed.help = true;
            continue;
        }
        if (argument.empty() || argument[0] != '-') {
            if (!parsed.positionals.empty())
                return makeError("one " + positionalName + " at a time (got " + parsed.positionals[0] + " and " + argument + ")");
            parsed.positionals.push_back(argument);
            continue;
        }
        const auto option = std::find_if(options.begin(), options.end(), [&](const CommandOption& candidate) {
            return std::find(candidate.names.begin(), candidate.names.end(), argument) != candidate.names.end();
        });
        if (option == options.end()) return makeError("unknown option " + argument);
        std::string value;
        if (!option->valueName.empty()) {
            if (i + 1 >= arguments.size()) return makeError(argument + " needs " + option->valueName);
            value = arguments[++i];
        }
        if (std::string refusal = option->apply(value); !refusal.empty()) return makeError(refusal);
    }
    return parsed;
}

}  // namespace glint
