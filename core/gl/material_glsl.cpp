// GLSL generated from a model's parameter table (see material_glsl.h).
#include "gl/material_glsl.h"

namespace glint {

std::string generateMaterialGlsl(const ModelInfo& model) {
    std::string fields, loads;
    int offset = 0;
    for (const ParamSpec& spec : model.params) {
        const std::string name = spec.name;
        const auto at = [&](int component) { return "materialValue(" + std::to_string(offset + component) + ")"; };
        switch (spec.kind) {
            case ParamKind::Scalar:
                fields += "    float " + name + ";\n";
                loads += "    p." + name + " = " + at(0) + ";\n";
                break;
            case ParamKind::Color:
                fields += "    vec3 " + name + ";\n";
                loads += "    p." + name + " = vec3(" + at(0) + ", " + at(1) + ", " + at(2) + ");\n";
                break;
            case ParamKind::Bool:
                fields += "    bool " + name + ";\n";
                loads += "    p." + name + " = " + at(0) + " > 0.5;\n";
                break;
            case ParamKind::Enum:
                fields += "    int " + name + ";\n";
                loads += "    p." + name + " = int(" + at(0) + " + 0.5);\n";
                break;
        }
        offset += componentCount(spec.kind);
    }
    return "// Generated from the parameter table of '" + std::string(model.id) + "'.\n" +
           "struct MaterialParams {\n" + fields + "};\n\n" +
           "MaterialParams loadMaterialParams() {\n    MaterialParams p;\n" + loads + "    return p;\n}\n\n" +
           "#include \"" + model.glslFile + "\"\n" + "#define GLINT_EVAL_BRDF " + model.glslEval + "\n";
}

}  // namespace glint
