// glTF 2.0 material and light import (see gltf.h): materials through gltf_openpbr.h, lights
// after KHR_lights_punctual. Sections: units · materials · lights and nodes · entry points.
#include "interchange/gltf.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include <glm/gtc/quaternion.hpp>

#include "interchange/gltf_openpbr.h"
#include "interchange/gltf_textures.h"
#include "light/photometry.h"
#include "math/constants.h"
#include "scene/json_object_reader.h"
#include "util/file_io.h"

namespace glint {

// --- units ----------------------------------------------------------------------------------

// cd = 683 lm/W · Y(colour) · Φ/4π (W/sr), so Φ = 4π · cd / (683 · Y). A black colour carries no power.
float radiantPowerFromCandela(float candela, glm::vec3 color) {
    const float luminanceWeight = kLumensPerWatt * relativeLuminance(color);
    return luminanceWeight > 0.0f ? 4.0f * kPi * candela / luminanceWeight : 0.0f;
}
float candelaFromRadiantPower(float radiantPower, glm::vec3 color) {
    return kLumensPerWatt * relativeLuminance(color) * radiantPower / (4.0f * kPi);
}
float irradianceFromLux(float lux, glm::vec3 color) {
    const float luminanceWeight = kLumensPerWatt * relativeLuminance(color);
    return luminanceWeight > 0.0f ? lux / luminanceWeight : 0.0f;
}
float luxFromIrradiance(float irradiance, glm::vec3 color) { return kLumensPerWatt * relativeLuminance(color) * irradiance; }

namespace {

// --- materials (gltf_openpbr.h) ---------------------------------------------------------------

struct Context {
    const JsonDocument& document;
    std::vector<Diagnostic>& warnings;
    std::string file;  // the glTF file: image URIs are relative to its folder and confined to it
    void warn(const std::string& pointer, const std::string& message) const {
        warnings.push_back(makeError("warning: " + pointer + ": " + message, document.locate(pointer)));
    }
};

// --- lights and nodes -----------------------------------------------------------------------

glm::mat4 localTransform(ObjectReader& node) {
    if (node.has("matrix")) {
        const nlohmann::json& value = node.take("matrix");
        if (!value.is_array() || value.size() != 16) node.fail("matrix", "expected an array of 16 numbers");
        glm::mat4 matrix;
        for (int i = 0; i < 16; ++i)
            matrix[i / 4][i % 4] = static_cast<float>(node.checkedNumber(
                value[i], appendPointer(appendPointer(node.pointer(), "matrix"), std::to_string(i)), "matrix", Bounds::any()));
        return matrix;  // column-major, as glTF stores it
    }
    const glm::vec3 translation = node.vec3("translation", glm::vec3(0.0f));
    const glm::vec4 rotation = node.vec4("rotation", {0, 0, 0, 1}, Bounds::between(-1, 1));
    const glm::vec3 scale = node.vec3("scale", glm::vec3(1.0f));
    const glm::quat quaternion(rotation.w, rotation.x, rotation.y, rotation.z);  // glTF stores x, y, z, w
    if (glm::length(rotation) < 1e-6f) node.fail("rotation", "must be a unit quaternion");
    return glm::translate(glm::mat4(1.0f), translation) * glm::mat4_cast(glm::normalize(quaternion)) *
           glm::scale(glm::mat4(1.0f), scale);
}

struct PunctualLight {
    Light light;
    std::string pointer;
};

PunctualLight readPunctualLight(const Context& context, ObjectReader& reader, int index) {
    constexpr const char* kTypes[] = {"directional", "point", "spot"};
    if (!reader.has("type")) reader.failHere("a light needs a \"type\"");
    const int type = reader.choice("type", kTypes, 1);
    Light light;
    light.name = reader.string("name", "gltf light " + std::to_string(index));
    light.color = reader.vec3("color", glm::vec3(1.0f), Bounds::between(0, 1));  // linear RGB, as the extension specifies
    const float intensity = static_cast<float>(reader.number("intensity", 1.0, Bounds::nonNegative()));
    if (reader.has("range")) {
        reader.number("range", 0.0, Bounds::positive());
        context.warn(appendPointer(reader.pointer(), "range"), "range is ignored: Glint's lights follow the inverse-square law to infinity");
    }
    if (type == 0) {
        light.type = LightType::Directional;
        light.irradiance = irradianceFromLux(intensity, light.color);
    } else {
        light.type = type == 1 ? LightType::Point : LightType::Spot;
        light.power = radiantPowerFromCandela(intensity, light.color);
    }
    if (type == 2) {
        ObjectReader spot = reader.object("spot");
        const double inner = spot.number("innerConeAngle", 0.0, Bounds::between(0, kPi / 2));
        const double outer = spot.number("outerConeAngle", kPi / 4, Bounds::between(0, kPi / 2));
        if (!(outer > 0.0)) spot.fail("outerConeAngle", "must be greater than 0");
        if (!(inner < outer)) spot.fail("innerConeAngle", "must be less than outerConeAngle");
        light.coneHalfAngleDegrees = static_cast<float>(glm::degrees(outer));
        light.edgeWidthDegrees = static_cast<float>(glm::degrees(outer - inner));
        light.falloffExponent = 0.0f;
        rejectUnknownGltfKeys(spot);
    }
    if (!std::isfinite(light.power) || !std::isfinite(light.irradiance) || !std::isfinite(intensity))
        reader.fail("intensity", "is too large for Glint (single-precision watts)");
    if (relativeLuminance(light.color) <= 0.0f && intensity > 0.0f)
        context.warn(reader.pointer(), "a colour of zero luminance carries no power at 683 lm/W; imported dark");
    rejectUnknownGltfKeys(reader);
    return {light, reader.pointer()};
}

void readLights(const Context& context, ObjectReader& root, ImportedFile& result) {
    std::vector<PunctualLight> punctual;
    if (root.has("extensions")) {
        ObjectReader extensions = root.object("extensions");
        if (extensions.has("KHR_lights_punctual")) {
            ObjectReader lights = extensions.object("KHR_lights_punctual");
            int index = 0;
            for (ObjectReader& light : lights.objectArray("lights")) punctual.push_back(readPunctualLight(context, light, index++));
            lights.rejectUnknownKeys();
        }
    }
    std::vector<ObjectReader> nodes = root.has("nodes") ? root.objectArray("nodes") : std::vector<ObjectReader>();
    // Parents, then each node's world matrix by walking up (a cycle or a shared child is refused).
    std::vector<int> parent(nodes.size(), -1);
    std::vector<glm::mat4> local(nodes.size());
    std::vector<int> lightOf(nodes.size(), -1);
    for (size_t i = 0; i < nodes.size(); ++i) {
        ObjectReader& node = nodes[i];
        local[i] = localTransform(node);
        if (node.has("children")) {
            const nlohmann::json& children = node.take("children");
            if (!children.is_array()) node.fail("children", "expected an array of node indices");
            for (const auto& child : children) {
                if (!child.is_number_unsigned() || child.get<size_t>() >= nodes.size())
                    node.fail("children", "every child must be the index of a node");
                const size_t c = child.get<size_t>();
                if (parent[c] >= 0 || c == i) node.fail("children", "node " + std::to_string(c) + " has more than one parent");
                parent[c] = static_cast<int>(i);
            }
        }
        if (node.has("extensions")) {
            ObjectReader extensions = node.object("extensions");
            if (extensions.has("KHR_lights_punctual")) {
                ObjectReader reference = extensions.object("KHR_lights_punctual");
                lightOf[i] = reference.integer("light", -1, 0, 1'000'000);
                if (lightOf[i] < 0 || lightOf[i] >= static_cast<int>(punctual.size()))
                    reference.fail("light", "no such light in KHR_lights_punctual.lights");
                rejectUnknownGltfKeys(reference);
            }
        }
    }
    std::vector<bool> used(punctual.size(), false);
    for (size_t i = 0; i < nodes.size(); ++i) {
        if (lightOf[i] < 0) continue;
        glm::mat4 world = local[i];
        size_t steps = 0;
        for (int up = parent[i]; up >= 0; up = parent[up]) {
            if (++steps > nodes.size()) nodes[i].failHere("the node hierarchy has a cycle");
            world = local[up] * world;
        }
        Light light = punctual[lightOf[i]].light;
        light.position = glm::vec3(world * glm::vec4(0, 0, 0, 1));
        const glm::vec3 direction = glm::vec3(world * glm::vec4(0, 0, -1, 0));  // lights shine along −Z
        if (!(glm::length(direction) > 1e-12f)) nodes[i].failHere("the node's transform has no direction (zero scale)");
        if (glm::any(glm::isnan(light.position)) || glm::any(glm::isinf(light.position)) ||
            glm::any(glm::isinf(direction)) || glm::any(glm::isnan(direction)))
            nodes[i].failHere("the node's transform is not finite in single precision");
        light.direction = glm::normalize(direction);
        used[lightOf[i]] = true;
        result.lights.push_back(light);
    }
    for (size_t i = 0; i < punctual.size(); ++i)
        if (!used[i]) context.warn(punctual[i].pointer, "no node places this light; skipped");
}

}  // namespace

// --- extensions -----------------------------------------------------------------------------

bool isSupportedGltfExtension(const std::string& name) {
    return isGltfMaterialExtension(name) || name == "KHR_lights_punctual" || name == "KHR_texture_transform";
}

std::optional<Diagnostic> unsupportedRequiredExtension(const JsonDocument& document) {
    const nlohmann::json& root = document.root();
    if (!root.is_object() || !root.contains("extensionsRequired")) return std::nullopt;
    const nlohmann::json& required = root["extensionsRequired"];
    if (!required.is_array()) return makeError("extensionsRequired: expected an array of names", document.locate("/extensionsRequired"));
    for (size_t i = 0; i < required.size(); ++i)
        if (!required[i].is_string() || !isSupportedGltfExtension(required[i].get<std::string>()))
            return makeError("the file requires the extension " + required[i].dump() +
                                 ", which Glint does not support: it is not opened (docs/interchange.md lists the extensions Glint reads)",
                             document.locate("/extensionsRequired/" + std::to_string(i)));
    return std::nullopt;
}

std::vector<std::string> unsupportedUsedExtensions(const nlohmann::json& root) {
    std::vector<std::string> names;
    if (!root.is_object() || !root.contains("extensionsUsed") || !root["extensionsUsed"].is_array()) return names;
    for (const auto& name : root["extensionsUsed"])
        if (name.is_string() && !isSupportedGltfExtension(name.get<std::string>()) &&
            std::find(names.begin(), names.end(), name.get<std::string>()) == names.end())
            names.push_back(name.get<std::string>());
    return names;
}

// --- entry points ---------------------------------------------------------------------------

namespace {

// `text` is the .gltf `file`, or the JSON chunk of the .glb `file` whose BIN chunk is `glbBin`.
Result<ImportedFile> parse(const std::string& text, const std::string& file, std::optional<std::string_view> glbBin) {
    auto document = JsonDocument::parse(text, glbBin ? file + " (JSON chunk)" : file);
    if (!document) return document.error();
    ImportedFile result;
    const Context context{*document, result.warnings, file};
    const GltfSource source{*document, file, glbBin.value_or(std::string_view())};
    try {
        ObjectReader root = readRoot(*document, "glTF");
        if (!root.has("asset")) root.failHere("not a glTF file: it has no \"asset\"");
        ObjectReader asset = root.object("asset");
        const std::string version = asset.requiredString("version");
        if (version.rfind("2.", 0) != 0)
            asset.fail("version", "glTF " + version + " is not supported (Glint reads glTF 2.x)");
        if (auto refusal = unsupportedRequiredExtension(*document)) return *refusal;
        for (const std::string& name : unsupportedUsedExtensions(document->root()))
            context.warn("/extensionsUsed", "extension " + name + " is not supported by Glint; what it adds is ignored");
        if (root.has("materials")) {
            int index = 0;
            for (ObjectReader& material : root.objectArray("materials"))
                result.materials.push_back(readGltfMaterial(material, source, index++));
        }
        readLights(context, root, result);
        const nlohmann::json& meshes = document->root().contains("meshes") ? document->root()["meshes"] : nlohmann::json();
        for (size_t i = 0; meshes.is_array() && i < meshes.size(); ++i)
            result.meshNames.push_back(meshes[i].is_object() && meshes[i].contains("name") && meshes[i]["name"].is_string()
                                           ? meshes[i]["name"].get<std::string>()
                                           : "mesh " + std::to_string(i));
        if (result.materials.empty() && result.lights.empty() && result.meshNames.empty())
            root.failHere("the file has no material and no light (KHR_lights_punctual), and no mesh, for Glint to open");
    } catch (const JsonReadError& error) {
        return error.diagnostic;
    } catch (const nlohmann::json::exception& error) {  // a shape no check above foresaw: still a message, never a crash
        return makeError(std::string("malformed glTF: ") + error.what(), {file});
    }
    return result;
}

}  // namespace

Result<ImportedFile> parseGltf(const std::string& text, const std::string& file) { return parse(text, file, std::nullopt); }

Result<ImportedFile> parseGlbJson(const std::string& text, const std::string& file, std::string_view bin) { return parse(text, file, bin); }

Result<ImportedFile> loadGltf(const std::string& path) { return parseTextFile(path, parseGltf); }

}  // namespace glint
