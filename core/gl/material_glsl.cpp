// GLSL generated from a model's parameter table (see material_glsl.h).
#include "gl/material_glsl.h"

#include "texture/procedural.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

// The registry's optional hooks: ambient reflectance (zero when absent), specular transport and
// environment lighting.
std::string hooks(const ModelInfo& model) {
    std::string glsl;
    if (model.glslAmbient) {
        glsl += "#define GLINT_AMBIENT_REFLECTANCE " + std::string(model.glslAmbient) + "\n";
    } else {
        glsl += "vec3 noAmbientReflectance(MaterialParams p, vec3 wo, ShadingFrame frame) { return vec3(0.0); }\n"
                "#define GLINT_AMBIENT_REFLECTANCE noAmbientReflectance\n";
    }
    if (model.glslTransport) glsl += "#define GLINT_SPECULAR_TRANSPORT " + std::string(model.glslTransport) + "\n";
    // The environment hook exists only where common/environment.glsl was included first.
    if (model.glslEnvironment)
        glsl += "#ifdef GLINT_HAS_ENVIRONMENT\n#define GLINT_ENVIRONMENT_LIGHTING " + std::string(model.glslEnvironment) +
                "\n#endif\n";
    return glsl;
}

// A choice's load: the constant GLINT_PARAM_<name> of a specialised program
// (gl/shader_specialisation.h), else the value from MaterialBlock.
std::string specialisable(const std::string& name, const std::string& generic) {
    const std::string constant = "GLINT_PARAM_" + name;
    return "#ifdef " + constant + "\n    p." + name + " = " + constant + ";\n#else\n    p." + name + " = " + generic +
           ";\n#endif\n";
}

}  // namespace

int TexturedParams::bitOf(BrdfModel model, const MaterialTexture& texture) {
    const int index = findParam(modelInfo(model).params, texture.parameter);
    GLINT_CHECK(index < kCoatNormalMapBit);  // the bits above the table's are the maps' and the procedural flag
    return index >= 0                               ? index
           : texture.parameter == kNormalMapKey     ? kNormalMapBit
           : texture.parameter == kCoatNormalMapKey ? kCoatNormalMapBit
                                                    : kOcclusionMapBit;
}

TexturedParams TexturedParams::of(const AnalyticMaterial& material) {
    TexturedParams textured;
    for (const MaterialTexture& texture : material.textures) {
        textured.mask |= std::uint64_t{1} << bitOf(material.model, texture);
        if (texture.kind != TextureKind::Image) textured.mask |= std::uint64_t{1} << kProceduralBit;
    }
    return textured;
}

std::string generateMaterialGlsl(const ModelInfo& model, TexturedParams textured) {
    std::string constants, fields, loads;
    int offset = 0;
    for (size_t index = 0; index < model.params.size(); ++index) {
        const ParamSpec& spec = model.params[index];
        const std::string name = spec.name;
        // A textured parameter reads its slot (common/textures.glsl) instead of MaterialBlock.
        const std::string slot = std::to_string(textured.slotOf(static_cast<int>(index)));
        const bool isTextured = textured.has(static_cast<int>(index));
        const auto at = [&](int component) { return "materialValue(" + std::to_string(offset + component) + ")"; };
        switch (spec.kind) {
            case ParamKind::Scalar:
                fields += "    float " + name + ";\n";
                loads += isTextured ? "    p." + name + " = textureScalar(" + slot + ");\n" : specialisable(name, at(0));
                break;
            case ParamKind::Color:
            case ParamKind::PerChannel:
                fields += "    vec3 " + name + ";\n";
                loads += "    p." + name + " = " +
                         (isTextured ? "textureColor(" + slot + ")" : "vec3(" + at(0) + ", " + at(1) + ", " + at(2) + ")") + ";\n";
                break;
            case ParamKind::Bool:
                fields += "    bool " + name + ";\n";
                loads += specialisable(name, at(0) + " > 0.5");
                break;
            case ParamKind::Enum:
                for (size_t option = 0; option < spec.options.size(); ++option)
                    constants += "const int " + glslOptionConstant(name, spec.options[option].id) + " = " +
                                 std::to_string(option) + ";\n";
                fields += "    int " + name + ";\n";
                loads += specialisable(name, "int(" + at(0) + " + 0.5)");
                break;
        }
        offset += componentCount(spec.kind);
    }
    std::string textures;
    if (textured.mask != 0) {
        textures = "#define GLINT_TEXTURED 1\n";
        if (textured.hasProcedural()) textures += "#define GLINT_PROCEDURAL_TEXTURES 1\n" + perlinTableGlsl();
        textures += "#include \"common/textures.glsl\"\n";
        if (textured.hasNormalMap()) textures += "#define GLINT_NORMAL_MAP_SLOT " + std::to_string(textured.normalMapSlot()) + "\n";
        if (textured.hasOcclusionMap())
            textures += "#define GLINT_OCCLUSION_SLOT " + std::to_string(textured.slotOf(TexturedParams::kOcclusionMapBit)) + "\n";
        if (textured.has(TexturedParams::kCoatNormalMapBit))
            textures += "#define GLINT_COAT_NORMAL_SLOT " + std::to_string(textured.slotOf(TexturedParams::kCoatNormalMapBit)) + "\n";
    }
    return "// Generated from the parameter table of '" + std::string(model.id) + "'.\n" + textures + constants +
           "struct MaterialParams {\n" + fields + "};\n\n" +
           "MaterialParams loadMaterialParams() {\n    MaterialParams p;\n" + loads + "    return p;\n}\n\n" +
           (model.glslTables ? model.glslTables() : std::string()) + "#include \"" + model.glslFile + "\"\n" + "#define GLINT_EVAL_BRDF " + model.glslEval + "\n" +
           hooks(model);
}

}  // namespace glint
