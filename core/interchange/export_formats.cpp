// Material export by extension (see export_formats.h).
#include "interchange/export_formats.h"

#include <algorithm>
#include <filesystem>

#include "brdf/model_switch.h"
#include "interchange/gltf.h"
#include "interchange/measured_brdf.h"
#include "interchange/materialx.h"
#include "interchange/mtl.h"
#include "util/text.h"

namespace glint {
namespace {

// ".mtl" for "Paint.MTL", as kExportExtensions lists them.
std::string dottedExtension(const std::string& path) { return "." + lowerExtension(path); }

// What the formats hold: analytic models. A measured table goes as Lambert with its albedo at
// normal viewing (switchModel), a .brdf shader not at all; each says so.
std::vector<ImportedMaterial> analyticMaterials(std::span<const ImportedMaterial> materials, const std::string& format,
                                                std::vector<Diagnostic>& warnings) {
    std::vector<ImportedMaterial> analytic;
    for (const ImportedMaterial& imported : materials) {
        const std::string warning = "warning: material '" + imported.material.name + "' is ";
        std::visit(Overloaded{[&](const AnalyticMaterial&) { analytic.push_back(imported); },
                              [&](const CustomMaterial&) {
                                  warnings.push_back(makeError(warning + "a BRDF Explorer shader, which " + format + " cannot hold: not written"));
                              },
                              [&](const MeasuredMaterial& measured) {
                                  warnings.push_back(makeError(warning + "the measured BRDF " + measured.brdf->displayName + ", which has no " +
                                                               format + " form: written as Lambert with its measured albedo at normal viewing"));
                                  analytic.push_back(imported);
                                  analytic.back().material = switchModel(imported.material, BrdfModel::Lambert).material;
                              }},
                   imported.material.kind);
    }
    return analytic;
}

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
    const std::string format = extension == ".mtlx" ? "MaterialX" : extension == ".mtl" ? "MTL" : "glTF";
    std::vector<Diagnostic> warnings;
    const std::vector<ImportedMaterial> analytic = analyticMaterials(materials, format, warnings);
    if (analytic.empty()) return makeError(format + " cannot hold a BRDF Explorer shader: nothing to export");
    ExportedText written = extension == ".mtlx" ? writeMaterialX(analytic, std::filesystem::absolute(outputPath).parent_path().string())
                           : extension == ".mtl" ? writeMtl(analytic)
                                                 : writeGltf(analytic.front(), lights, outputPath);
    written.warnings.insert(written.warnings.begin(), warnings.begin(), warnings.end());
    return written;
}

}  // namespace glint
