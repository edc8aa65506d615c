// Errors of referenced files, without their bytes (see referenced_file_error.h).
#include "util/referenced_file_error.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "util/reference_confinement.h"

namespace glint {
namespace {

// Whether `error` may quote the file: the parsers that quote a line say where it is (a line
// number) or set the quote off ('…', "…", `…`). A message about the whole file (its size, a limit)
// does neither and is kept; an apostrophe within a word ("Glint's", "4.1's") sets nothing off.
bool mayQuote(const Diagnostic& error, const std::string& file) {
    if (error.where.line > 0) return true;
    std::string message = error.message;
    const auto erase = [&message](const std::string& part) {
        for (size_t at = message.find(part); !part.empty() && at != std::string::npos; at = message.find(part))
            message.erase(at, part.size());
    };
    erase(file);  // the file's own name, quoted or not, quotes nothing of it
    erase(std::filesystem::path(file).filename().string());
    for (const char* emptyQuote : {"''", "\"\"", "``"}) erase(emptyQuote);
    const auto wordCharacter = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0; };
    for (size_t at = 1; at + 1 < message.size(); ++at)
        if (message[at] == '\'' && wordCharacter(message[at - 1]) && wordCharacter(message[at + 1])) message[at] = ' ';
    return message.find_first_of("'\"`") != std::string::npos;
}

// Whether any of the file could have been read: when not, its error says why (missing, a folder,
// no permission) and holds nothing of it.
bool readable(const std::string& file) {
    std::error_code code;
    if (!std::filesystem::is_regular_file(file, code)) return false;
    return std::ifstream(file, std::ios::binary).good();
}

}  // namespace

std::string referencedFileProblem(const std::string& file, const Diagnostic& error, const std::string& kind) {
    if (!readable(file) || !mayQuote(error, file) || isReferenceRefusal(error)) return error.format();
    const std::string where = error.where.line > 0 ? " (line " + std::to_string(error.where.line) + ")" : "";
    return "'" + file + "' is not a valid " + kind + where +
           "; open it on its own for the details, left out here as they may quote it";
}

}  // namespace glint
