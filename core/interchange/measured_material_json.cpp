// MERL materials in JSON (see measured_material_json.h).
#include "interchange/measured_material_json.h"

#include <filesystem>
#include <system_error>

#include "interchange/measured_brdf.h"
#include "util/referenced_path.h"

namespace glint {

namespace fs = std::filesystem;

Material readMeasuredMaterial(ObjectReader& reader, std::string name) {
    const std::string model = reader.requiredString("model");
    if (model != kMeasuredModelId)
        reader.fail("model", "a material with \"merl_file\" has \"model\": \"merl\", not \"" + model + "\"");
    const std::string written = reader.requiredString("merl_file");
    const fs::path path = resolveReferencedPath(written, reader.file());
    std::error_code error;
    if (!fs::is_regular_file(path, error))  // never a device or a fifo
        reader.fail("merl_file", "'" + path.string() + "' is not a readable MERL .binary file");
    auto brdf = loadMeasuredBrdf(path.string());
    if (!brdf) reader.fail("merl_file", "cannot use '" + written + "': " + brdf.error().format());
    Material material = measuredBrdfMaterial(std::move(*brdf));
    material.name = std::move(name);
    static constexpr const char* kKnown[] = {"name", "model", "format", "version", "merl_file"};
    reader.rejectUnknownKeys(kKnown);
    return material;
}

nlohmann::json measuredMaterialBody(const Material& material, const std::string& savedTo) {
    return {{"name", material.name}, {"model", kMeasuredModelId}, {"merl_file", referencedPathFor(material.measured->path, savedTo)}};
}

}  // namespace glint
