// glTF 2.0 material and light import (see gltf.h). Mapping after the glTF 2.0 specification,
// Appendix B (BRDF implementation), and the KHR_materials_* / KHR_lights_punctual extension specs.
// Sections: units · materials · extensions · lights and nodes · entry points.
#include "interchange/gltf.h"

#include <cmath>
#include <filesystem>
#include <set>

#include <glm/gtc/quaternion.hpp>

#include "interchange/material_values.h"
#include "light/photometry.h"
#include "math/constants.h"
#include "scene/json_object_reader.h"
#include "texture/material_texture.h"
#include "texture/texture_image.h"
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

// --- materials ------------------------------------------------------------------------------

// Extensions whose absence from Glint does not change what the file means to a viewer.
const std::set<std::string> kKnownExtensions = {
    "KHR_materials_ior", "KHR_materials_specular", "KHR_materials_transmission", "KHR_materials_volume",
    "KHR_materials_clearcoat", "KHR_materials_emissive_strength", "KHR_lights_punctual"};

struct Context {
    const JsonDocument& document;
    std::vector<Diagnostic>& warnings;
    std::filesystem::path folder;  // image URIs are relative to it
    void warn(const std::string& pointer, const std::string& message) const {
        warnings.push_back(makeError("warning: " + pointer + ": " + message, document.locate(pointer)));
    }
};

glm::vec4 readVec4(ObjectReader& reader, const std::string& key, glm::vec4 fallback, Bounds bounds) {
    if (!reader.has(key)) return fallback;
    const nlohmann::json& value = reader.take(key);
    const std::string pointer = appendPointer(reader.pointer(), key);
    if (!value.is_array() || value.size() != 4) reader.fail(key, "expected an array of 4 numbers");
    glm::vec4 result;
    for (int i = 0; i < 4; ++i)
        result[i] = static_cast<float>(reader.checkedNumber(value[i], appendPointer(pointer, std::to_string(i)),
                                                            key + "[" + std::to_string(i) + "]", bounds));
    return result;
}

// A texture slot ({"index": n, ...}) kept as a reference to the image's URI.
void readTexture(const Context& context, ObjectReader& reader, const std::string& key, const nlohmann::json& root,
                 ImportedMaterial& imported) {
    if (!reader.has(key)) return;
    ObjectReader texture = reader.object(key);
    const int index = texture.integer("index", -1, 0, 1'000'000);
    if (index < 0) texture.failHere("a texture needs an \"index\"");
    std::string path = "(texture " + std::to_string(index) + ")";
    const auto& textures = root.contains("textures") ? root["textures"] : nlohmann::json();
    if (!textures.is_array() || index >= static_cast<int>(textures.size()))
        texture.fail("index", "texture " + std::to_string(index) + " does not exist");
    const auto& entry = textures[index];
    if (entry.is_object() && entry.contains("source") && entry["source"].is_number_unsigned() && root.contains("images") &&
        root["images"].is_array() && entry["source"].get<size_t>() < root["images"].size()) {
        const auto& image = root["images"][entry["source"].get<size_t>()];
        if (image.is_object() && image.contains("uri") && image["uri"].is_string()) {
            const std::string uri = image["uri"].get<std::string>();
            path = uri.rfind("data:", 0) == 0 ? "(embedded data URI)" : uri;
        }
    }
    imported.textures.push_back({key, path, ""});
}

