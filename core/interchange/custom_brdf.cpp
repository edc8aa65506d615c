// A .brdf file as a Glint model (see custom_brdf.h).
#include "interchange/custom_brdf.h"

#include <filesystem>

#include "scene/preview_stage.h"
#include "scene/scene.h"
#include "snapshot/case_source.h"
#include "util/text.h"

namespace glint {

std::shared_ptr<const CustomBrdf> makeCustomBrdf(BrdfFile file) {
    auto custom = std::make_shared<CustomBrdf>();
    custom->file = std::move(file);
    custom->displayName = std::filesystem::path(custom->file.path).filename().string();
    for (const BrdfFileParam& param : custom->file.params) {
        ParamSpec spec{param.name.c_str(), param.name.c_str(), "", param.kind};
        if (param.kind == ParamKind::Scalar) {
            spec.sliderMin = spec.validMin = param.min;
            spec.sliderMax = spec.validMax = param.max;
        } else if (param.kind == ParamKind::Color) {
            spec.validMax = kUnbounded;  // BRDF Explorer colours may exceed 1 (a scale, not an albedo)
        }
        spec.defaultValue = param.defaultValue;
        spec.help = "From the .brdf file's parameters block";
        custom->table.push_back(spec);
    }
    return custom;
}

Result<std::shared_ptr<const CustomBrdf>> loadCustomBrdf(const std::string& path) {
    auto file = loadBrdfFile(path);
    if (!file) return file.error();
    return makeCustomBrdf(std::move(*file));
}

Material customBrdfMaterial(std::shared_ptr<const CustomBrdf> brdf) {
    std::string name = std::filesystem::path(brdf->displayName).stem().string();
    std::vector<float> values = defaultValues(brdf->table);
    return Material{std::move(name), CustomMaterial{std::move(brdf), std::move(values)}};
}

bool isBrdfFilePath(const std::string& path) {
    return lowerExtension(path) == "brdf";
}

Result<Scene> loadBrdfPreviewStage(const std::string& path, std::vector<Diagnostic>* warnings, int width, int height) {
    auto brdf = loadCustomBrdf(path);
    if (!brdf) return brdf.error();
    if (warnings) warnings->insert(warnings->end(), (*brdf)->file.warnings.begin(), (*brdf)->file.warnings.end());
    return previewStage(customBrdfMaterial(std::move(*brdf)), width > 0 ? width : kDefaultMaterialPreviewSize,
                        height > 0 ? height : kDefaultMaterialPreviewSize);
}

Status referenceCanRender(const Scene& scene) {
    for (const Material& material : scene.materials)
        if (const CustomMaterial* custom = material.custom())
            return makeError("material '" + material.name + "' uses the custom BRDF " + custom->brdf->file.path +
                             ": custom .brdf shaders run only on the GPU preview, not on the CPU reference");
    return success();
}

}  // namespace glint
