// Where shader text comes from and how it is assembled: files under shaders/ (read from disk in
// development builds, embedded in release builds), a small #include preprocessor that emits
// #line so compile errors name the right file and line, and the mapping of GL's error log
// back to those files. It compiles nothing; shader_program.h does.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "util/diagnostic.h"

namespace glint {

struct EmbeddedShader {
    const char* path;  // relative to shaders/
    const char* source;
};
const std::vector<EmbeddedShader>& embeddedShaders();  // generated at build time

class ShaderSources {
public:
    // Embedded copies; or, when `directory` is non-empty and exists, the files on disk.
    explicit ShaderSources(std::string directory = {});
    Result<std::string> read(const std::string& path) const;
    // Modification time of a file on disk (0 when embedded or missing): for hot reload.
    long long modificationTime(const std::string& path) const;
    bool readsFromDisk() const { return !directory_.empty(); }

private:
    std::string directory_;
};

// The sources a program should use: $GLINT_SHADER_DIR if set; else, in development builds, the
// source tree's shaders/ (hot-reloadable); else the embedded copies.
ShaderSources defaultShaderSources();

// The text has no #line directives: drivers do not all honour their source-string numbers (Mesa
// reports an undeclared name in an included file as line N of string 0), so a compile log's line
// numbers are counted in the whole text and mapped back through `lineOrigins`.
struct AssembledShader {
    struct Origin {
        int file;  // index into `files`
        int line;  // 1-based, in that file
    };
    std::string text;                 // ready for glShaderSource
    std::vector<std::string> files;   // the files it was assembled from (and "<generated prelude>")
    std::vector<Origin> lineOrigins;  // where each line of `text` comes from
};

// Generated files that #include can name beside the real ones, e.g. "generated/material.glsl".
using GeneratedShaderFiles = std::map<std::string, std::string>;

// Resolves `#include "path"` (relative to shaders/, or a generated file) recursively, once per
// file, and puts `prelude` (generated #defines) right after the #version line.
Result<AssembledShader> assembleShader(const ShaderSources& sources, const std::string& path,
                                       const std::string& prelude = {},
                                       const GeneratedShaderFiles& generated = {});

// Rewrites "0:812(5): error: ..." (Mesa) or "0(812) : error ..." (NVIDIA), line 812 of the
// assembled text, to "file:12:5: error: ..." in the file that line came from.
std::string mapCompileLog(const std::string& log, const AssembledShader& shader);

}  // namespace glint
