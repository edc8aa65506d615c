// .brdf and MERL materials in JSON (see file_material_json.h).
#include "interchange/file_material_json.h"

#include <filesystem>
#include <system_error>

#include "interchange/custom_brdf.h"
#include "interchange/measured_brdf.h"
#include "scene/param_values_json.h"
#include "util/referenced_file_error.h"
#include "util/referenced_path.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// The regular file (never a device or a fifo) named by `key`, of a material whose "model" must be `modelId`.
fs::path referencedFile(ObjectReader& reader, const char* modelId, const char* key, const std::string& what) {
    const std::string model = reader.requiredString("model");
    if (model != modelId)
        reader.fail("model", std::string("a material with \"") + key + "\" has \"model\": \"" + modelId + "\", not \"" + model + "\"");
    const fs::path path = reader.referencedFile(key);
    std::error_code error;
    if (!fs::is_regular_file(path, error)) reader.fail(key, "'" + path.string() + "' is not a readable " + what);
    return path;
}

}  // namespace

Material readCustomBrdfMaterial(ObjectReader& reader, std::string name) {
    const fs::path path = referencedFile(reader, kCustomBrdfModelId, "brdf_file", ".brdf file");
    std::error_code error;
    if (fs::file_size(path, error) > kMaxBrdfFileBytes) reader.fail("brdf_file", "'" + path.string() + "' is larger than 1 MiB");
    auto brdf = loadCustomBrdf(path.lexically_normal().string());
    if (!brdf) reader.fail("brdf_file", referencedFileProblem(path.string(), brdf.error(), ".brdf file"));
    Material material = customBrdfMaterial(std::move(*brdf));
    material.name = std::move(name);
    material.custom()->values = readParamValues(reader, material.custom()->brdf->table);
    static constexpr const char* kReserved[] = {"name", "model", "format", "version", "brdf_file"};
    reader.rejectUnknownKeys(kReserved);
    return material;
}

Material readMeasuredMaterial(ObjectReader& reader, std::string name) {
    const fs::path path = referencedFile(reader, kMeasuredModelId, "merl_file", "MERL .binary file");
    auto brdf = loadMeasuredBrdf(path.string());
    if (!brdf) reader.fail("merl_file", referencedFileProblem(path.string(), brdf.error(), "MERL .binary file"));
    Material material = measuredBrdfMaterial(std::move(*brdf));
    material.name = std::move(name);
    static constexpr const char* kKnown[] = {"name", "model", "format", "version", "merl_file"};
    reader.rejectUnknownKeys(kKnown);
    return material;
}

nlohmann::json customBrdfMaterialBody(const std::string& name, const CustomMaterial& material, const std::string& savedTo) {
    nlohmann::json out = {{"name", name}, {"model", kCustomBrdfModelId}, {"brdf_file", referencedPathFor(material.brdf->file.path, savedTo)}};
    writeParamValues(out, material.brdf->table, material.values);
    return out;
}

nlohmann::json measuredMaterialBody(const std::string& name, const MeasuredMaterial& material, const std::string& savedTo) {
    return {{"name", name}, {"model", kMeasuredModelId}, {"merl_file", referencedPathFor(material.brdf->path, savedTo)}};
}

}  // namespace glint
