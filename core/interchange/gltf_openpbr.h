// glTF 2.0 materials ↔ Glint's `openpbr` model (OpenPBR Surface, brdf/openpbr_params.h):
// pbrMetallicRoughness with its textures and KHR_texture_transform, and KHR_materials_ior,
// _specular, _clearcoat, _sheen, _transmission, _volume, _iridescence, _anisotropy,
// _emissive_strength, _dispersion and _unlit, after the extension specifications and the
// OpenPBR specification's glTF notes. The table of what maps to what is docs/interchange.md.
//
// Emission: glTF's emissive colour (emissiveFactor × emissiveTexture × emissiveStrength) is read
// as a radiance of that many W/(m²·sr) per channel, i.e. 1 is the display's white at exposure 0:
// emission_color = emissiveFactor and emission_luminance = kGltfEmissionNits × emissiveStrength.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "interchange/gltf_textures.h"
#include "interchange/imported.h"
#include "math/constants.h"
#include "scene/json_document.h"

namespace glint {

// The luminance [nit] of glTF's emissive colour 1 (white): 683 lm/W × 1 W/(m²·sr).
inline constexpr float kGltfEmissionNits = kLumensPerWatt;

// Extensions a glTF material may use that Glint reads.
bool isGltfMaterialExtension(const std::string& name);

// One entry of "materials" onto an openpbr material: what does not map exactly is a warning
// located at its JSON pointer; what Glint reads but does not render (dispersion, the iridescence
// minimum) is kept in ImportedMaterial::gltfKept for export.
// Its images are read from `source` (gltf_images.h) or from files in the folder of its file.
ImportedMaterial readGltfMaterial(ObjectReader& reader, const GltfSource& source, int index);

// The glTF material of an openpbr material, with its kept values merged back; its images go
// through `textures`. Warnings say what glTF cannot hold.
nlohmann::json gltfOpenPbrMaterial(const ImportedMaterial& imported, GltfTextureWriter& textures,
                                   std::vector<std::string>& extensionsUsed, std::vector<Diagnostic>& warnings);

}  // namespace glint
