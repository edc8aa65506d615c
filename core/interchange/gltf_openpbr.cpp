// glTF materials ↔ openpbr (see gltf_openpbr.h). Sections: the texture table · import · export.
#include "interchange/gltf_openpbr.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "interchange/material_values.h"
#include "scene/json_vectors.h"
#include "texture/texture_edit.h"

namespace glint {
namespace {

using nlohmann::json;

// --- the texture table ------------------------------------------------------------------------

// A glTF texture slot that drives an openpbr parameter. Scalars read `channel` as factor × texel
// (MaterialTexture range [0, factor]); colours multiply the texel by their factor (colorFactor).
struct TextureSlot {
    const char* extension;  // "" for the core material; "pbrMetallicRoughness" for its object
    const char* key;        // the textureInfo's key
    const char* parameter;  // openpbr parameter, or a surface map's key (texture/material_texture.h)
    TextureChannel channel = TextureChannel::R;  // scalars
    bool srgb = false;      // colour textures are sRGB-encoded (glTF 2.0 §3.9.2)
};

constexpr TextureSlot kTextureSlots[] = {
    {"pbrMetallicRoughness", "baseColorTexture", "base_color", TextureChannel::R, true},
    {"pbrMetallicRoughness", "metallicRoughnessTexture", "specular_roughness", TextureChannel::G},
    {"pbrMetallicRoughness", "metallicRoughnessTexture", "base_metalness", TextureChannel::B},
    {"", "normalTexture", kNormalMapKey},
    {"", "occlusionTexture", kOcclusionMapKey},
    {"", "emissiveTexture", "emission_color", TextureChannel::R, true},
    {"KHR_materials_specular", "specularTexture", "specular_weight", TextureChannel::A},
    {"KHR_materials_specular", "specularColorTexture", "specular_color", TextureChannel::R, true},
    {"KHR_materials_clearcoat", "clearcoatTexture", "coat_weight", TextureChannel::R},
    {"KHR_materials_clearcoat", "clearcoatRoughnessTexture", "coat_roughness", TextureChannel::G},
    {"KHR_materials_clearcoat", "clearcoatNormalTexture", kCoatNormalMapKey},
    {"KHR_materials_sheen", "sheenColorTexture", "fuzz_color", TextureChannel::R, true},
    {"KHR_materials_sheen", "sheenRoughnessTexture", "fuzz_roughness", TextureChannel::A},
    {"KHR_materials_transmission", "transmissionTexture", "transmission_weight", TextureChannel::R},
    {"KHR_materials_volume", "thicknessTexture", "geometry_thickness", TextureChannel::G},
    {"KHR_materials_iridescence", "iridescenceTexture", "thin_film_weight", TextureChannel::R},
    {"KHR_materials_iridescence", "iridescenceThicknessTexture", "thin_film_thickness", TextureChannel::G},
    {"KHR_materials_anisotropy", "anisotropyTexture", "specular_roughness_anisotropy", TextureChannel::B},
};

const std::set<std::string> kMaterialExtensions = {
    "KHR_materials_ior", "KHR_materials_specular", "KHR_materials_clearcoat", "KHR_materials_sheen",
    "KHR_materials_transmission", "KHR_materials_volume", "KHR_materials_iridescence", "KHR_materials_anisotropy",
    "KHR_materials_emissive_strength", "KHR_materials_dispersion", "KHR_materials_unlit"};

constexpr float kGltfCoatIor = 1.5f;  // KHR_materials_clearcoat's fixed index

// --- import -----------------------------------------------------------------------------------

struct Reading {
    const GltfSource& source;
    ImportedMaterial& imported;
    json kept = json::object();  // ImportedMaterial::gltfKept
    std::vector<MaterialTexture> textures;

