// MaterialX documents (.mtlx, MaterialX 1.38/1.39): reading every surfacematerial (or, without
// one, every surface shader) whose shader is an open_pbr_surface, standard_surface or gltf_pbr
// into a Glint openpbr material, and writing Glint materials as open_pbr_surface shaders with
// surfacematerials (ND_open_pbr_surface_surfaceshader). Image nodes become material textures
// where Glint's textures can carry them; anything else is a located warning. No geometry, looks
// or lights are read.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "interchange/imported.h"

namespace glint {

// Parses .mtlx text; `file` names it in messages (file:line:column) and locates its images.
// Not well-formed XML, a root that is not <materialx>, malformed values and broken connections
// are errors; a document with no readable shader is an error naming the shaders it holds.
Result<ImportedFile> parseMaterialX(std::string_view text, const std::string& file);
Result<ImportedFile> loadMaterialX(const std::string& path);

// One open_pbr_surface and surfacematerial per material; a material in another model is
// converted first (model_switch.h) and what the conversion dropped is a warning. Image
// textures are written as image nodes with paths relative to `folder` (absolute when empty).
ExportedText writeMaterialX(std::span<const ImportedMaterial> materials, const std::string& folder);

}  // namespace glint
