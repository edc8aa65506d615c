// Shader sources, #include preprocessing and error-log mapping (see shader_sources.h).
#include "gl/shader_sources.h"

#include <charconv>
#include <cstdlib>
#include <regex>
#include <set>
#include <sstream>
#include <sys/stat.h>

#include "util/file_io.h"

namespace glint {

ShaderSources::ShaderSources(std::string directory) {
    struct stat info {};
    if (!directory.empty() && ::stat(directory.c_str(), &info) == 0 && S_ISDIR(info.st_mode))
        directory_ = std::move(directory);
}

Result<std::string> ShaderSources::read(const std::string& path) const {
    if (!directory_.empty()) return readTextFile(directory_ + "/" + path);
    for (const EmbeddedShader& shader : embeddedShaders())
        if (path == shader.path) return std::string(shader.source);
    return makeError("no such shader in this build", {path});
}

long long ShaderSources::modificationTime(const std::string& path) const {
    if (directory_.empty()) return 0;
    struct stat info {};
    if (::stat((directory_ + "/" + path).c_str(), &info) != 0) return 0;
    return static_cast<long long>(info.st_mtim.tv_sec) * 1'000'000'000LL + info.st_mtim.tv_nsec;
}

ShaderSources defaultShaderSources() {
    if (const char* directory = std::getenv("GLINT_SHADER_DIR"); directory && *directory)
        return ShaderSources(directory);
#ifdef GLINT_SOURCE_SHADER_DIR
    return ShaderSources(GLINT_SOURCE_SHADER_DIR);
#else
    return ShaderSources();
#endif
}

namespace {

struct Assembler {
    const ShaderSources& sources;
    const GeneratedShaderFiles& generated;
    AssembledShader out;
    std::set<std::string> included;

    void emit(const std::string& line, int fileIndex, int lineNumber) {
        out.text += line + "\n";
        out.lineOrigins.push_back({fileIndex, lineNumber});
    }

    Status append(const std::string& path, const SourceLocation& includedFrom, const std::string& prelude,
                  int depth) {
        if (depth > 32) return makeError("#include nested too deeply (a cycle?)", includedFrom);
        if (!included.insert(path).second) return success();  // once per file
        const auto generatedFile = generated.find(path);
        auto text = generatedFile != generated.end() ? Result<std::string>(generatedFile->second) : sources.read(path);
        if (!text) {
            if (includedFrom.file.empty()) return text.error();
            return makeError("cannot include \"" + path + "\": " + text.error().message, includedFrom);
        }
        const int fileIndex = static_cast<int>(out.files.size());
        out.files.push_back(path);
        std::istringstream lines(*text);
        std::string line;
        int lineNumber = 0;
        static const std::regex includePattern(R"(^\s*#\s*include\s+"([^"]+)\"\s*$)");
        while (std::getline(lines, line)) {
            ++lineNumber;
            std::smatch match;
            if (std::regex_match(line, match, includePattern)) {
                if (Status status = append(match[1], {path, lineNumber, 1}, {}, depth + 1); !status) return status;
                continue;
            }
            emit(line, fileIndex, lineNumber);
            if (lineNumber == 1 && depth == 0 && line.rfind("#version", 0) == 0 && !prelude.empty()) {
                const int preludeIndex = static_cast<int>(out.files.size());
                out.files.push_back("<generated prelude>");
                std::istringstream preludeLines(prelude);
                for (int preludeLine = 1; std::getline(preludeLines, line); ++preludeLine) emit(line, preludeIndex, preludeLine);
            }
        }
        return success();
    }
};

}  // namespace

Result<AssembledShader> assembleShader(const ShaderSources& sources, const std::string& path,
                                       const std::string& prelude, const GeneratedShaderFiles& generated) {
    Assembler assembler{sources, generated, {}, {}};
    if (Status status = assembler.append(path, {}, prelude, 0); !status) return status.error();
    return std::move(assembler.out);
}

std::string mapCompileLog(const std::string& log, const AssembledShader& shader) {
    static const std::regex mesaPattern(R"(^(\d+):(\d+)\((\d+)\):\s*)");
    static const std::regex nvidiaPattern(R"(^(\d+)\((\d+)\)\s*:\s*)");
    // "file:line" of line `assembledLine` of the text (the driver's count, from 1).
    auto origin = [&](const std::string& assembledLine) {
        size_t i = 0;
        std::from_chars(assembledLine.data(), assembledLine.data() + assembledLine.size(), i);
        if (i < 1 || i > shader.lineOrigins.size()) return "<line " + assembledLine + ">";
        const AssembledShader::Origin& from = shader.lineOrigins[i - 1];
        return shader.files[static_cast<size_t>(from.file)] + ":" + std::to_string(from.line);
    };
    std::istringstream lines(log);
    std::string line, mapped;
    while (std::getline(lines, line)) {
        std::smatch match;
        if (std::regex_search(line, match, mesaPattern))
            line = origin(match[2]) + ":" + match[3].str() + ": " + match.suffix().str();
        else if (std::regex_search(line, match, nvidiaPattern))
            line = origin(match[2]) + ": " + match.suffix().str();
        if (!line.empty()) mapped += line + "\n";
    }
    return mapped;
}

}  // namespace glint