    void warn(const std::string& pointer, const std::string& message) const {
        imported.warnings.push_back(makeError("warning: " + pointer + ": " + message, source.document.locate(pointer)));
    }
    void note(const std::string& pointer, const std::string& message) const {
        imported.warnings.push_back(makeError("note: " + pointer + ": " + message, source.document.locate(pointer)));
    }
    json& keptAt(const std::string& extension) {
        return extension.empty() ? kept : kept["extensions"][extension];
    }

    // The slots of kTextureSlots under `object` (`extension` names it): each a MaterialTexture.
    void readSlots(ObjectReader& object, const std::string& extension, const std::map<std::string, glm::vec2>& ranges,
                   const std::map<std::string, glm::vec3>& colorFactors) {
        std::map<std::string, GltfTextureInfo> infos;
        for (const TextureSlot& slot : kTextureSlots) {
            if (slot.extension != extension) continue;
            if (!infos.count(slot.key)) {
                auto info = readGltfTextureInfo(object, slot.key, source);
                if (!info) continue;
                infos[slot.key] = *info;
            }
            const GltfTextureInfo& info = infos[slot.key];
            if (info.texCoord != 0)
                warn(info.pointer, "texCoord " + std::to_string(info.texCoord) + " is read as texCoord 0: Glint's shapes have one UV set");
            auto texture = gltfImageTexture(info, slot.parameter, slot.srgb ? TextureColorSpace::Srgb : TextureColorSpace::Linear);
            if (!texture) {
                warn(info.pointer, "texture not rendered: " + texture.error().format());
                continue;
            }
            texture->channel = slot.channel;
            if (auto range = ranges.find(slot.parameter); range != ranges.end()) texture->range = range->second;
            if (auto factor = colorFactors.find(slot.parameter); factor != colorFactors.end()) texture->colorFactor = factor->second;
            if (isNormalMapKey(slot.parameter)) texture->normalScale = info.scale;
            // glTF: occlusion = 1 + strength·(texel − 1) = mix(1 − strength, 1, texel).
            if (std::string(slot.parameter) == kOcclusionMapKey) texture->range = {1.0f - info.scale, 1.0f};
            textures.push_back(std::move(*texture));
        }
    }

};

float number(ObjectReader& reader, const char* key, double fallback, Bounds bounds) {
    return static_cast<float>(reader.number(key, fallback, bounds));
}

}  // namespace

bool isGltfMaterialExtension(const std::string& name) { return kMaterialExtensions.count(name) > 0; }

ImportedMaterial readGltfMaterial(ObjectReader& reader, const GltfSource& source, int index) {
    ImportedMaterial imported;
    Reading reading{source, imported};
    Material& m = imported.material;
    m = Material::withDefaults(reader.string("name", "gltf material " + std::to_string(index)), BrdfModel::OpenPbr);
    std::map<std::string, glm::vec2> ranges;      // scalar textures: [0, factor]
    std::map<std::string, glm::vec3> colorFactors;

    glm::vec4 baseColor(1.0f);
    float metallic = 1.0f, roughness = 1.0f;
    std::optional<ObjectReader> pbr;
    if (reader.has("pbrMetallicRoughness")) {
        pbr.emplace(reader.object("pbrMetallicRoughness"));
        baseColor = pbr->vec4("baseColorFactor", baseColor, Bounds::between(0, 1));
        metallic = number(*pbr, "metallicFactor", 1.0, Bounds::between(0, 1));
        roughness = number(*pbr, "roughnessFactor", 1.0, Bounds::between(0, 1));
    }
    setParam(m, "base_color", glm::vec3(baseColor));
    setParam(m, "base_metalness", metallic);
    setParam(m, "specular_roughness", roughness);
    ranges["base_metalness"] = {0.0f, metallic};
    ranges["specular_roughness"] = {0.0f, roughness};
    colorFactors["base_color"] = glm::vec3(baseColor);
    if (pbr) {
        reading.readSlots(*pbr, "pbrMetallicRoughness", ranges, colorFactors);
        rejectUnknownGltfKeys(*pbr);
    }

    const glm::vec3 emissive = reader.vec3("emissiveFactor", glm::vec3(0.0f), Bounds::between(0, 1));
    const std::string alphaMode = reader.string("alphaMode", "OPAQUE");
    if (alphaMode != "OPAQUE" && alphaMode != "MASK" && alphaMode != "BLEND") reader.fail("alphaMode", "expected \"OPAQUE\", \"MASK\" or \"BLEND\"");
    if (alphaMode != "OPAQUE" || baseColor.a < 1.0f)
        reading.warn(reader.pointer(), "alpha (alphaMode " + alphaMode + ", alpha " + std::to_string(baseColor.a) +
                                           ") is ignored: Glint draws opaque surfaces");
    reader.number("alphaCutoff", 0.5, Bounds::nonNegative());
    reader.boolean("doubleSided", false);  // Glint shades both sides of its shapes' outer surface alike

    std::optional<ObjectReader> extensions;
    if (reader.has("extensions")) extensions.emplace(reader.object("extensions"));
    auto extension = [&](const char* name) -> std::optional<ObjectReader> {
        if (!extensions || !extensions->has(name)) return std::nullopt;
        return extensions->object(name);
    };
    auto pointerOf = [&](const char* name) { return appendPointer(extensions->pointer(), name); };
    // A factor that also scales its texture: the parameter's value, and the texture's range [0, factor].
    auto factor = [&](ObjectReader& object, const char* key, double fallback, Bounds bounds, const char* parameter) {
        const float value = number(object, key, fallback, bounds);
        setParam(m, parameter, value);
        ranges[parameter] = {0.0f, value};
        return value;
    };

    if (auto ior = extension("KHR_materials_ior")) {
        setParam(m, "specular_ior", number(*ior, "ior", 1.5, Bounds::between(1, 1e6)));
        rejectUnknownGltfKeys(*ior);
    }
    if (auto specular = extension("KHR_materials_specular")) {
        factor(*specular, "specularFactor", 1.0, Bounds::between(0, 1), "specular_weight");
        glm::vec3 color = specular->vec3("specularColorFactor", glm::vec3(1.0f), Bounds::nonNegative());
        if (glm::any(glm::greaterThan(color, glm::vec3(1.0f)))) {
            reading.warn(pointerOf("KHR_materials_specular"), "specularColorFactor above 1 is clipped to 1 (OpenPBR's specular_color is a reflectance)");
            color = glm::min(color, glm::vec3(1.0f));
        }
        setParam(m, "specular_color", color);
        colorFactors["specular_color"] = color;
        reading.readSlots(*specular, "KHR_materials_specular", ranges, colorFactors);
        rejectUnknownGltfKeys(*specular);
    }
    if (auto coat = extension("KHR_materials_clearcoat")) {
        factor(*coat, "clearcoatFactor", 0.0, Bounds::between(0, 1), "coat_weight");
        factor(*coat, "clearcoatRoughnessFactor", 0.0, Bounds::between(0, 1), "coat_roughness");
        setParam(m, "coat_ior", kGltfCoatIor);
        setParam(m, "coat_darkening", 0.0f);  // glTF's coat only attenuates by its Fresnel: no internal reflections
        reading.readSlots(*coat, "KHR_materials_clearcoat", ranges, colorFactors);
        rejectUnknownGltfKeys(*coat);
    }
    if (auto sheen = extension("KHR_materials_sheen")) {
        const glm::vec3 color = sheen->vec3("sheenColorFactor", glm::vec3(0.0f), Bounds::between(0, 1));
        factor(*sheen, "sheenRoughnessFactor", 0.0, Bounds::between(0, 1), "fuzz_roughness");
        setParam(m, "fuzz_weight", 1.0f);
        setParam(m, "fuzz_color", color);
        colorFactors["fuzz_color"] = color;
        reading.readSlots(*sheen, "KHR_materials_sheen", ranges, colorFactors);
        rejectUnknownGltfKeys(*sheen);
    }
    bool transmits = false;
    if (auto transmission = extension("KHR_materials_transmission")) {
        factor(*transmission, "transmissionFactor", 0.0, Bounds::between(0, 1), "transmission_weight");
        reading.readSlots(*transmission, "KHR_materials_transmission", ranges, colorFactors);
        rejectUnknownGltfKeys(*transmission);
        transmits = true;
        // glTF tints transmitted light by the base colour; without a volume, so does transmission_color.
        setParam(m, "transmission_color", glm::vec3(baseColor));
        setParam(m, "geometry_thin_walled", 1.0f);  // glTF: without KHR_materials_volume the surface is thin
    }
    if (auto volume = extension("KHR_materials_volume")) {
        // In the mesh's units, taken as metres.
        const float thickness = factor(*volume, "thicknessFactor", 0.0, Bounds::nonNegative(), "geometry_thickness");
        const float distance = number(*volume, "attenuationDistance", std::numeric_limits<double>::max(), Bounds::positive());
        const glm::vec3 color = volume->vec3("attenuationColor", glm::vec3(1.0f), Bounds::between(0, 1));
        reading.readSlots(*volume, "KHR_materials_volume", ranges, colorFactors);
        rejectUnknownGltfKeys(*volume);
        if (thickness > 0.0f) setParam(m, "geometry_thin_walled", 0.0f);
        if (std::isfinite(distance) && distance < std::numeric_limits<float>::max()) {
            setParam(m, "transmission_color", color);
            setParam(m, "transmission_depth", distance);
            if (transmits && glm::vec3(baseColor) != glm::vec3(1.0f))
                reading.note(pointerOf("KHR_materials_volume"),
                             "the volume's attenuation is transmission_color; baseColor's own tint of the transmitted light is not kept");
        }
    }
    if (auto iridescence = extension("KHR_materials_iridescence")) {
        factor(*iridescence, "iridescenceFactor", 0.0, Bounds::between(0, 1), "thin_film_weight");
        const float filmIor = number(*iridescence, "iridescenceIor", 1.3, Bounds::between(1, 1e6));
        const float minimum = number(*iridescence, "iridescenceThicknessMinimum", 100.0, Bounds::nonNegative());
        const float maximum = number(*iridescence, "iridescenceThicknessMaximum", 400.0, Bounds::nonNegative());
        setParam(m, "thin_film_ior", filmIor);
        setParam(m, "thin_film_thickness", maximum / 1000.0f);  // nm → µm; without a texture glTF uses the maximum
        ranges["thin_film_thickness"] = {minimum / 1000.0f, maximum / 1000.0f};
        const size_t before = reading.textures.size();
        reading.readSlots(*iridescence, "KHR_materials_iridescence", ranges, colorFactors);
        const bool thicknessTextured = std::any_of(reading.textures.begin() + static_cast<long>(before), reading.textures.end(),
                                                   [](const MaterialTexture& t) { return t.parameter == "thin_film_thickness"; });
        if (!thicknessTextured && iridescence->has("iridescenceThicknessMinimum"))
            reading.keptAt("KHR_materials_iridescence")["iridescenceThicknessMinimum"] = minimum;
        rejectUnknownGltfKeys(*iridescence);
    }
    if (auto anisotropy = extension("KHR_materials_anisotropy")) {
        factor(*anisotropy, "anisotropyStrength", 0.0, Bounds::between(0, 1), "specular_roughness_anisotropy");
        setParam(m, "geometry_tangent_rotation", glm::degrees(number(*anisotropy, "anisotropyRotation", 0.0, Bounds::any())));
        if (anisotropy->has("anisotropyTexture"))
            reading.warn(appendPointer(pointerOf("KHR_materials_anisotropy"), "anisotropyTexture"),
                         "its blue channel (strength) is used; the direction in red and green is not (one tangent rotation per material)");
        reading.readSlots(*anisotropy, "KHR_materials_anisotropy", ranges, colorFactors);
        rejectUnknownGltfKeys(*anisotropy);
    }
    float emissiveStrength = 1.0f;
    if (auto strength = extension("KHR_materials_emissive_strength")) {
        emissiveStrength = number(*strength, "emissiveStrength", 1.0, Bounds::nonNegative());
        rejectUnknownGltfKeys(*strength);
    }
    if (emissive != glm::vec3(0.0f)) {
        setParam(m, "emission_color", emissive);
        setParam(m, "emission_luminance", kGltfEmissionNits * emissiveStrength);
    }
    colorFactors["emission_color"] = emissive;
    if (auto dispersion = extension("KHR_materials_dispersion")) {
        const float value = number(*dispersion, "dispersion", 0.0, Bounds::nonNegative());
        reading.keptAt("KHR_materials_dispersion")["dispersion"] = value;
        if (value > 0.0f)
            reading.note(pointerOf("KHR_materials_dispersion"),
                         "dispersion " + std::to_string(value) + " (Abbe number " + std::to_string(20.0f / value) +
                             ") is kept for export, not rendered: Glint refracts every wavelength alike");
        rejectUnknownGltfKeys(*dispersion);
    }
    if (auto unlit = extension("KHR_materials_unlit")) {
        rejectUnknownGltfKeys(*unlit);
        // Closest form: no reflection, emitting the base colour as radiance (1 = the display's white).
        setParam(m, "base_weight", 0.0f);
        setParam(m, "specular_weight", 0.0f);
        setParam(m, "emission_color", glm::vec3(baseColor));
        setParam(m, "emission_luminance", kGltfEmissionNits);
        reading.note(pointerOf("KHR_materials_unlit"),
                     "unlit is imported as a black, non-reflecting surface emitting the base colour (base_weight 0, specular_weight 0, "
                     "emission 683 nits × baseColor): lights do not change it, the display's exposure and tone map do");
        for (MaterialTexture& texture : reading.textures)
            if (texture.parameter == "base_color") texture.parameter = "emission_color";
    }
    reading.readSlots(reader, "", ranges, colorFactors);
    if (extensions) {
        // One not in "extensionsUsed" is named here; the file's warning names those listed there, once.
        const json& used = source.document.root().value("extensionsUsed", json::array());
        for (const auto& [key, value] : reader.take("extensions").items())
            if (!isGltfMaterialExtension(key) && (!used.is_array() || std::find(used.begin(), used.end(), key) == used.end()))
                reading.warn(appendPointer(extensions->pointer(), key), "extension not supported by Glint (nor listed in extensionsUsed); ignored");
    }
    rejectUnknownGltfKeys(reader);

    // The textures, table order; Glint binds at most kMaxMaterialTextures.
    for (MaterialTexture& texture : reading.textures) {
        if (static_cast<int>(m.analytic()->textures.size()) >= kMaxMaterialTextures) {
            reading.warn(reader.pointer(), "more than " + std::to_string(kMaxMaterialTextures) + " textures: '" + texture.parameter +
                                               "' uses its constant value");
            continue;
        }
        putTexture(*m.analytic(), std::move(texture));
    }
    if (auto problem = findOutOfRange(m)) reader.failHere(*problem);
    if (!reading.kept.empty()) imported.gltfKept = reading.kept.dump();
    return imported;
}

// --- export -------------------------------------------------------------------------------------

namespace {

struct Writing {
    const Material& material;
    std::vector<Diagnostic>& warnings;
    void lost(const std::string& what) const {
        warnings.push_back(makeError("warning: '" + material.name + "' (openpbr): " + what));
    }
    float scalar(const char* name) const { return paramScalar(material, name); }
    glm::vec3 color(const char* name) const { return paramValue(material, name); }
};

// Merges `patch` into `target` (RFC 7386 without deletions), turning kept {"uri": ...}
// textureInfos back into {"index": ...}.
void mergeKept(json& target, const json& patch, GltfTextureWriter& textures) {
    for (const auto& [key, value] : patch.items()) {
        if (value.is_object() && value.contains("uri")) {
            json members = value;
            const std::string uri = members["uri"].get<std::string>();
            members.erase("uri");
            target[key] = textures.keptTextureInfo(uri, members);
        } else if (value.is_object()) {
            mergeKept(target[key], value, textures);
        } else {
            target[key] = value;
        }
    }
}

}  // namespace

json gltfOpenPbrMaterial(const ImportedMaterial& imported, GltfTextureWriter& textures, std::vector<std::string>& extensionsUsed,
                         std::vector<Diagnostic>& warnings) {
    const Material& material = imported.material;
    const Writing w{material, warnings};
    json out = {{"name", material.name}};
    json pbr = json::object();
    json extensions = json::object();
    const glm::vec3 baseColor = w.color("base_color");
    const float emission = w.scalar("emission_luminance");
    const bool unlit = w.scalar("base_weight") == 0.0f && w.scalar("specular_weight") == 0.0f && emission == kGltfEmissionNits &&
                       w.scalar("coat_weight") == 0.0f && w.scalar("fuzz_weight") == 0.0f && w.scalar("transmission_weight") == 0.0f;
    pbr["baseColorFactor"] = {baseColor.r, baseColor.g, baseColor.b, 1.0};
    pbr["metallicFactor"] = w.scalar("base_metalness");
    pbr["roughnessFactor"] = w.scalar("specular_roughness");
    if (!unlit && w.scalar("base_weight") != 1.0f) w.lost("base_weight " + std::to_string(w.scalar("base_weight")) + " has no glTF form; written as 1");
    if (w.scalar("base_diffuse_roughness") != 0.0f) w.lost("base_diffuse_roughness has no glTF form (glTF's diffuse is Lambertian)");
    if (w.scalar("specular_ior") != 1.5f) extensions["KHR_materials_ior"] = {{"ior", w.scalar("specular_ior")}};
    if (!unlit && (w.scalar("specular_weight") != 1.0f || w.color("specular_color") != glm::vec3(1.0f))) {
        if (w.scalar("specular_weight") > 1.0f) w.lost("specular_weight above 1 is written as specularFactor 1");
        extensions["KHR_materials_specular"] = {{"specularFactor", std::min(w.scalar("specular_weight"), 1.0f)},
                                                {"specularColorFactor", vec3Json(w.color("specular_color"))}};
    }
    if (w.scalar("transmission_weight") > 0.0f) {
        extensions["KHR_materials_transmission"] = {{"transmissionFactor", w.scalar("transmission_weight")}};
        const float depth = w.scalar("transmission_depth");
        const bool thin = w.scalar("geometry_thin_walled") > 0.5f;
        if (depth == 0.0f && w.color("transmission_color") != baseColor)
            w.lost("glTF tints transmitted light by the base colour: transmission_color (depth 0) is not written");
        if (!thin || depth > 0.0f) {
            // The thickness, or the exported sphere's diameter [m] when it has none (a sphere uses its chord).
            const float thickness = w.scalar("geometry_thickness");
            json volume = {{"thicknessFactor", thickness > 0.0f ? thickness : 2.0f}};
            if (depth > 0.0f) {
                volume["attenuationDistance"] = depth;
                volume["attenuationColor"] = vec3Json(w.color("transmission_color"));
            }
            if (thin) w.lost("a thin-walled material with a transmission depth is written as a volume (glTF's thin walls do not absorb)");
            if (depth > 0.0f && baseColor != glm::vec3(1.0f))
                w.lost("glTF tints transmitted light by baseColorFactor as well as by the volume's attenuationColor");
            extensions["KHR_materials_volume"] = volume;
        }
    }
    if (w.scalar("coat_weight") > 0.0f) {
        extensions["KHR_materials_clearcoat"] = {{"clearcoatFactor", w.scalar("coat_weight")},
                                                 {"clearcoatRoughnessFactor", w.scalar("coat_roughness")}};
        if (w.scalar("coat_ior") != kGltfCoatIor) w.lost("glTF's clear coat has ior 1.5; coat_ior " + std::to_string(w.scalar("coat_ior")) + " is not kept");
        if (w.color("coat_color") != glm::vec3(1.0f)) w.lost("glTF's clear coat is colourless; coat_color is not kept");
        if (w.scalar("coat_darkening") != 0.0f) w.lost("glTF's clear coat does not darken the base (coat_darkening 0); coat_darkening is not kept");
        if (w.scalar("coat_roughness_anisotropy") != 0.0f) w.lost("glTF's clear coat is isotropic; coat_roughness_anisotropy is not kept");
    }
    if (w.scalar("fuzz_weight") > 0.0f) {
        if (w.scalar("fuzz_weight") != 1.0f) w.lost("fuzz_weight is multiplied into sheenColorFactor (glTF's sheen has no weight)");
        extensions["KHR_materials_sheen"] = {{"sheenColorFactor", vec3Json(w.scalar("fuzz_weight") * w.color("fuzz_color"))},
                                             {"sheenRoughnessFactor", w.scalar("fuzz_roughness")}};
    }
    if (w.scalar("thin_film_weight") > 0.0f)
        extensions["KHR_materials_iridescence"] = {{"iridescenceFactor", w.scalar("thin_film_weight")},
                                                   {"iridescenceIor", w.scalar("thin_film_ior")},
                                                   {"iridescenceThicknessMaximum", w.scalar("thin_film_thickness") * 1000.0f}};
    if (w.scalar("specular_roughness_anisotropy") > 0.0f)
        extensions["KHR_materials_anisotropy"] = {{"anisotropyStrength", w.scalar("specular_roughness_anisotropy")},
                                                  {"anisotropyRotation", glm::radians(w.scalar("geometry_tangent_rotation"))}};
    if (unlit) {
        pbr["baseColorFactor"] = {w.color("emission_color").r, w.color("emission_color").g, w.color("emission_color").b, 1.0};
        extensions["KHR_materials_unlit"] = json::object();
    } else if (emission > 0.0f) {
        out["emissiveFactor"] = vec3Json(w.color("emission_color"));
        if (emission != kGltfEmissionNits) extensions["KHR_materials_emissive_strength"] = {{"emissiveStrength", emission / kGltfEmissionNits}};
    }

    // Textures: each onto its glTF slot; the metallic-roughness pair shares one.
    auto objectFor = [&](const TextureSlot& slot) -> json& {
        if (std::string(slot.extension) == "pbrMetallicRoughness") return pbr;
        if (std::string(slot.extension).empty()) return out;
        return extensions[slot.extension];
    };
    const AnalyticMaterial& analytic = *material.analytic();
    const MaterialTexture* metallicRoughness[2] = {findTexture(analytic, "specular_roughness"), findTexture(analytic, "base_metalness")};
    for (const MaterialTexture& texture : analytic.textures) {
        std::string parameter = texture.parameter;
        if (unlit && parameter == "emission_color") parameter = "base_color";
        else if (parameter == "emission_color" && emission == 0.0f) continue;  // no emission: the texture does not show
        const TextureSlot* slot = nullptr;
        for (const TextureSlot& candidate : kTextureSlots)
            if (candidate.parameter == parameter) slot = &candidate;
        const bool color = slot && slot->srgb;
        if (!slot || texture.kind != TextureKind::Image) {
            w.lost("the " + std::string(texture.kind == TextureKind::Image ? "" : "procedural ") + "texture on '" + parameter +
                   "' has no glTF form; its constant value is written");
            continue;
        }
        if (texture.colorSpace != (color ? TextureColorSpace::Srgb : TextureColorSpace::Linear))
            w.lost("the texture on '" + parameter + "' is decoded as " + (color ? "linear" : "sRGB") + "; glTF's " + slot->key + " is " +
                   (color ? "sRGB" : "linear"));
        if (texture.filter == TextureFilter::Anisotropic) w.lost("anisotropic filtering is written as trilinear (glTF samplers have no anisotropy)");
        json& object = objectFor(*slot);
        if (parameter == "base_metalness" && metallicRoughness[0]) {
            if (metallicRoughness[0]->file != texture.file || metallicRoughness[0]->gltfImage != texture.gltfImage ||
                metallicRoughness[0]->tiling != texture.tiling ||
                metallicRoughness[0]->offset != texture.offset || metallicRoughness[0]->rotation != texture.rotation)
                w.lost("metalness and roughness textures differ: glTF holds one metallicRoughnessTexture; the roughness one is written");
        } else {
            auto info = textures.textureInfo(texture, extensionsUsed);
            if (!info) {
                w.lost("the texture on '" + parameter + "' is not written: " + info.error().format());
                continue;
            }
            object[slot->key] = std::move(*info);
            if (isNormalMapKey(parameter) && texture.normalScale != 1.0f) object[slot->key]["scale"] = texture.normalScale;
        }
        if (parameter == kOcclusionMapKey) {
            if (texture.range.y != 1.0f || texture.channel != TextureChannel::R)
                w.lost("glTF's occlusionTexture reads red as 1 + strength·(texel − 1); the occlusion map's maximum or channel is not kept");
            if (texture.range.x != 0.0f) object[slot->key]["strength"] = 1.0f - texture.range.x;
        }
        if (isSurfaceMapKey(parameter)) continue;
        if (color) {
            const json factor = vec3Json(texture.colorFactor);
            if (parameter == "base_color") pbr["baseColorFactor"] = {factor[0], factor[1], factor[2], 1.0};
            else if (parameter == "emission_color") out["emissiveFactor"] = factor;
            else if (parameter == "specular_color") object["specularColorFactor"] = factor;
            else if (parameter == "fuzz_color") object["sheenColorFactor"] = factor;
            continue;
        }
        if (texture.channel != slot->channel)
            w.lost("the texture on '" + parameter + "' reads another channel than glTF's " + slot->key + " (" + "RGBA"[static_cast<int>(slot->channel)] + ")");
        if (parameter == "thin_film_thickness") {
            object["iridescenceThicknessMinimum"] = texture.range.x * 1000.0f;
            object["iridescenceThicknessMaximum"] = texture.range.y * 1000.0f;
            continue;
        }
        if (texture.range.x != 0.0f) w.lost("the texture on '" + parameter + "' has a minimum above 0; glTF multiplies the texel by a factor");
        static const std::map<std::string, const char*> kFactorKeys = {
            {"specular_roughness", "roughnessFactor"}, {"base_metalness", "metallicFactor"}, {"specular_weight", "specularFactor"},
            {"coat_weight", "clearcoatFactor"}, {"coat_roughness", "clearcoatRoughnessFactor"}, {"fuzz_roughness", "sheenRoughnessFactor"},
            {"transmission_weight", "transmissionFactor"}, {"thin_film_weight", "iridescenceFactor"},
            {"specular_roughness_anisotropy", "anisotropyStrength"}, {"geometry_thickness", "thicknessFactor"}};
        object[kFactorKeys.at(parameter)] = texture.range.y;
    }
    if (!imported.gltfKept.empty()) {
        json kept = json::parse(imported.gltfKept);
        if (kept.contains("extensions")) {
            json keptExtensions = kept["extensions"];
            kept.erase("extensions");
            for (auto& [name, value] : keptExtensions.items())
                if (extensions.contains(name) || name == "KHR_materials_dispersion") mergeKept(extensions[name], value, textures);
        }
        mergeKept(out, kept, textures);
    }
    out["pbrMetallicRoughness"] = pbr;
    if (!extensions.empty()) out["extensions"] = extensions;
    for (const auto& [name, value] : extensions.items()) extensionsUsed.push_back(name);
    return out;
}

}  // namespace glint
