// The one command line (see command_line.h).
#include "cli/command_line.h"

#include <cctype>
#include <cstdio>
#include <regex>
#include <string>
#include <utility>

#include "util/reference_confinement.h"

namespace glint {
namespace {

// The command whose options failed (the innermost chosen), or `glint` itself.
CLI::App* failingCommand(CLI::App& glint) {
    CLI::App* command = &glint;
    while (!command->get_subcommands().empty()) command = command->get_subcommands().front();
    return command;
}

// CLI11's message in Glint's words where a check of ours refused ("--size: needs …" becomes
// "--size needs …"), an unknown option or a second positional named as such.
std::string mistake(CLI::App& command, const CLI::ParseError& error) {
    const std::string what = error.what();
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
        const std::string extra = command.remaining().empty() ? what : command.remaining().front();
        if (extra.rfind("-", 0) == 0) return "unknown option " + extra;
        for (const CLI::Option* positional : command.get_options([](const CLI::Option* option) { return option->get_positional(); })) {
            std::string name = positional->get_name();
            for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            const std::string given = positional->results().empty() ? "" : positional->results().front();
            return "one " + name + " at a time (got " + given + " and " + extra + ")";
        }
        return "takes no arguments (got " + extra + ")";
    }
    static const std::regex located("^(-[-A-Za-z0-9]+): (needs .*|1 required .* missing)$");
    std::smatch match;
    if (!std::regex_match(what, match, located)) return what;
    if (match[2].str().rfind("needs", 0) == 0) return match[1].str() + " " + match[2].str();
    CLI::Option* option = command.get_option_no_throw(match[1].str());
    const CLI::Validator* check = nullptr;
    try {
        check = option ? option->get_validator("needs") : nullptr;
    } catch (const CLI::OptionNotFound&) {
    }
    return check ? match[1].str() + " needs " + check->get_description() : what;
}

}  // namespace

CLI::App* addCommand(CLI::App& glint, const std::string& name, const std::string& summary, std::function<int()> run) {
    CLI::App* command = glint.add_subcommand(name, summary);
    command->option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);  // `-o a -o b`: b, as before
    command->callback([run = std::move(run)] { throw CLI::RuntimeError(run()); });
    return command;
}

CLI::Validator needs(const std::string& what, std::function<bool(const std::string& value)> accepts) {
    return CLI::Validator(
        [what, accepts = std::move(accepts)](std::string& value) {
            return accepts(value) ? std::string() : "needs " + what + " (got " + value + ")";
        },
        what, "needs");
}

CLI::Validator needsWholeNumber(const std::string& what, int low, int high) {
    return needs(what, [low, high](const std::string& value) {
        return std::regex_match(value, std::regex("[0-9]{1,9}")) && std::stoi(value) >= low && std::stoi(value) <= high;
    });
}

CLI::Option* addPixelSize(CLI::App& command, int& width, int& height, int low, int high, const std::string& description) {
    static const std::regex sizePattern(R"(([0-9]{1,5})x([0-9]{1,5}))");
    const std::string range = std::to_string(low) + "x" + std::to_string(low) + " to " + std::to_string(high) + "x" + std::to_string(high);
    return command
        .add_option_function<std::string>(
            "--size",
            [&width, &height](const std::string& value) {
                std::smatch match;
                std::regex_match(value, match, sizePattern);
                width = std::stoi(match[1]), height = std::stoi(match[2]);
            },
            description)
        ->check(needs("WIDTHxHEIGHT from " + range + ", e.g. 512x512", [low, high](const std::string& value) {
            std::smatch match;
            if (!std::regex_match(value, match, sizePattern)) return false;
            const int w = std::stoi(match[1]), h = std::stoi(match[2]);
            return w >= low && h >= low && w <= high && h <= high;
        }))
        ->type_name("WxH");
}

int commandFailed(const std::string& command, const std::string& message, int exitCode) {
    std::fprintf(stderr, "glint%s%s: %s\n", command.empty() ? "" : " ", command.c_str(), message.c_str());
    return exitCode;
}

int usageError(const std::string& command, const std::string& message) {
    return commandFailed(command, message + "\nRun `glint " + command + " --help` for the options.");
}

void addOutsideReferencesFlag(CLI::App& command) {
    command.add_flag_callback("--allow-outside-references", [] { setOutsideReferencesAllowed(true); },
                              "read files that a file names outside its own folder (a material library, texture, "
                              "buffer, mesh or environment: refused by default)");
}

void refuse(const std::string& message) { throw CLI::ValidationError(message); }

int runCommandLine(CLI::App& glint, int argc, char** argv, bool& chosen) {
    chosen = true;
    try {
        glint.parse(argc, argv);
    } catch (const CLI::RuntimeError& finished) {  // a command ran (addCommand): its exit code
        return finished.get_exit_code();
    } catch (const CLI::Success& success) {  // --help, --version
        return glint.exit(success);
    } catch (const CLI::ParseError& error) {
        CLI::App* command = failingCommand(glint);
        if (command != &glint) return usageError(command->get_name(), mistake(*command, error));
        return commandFailed("", mistake(*command, error) + "\nRun `glint --help` for the commands.");
    }
    chosen = false;
    return 0;
}

}  // namespace glint