// The textures Glint's material textures (texture/material_texture.h) carry: baseColorTexture as
// the diffuse albedo of a dielectric (metallicFactor 0) and normalTexture as the normal map, from
// image files beside the glTF. The others stay references, with a warning each: they belong to a
// standard surface Glint does not have yet.
void useTextures(const Context& context, const std::string& pointer, ImportedMaterial& imported, glm::vec4 baseColor,
                 float metallic) {
    for (const TextureReference& reference : imported.textures) {
        const bool baseColorSlot = reference.slot == "baseColorTexture";
        const std::string where = pointer + (baseColorSlot || reference.slot == "metallicRoughnessTexture"
                                                 ? "/pbrMetallicRoughness/" + reference.slot
                                                 : "/" + reference.slot);
        const bool carried = (baseColorSlot && imported.material.model == BrdfModel::CookTorrance && metallic == 0.0f) ||
                             reference.slot == "normalTexture";
        if (!carried) {
            context.warn(where, "texture kept as a reference (" + reference.path + ") but not rendered: Glint's textures carry " +
                                    "baseColorTexture on a dielectric (metallicFactor 0) and normalTexture only");
            continue;
        }
        if (reference.path.empty() || reference.path[0] == '(') {
            context.warn(where, "texture " + reference.path + " not rendered: Glint reads texture images from files only");
            continue;
        }
        MaterialTexture texture;
        texture.parameter = baseColorSlot ? "diffuse_albedo" : kNormalMapKey;
        texture.kind = TextureKind::Image;
        texture.file = (context.folder / reference.path).lexically_normal().string();
        texture.colorSpace = baseColorSlot ? TextureColorSpace::Srgb : TextureColorSpace::Linear;  // glTF 2.0 §3.9.3, §3.9.4
        auto image = loadTextureImage(texture.file, texture.colorSpace);
        if (!image) {
            context.warn(where, "texture not rendered: " + image.error().format());
            continue;
        }
        texture.image = *image;
        imported.material.textures.push_back(std::move(texture));
        if (baseColorSlot && glm::vec3(baseColor) != glm::vec3(1.0f))
            context.warn(where, "the texture is used as the albedo; baseColorFactor is not multiplied into it");
    }
}

// F0 → index: a dielectric n = (1 + √F0)/(1 − √F0) (inverting F0 = ((n−1)/(n+1))²); a conductor
// with n = 1 and κ = 2√(F0/(1 − F0)) (inverting F0 = κ²/(4 + κ²)).
float dielectricIorForF0(float f0) { return (1.0f + std::sqrt(f0)) / (1.0f - std::sqrt(f0)); }
float conductorExtinctionForF0(float f0) { return 2.0f * std::sqrt(f0 / (1.0f - f0)); }

