// Custom BRDF programs (see custom_brdf_program.h).
#include "gl/custom_brdf_program.h"

#include <algorithm>
#include <regex>
#include <sstream>

#include "gl/uniform_blocks.h"

namespace glint {
namespace {

bool keepsItsName(const std::string& name) {
    static const std::regex swizzle("[xyzwrgbastpq]{1,4}");
    return std::regex_match(name, swizzle);
}

std::string includeName(const BrdfFile& file) {
    const bool plain = !file.path.empty() && file.path.find_first_of("\"\n\r") == std::string::npos;
    return plain ? file.path : "custom.brdf";
}

// Compile errors name the .brdf's include name (shader_sources.h maps them); the user knows its path.
std::string nameTheBrdfFile(const std::string& log, const BrdfFile& file) {
    const std::string included = includeName(file) + ":";
    std::istringstream lines(log);
    std::string line, out;
    while (std::getline(lines, line)) {
        if (line.rfind(included, 0) == 0) line = file.path + ":" + line.substr(included.size());
        out += line + "\n";
    }
    if (!out.empty()) out.pop_back();
    return out;
}

const char* glslType(ParamKind kind) {
    return kind == ParamKind::Bool ? "bool" : kind == ParamKind::Color ? "vec3" : "float";
}

}  // namespace

std::string customBrdfGlslName(const std::string& name) { return keepsItsName(name) ? name : "glintBrdf_" + name; }

GeneratedShaderFiles customBrdfShaderFiles(const CustomBrdf& brdf) {
    const BrdfFile& file = brdf.file;
    std::vector<std::string> renamed = file.topLevelNames;
    for (const BrdfFileParam& param : file.params) renamed.push_back(param.name);
    std::sort(renamed.begin(), renamed.end());
    renamed.erase(std::unique(renamed.begin(), renamed.end()), renamed.end());
    std::string defines, undefines, uniforms;
    for (const std::string& name : renamed) {
        if (keepsItsName(name)) continue;
        defines += "#define " + name + " " + customBrdfGlslName(name) + "\n";
        undefines += "#undef " + name + "\n";
    }
    for (const std::string& macro : file.macroNames) undefines += "#undef " + macro + "\n";
    for (const BrdfFileParam& param : file.params)
        if (std::find(file.declaredUniforms.begin(), file.declaredUniforms.end(), param.name) == file.declaredUniforms.end())
            uniforms += "uniform " + std::string(glslType(param.kind)) + " " + param.name + ";\n";
    const std::string name = includeName(file);
    std::string wrapper =
        "// Generated for the custom BRDF '" + name + "' (core/gl/custom_brdf_program.cpp): BRDF Explorer's\n"
        "// BRDF(L, V, N, X, Y) with L = wi, V = wo, N, X, Y = the shading frame's normal, tangent, bitangent.\n"
        "struct MaterialParams { float unused; };\n"
        "MaterialParams loadMaterialParams() { MaterialParams p; p.unused = 0.0; return p; }\n" +
        defines + uniforms + "#include \"" + name + "\"\n" +
        "vec3 glintEvalCustomBrdf(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {\n"
        "    return BRDF(wi, wo, frame.normal, frame.tangent, frame.bitangent);\n"
        "}\n" +
        undefines +
        "#define GLINT_EVAL_BRDF glintEvalCustomBrdf\n"
        "// A custom BRDF reflects no ambient light (its albedo is unknown without integrating it).\n"
        "vec3 glintCustomNoAmbient(MaterialParams p, vec3 wo, ShadingFrame frame) { return vec3(0.0); }\n"
        "#define GLINT_AMBIENT_REFLECTANCE glintCustomNoAmbient\n";
    return {{"generated/material.glsl", std::move(wrapper)},
            {name, file.shaderText}};
}

Result<const ShaderProgram*> CustomBrdfPrograms::program(const ShaderSources& sources, const CustomBrdf& brdf,
                                                        SurfaceVariant variant, std::uint64_t frame) {
    return cached(sources, brdf, "surface.vert", "surface.frag", variant.prelude(), frame);
}

Result<const ShaderProgram*> CustomBrdfPrograms::samplingProgram(const ShaderSources& sources, const CustomBrdf& brdf,
                                                                std::uint64_t frame) {
    return cached(sources, brdf, "fullscreen.vert", "brdf_sampler.frag", "", frame);
}

Result<const ShaderProgram*> CustomBrdfPrograms::cached(const ShaderSources& sources, const CustomBrdf& brdf,
                                                       const std::string& vertexPath, const std::string& fragmentPath,
                                                       const std::string& prelude, std::uint64_t frame) {
    const GeneratedShaderFiles files = customBrdfShaderFiles(brdf);
    std::string key;
    for (const auto& [path, text] : files) key += path + '\n' + text + '\0';
    const std::pair<std::string, std::string> id{key, vertexPath + '\n' + fragmentPath + '\n' + prelude};
    auto* entry = programs_.use(id, frame);
    if (!entry) {
        auto built = ShaderProgram::build(sources, vertexPath, fragmentPath, prelude, files);
        if (built) {
            built->bindBlock("FrameBlock", kFrameBinding);
            built->bindBlock("LightBlock", kLightBinding);
            built->bindBlock("MaterialBlock", kMaterialBinding);
            entry = &programs_.insert(id, std::move(*built), frame);
        } else {
            entry = &programs_.insert(id, makeError(nameTheBrdfFile(built.error().message, brdf.file), {brdf.file.path}), frame);
        }
    }
    if (const auto* error = std::get_if<Diagnostic>(entry)) return *error;
    return &std::get<ShaderProgram>(*entry);
}

void setCustomBrdfUniforms(const ShaderProgram& program, const CustomBrdf& brdf, const std::vector<float>& values) {
    GLINT_CHECK(static_cast<int>(values.size()) == packedSize(brdf.table));
    for (size_t i = 0; i < brdf.table.size(); ++i) {
        const ParamSpec& spec = brdf.table[i];
        const float* value = values.data() + packedOffset(brdf.table, static_cast<int>(i));
        const GLint location = program.uniform(customBrdfGlslName(spec.name).c_str());
        if (location < 0) continue;  // declared but unused: the compiler dropped it
        if (spec.kind == ParamKind::Bool) glUniform1i(location, value[0] > 0.5f ? 1 : 0);
        else if (spec.kind == ParamKind::Color) glUniform3f(location, value[0], value[1], value[2]);
        else glUniform1f(location, value[0]);
    }
}

}  // namespace glint
