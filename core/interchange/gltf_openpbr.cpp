// glTF materials ↔ openpbr (see gltf_openpbr.h). Sections: the texture table · import · export.
#include "interchange/gltf_openpbr.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

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


constexpr float kGltfCoatIor = 1.5f;  // KHR_materials_clearcoat's fixed index

// --- import -----------------------------------------------------------------------------------

struct Reading {
    const GltfSource& source;
    ImportedMaterial& imported;
    Material& m;  // imported.material, in openpbr
    json kept = json::object();  // ImportedMaterial::gltfKept
    std::vector<MaterialTexture> textures;
    std::map<std::string, glm::vec2> ranges;  // scalar textures: [0, factor]
    std::map<std::string, glm::vec3> colorFactors;
    glm::vec4 baseColor{1.0f};
    bool transmits = false;         // KHR_materials_transmission is present
    float emissiveStrength = 1.0f;  // KHR_materials_emissive_strength

    void warn(const std::string& pointer, const std::string& message) const {
        imported.warnings.push_back(makeError("warning: " + pointer + ": " + message, source.document.locate(pointer)));
    }
    void note(const std::string& pointer, const std::string& message) const {
        imported.warnings.push_back(makeError("note: " + pointer + ": " + message, source.document.locate(pointer)));
    }
    json& keptAt(const std::string& extension) {
        return extension.empty() ? kept : kept["extensions"][extension];
    }

    // A factor that also scales its texture: the parameter's value, and the texture's range [0, factor].
    float factor(ObjectReader& object, const char* key, double fallback, Bounds bounds, const char* parameter) {
        const float value = static_cast<float>(object.number(key, fallback, bounds));
        setParam(m, parameter, value);
        ranges[parameter] = {0.0f, value};
        return value;
    }

