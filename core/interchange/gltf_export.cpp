// glTF 2.0 export (see gltf.h): one UV sphere carrying the material (openpbr through
// gltf_openpbr.h, with its textures), the lights as nodes with KHR_lights_punctual, the geometry
// in one buffer embedded as a base64 data URI.
// Sections: geometry buffer · material · lights · assembly.
#include "interchange/gltf.h"

#include <cmath>
#include <algorithm>
#include <set>

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "brdf/export_forms.h"
#include "brdf/model_registry.h"
#include "geometry/mesh.h"
#include "interchange/base64.h"
#include "interchange/gltf_openpbr.h"
#include "interchange/gltf_textures.h"
#include "light/photometry.h"
#include "scene/json_vectors.h"

namespace glint {
namespace {

using nlohmann::json;

constexpr int kSphereSegments = 48, kSphereRings = 24;
// glTF component types and buffer-view targets (glTF 2.0 §5.1.3, §5.11.4).
constexpr int kFloat = 5126, kUnsignedShort = 5123, kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// --- geometry buffer ------------------------------------------------------------------------

template <class T>
void append(std::vector<uint8_t>& bytes, const T& value) {
    const auto* raw = reinterpret_cast<const uint8_t*>(&value);
    bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

// Positions, normals (float VEC3 each), texture coordinates (float VEC2, glTF's v down: 1 − Glint's
// v) then indices (uint16), with accessors and views.
void addSphere(json& gltf) {
    const Mesh sphere = makeUvSphere(glm::vec3(0.0f), 1.0f, kSphereSegments, kSphereRings);
    std::vector<uint8_t> bytes;
    for (const Vertex& vertex : sphere.vertices) append(bytes, vertex.position);
    const size_t positionBytes = bytes.size();
    for (const Vertex& vertex : sphere.vertices) append(bytes, vertex.normal);
    const size_t normalBytes = bytes.size() - positionBytes;
    for (const Vertex& vertex : sphere.vertices) append(bytes, glm::vec2(vertex.uv.x, 1.0f - vertex.uv.y));
    const size_t uvBytes = bytes.size() - positionBytes - normalBytes;
    for (uint32_t index : sphere.indices) append(bytes, static_cast<uint16_t>(index));
    const size_t indexBytes = bytes.size() - positionBytes - normalBytes - uvBytes;
    while (bytes.size() % 4) bytes.push_back(0);  // buffer length a multiple of 4 (§5.9)
    const int vertexCount = static_cast<int>(sphere.vertices.size());
    const MeshBounds bounds = meshBounds(sphere);
    gltf["buffers"] = json::array({{{"byteLength", bytes.size()},
                                    {"uri", "data:application/octet-stream;base64," + encodeBase64(bytes)}}});
    gltf["bufferViews"] = json::array({
        {{"buffer", 0}, {"byteOffset", 0}, {"byteLength", positionBytes}, {"target", kArrayBuffer}},
        {{"buffer", 0}, {"byteOffset", positionBytes}, {"byteLength", normalBytes}, {"target", kArrayBuffer}},
        {{"buffer", 0}, {"byteOffset", positionBytes + normalBytes}, {"byteLength", uvBytes}, {"target", kArrayBuffer}},
        {{"buffer", 0}, {"byteOffset", positionBytes + normalBytes + uvBytes}, {"byteLength", indexBytes}, {"target", kElementArrayBuffer}},
    });
    gltf["accessors"] = json::array({
        {{"bufferView", 0}, {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC3"},
         {"min", {bounds.low.x, bounds.low.y, bounds.low.z}}, {"max", {bounds.high.x, bounds.high.y, bounds.high.z}}},
        {{"bufferView", 1}, {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC3"}},
        {{"bufferView", 2}, {"componentType", kFloat}, {"count", vertexCount}, {"type", "VEC2"}},
        {{"bufferView", 3}, {"componentType", kUnsignedShort}, {"count", sphere.indices.size()}, {"type", "SCALAR"}},
    });
    gltf["meshes"] = json::array({{{"name", "sphere"},
                                   {"primitives", json::array({{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}, {"TEXCOORD_0", 2}}},
                                                                {"indices", 3},
                                                                {"material", 0}}})}}});
}

// --- material -------------------------------------------------------------------------------

// A model's glTF form (brdf/export_forms.h) as a glTF material.
json formJson(const std::string& name, const GltfForm& form, std::set<std::string>& extensionsUsed) {
    const glm::vec3 base = form.baseColor;
    json out = {{"name", name},
                {"pbrMetallicRoughness", {{"baseColorFactor", {base.r, base.g, base.b, 1.0}},
                                          {"metallicFactor", form.kind == GltfForm::Kind::Metal ? 1.0 : 0.0},
                                          {"roughnessFactor", std::sqrt(form.alpha)}}}};
    if (form.kind == GltfForm::Kind::Metal) return out;
    json& extensions = out["extensions"];
    extensions["KHR_materials_ior"] = {{"ior", form.ior}};
    extensionsUsed.insert("KHR_materials_ior");
    if (form.kind == GltfForm::Kind::Dielectric) return out;
    extensions["KHR_materials_transmission"] = {{"transmissionFactor", 1.0}};
    extensionsUsed.insert("KHR_materials_transmission");
    const float strongest = std::max({form.absorption.r, form.absorption.g, form.absorption.b});
    if (strongest > 0.0f) {
        // KHR_materials_volume: σ = −ln(c)/d. Choosing d = 1/max σ keeps every c ≥ e^−1 (no underflow).
        const float distance = 1.0f / strongest;
        extensions["KHR_materials_volume"] = {{"thicknessFactor", 2.0},  // the sphere's diameter
                                              {"attenuationDistance", distance},
                                              {"attenuationColor", vec3Json(glm::exp(-form.absorption * distance))}};
        extensionsUsed.insert("KHR_materials_volume");
    }
    return out;
}

// --- lights ---------------------------------------------------------------------------------

// A node rotation taking glTF's light axis −Z onto `direction`.
glm::quat rotationTowards(glm::vec3 direction) {
    const glm::vec3 from(0, 0, -1), to = glm::normalize(direction);
    const float cosine = glm::dot(from, to);
    if (cosine < -0.999999f) return glm::quat(0, 0, 1, 0);  // half turn about +y
    const glm::vec3 axis = glm::cross(from, to);
    return glm::normalize(glm::quat(1.0f + cosine, axis.x, axis.y, axis.z));
}

void addLights(json& gltf, std::span<const Light> lights, std::vector<Diagnostic>& warnings) {
    json punctual = json::array();
    for (const Light& light : lights) {
        auto lost = [&](const std::string& what) { warnings.push_back(makeError("warning: light '" + light.name + "': " + what)); };
        if (light.type == LightType::Ambient) {
            lost("glTF has no ambient light; not written");
            continue;
        }
        if (!light.enabled) lost("written although it is switched off (glTF lights have no switch)");
        if (light.attenuation.enabled) lost("the classic attenuation is not kept (glTF is inverse-square)");
        json entry = {{"name", light.name}, {"color", vec3Json(light.color)}};
        json node = {{"name", light.name}};
        if (light.type == LightType::Directional) {
            entry["type"] = "directional";
            entry["intensity"] = luxFromIrradiance(light.irradiance, light.color);
        } else {
            entry["type"] = light.type == LightType::Point ? "point" : "spot";
            entry["intensity"] = candelaFromRadiantPower(light.power, light.color);
            node["translation"] = vec3Json(light.position);
        }
        if (light.type == LightType::Spot) {
            const float outer = glm::radians(light.coneHalfAngleDegrees);
            float inner = glm::radians(light.coneHalfAngleDegrees - light.edgeWidthDegrees);
            if (!(inner < outer)) {
                inner = outer * 0.999f;
                lost("a hard edge is written with innerConeAngle just below outerConeAngle (glTF needs inner < outer)");
            }
            entry["spot"] = {{"innerConeAngle", inner}, {"outerConeAngle", outer}};
            if (light.falloffExponent != 0.0f) lost("the cos^a falloff is not kept");
        }
        if (light.type != LightType::Point) {
            const glm::quat rotation = rotationTowards(light.direction);
            node["rotation"] = {rotation.x, rotation.y, rotation.z, rotation.w};
        }
        if (relativeLuminance(light.color) <= 0.0f) lost("a colour of zero luminance has no photometric intensity; written as 0");
        node["extensions"] = {{"KHR_lights_punctual", {{"light", punctual.size()}}}};
        punctual.push_back(entry);
        gltf["nodes"].push_back(node);
        gltf["scenes"][0]["nodes"].push_back(gltf["nodes"].size() - 1);
    }
    if (!punctual.empty()) gltf["extensions"]["KHR_lights_punctual"] = {{"lights", punctual}};
}

}  // namespace

// --- assembly -------------------------------------------------------------------------------

ExportedText writeGltf(const ImportedMaterial& imported, std::span<const Light> lights, const std::string& targetFile) {
    ExportedText out;
    std::set<std::string> extensionsUsed;
    GltfTextureWriter textures(targetFile);
    json gltf = {{"asset", {{"version", "2.0"}, {"generator", "Glint"}}}, {"scene", 0}};
    gltf["scenes"] = json::array({{{"nodes", json::array({0})}}});
    gltf["nodes"] = json::array({{{"name", "sphere"}, {"mesh", 0}}});
    addSphere(gltf);
    GLINT_CHECK(imported.material.analytic());  // exportMaterials converts the other kinds
    const AnalyticMaterial& material = *imported.material.analytic();
    const std::string& name = imported.material.name;
    auto lost = [&](const std::string& what) {
        out.warnings.push_back(makeError("warning: '" + name + "' (" + modelInfo(material.model).id + "): " + what));
    };
    const json written = dispatch(material.model, [&](auto model) -> json {
        using M = decltype(model);
        if constexpr (IsGltfOpenPbr<M>) {
            std::vector<std::string> used;
            json openPbr = gltfOpenPbrMaterial(imported, textures, used, out.warnings);
            extensionsUsed.insert(used.begin(), used.end());
            return openPbr;
        } else {
            GltfForm form{.lost = {"the model has no glTF form; written as a rough dielectric"}};
            if constexpr (HasGltfForm<M>) form = M::gltfForm(unpack<M>(material.values.data()));
            for (const std::string& what : form.lost) lost(what);
            if (!material.textures.empty())
                out.warnings.push_back(makeError("warning: material textures are written to glTF for the openpbr model only"));
            return formJson(name, form, extensionsUsed);
        }
    });
    gltf["materials"] = json::array({written});
    textures.writeInto(gltf);  // the openpbr material's textures; none for the other models
    if (!imported.textures.empty() && imported.gltfKept.empty())
        out.warnings.push_back(makeError("warning: " + std::to_string(imported.textures.size()) +
                                         " texture map(s) the source names but Glint does not render are not written to glTF"));
    addLights(gltf, lights, out.warnings);
    if (gltf.contains("extensions")) extensionsUsed.insert("KHR_lights_punctual");
    if (!extensionsUsed.empty()) gltf["extensionsUsed"] = json(std::vector<std::string>(extensionsUsed.begin(), extensionsUsed.end()));
    out.text = gltf.dump(2) + "\n";
    return out;
}

}  // namespace glint
