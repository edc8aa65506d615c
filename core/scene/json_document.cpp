// JsonDocument: parse with nlohmann::json, then index value positions (see json_document.h).
#include "scene/json_document.h"

#include <cctype>
#include <cstring>
#include <tuple>

namespace glint {
namespace {

// Line and column (1-based, columns in characters) of each byte offset, computed on demand.
class TextPositions {
public:
    explicit TextPositions(const std::string& text) : text_(text) {}
    std::pair<int, int> at(size_t offset) {
        for (; scanned_ < offset && scanned_ < text_.size(); ++scanned_) {
            const unsigned char c = static_cast<unsigned char>(text_[scanned_]);
            if (c == '\n') { ++line_; column_ = 1; }
            else if ((c & 0xC0) != 0x80) ++column_;  // UTF-8 continuation bytes add no column
        }
        return {line_, column_};
    }

private:
    const std::string& text_;
    size_t scanned_ = 0;
    int line_ = 1, column_ = 1;
};

// A scan of text nlohmann::json has already accepted, recording where each value starts.
class PositionIndexer {
public:
    PositionIndexer(const std::string& text, std::unordered_map<std::string, std::pair<int, int>>& out)
        : text_(text), positions_(text), out_(out) {}

    void run() {
        if (text_.compare(0, 3, "\xEF\xBB\xBF") == 0) offset_ = 3;
        value("");
    }

private:
    void skipSpace() {
        while (offset_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[offset_]))) ++offset_;
    }
    std::string stringToken() {  // at the opening quote; returns the raw (unescaped) content
        std::string content;
        ++offset_;
        while (offset_ < text_.size() && text_[offset_] != '"') {
            if (text_[offset_] == '\\' && offset_ + 1 < text_.size()) {
                const char escaped = text_[offset_ + 1];
                const char* from = "\"\\/bfnrt";
                const char* to = "\"\\/\b\f\n\r\t";
                if (const char* found = std::strchr(from, escaped); found && escaped) {
                    content += to[found - from];
                    offset_ += 2;
                    continue;
                }
                content += text_.substr(offset_, 6);  // \uXXXX kept raw: rare in keys
                offset_ += 6;
                continue;
            }
            content += text_[offset_++];
        }
        ++offset_;
        return content;
    }
    void value(const std::string& pointer) {
        skipSpace();
        if (!out_.count(pointer)) out_[pointer] = positions_.at(offset_);
        if (offset_ >= text_.size()) return;
        const char c = text_[offset_];
        if (c == '{') {
            ++offset_;
            skipSpace();
            while (offset_ < text_.size() && text_[offset_] != '}') {
                const auto keyPosition = positions_.at(offset_);
                const std::string member = appendPointer(pointer, stringToken());
                out_[member] = keyPosition;
                skipSpace();
                ++offset_;  // ':'
                value(member);
                skipSpace();
                if (offset_ < text_.size() && text_[offset_] == ',') ++offset_;
                skipSpace();
            }
            ++offset_;
        } else if (c == '[') {
            ++offset_;
            skipSpace();
            for (int index = 0; offset_ < text_.size() && text_[offset_] != ']'; ++index) {
                value(appendPointer(pointer, std::to_string(index)));
                skipSpace();
                if (offset_ < text_.size() && text_[offset_] == ',') ++offset_;
                skipSpace();
            }
            ++offset_;
        } else if (c == '"') {
            stringToken();
        } else {
            while (offset_ < text_.size() && !std::strchr(",]} \t\r\n", text_[offset_])) ++offset_;
        }
    }

    const std::string& text_;
    TextPositions positions_;
    std::unordered_map<std::string, std::pair<int, int>>& out_;
    size_t offset_ = 0;
};

}  // namespace

std::string appendPointer(const std::string& pointer, const std::string& token) {
    std::string result = pointer + "/";
    for (char c : token) {
        if (c == '~') result += "~0";
        else if (c == '/') result += "~1";
        else result += c;
    }
    return result;
}

Result<JsonDocument> JsonDocument::parse(const std::string& text, const std::string& file) {
    JsonDocument document;
    document.file_ = file;
    try {
        document.root_ = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        // nlohmann's message reads "[json.exception.parse_error.101] parse error at line L,
        // column C: what"; keep "what" and compute the location ourselves.
        std::string message = error.what();
        if (const size_t colon = message.find(": "); colon != std::string::npos) message = message.substr(colon + 2);
        TextPositions positions(text);
        const size_t offset = error.byte > 0 ? error.byte - 1 : 0;
        const auto [line, column] = positions.at(offset);
        return makeError("invalid JSON: " + message, {file, line, column});
    } catch (const nlohmann::json::exception& error) {
        // e.g. "number overflow parsing '1e999'": no byte offset, so find the quoted token.
        std::string message = error.what();
        if (const size_t bracket = message.find("] "); bracket != std::string::npos) message = message.substr(bracket + 2);
        SourceLocation where{file};
        const size_t open = message.find('\''), close = message.rfind('\'');
        if (open != std::string::npos && close > open) {
            if (const size_t at = text.find(message.substr(open + 1, close - open - 1)); at != std::string::npos) {
                TextPositions positions(text);
                std::tie(where.line, where.column) = positions.at(at);
            }
        }
        return makeError("invalid JSON: " + message, where);
    }
    PositionIndexer(text, document.positions_).run();
    return document;
}

SourceLocation JsonDocument::locate(const std::string& pointer) const {
    if (auto found = positions_.find(pointer); found != positions_.end())
        return {file_, found->second.first, found->second.second};
    return {file_};
}

}  // namespace glint