ImportedMaterial readMaterial(const Context& fileContext, ObjectReader& reader, const nlohmann::json& root, int index) {
    ImportedMaterial imported;
    const Context context{fileContext.document, imported.warnings, fileContext.folder};  // this material's warnings stay with it
    const std::string name = reader.string("name", "gltf material " + std::to_string(index));
    glm::vec4 baseColor(1.0f);
    float metallic = 1.0f, roughness = 1.0f;
    if (reader.has("pbrMetallicRoughness")) {
        ObjectReader pbr = reader.object("pbrMetallicRoughness");
        baseColor = readVec4(pbr, "baseColorFactor", baseColor, Bounds::between(0, 1));
        metallic = static_cast<float>(pbr.number("metallicFactor", metallic, Bounds::between(0, 1)));
        roughness = static_cast<float>(pbr.number("roughnessFactor", roughness, Bounds::between(0, 1)));
        readTexture(context, pbr, "baseColorTexture", root, imported);
        readTexture(context, pbr, "metallicRoughnessTexture", root, imported);
        pbr.expect({"extensions", "extras"});
        pbr.rejectUnknownKeys();
    }
    for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) readTexture(context, reader, key, root, imported);
    const glm::vec3 emissive = reader.vec3("emissiveFactor", glm::vec3(0.0f), Bounds::between(0, 1));
    const std::string alphaMode = reader.string("alphaMode", "OPAQUE");
    if (alphaMode != "OPAQUE" && alphaMode != "MASK" && alphaMode != "BLEND")
        reader.fail("alphaMode", "expected \"OPAQUE\", \"MASK\" or \"BLEND\"");
    if (alphaMode != "OPAQUE" || baseColor.a < 1.0f)
        context.warn(reader.pointer(), "alpha (alphaMode " + alphaMode + ", alpha " + std::to_string(baseColor.a) +
                                           ") is ignored: Glint draws opaque surfaces");
    reader.number("alphaCutoff", 0.5, Bounds::nonNegative());
    reader.boolean("doubleSided", false);
    reader.expect({"extras"});

    // Extensions (each optional).
    float ior = 1.5f, specularFactor = 1.0f, transmission = 0.0f, emissiveStrength = 1.0f;
    glm::vec3 specularColor(1.0f), attenuationColor(1.0f);
    float attenuationDistance = std::numeric_limits<float>::infinity();
    if (reader.has("extensions")) {
        ObjectReader extensions = reader.object("extensions");
        if (extensions.has("KHR_materials_ior")) {
            ObjectReader extension = extensions.object("KHR_materials_ior");
            ior = static_cast<float>(extension.number("ior", ior, Bounds::between(1, 1e6)));
            extension.expect({"extras"});
            extension.rejectUnknownKeys();
        }
        if (extensions.has("KHR_materials_specular")) {
            ObjectReader extension = extensions.object("KHR_materials_specular");
            specularFactor = static_cast<float>(extension.number("specularFactor", 1.0, Bounds::between(0, 1)));
            specularColor = extension.vec3("specularColorFactor", specularColor, Bounds::nonNegative());
            readTexture(context, extension, "specularTexture", root, imported);
            readTexture(context, extension, "specularColorTexture", root, imported);
            extension.expect({"extras"});
            extension.rejectUnknownKeys();
        }
        if (extensions.has("KHR_materials_transmission")) {
            ObjectReader extension = extensions.object("KHR_materials_transmission");
            transmission = static_cast<float>(extension.number("transmissionFactor", 0.0, Bounds::between(0, 1)));
            readTexture(context, extension, "transmissionTexture", root, imported);
            extension.expect({"extras"});
            extension.rejectUnknownKeys();
        }
        if (extensions.has("KHR_materials_volume")) {
            ObjectReader extension = extensions.object("KHR_materials_volume");
            extension.number("thicknessFactor", 0.0, Bounds::nonNegative());
            attenuationDistance = static_cast<float>(
                extension.number("attenuationDistance", std::numeric_limits<double>::max(), Bounds::positive()));
            attenuationColor = extension.vec3("attenuationColor", attenuationColor, Bounds::between(0, 1));
            readTexture(context, extension, "thicknessTexture", root, imported);
            extension.expect({"extras"});
            extension.rejectUnknownKeys();
        }
        if (extensions.has("KHR_materials_clearcoat")) {
            ObjectReader extension = extensions.object("KHR_materials_clearcoat");
            const double clearcoat = extension.number("clearcoatFactor", 0.0, Bounds::between(0, 1));
            extension.number("clearcoatRoughnessFactor", 0.0, Bounds::between(0, 1));
            for (const char* key : {"clearcoatTexture", "clearcoatRoughnessTexture", "clearcoatNormalTexture"})
                readTexture(context, extension, key, root, imported);
            extension.expect({"extras"});
            extension.rejectUnknownKeys();
            if (clearcoat > 0)
                context.warn(appendPointer(extensions.pointer(), "KHR_materials_clearcoat"),
                             "Glint's Cook-Torrance has no clear-coat layer; the coat is ignored (the base layer is imported)");
        }
        if (extensions.has("KHR_materials_emissive_strength")) {
            ObjectReader extension = extensions.object("KHR_materials_emissive_strength");
            emissiveStrength = static_cast<float>(extension.number("emissiveStrength", 1.0, Bounds::nonNegative()));
            extension.expect({"extras"});
            extension.rejectUnknownKeys();
        }
        for (const auto& [key, value] : reader.take("extensions").items())
            if (!kKnownExtensions.count(key))
                context.warn(appendPointer(extensions.pointer(), key), "extension not supported by Glint; ignored");
    }
    if (emissive != glm::vec3(0.0f) && emissiveStrength > 0.0f)
        context.warn(reader.pointer(), "emission (emissiveFactor × strength " + std::to_string(emissiveStrength) +
                                           ") is ignored: Glint's materials do not emit light");
    reader.rejectUnknownKeys();

    Material& material = imported.material;
    if (transmission > 0.0f) {
        material = Material::withDefaults(name, BrdfModel::Glass);
        if (ior > 4.0f) reader.fail("extensions", "KHR_materials_ior: ior " + std::to_string(ior) + " is above glass's limit 4");
        setParam(material, "ior", ior);
        glm::vec3 absorption(0.0f);  // KHR_materials_volume: σ = −ln(attenuationColor) / attenuationDistance
        if (std::isfinite(attenuationDistance) && attenuationDistance < 1e30f) {
            for (int c = 0; c < 3; ++c) {
                if (attenuationColor[c] <= 0.0f)
                    reader.fail("extensions", "KHR_materials_volume: attenuationColor 0 means infinite absorption, which Glint refuses");
                absorption[c] = -std::log(attenuationColor[c]) / attenuationDistance;
            }
        }
        setParam(material, "absorption", absorption);
        if (transmission < 1.0f)
            context.warn(reader.pointer(), "transmissionFactor " + std::to_string(transmission) +
                                               " imported as a fully transmitting Glint glass (exact Fresnel)");
        if (roughness > 0.0f)
            context.warn(reader.pointer(), "Glint's glass is smooth: roughness " + std::to_string(roughness) + " is ignored");
        if (glm::vec3(baseColor) != glm::vec3(1.0f))
            context.warn(reader.pointer(), "a transmitting material's base colour is ignored (use KHR_materials_volume attenuation)");
    } else {
        material = Material::withDefaults(name, BrdfModel::CookTorrance);
        // glTF Appendix B: dielectric F0 = min(((n−1)/(n+1))² · specularColor, 1) · specularFactor;
        // mix(dielectric, metal, metallic) with metal F0 = baseColor, diffuse = baseColor·(1 − metallic).
        const float dielectricF0 = ((ior - 1.0f) / (ior + 1.0f)) * ((ior - 1.0f) / (ior + 1.0f));
        const glm::vec3 specularF0 = glm::min(glm::vec3(dielectricF0) * specularColor, glm::vec3(1.0f)) * specularFactor;
        const glm::vec3 f0 = glm::mix(specularF0, glm::vec3(baseColor), metallic);
        setParam(material, "diffuse_albedo", glm::vec3(baseColor) * (1.0f - metallic));
        glm::vec3 iorRgb(1.0f), extinction(0.0f);
        const bool plainDielectric = metallic == 0.0f && specularColor == glm::vec3(1.0f) && specularFactor == 1.0f;
        for (int c = 0; c < 3; ++c) {
            const float limited = std::min(f0[c], 0.999f);
            if (plainDielectric) iorRgb[c] = ior;
            else if (metallic == 0.0f && limited > 0.0f) iorRgb[c] = dielectricIorForF0(limited);
            else extinction[c] = conductorExtinctionForF0(limited);
        }
        if (glm::any(glm::greaterThan(f0, glm::vec3(0.999f))))
            context.warn(reader.pointer(), "a normal-incidence reflectance of 1 is imported as 0.999");
        if (metallic > 0.0f && metallic < 1.0f)
            context.warn(reader.pointer(), "metallicFactor " + std::to_string(metallic) +
                                               " is imported as one lobe with F0 = mix(dielectric F0, baseColor, metallic)");
        setParam(material, "ior", iorRgb);
        setParam(material, "extinction", extinction);
        const float alpha = roughness * roughness;  // glTF's roughness is perceptual: α = r²
        if (alpha < 0.001f)
            context.warn(reader.pointer(), "roughness " + std::to_string(roughness) + " is below Glint's α ≥ 0.001; imported as α = 0.001");
        setParam(material, "roughness", std::max(alpha, 0.001f));
        setParam(material, "distribution", 1.0f);  // GGX
        setParam(material, "geometry", 1.0f);      // height-correlated Smith
        setParam(material, "fresnel", 0.0f);       // Schlick, as glTF's reference BRDF
    }
    if (auto problem = findOutOfRange(material)) reader.failHere(*problem);
    useTextures(context, reader.pointer(), imported, baseColor, metallic);
    return imported;
}

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
    const glm::vec4 rotation = readVec4(node, "rotation", {0, 0, 0, 1}, Bounds::between(-1, 1));
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
        spot.expect({"extras"});
        spot.rejectUnknownKeys();
    }
    if (!std::isfinite(light.power) || !std::isfinite(light.irradiance) || !std::isfinite(intensity))
        reader.fail("intensity", "is too large for Glint (single-precision watts)");
    if (relativeLuminance(light.color) <= 0.0f && intensity > 0.0f)
        context.warn(reader.pointer(), "a colour of zero luminance carries no power at 683 lm/W; imported dark");
    reader.expect({"extras"});
    reader.rejectUnknownKeys();
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
                reference.expect({"extras"});
                reference.rejectUnknownKeys();
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

