// The formats Glint writes materials to, by the output's extension: .mtl (every material, as a
// library), .gltf (the first material on a sphere, plus lights) and .mtlx (every material as a
// MaterialX open_pbr_surface). Used by `glint export` and
// File ▸ Export material…; it returns text and warnings and writes no file.
#pragma once

#include <span>
#include <string>

#include "interchange/imported.h"

namespace glint {

inline constexpr const char* kExportExtensions[] = {".mtl", ".gltf", ".mtlx"};
bool isExportPath(const std::string& path);  // ends in one of them (any case)

// The text for `outputPath` (its extension, any case, picks the format) and the warnings about
// what the format cannot hold; an error for another extension or no material. The formats hold
// analytic models only: a measured table is written as Lambert with its albedo at normal viewing,
// a .brdf shader is left out (a warning each); the writers below see analytic materials only.
Result<ExportedText> exportMaterials(std::span<const ImportedMaterial> materials, std::span<const Light> lights,
                                     const std::string& outputPath);

}  // namespace glint
