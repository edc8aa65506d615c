// Material export by extension (see export_formats.h).
#include "interchange/export_formats.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "interchange/gltf.h"
#include "interchange/materialx.h"
#include "interchange/mtl.h"

namespace glint {

namespace {

std::string lowerCaseExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return extension;
}

}  // namespace

bool isExportPath(const std::string& path) {
    const std::string extension = lowerCaseExtension(path);
    return std::any_of(std::begin(kExportExtensions), std::end(kExportExtensions), [&](const char* e) { return extension == e; });
}

Result<ExportedText> exportMaterials(std::span<const ImportedMaterial> materials, std::span<const Light> lights,
                                     const std::string& outputPath) {
    if (!isExportPath(outputPath)) return makeError("the output must end in .mtl, .gltf or .mtlx (got '" + outputPath + "')");
    if (materials.empty()) return makeError("no material to export");
    const std::string extension = lowerCaseExtension(outputPath);
    if (extension == ".mtlx") return writeMaterialX(materials, std::filesystem::absolute(outputPath).parent_path().string());
    return extension == ".mtl" ? writeMtl(materials) : writeGltf(materials.front(), lights, outputPath);
}

}  // namespace glint
