// JsonDocument: a parsed JSON file that remembers where every value came from, so that errors
// found after parsing (unknown key, wrong type, value out of range) can name file:line:column.
// nlohmann::json parses; a second, small scan maps JSON pointers to positions in the text.
#pragma once

#include <string>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "util/diagnostic.h"

namespace glint {

class JsonDocument {
public:
    // Parses `text`; `file` is used in messages only.
    static Result<JsonDocument> parse(const std::string& text, const std::string& file);

    const nlohmann::json& root() const { return root_; }
    const std::string& file() const { return file_; }

    // Where the value at `pointer` (RFC 6901, "" for the root) starts; for an object member,
    // where its key starts. Falls back to the file alone when the pointer is unknown.
    SourceLocation locate(const std::string& pointer) const;

private:
    nlohmann::json root_;
    std::string file_;
    std::unordered_map<std::string, std::pair<int, int>> positions_;  // pointer → (line, column)
};

// Appends one reference token to a JSON pointer, escaping '~' and '/'.
std::string appendPointer(const std::string& pointer, const std::string& token);

}  // namespace glint
