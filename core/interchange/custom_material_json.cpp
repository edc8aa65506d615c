// .brdf materials in JSON (see custom_material_json.h).
#include "interchange/custom_material_json.h"

#include <filesystem>
#include <system_error>

#include "interchange/custom_brdf.h"
#include "scene/param_values_json.h"
#include "util/referenced_path.h"

namespace glint {

namespace fs = std::filesystem;

Material readCustomBrdfMaterial(ObjectReader& reader, std::string name) {
    const std::string model = reader.requiredString("model");
    if (model != kCustomBrdfModelId)
        reader.fail("model", "a material with \"brdf_file\" has \"model\": \"brdf_file\", not \"" + model + "\"");
    const std::string written = reader.requiredString("brdf_file");
    const fs::path path = resolveReferencedPath(written, reader.file());
    std::error_code error;
    // Only a regular file of sane size is read (never a device or a fifo).
    if (!fs::is_regular_file(path, error))
        reader.fail("brdf_file", "'" + path.string() + "' is not a readable .brdf file");
    if (fs::file_size(path, error) > kMaxBrdfFileBytes) reader.fail("brdf_file", "'" + path.string() + "' is larger than 1 MiB");
    auto brdf = loadCustomBrdf(path.lexically_normal().string());
    if (!brdf) reader.fail("brdf_file", "cannot use '" + written + "': " + brdf.error().format());
    Material material = customBrdfMaterial(std::move(*brdf));
    material.name = std::move(name);
    material.values = readParamValues(reader, material.custom->table);
    static constexpr const char* kReserved[] = {"name", "model", "format", "version", "brdf_file"};
    reader.rejectUnknownKeys(kReserved);
    return material;
}

nlohmann::json customBrdfMaterialBody(const Material& material, const std::string& savedTo) {
    nlohmann::json out = {{"name", material.name}, {"model", kCustomBrdfModelId},
                          {"brdf_file", referencedPathFor(material.custom->file.path, savedTo)}};
    writeParamValues(out, material.custom->table, material.values);
    return out;
}

}  // namespace glint
