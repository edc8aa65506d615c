// glTF 2.0 materials and lights: importing pbrMetallicRoughness with its textures and the
// KHR_materials_* extensions onto the openpbr model (gltf_openpbr.h), and KHR_lights_punctual
// lights with their photometric units converted; exporting a material on a UV sphere, plus
// lights, as a .gltf with the geometry embedded. Meshes, animations and cameras are not read here.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "interchange/imported.h"
#include "scene/json_document.h"

namespace glint {

// Parses glTF 2.0 JSON text (not .glb); `file` names it in messages (file:line:column and the
// JSON key). Every material becomes an ImportedMaterial, every light used by a node a Light, every
// mesh a name; a file with none of them is an error.
Result<ImportedFile> parseGltf(const std::string& text, const std::string& file);
// The JSON chunk `text` of the .glb `file`, whose BIN chunk (buffer 0) is `bin`; messages name
// "FILE (JSON chunk):line:column".
Result<ImportedFile> parseGlbJson(const std::string& text, const std::string& file, std::string_view bin);
Result<ImportedFile> loadGltf(const std::string& path);

// A .gltf with one node: a UV sphere of radius 1 (with texture coordinates) carrying `material`,
// the buffer embedded as a base64 data URI, and one node per light (KHR_lights_punctual).
// Texture images are referenced relative to the folder of `targetFile` (absolute when it is "").
// Warnings say what glTF cannot hold (e.g. an ambient light, a Beckmann distribution).
ExportedText writeGltf(const ImportedMaterial& material, std::span<const Light> lights, const std::string& targetFile = "");

// Extensions Glint reads (gltf_openpbr.h's material extensions, KHR_lights_punctual,
// KHR_texture_transform): a file may require these only.
bool isSupportedGltfExtension(const std::string& name);
// The refusal of a file whose "extensionsRequired" names an extension Glint lacks, located at that
// name and naming it; nothing when it names none. Every reader of a glTF checks it first.
std::optional<Diagnostic> unsupportedRequiredExtension(const JsonDocument& document);
// The names in "extensionsUsed" Glint lacks, each once, for one warning each.
std::vector<std::string> unsupportedUsedExtensions(const nlohmann::json& root);

// Photometric ↔ radiometric light units at 683 lm/W weighted by the luminance Y of the colour
// (light/photometry.h): glTF point and spot intensity in cd ↔ Glint's power Φ in W of the
// isotropic light (I = Φ/4π); directional illuminance in lx ↔ irradiance M in W/m².
float radiantPowerFromCandela(float candela, glm::vec3 color);
float candelaFromRadiantPower(float radiantPower, glm::vec3 color);
float irradianceFromLux(float lux, glm::vec3 color);
float luxFromIrradiance(float irradiance, glm::vec3 color);

}  // namespace glint
