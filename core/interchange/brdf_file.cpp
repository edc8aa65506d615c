// BRDF Explorer .brdf reader (see brdf_file.h).
// Sections: tokens and numbers · parameter lines · the shader's top-level names · the file.
#include "interchange/brdf_file.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <regex>

#include "util/file_io.h"
#include "util/text.h"

namespace glint {
namespace {

// --- tokens and numbers -------------------------------------------------------------------------

struct Token {
    std::string_view text;
    int column = 0;  // 1-based
};

std::vector<Token> splitTokens(std::string_view line) {
    std::vector<Token> tokens;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i >= line.size() || line[i] == '#') break;  // a trailing comment ends the line
        const size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        tokens.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
    }
    return tokens;
}

Result<float> parseNumber(const Token& token, const std::string& what, const std::string& path, int line) {
    const SourceLocation where{path, line, token.column};
    const std::string text(token.text);
    if (text.size() > 64) return makeError(what + ": '" + text.substr(0, 24) + "…' is not a number", where);
    char* end = nullptr;
    errno = 0;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || text.find_first_of("xXnN") != std::string::npos)
        return makeError(what + ": '" + text + "' is not a number", where);
    if (errno == ERANGE || !std::isfinite(value) || std::fabs(value) > kMaxBrdfNumber)
        return makeError(what + ": " + text + " is too large (the limit is 1e30)", where);
    return static_cast<float>(value);
}