// --- entry points ---------------------------------------------------------------------------

Result<ImportedFile> parseGltf(const std::string& text, const std::string& file) {
    auto document = JsonDocument::parse(text, file);
    if (!document) return document.error();
    ImportedFile result;
    // A .glb's JSON chunk is named "FILE (JSON chunk)": its folder is the file's.
    const Context context{*document, result.warnings, std::filesystem::path(file).parent_path()};
    try {
        ObjectReader root = readRoot(*document, "glTF");
        if (!root.has("asset")) root.failHere("not a glTF file: it has no \"asset\"");
        ObjectReader asset = root.object("asset");
        const std::string version = asset.requiredString("version");
        if (version.rfind("2.", 0) != 0)
            asset.fail("version", "glTF " + version + " is not supported (Glint reads glTF 2.x)");
        if (root.has("extensionsRequired")) {
            const nlohmann::json& required = root.take("extensionsRequired");
            if (!required.is_array()) root.fail("extensionsRequired", "expected an array of names");
            for (const auto& name : required)
                if (!name.is_string() || !kKnownExtensions.count(name.get<std::string>()))
                    root.fail("extensionsRequired", "the file requires " + name.dump() + ", which Glint does not support");
        }
        if (root.has("materials")) {
            int index = 0;
            for (ObjectReader& material : root.objectArray("materials"))
                result.materials.push_back(readMaterial(context, material, document->root(), index++));
        }
        readLights(context, root, result);
        const nlohmann::json& meshes = document->root().contains("meshes") ? document->root()["meshes"] : nlohmann::json();
        for (size_t i = 0; meshes.is_array() && i < meshes.size(); ++i)
            result.meshNames.push_back(meshes[i].is_object() && meshes[i].contains("name") && meshes[i]["name"].is_string()
                                           ? meshes[i]["name"].get<std::string>()
                                           : "mesh " + std::to_string(i));
        if (result.materials.empty() && result.lights.empty())
            root.failHere("the file has no material and no light (KHR_lights_punctual) for Glint to open");
    } catch (const JsonReadError& error) {
        return error.diagnostic;
    } catch (const nlohmann::json::exception& error) {  // a shape no check above foresaw: still a message, never a crash
        return makeError(std::string("malformed glTF: ") + error.what(), {file});
    }
    return result;
}

Result<ImportedFile> loadGltf(const std::string& path) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parseGltf(*text, path);
}

}  // namespace glint
