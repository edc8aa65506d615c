// Reader for BRDF Explorer's analytic `.brdf` files (Disney, 2012): the `analytic` header, one
// `::begin parameters` block (float / bool / color lines) and one `::begin shader` block holding
// GLSL with `vec3 BRDF(vec3 L, vec3 V, vec3 N, vec3 X, vec3 Y)`. It checks the file and locates
// every error (file:line:column); it does not compile the GLSL (core/gl/custom_brdf_program.h does).
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "brdf/param_table.h"
#include "util/diagnostic.h"

namespace glint {

inline constexpr size_t kMaxBrdfFileBytes = 1 << 20;  // 1 MiB: analytic BRDFs are a few KiB
inline constexpr int kMaxBrdfParameters = 64;
inline constexpr float kMaxBrdfNumber = 1e30f;         // larger magnitudes are refused as "huge"

// One `float name min max default`, `bool name 0|1` or `color name r g b` line.
struct BrdfFileParam {
    std::string name;
    ParamKind kind = ParamKind::Scalar;  // Scalar (float), Bool or Color
    float min = 0.0f, max = 1.0f;        // float: the slider range (also the valid range); others 0..1
    std::array<float, 3> defaultValue{0, 0, 0};
    int line = 0;
};

struct BrdfFile {
    std::string path;  // as given, for messages and #line
    std::string sourceText;  // the file as read
    std::vector<BrdfFileParam> params;
    // The whole file with every line outside the shader block blanked, so that line N of this
    // text is line N of the file (compile errors then name the file's own lines).
    std::string shaderText;
    int shaderLine = 0;  // the `::begin shader` line
    // Names the shader declares at the top level (functions, constants, globals, uniforms, structs)
    // and names it #defines: the generated wrapper renames or #undefs them (custom_brdf_glsl.h).
    std::vector<std::string> topLevelNames;
    std::vector<std::string> macroNames;
    std::vector<std::string> declaredUniforms;  // parameters the shader declares as `uniform T name;`
    std::vector<Diagnostic> warnings;           // sections skipped (BRDF Explorer's `isFunc`, ...), located
};

// Parses .brdf text; `path` names it in messages.
Result<BrdfFile> parseBrdfFile(std::string_view text, const std::string& path);
Result<BrdfFile> loadBrdfFile(const std::string& path);

// --- shared with .bparam (bparam_file.h) ---------------------------------------------------------

// The first word of a header line (`analytic`, `bparam NAME`): BRDF Explorer reads only the word
// before the first space, so `analytic  # comment` is an `analytic` header.
std::string_view headerWord(std::string_view line);
// Checks that `text` is UTF-8; the error names the line and column of the first bad byte.
Status checkUtf8(std::string_view text, const std::string& path);
// Parses one parameter line (already split from its block); `line` locates errors.
Result<BrdfFileParam> parseBrdfParamLine(std::string_view lineText, const std::string& path, int line);
// Formats one parameter as a line of a parameters block with `value` as its default.
std::string formatBrdfParamLine(const BrdfFileParam& param, const float* value);

}  // namespace glint