bool isIdentifier(std::string_view name) {
    if (name.empty() || name.size() > 64 || std::isdigit(static_cast<unsigned char>(name[0]))) return false;
    return std::all_of(name.begin(), name.end(),
                       [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

// --- parameter lines ----------------------------------------------------------------------------

Status checkName(const Token& token, const std::string& path, int line) {
    if (!isIdentifier(token.text) || token.text.rfind("gl_", 0) == 0 || token.text.find("__") != std::string_view::npos)
        return makeError("parameter name '" + std::string(token.text) +
                             "' is not a GLSL identifier (letters, digits, _; at most 64; not gl_ or __)",
                         {path, line, token.column});
    return success();
}

}  // namespace

std::string_view headerWord(std::string_view line) {
    const std::string_view content = trimmed(line);
    return content.substr(0, content.find_first_of(" \t"));
}

Status checkUtf8(std::string_view text, const std::string& path) {
    int line = 1, column = 1;
    for (size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        int length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
        bool valid = length > 0 && i + length <= text.size() && byte != 0xC0 && byte != 0xC1 && byte <= 0xF4;
        for (int k = 1; valid && k < length; ++k) valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
        if (!valid) return makeError("the file is not UTF-8 text (bad byte here)", {path, line, column});
        if (byte == 0) return makeError("the file holds a NUL byte (not a text file)", {path, line, column});
        if (byte == '\n') ++line, column = 1;
        else ++column;
        i += length;
    }
    return success();
}

Result<BrdfFileParam> parseBrdfParamLine(std::string_view lineText, const std::string& path, int line) {
    const std::vector<Token> tokens = splitTokens(lineText);
    GLINT_CHECK(!tokens.empty());
    BrdfFileParam param;
    param.line = line;
    const std::string type(tokens[0].text);
    const auto expectCount = [&](size_t count, const char* form) -> Status {
        if (tokens.size() == count) return success();
        const int column = tokens.size() > count ? tokens[count].column : static_cast<int>(lineText.size()) + 1;
        return makeError(std::string(tokens.size() > count ? "extra text after " : "incomplete ") + type +
                             " parameter (expected '" + form + "')",
                         {path, line, column});
    };
    if (type == "float") {
        if (Status counted = expectCount(5, "float name min max default"); !counted) return counted.error();
    } else if (type == "bool") {
        if (Status counted = expectCount(3, "bool name 0|1"); !counted) return counted.error();
    } else if (type == "color") {
        if (Status counted = expectCount(5, "color name r g b"); !counted) return counted.error();
    } else {
        return makeError("unknown parameter type '" + type + "' (expected float, bool or color)",
                         {path, line, tokens[0].column});
    }
    if (Status named = checkName(tokens[1], path, line); !named) return named.error();
    param.name = std::string(tokens[1].text);
    float numbers[3];
    static const char* const kFloatWhat[] = {"min", "max", "default"};
    for (size_t i = 2; i < tokens.size(); ++i) {
        const std::string what = param.name + " " + (type == "float" ? kFloatWhat[i - 2] : type == "bool" ? "value" : "rgb");
        auto number = parseNumber(tokens[i], what, path, line);
        if (!number) return number.error();
        numbers[i - 2] = *number;
    }
    if (type == "float") {
        param.kind = ParamKind::Scalar;
        param.min = numbers[0], param.max = numbers[1];
        if (param.min > param.max)
            return makeError(param.name + ": min " + std::string(tokens[2].text) + " is greater than max " +
                                 std::string(tokens[3].text),
                             {path, line, tokens[2].column});
        if (numbers[2] < param.min || numbers[2] > param.max)
            return makeError(param.name + ": default " + std::string(tokens[4].text) + " lies outside [" +
                                 std::string(tokens[2].text) + ", " + std::string(tokens[3].text) + "]",
                             {path, line, tokens[4].column});
        param.defaultValue = {numbers[2], 0, 0};
    } else if (type == "bool") {
        param.kind = ParamKind::Bool;
        if (numbers[0] != 0.0f && numbers[0] != 1.0f)
            return makeError(param.name + ": a bool is 0 or 1, not " + std::string(tokens[2].text),
                             {path, line, tokens[2].column});
        param.defaultValue = {numbers[0], 0, 0};
    } else {
        param.kind = ParamKind::Color;
        for (int c = 0; c < 3; ++c)
            if (numbers[c] < 0.0f)
                return makeError(param.name + ": a colour channel must be at least 0, not " +
                                     std::string(tokens[2 + c].text),
                                 {path, line, tokens[2 + c].column});
        param.defaultValue = {numbers[0], numbers[1], numbers[2]};
    }
    return param;
}

std::string formatBrdfParamLine(const BrdfFileParam& param, const float* value) {
    char text[256];
    switch (param.kind) {
        case ParamKind::Bool: std::snprintf(text, sizeof text, "bool %s %d", param.name.c_str(), value[0] > 0.5f); break;
        case ParamKind::Color:
            std::snprintf(text, sizeof text, "color %s %.9g %.9g %.9g", param.name.c_str(), value[0], value[1], value[2]);
            break;
        default:
            std::snprintf(text, sizeof text, "float %s %.9g %.9g %.9g", param.name.c_str(), param.min, param.max, value[0]);
    }
    return text;
}

namespace {

// --- the shader's top-level names ---------------------------------------------------------------

// Comments become spaces (newlines kept) so that positions stay put.
std::string withoutComments(std::string_view text) {
    std::string out(text);
    for (size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            out[i] = out[i + 1] = ' ';
            i += 2;
            while (i + 1 < out.size() && !(out[i] == '*' && out[i + 1] == '/')) {
                if (out[i] != '\n') out[i] = ' ';
                ++i;
            }
            for (size_t k = i; k < std::min(i + 2, out.size()); ++k) out[k] = ' ';
        }
    }
    return out;
}

bool isIdentifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// GLSL's built-in type names: `precision highp float;` must not read as declaring `float`.
bool isBuiltinType(const std::string& word) {
    static const std::regex builtin(R"((u|i|b|d)?vec[234]|d?mat[234](x[234])?|float|double|int|uint|bool|void)");
    return std::regex_match(word, builtin);
}

// Identifiers declared at brace and parenthesis depth 0: a name that follows another identifier
// (its type) and precedes '(', '=', ';', '[' or ','; and the name after `struct`. Also the
// names of #define lines, and `uniform TYPE NAME` declarations.
struct ShaderNames {
    std::vector<std::string> declared, macros;
    struct Uniform {
        std::string type, name;
        size_t offset;  // into the scanned text
    };
    std::vector<Uniform> uniforms;
    bool hasBrdf = false;
};

ShaderNames scanShader(const std::string& code) {
    ShaderNames names;
    int braces = 0, parens = 0;
    std::vector<std::string> statement;  // identifiers of the current depth-0 statement
    size_t i = 0;
    while (i < code.size()) {
        const char c = code[i];
        if (c == '#') {  // a preprocessor line: remember #define names
            const size_t end = code.find('\n', i);
            const std::string_view line(code.data() + i, (end == std::string::npos ? code.size() : end) - i);
            const std::vector<Token> tokens = splitTokens(std::string_view(line).substr(1));
            if (tokens.size() >= 2 && tokens[0].text == "define") {
                std::string_view name = tokens[1].text;
                name = name.substr(0, std::find_if_not(name.begin(), name.end(), isIdentifierChar) - name.begin());
                if (!name.empty()) names.macros.emplace_back(name);
            }
            i = end == std::string::npos ? code.size() : end;
            continue;
        }
        if (isIdentifierChar(c) && !std::isdigit(static_cast<unsigned char>(c))) {
            const size_t start = i;
            while (i < code.size() && isIdentifierChar(code[i])) ++i;
            const std::string word = code.substr(start, i - start);
            if (braces == 0 && parens == 0) {
                size_t next = i;
                while (next < code.size() && std::isspace(static_cast<unsigned char>(code[next]))) ++next;
                const char follow = next < code.size() ? code[next] : '\0';
                const bool declares = !statement.empty() && statement.back() != "return" &&
                                      (follow == '(' || follow == '=' || follow == ';' || follow == '[' || follow == ',');
                if ((declares || (!statement.empty() && statement.back() == "struct")) && !isBuiltinType(word)) {
                    names.declared.push_back(word);
                    if (word == "BRDF" && follow == '(' && statement.back() == "vec3") names.hasBrdf = true;
                    if (statement.size() >= 2 && statement[statement.size() - 2] == "uniform")
                        names.uniforms.push_back({statement.back(), word, start});
                }
                statement.push_back(word);
            }
            continue;
        }
        if (std::isdigit(static_cast<unsigned char>(c))) {
            while (i < code.size() && (isIdentifierChar(code[i]) || code[i] == '.')) ++i;
            continue;
        }
        if (c == '{') ++braces;
        else if (c == '}') {
            braces = std::max(0, braces - 1);
            if (braces == 0) statement.clear();
        } else if (c == '(') ++parens;
        else if (c == ')') parens = std::max(0, parens - 1);
        else if (c == ';' && braces == 0) statement.clear();
        ++i;
    }
    std::sort(names.declared.begin(), names.declared.end());
    names.declared.erase(std::unique(names.declared.begin(), names.declared.end()), names.declared.end());
    return names;
}

const char* glslTypeOf(ParamKind kind) {
    return kind == ParamKind::Bool ? "bool" : kind == ParamKind::Color ? "vec3" : "float";
}

// --- the file -----------------------------------------------------------------------------------

enum class Block { None, Parameters, Shader, Skipped };  // Skipped: a section BRDF Explorer knows, Glint does not use

// Reads the file a line at a time: the header, the blocks and the parameter lines.
class BrdfFileReader {
public:
    explicit BrdfFileReader(const std::string& path) { file_.path = path; }

    // One line (without its end); `content` is it trimmed, `here` where the content starts.
    Status readLine(std::string_view line, std::string_view content, const SourceLocation& here) {
        if (content.rfind("::", 0) == 0) {
            shaderLines_ += "\n";
            return readMarker(content, here);
        }
        if (block_ == Block::Shader) {
            shaderLines_ += std::string(line) + "\n";
            return success();
        }
        shaderLines_ += "\n";
        if (block_ == Block::Skipped || content.empty() || content[0] == '#') return success();
        if (block_ == Block::Parameters) return readParameter(line, here);
        if (!sawHeader_ && headerWord(content) == "analytic") {
            sawHeader_ = true;
            return success();
        }
        if (!sawHeader_)
            return makeError("the file must start with the line 'analytic' (only analytic BRDFs are supported; found '" +
                                 std::string(content.substr(0, 40)) + "')",
                             here);
        return makeError("text outside a block (expected '::begin parameters' or '::begin shader')", here);
    }

    // The file, once every line is read (`lastLine` the number of the last).
    Result<BrdfFile> finish(std::string_view text, int lastLine) {
        const std::string& path = file_.path;
        if (block_ != Block::None)
            return makeError("unterminated block: '::begin " +
                                 (block_ == Block::Shader ? std::string("shader") : block_ == Block::Parameters ? "parameters" : skippedSection_) +
                                 "' has no matching ::end",
                             {path, blockLine_, 1});
        if (!sawHeader_) return makeError("the file must start with the line 'analytic'", {path, 1, 1});
        if (!sawShader_) return makeError("no '::begin shader' block", {path, lastLine, 1});
        const std::string code = withoutComments(shaderLines_);
        const ShaderNames names = scanShader(code);
        if (!names.hasBrdf)
            return makeError("the shader block defines no 'vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)'",
                             {path, file_.shaderLine, 1});
        for (const ShaderNames::Uniform& uniform : names.uniforms)
            if (Status matched = matchUniform(uniform, code); !matched) return matched.error();
        file_.shaderText = std::move(shaderLines_);
        file_.sourceText = std::string(text);
        file_.topLevelNames = names.declared;
        file_.macroNames = names.macros;
        return std::move(file_);
    }

private:
    // '::begin SECTION' or '::end SECTION'.
    Status readMarker(std::string_view content, const SourceLocation& here) {
        const std::vector<Token> tokens = splitTokens(content.substr(2));
        const std::string verb = tokens.empty() ? "" : std::string(tokens[0].text);
        const std::string section = tokens.size() > 1 ? std::string(tokens[1].text) : "";
        if (tokens.size() != 2 || (verb != "begin" && verb != "end")) return makeError("expected '::begin SECTION' or '::end SECTION'", here);
        const Block named = section == "parameters" ? Block::Parameters : section == "shader" ? Block::Shader : Block::Skipped;
        if (verb == "end") {
            if (block_ != named || (named == Block::Skipped && section != skippedSection_))
                return makeError("'::end " + section + "' without '::begin " + section + "'", here);
            block_ = Block::None;
            return success();
        }
        if (block_ != Block::None)
            return makeError("'::begin " + section + "' inside the block opened at line " + std::to_string(blockLine_) +
                                 " (close it with ::end first)",
                             here);
        if (!sawHeader_) return makeError("the file must start with the line 'analytic'", here);
        if (named == Block::Skipped) {  // BRDF Explorer warns and reads on; so does Glint
            file_.warnings.push_back(makeError(
                "warning: section '" + section + "' is skipped" +
                    (section == "isFunc" ? " (BRDF Explorer's importance-sampling function, which Glint does not use)"
                                         : " (Glint reads 'parameters' and 'shader')"),
                {here.file, here.line, here.column + 2 + tokens[1].column - 1}));
            skippedSection_ = section;
        } else {
            bool& seen = named == Block::Parameters ? sawParameters_ : sawShader_;
            if (seen) return makeError("a second '::begin " + section + "' block", here);
            seen = true;
        }
        block_ = named;
        blockLine_ = here.line;
        if (named == Block::Shader) file_.shaderLine = here.line;
        return success();
    }

    Status readParameter(std::string_view line, const SourceLocation& here) {
        auto param = parseBrdfParamLine(line, file_.path, here.line);
        if (!param) return param.error();
        for (const BrdfFileParam& other : file_.params)
            if (other.name == param->name)
                return makeError("parameter '" + param->name + "' is declared twice (first at line " + std::to_string(other.line) + ")",
                                 {file_.path, here.line, static_cast<int>(line.find(param->name, 4)) + 1});
        if (static_cast<int>(file_.params.size()) >= kMaxBrdfParameters)
            return makeError("more than " + std::to_string(kMaxBrdfParameters) + " parameters", here);
        file_.params.push_back(std::move(*param));
        return success();
    }

    // A uniform named as a parameter must have the parameter's type; others are the shader's own (left at zero).
    Status matchUniform(const ShaderNames::Uniform& uniform, const std::string& code) {
        const auto param = std::find_if(file_.params.begin(), file_.params.end(),
                                        [&](const BrdfFileParam& p) { return p.name == uniform.name; });
        if (param == file_.params.end()) return success();
        if (uniform.type != glslTypeOf(param->kind))
            return makeError("'uniform " + uniform.type + " " + uniform.name + "' does not match the parameter declared at line " +
                                 std::to_string(param->line) + " (a " + glslTypeOf(param->kind) + ")",
                             {file_.path, 1 + static_cast<int>(std::count(code.begin(), code.begin() + uniform.offset, '\n')),
                              static_cast<int>(uniform.offset - code.rfind('\n', uniform.offset))});
        file_.declaredUniforms.push_back(uniform.name);
        return success();
    }

    BrdfFile file_;
    Block block_ = Block::None;
    int blockLine_ = 0;
    std::string skippedSection_;  // the open Block::Skipped's name
    bool sawHeader_ = false, sawParameters_ = false, sawShader_ = false;
    std::string shaderLines_;  // the shader block's lines; others blank
};

}  // namespace

Result<BrdfFile> parseBrdfFile(std::string_view text, const std::string& path) {
    if (text.size() > kMaxBrdfFileBytes)
        return makeError("the file is " + std::to_string(text.size()) + " bytes; a .brdf file may hold at most 1 MiB",
                         {path, 1, 1});
    if (Status utf8 = checkUtf8(text, path); !utf8) return utf8.error();
    BrdfFileReader reader(path);
    int lineNumber = 0;
    for (size_t position = 0; position <= text.size();) {
        const size_t end = std::min(text.find('\n', position), text.size());
        std::string_view line = text.substr(position, end - position);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        const bool last = end >= text.size();
        position = end + 1;
        ++lineNumber;
        if (last && line.empty()) {  // the end of a file that ends with a newline
            lineNumber = std::max(1, lineNumber - 1);
            break;
        }
        const std::string_view content = trimmed(line);
        const int column = static_cast<int>(content.data() - line.data()) + 1;
        if (Status read = reader.readLine(line, content, {path, lineNumber, column}); !read) return read.error();
    }
    return reader.finish(text, lineNumber);
}

Result<BrdfFile> loadBrdfFile(const std::string& path) { return parseTextFile(path, parseBrdfFile); }

}  // namespace glint