    // The slots of kTextureSlots under `object` (`extension` names it): each a MaterialTexture.
    void readSlots(ObjectReader& object, const std::string& extension) {
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

// The core material: pbrMetallicRoughness, and alpha, which Glint does not draw.
void readMetallicRoughness(Reading& r, ObjectReader& material) {
    float metallic = 1.0f, roughness = 1.0f;
    std::optional<ObjectReader> pbr;
    if (material.has("pbrMetallicRoughness")) {
        pbr.emplace(material.object("pbrMetallicRoughness"));
        r.baseColor = pbr->vec4("baseColorFactor", r.baseColor, Bounds::between(0, 1));
        metallic = number(*pbr, "metallicFactor", 1.0, Bounds::between(0, 1));
        roughness = number(*pbr, "roughnessFactor", 1.0, Bounds::between(0, 1));
    }
    setParam(r.m, "base_color", glm::vec3(r.baseColor));
    setParam(r.m, "base_metalness", metallic);
    setParam(r.m, "specular_roughness", roughness);
    r.ranges["base_metalness"] = {0.0f, metallic};
    r.ranges["specular_roughness"] = {0.0f, roughness};
    r.colorFactors["base_color"] = glm::vec3(r.baseColor);
    if (pbr) {
        r.readSlots(*pbr, "pbrMetallicRoughness");
        rejectUnknownGltfKeys(*pbr);
    }
}

void readAlpha(Reading& r, ObjectReader& material) {
    const std::string alphaMode = material.string("alphaMode", "OPAQUE");
    if (alphaMode != "OPAQUE" && alphaMode != "MASK" && alphaMode != "BLEND") material.fail("alphaMode", "expected \"OPAQUE\", \"MASK\" or \"BLEND\"");
    if (alphaMode != "OPAQUE" || r.baseColor.a < 1.0f)
        r.warn(material.pointer(), "alpha (alphaMode " + alphaMode + ", alpha " + std::to_string(r.baseColor.a) +
                                       ") is ignored: Glint draws opaque surfaces");
    material.number("alphaCutoff", 0.5, Bounds::nonNegative());
    material.boolean("doubleSided", false);  // Glint shades both sides of its shapes' outer surface alike
}

// --- the material extensions, each read from its object into openpbr ---

void readIor(Reading& r, ObjectReader& ior) { setParam(r.m, "specular_ior", number(ior, "ior", 1.5, Bounds::between(1, 1e6))); }

void readSpecular(Reading& r, ObjectReader& specular) {
    r.factor(specular, "specularFactor", 1.0, Bounds::between(0, 1), "specular_weight");
    glm::vec3 color = specular.vec3("specularColorFactor", glm::vec3(1.0f), Bounds::nonNegative());
    if (glm::any(glm::greaterThan(color, glm::vec3(1.0f)))) {
        r.warn(specular.pointer(), "specularColorFactor above 1 is clipped to 1 (OpenPBR's specular_color is a reflectance)");
        color = glm::min(color, glm::vec3(1.0f));
    }
    setParam(r.m, "specular_color", color);
    r.colorFactors["specular_color"] = color;
    r.readSlots(specular, "KHR_materials_specular");
}

void readClearcoat(Reading& r, ObjectReader& coat) {
    r.factor(coat, "clearcoatFactor", 0.0, Bounds::between(0, 1), "coat_weight");
    r.factor(coat, "clearcoatRoughnessFactor", 0.0, Bounds::between(0, 1), "coat_roughness");
    setParam(r.m, "coat_ior", kGltfCoatIor);
    setParam(r.m, "coat_darkening", 0.0f);  // glTF's coat only attenuates by its Fresnel: no internal reflections
    r.readSlots(coat, "KHR_materials_clearcoat");
}

void readSheen(Reading& r, ObjectReader& sheen) {
    const glm::vec3 color = sheen.vec3("sheenColorFactor", glm::vec3(0.0f), Bounds::between(0, 1));
    r.factor(sheen, "sheenRoughnessFactor", 0.0, Bounds::between(0, 1), "fuzz_roughness");
    setParam(r.m, "fuzz_weight", 1.0f);
    setParam(r.m, "fuzz_color", color);
    r.colorFactors["fuzz_color"] = color;
    r.readSlots(sheen, "KHR_materials_sheen");
}

void readTransmission(Reading& r, ObjectReader& transmission) {
    r.factor(transmission, "transmissionFactor", 0.0, Bounds::between(0, 1), "transmission_weight");
    r.readSlots(transmission, "KHR_materials_transmission");
    r.transmits = true;
    // glTF tints transmitted light by the base colour; without a volume, so does transmission_color.
    setParam(r.m, "transmission_color", glm::vec3(r.baseColor));
    setParam(r.m, "geometry_thin_walled", 1.0f);  // glTF: without KHR_materials_volume the surface is thin
}

void readVolume(Reading& r, ObjectReader& volume) {
    // In the mesh's units, taken as metres.
    const float thickness = r.factor(volume, "thicknessFactor", 0.0, Bounds::nonNegative(), "geometry_thickness");
    const float distance = number(volume, "attenuationDistance", std::numeric_limits<double>::max(), Bounds::positive());
    const glm::vec3 color = volume.vec3("attenuationColor", glm::vec3(1.0f), Bounds::between(0, 1));
    r.readSlots(volume, "KHR_materials_volume");
    if (thickness > 0.0f) setParam(r.m, "geometry_thin_walled", 0.0f);
    if (std::isfinite(distance) && distance < std::numeric_limits<float>::max()) {
        setParam(r.m, "transmission_color", color);
        setParam(r.m, "transmission_depth", distance);
        if (r.transmits && glm::vec3(r.baseColor) != glm::vec3(1.0f))
            r.note(volume.pointer(), "the volume's attenuation is transmission_color; baseColor's own tint of the transmitted light is not kept");
    }
}

void readIridescence(Reading& r, ObjectReader& iridescence) {
    r.factor(iridescence, "iridescenceFactor", 0.0, Bounds::between(0, 1), "thin_film_weight");
    const float filmIor = number(iridescence, "iridescenceIor", 1.3, Bounds::between(1, 1e6));
    const float minimum = number(iridescence, "iridescenceThicknessMinimum", 100.0, Bounds::nonNegative());
    const float maximum = number(iridescence, "iridescenceThicknessMaximum", 400.0, Bounds::nonNegative());
    setParam(r.m, "thin_film_ior", filmIor);
    setParam(r.m, "thin_film_thickness", maximum / 1000.0f);  // nm → µm; without a texture glTF uses the maximum
    r.ranges["thin_film_thickness"] = {minimum / 1000.0f, maximum / 1000.0f};
    const size_t before = r.textures.size();
    r.readSlots(iridescence, "KHR_materials_iridescence");
    const bool thicknessTextured = std::any_of(r.textures.begin() + static_cast<long>(before), r.textures.end(),
                                               [](const MaterialTexture& t) { return t.parameter == "thin_film_thickness"; });
    if (!thicknessTextured && iridescence.has("iridescenceThicknessMinimum"))
        r.keptAt("KHR_materials_iridescence")["iridescenceThicknessMinimum"] = minimum;
}

void readAnisotropy(Reading& r, ObjectReader& anisotropy) {
    r.factor(anisotropy, "anisotropyStrength", 0.0, Bounds::between(0, 1), "specular_roughness_anisotropy");
    setParam(r.m, "geometry_tangent_rotation", glm::degrees(number(anisotropy, "anisotropyRotation", 0.0, Bounds::any())));
    if (anisotropy.has("anisotropyTexture"))
        r.warn(appendPointer(anisotropy.pointer(), "anisotropyTexture"),
               "its blue channel (strength) is used; the direction in red and green is not (one tangent rotation per material)");
    r.readSlots(anisotropy, "KHR_materials_anisotropy");
}

void readEmissiveStrength(Reading& r, ObjectReader& strength) {
    r.emissiveStrength = number(strength, "emissiveStrength", 1.0, Bounds::nonNegative());
}

void readDispersion(Reading& r, ObjectReader& dispersion) {
    const float value = number(dispersion, "dispersion", 0.0, Bounds::nonNegative());
    r.keptAt("KHR_materials_dispersion")["dispersion"] = value;
    if (value > 0.0f)
        r.note(dispersion.pointer(), "dispersion " + std::to_string(value) + " (Abbe number " + std::to_string(20.0f / value) +
                                         ") is kept for export, not rendered: Glint refracts every wavelength alike");
}

// Closest form: no reflection, emitting the base colour as radiance (1 = the display's white).
void readUnlit(Reading& r, ObjectReader& unlit) {
    setParam(r.m, "base_weight", 0.0f);
    setParam(r.m, "specular_weight", 0.0f);
    setParam(r.m, "emission_color", glm::vec3(r.baseColor));
    setParam(r.m, "emission_luminance", kGltfEmissionNits);
    r.note(unlit.pointer(), "unlit is imported as a black, non-reflecting surface emitting the base colour (base_weight 0, specular_weight 0, "
                            "emission 683 nits × baseColor): lights do not change it, the display's exposure and tone map do");
    for (MaterialTexture& texture : r.textures)
        if (texture.parameter == "base_color") texture.parameter = "emission_color";
}

// In the order they are read: the volume reads what transmission set; unlit, read after the
// emission is set, overrides it.
constexpr std::pair<const char*, void (*)(Reading&, ObjectReader&)> kExtensionReaders[] = {
    {"KHR_materials_ior", readIor},
    {"KHR_materials_specular", readSpecular},
    {"KHR_materials_clearcoat", readClearcoat},
    {"KHR_materials_sheen", readSheen},
    {"KHR_materials_transmission", readTransmission},
    {"KHR_materials_volume", readVolume},
    {"KHR_materials_iridescence", readIridescence},
    {"KHR_materials_anisotropy", readAnisotropy},
    {"KHR_materials_emissive_strength", readEmissiveStrength},
    {"KHR_materials_dispersion", readDispersion},
};

// The extensions Glint reads, then a warning for each other one not in "extensionsUsed" (the
// file's own warning names those listed there, once).
void readExtensions(Reading& r, ObjectReader& material, glm::vec3 emissive) {
    std::optional<ObjectReader> extensions;
    if (material.has("extensions")) extensions.emplace(material.object("extensions"));
    const auto readIfPresent = [&](const char* name, void (*read)(Reading&, ObjectReader&)) {
        if (!extensions || !extensions->has(name)) return;
        ObjectReader extension = extensions->object(name);
        read(r, extension);
        rejectUnknownGltfKeys(extension);
    };
    for (const auto& [name, read] : kExtensionReaders) readIfPresent(name, read);
    if (emissive != glm::vec3(0.0f)) {
        setParam(r.m, "emission_color", emissive);
        setParam(r.m, "emission_luminance", kGltfEmissionNits * r.emissiveStrength);
    }
    r.colorFactors["emission_color"] = emissive;
    readIfPresent("KHR_materials_unlit", readUnlit);
    r.readSlots(material, "");
    if (!extensions) return;
    const json& used = r.source.document.root().value("extensionsUsed", json::array());
    for (const auto& [key, value] : material.take("extensions").items())
        if (!isGltfMaterialExtension(key) && (!used.is_array() || std::find(used.begin(), used.end(), key) == used.end()))
            r.warn(appendPointer(extensions->pointer(), key), "extension not supported by Glint (nor listed in extensionsUsed); ignored");
}

// The textures, table order; Glint binds at most kMaxMaterialTextures.
void attachTextures(Reading& r, const ObjectReader& material) {
    for (MaterialTexture& texture : r.textures) {
        if (static_cast<int>(r.m.analytic()->textures.size()) >= kMaxMaterialTextures) {
            r.warn(material.pointer(), "more than " + std::to_string(kMaxMaterialTextures) + " textures: '" + texture.parameter +
                                           "' uses its constant value");
            continue;
        }
        putTexture(*r.m.analytic(), std::move(texture));
    }
}

}  // namespace

bool isGltfMaterialExtension(const std::string& name) {
    return name == "KHR_materials_unlit" ||
           std::any_of(std::begin(kExtensionReaders), std::end(kExtensionReaders), [&](const auto& reader) { return name == reader.first; });
}

ImportedMaterial readGltfMaterial(ObjectReader& reader, const GltfSource& source, int index) {
    ImportedMaterial imported;
    imported.material = Material::withDefaults(reader.string("name", "gltf material " + std::to_string(index)), BrdfModel::OpenPbr);
    Reading reading{source, imported, imported.material};
    readMetallicRoughness(reading, reader);
    const glm::vec3 emissive = reader.vec3("emissiveFactor", glm::vec3(0.0f), Bounds::between(0, 1));
    readAlpha(reading, reader);
    readExtensions(reading, reader, emissive);
    rejectUnknownGltfKeys(reader);
    attachTextures(reading, reader);
    if (auto problem = findOutOfRange(imported.material)) reader.failHere(*problem);
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

// The material object being written, its pbrMetallicRoughness and its extensions.
struct GltfMaterialJson {
    json out, pbr, extensions;
};

// What readUnlit makes of KHR_materials_unlit: no reflection, emitting 683 nits × a colour.
bool isUnlit(const Writing& w) {
    return w.scalar("base_weight") == 0.0f && w.scalar("specular_weight") == 0.0f && w.scalar("emission_luminance") == kGltfEmissionNits &&
           w.scalar("coat_weight") == 0.0f && w.scalar("fuzz_weight") == 0.0f && w.scalar("transmission_weight") == 0.0f;
}

// The base, specular and emission factors, and unlit.
void writeCore(const Writing& w, bool unlit, GltfMaterialJson& written) {
    const glm::vec3 baseColor = unlit ? w.color("emission_color") : w.color("base_color");
    const float emission = w.scalar("emission_luminance");
    written.pbr["baseColorFactor"] = {baseColor.r, baseColor.g, baseColor.b, 1.0};
    written.pbr["metallicFactor"] = w.scalar("base_metalness");
    written.pbr["roughnessFactor"] = w.scalar("specular_roughness");
    if (!unlit && w.scalar("base_weight") != 1.0f) w.lost("base_weight " + std::to_string(w.scalar("base_weight")) + " has no glTF form; written as 1");
    if (w.scalar("base_diffuse_roughness") != 0.0f) w.lost("base_diffuse_roughness has no glTF form (glTF's diffuse is Lambertian)");
    if (w.scalar("specular_ior") != 1.5f) written.extensions["KHR_materials_ior"] = {{"ior", w.scalar("specular_ior")}};
    if (!unlit && (w.scalar("specular_weight") != 1.0f || w.color("specular_color") != glm::vec3(1.0f))) {
        if (w.scalar("specular_weight") > 1.0f) w.lost("specular_weight above 1 is written as specularFactor 1");
        written.extensions["KHR_materials_specular"] = {{"specularFactor", std::min(w.scalar("specular_weight"), 1.0f)},
                                                        {"specularColorFactor", vec3Json(w.color("specular_color"))}};
    }
    if (unlit) {
        written.extensions["KHR_materials_unlit"] = json::object();
    } else if (emission > 0.0f) {
        written.out["emissiveFactor"] = vec3Json(w.color("emission_color"));
        if (emission != kGltfEmissionNits)
            written.extensions["KHR_materials_emissive_strength"] = {{"emissiveStrength", emission / kGltfEmissionNits}};
    }
}

void writeTransmission(const Writing& w, json& extensions) {
    if (w.scalar("transmission_weight") <= 0.0f) return;
    extensions["KHR_materials_transmission"] = {{"transmissionFactor", w.scalar("transmission_weight")}};
    const float depth = w.scalar("transmission_depth");
    const bool thin = w.scalar("geometry_thin_walled") > 0.5f;
    const glm::vec3 baseColor = w.color("base_color");
    if (depth == 0.0f && w.color("transmission_color") != baseColor)
        w.lost("glTF tints transmitted light by the base colour: transmission_color (depth 0) is not written");
    if (thin && depth == 0.0f) return;
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

// The coat, fuzz, thin film and anisotropy.
void writeLayers(const Writing& w, json& extensions) {
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
}

// The factor a scalar texture's maximum is written as, beside its textureInfo.
void writeScalarFactor(const Writing& w, const MaterialTexture& texture, const TextureSlot& slot, json& object) {
    const std::string& parameter = texture.parameter;
    if (texture.channel != slot.channel)
        w.lost("the texture on '" + parameter + "' reads another channel than glTF's " + slot.key + " (" + "RGBA"[static_cast<int>(slot.channel)] + ")");
    if (parameter == "thin_film_thickness") {
        object["iridescenceThicknessMinimum"] = texture.range.x * 1000.0f;
        object["iridescenceThicknessMaximum"] = texture.range.y * 1000.0f;
        return;
    }
    if (texture.range.x != 0.0f) w.lost("the texture on '" + parameter + "' has a minimum above 0; glTF multiplies the texel by a factor");
    static const std::map<std::string, const char*> kFactorKeys = {
        {"specular_roughness", "roughnessFactor"}, {"base_metalness", "metallicFactor"}, {"specular_weight", "specularFactor"},
        {"coat_weight", "clearcoatFactor"}, {"coat_roughness", "clearcoatRoughnessFactor"}, {"fuzz_roughness", "sheenRoughnessFactor"},
        {"transmission_weight", "transmissionFactor"}, {"thin_film_weight", "iridescenceFactor"},
        {"specular_roughness_anisotropy", "anisotropyStrength"}, {"geometry_thickness", "thicknessFactor"}};
    object[kFactorKeys.at(parameter)] = texture.range.y;
}

// The textureInfo of `texture` in `object`, or whether the metallic-roughness pair's other half
// already wrote it; false when it could not be written (w says why).
bool writeTextureInfo(const Writing& w, const MaterialTexture& texture, const TextureSlot& slot, GltfTextureWriter& textures,
                      std::vector<std::string>& extensionsUsed, json& object) {
    const MaterialTexture* roughness = findTexture(*w.material.analytic(), "specular_roughness");
    if (texture.parameter == "base_metalness" && roughness) {
        if (roughness->file != texture.file || roughness->gltfImage != texture.gltfImage || roughness->tiling != texture.tiling ||
            roughness->offset != texture.offset || roughness->rotation != texture.rotation)
            w.lost("metalness and roughness textures differ: glTF holds one metallicRoughnessTexture; the roughness one is written");
        return true;
    }
    auto info = textures.textureInfo(texture, extensionsUsed);
    if (!info) {
        w.lost("the texture on '" + texture.parameter + "' is not written: " + info.error().format());
        return false;
    }
    object[slot.key] = std::move(*info);
    if (isNormalMapKey(texture.parameter) && texture.normalScale != 1.0f) object[slot.key]["scale"] = texture.normalScale;
    return true;
}

// One texture onto its glTF slot (unlit's emission onto the base colour's).
void writeTexture(const Writing& w, MaterialTexture texture, bool unlit, GltfTextureWriter& textures,
                  std::vector<std::string>& extensionsUsed, GltfMaterialJson& written) {
    if (unlit && texture.parameter == "emission_color") texture.parameter = "base_color";
    else if (texture.parameter == "emission_color" && w.scalar("emission_luminance") == 0.0f) return;  // no emission: it does not show
    const std::string& parameter = texture.parameter;
    const auto slot = std::find_if(std::begin(kTextureSlots), std::end(kTextureSlots),
                                   [&](const TextureSlot& candidate) { return candidate.parameter == parameter; });
    if (slot == std::end(kTextureSlots) || texture.kind != TextureKind::Image) {
        w.lost("the " + std::string(texture.kind == TextureKind::Image ? "" : "procedural ") + "texture on '" + parameter +
               "' has no glTF form; its constant value is written");
        return;
    }
    const bool color = slot->srgb;
    if (texture.colorSpace != (color ? TextureColorSpace::Srgb : TextureColorSpace::Linear))
        w.lost("the texture on '" + parameter + "' is decoded as " + (color ? "linear" : "sRGB") + "; glTF's " + slot->key + " is " +
               (color ? "sRGB" : "linear"));
    if (texture.filter == TextureFilter::Anisotropic) w.lost("anisotropic filtering is written as trilinear (glTF samplers have no anisotropy)");
    const std::string extension = slot->extension;
    json& object = extension == "pbrMetallicRoughness" ? written.pbr : extension.empty() ? written.out : written.extensions[extension];
    if (!writeTextureInfo(w, texture, *slot, textures, extensionsUsed, object)) return;
    if (parameter == kOcclusionMapKey) {
        if (texture.range.y != 1.0f || texture.channel != TextureChannel::R)
            w.lost("glTF's occlusionTexture reads red as 1 + strength·(texel − 1); the occlusion map's maximum or channel is not kept");
        if (texture.range.x != 0.0f) object[slot->key]["strength"] = 1.0f - texture.range.x;
    }
    if (isSurfaceMapKey(parameter)) return;
    if (!color) return writeScalarFactor(w, texture, *slot, object);
    const json factor = vec3Json(texture.colorFactor);
    if (parameter == "base_color") written.pbr["baseColorFactor"] = {factor[0], factor[1], factor[2], 1.0};
    else if (parameter == "emission_color") written.out["emissiveFactor"] = factor;
    else if (parameter == "specular_color") object["specularColorFactor"] = factor;
    else if (parameter == "fuzz_color") object["sheenColorFactor"] = factor;
}

// What the import kept (ImportedMaterial::gltfKept), merged back: kept extensions only where the
// material still has them, but for dispersion, which Glint never writes itself.
void writeKept(const std::string& gltfKept, GltfTextureWriter& textures, GltfMaterialJson& written) {
    json kept = json::parse(gltfKept);
    if (kept.contains("extensions")) {
        json keptExtensions = kept["extensions"];
        kept.erase("extensions");
        for (auto& [name, value] : keptExtensions.items())
            if (written.extensions.contains(name) || name == "KHR_materials_dispersion") mergeKept(written.extensions[name], value, textures);
    }
    mergeKept(written.out, kept, textures);
}

}  // namespace

json gltfOpenPbrMaterial(const ImportedMaterial& imported, GltfTextureWriter& textures, std::vector<std::string>& extensionsUsed,
                         std::vector<Diagnostic>& warnings) {
    const Material& material = imported.material;
    GltfMaterialJson written{{{"name", material.name}}, json::object(), json::object()};
    const Writing w{material, warnings};
    const bool unlit = isUnlit(w);
    writeCore(w, unlit, written);
    writeTransmission(w, written.extensions);
    writeLayers(w, written.extensions);
    const AnalyticMaterial& analytic = *material.analytic();
    for (const MaterialTexture& texture : analytic.textures) writeTexture(w, texture, unlit, textures, extensionsUsed, written);
    if (!imported.gltfKept.empty()) writeKept(imported.gltfKept, textures, written);
    written.out["pbrMetallicRoughness"] = written.pbr;
    if (!written.extensions.empty()) written.out["extensions"] = written.extensions;
    for (const auto& [name, value] : written.extensions.items()) extensionsUsed.push_back(name);
    return written.out;
}

}  // namespace glint
