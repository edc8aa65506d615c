// Material export by extension (see export_formats.h).
#include "interchange/export_formats.h"

#include <algorithm>
#include <filesystem>

#include "interchange/gltf.h"
#include "interchange/materialx.h"
#include "interchange/mtl.h"
#include "util/text.h"

namespace glint {
namespace {

// ".mtl" for "Paint.MTL", as kExportExtensions lists them.
std::string dottedExtension(const std::string& path) { return "." + lowerExtension(path); }

}  // namespace

bool isExportPath(const std::string& path) {
    const std::string extension = dottedExtension(path);
    return std::any_of(std::begin(kExportExtensions), std::end(kExportExtensions), [&](const char* e) { return extension == e; });
}

Result<ExportedText> exportMaterials(std::span<const ImportedMaterial> materials, std::span<const Light> lights,
                                     const std::string& outputPath) {
    if (!isExportPath(outputPath)) return makeError("the output must end in .mtl, .gltf or .mtlx (got '" + outputPath + "')");
    if (materials.empty()) return makeError("no material to export");
    const std::string extension = dottedExtension(outputPath);
    if (extension == ".mtlx") return writeMaterialX(materials, std::filesystem::absolute(outputPath).parent_path().string());
    return extension == ".mtl" ? writeMtl(materials) : writeGltf(materials.front(), lights, outputPath);
}

}  // namespace glint
