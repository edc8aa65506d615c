// standard_surface, gltf_pbr and open_pbr_surface inputs as OpenPBR inputs (see materialx_shaders.h).
#include "interchange/materialx_shaders.h"

#include <cmath>
#include <map>
#include <span>

#include "math/constants.h"
#include "texture/material_texture.h"

namespace glint {
namespace {

using Defaults = std::map<std::string, glm::vec3, std::less<>>;

// Each shader's inputs and defaults, from its MaterialX 1.39 node definition (libraries/bxdf/).
// Connection-only inputs (normal, tangent) default to zero.
const Defaults kOpenPbrDefaults = {
    {"base_weight", glm::vec3(1)}, {"base_color", glm::vec3(0.8f)}, {"base_diffuse_roughness", glm::vec3(0)},
    {"base_metalness", glm::vec3(0)}, {"specular_weight", glm::vec3(1)}, {"specular_color", glm::vec3(1)},
    {"specular_roughness", glm::vec3(0.3f)}, {"specular_ior", glm::vec3(1.5f)}, {"specular_roughness_anisotropy", glm::vec3(0)},
    {"transmission_weight", glm::vec3(0)}, {"transmission_color", glm::vec3(1)}, {"transmission_depth", glm::vec3(0)},
    {"transmission_scatter", glm::vec3(0)}, {"transmission_scatter_anisotropy", glm::vec3(0)},
    {"transmission_dispersion_scale", glm::vec3(0)}, {"transmission_dispersion_abbe_number", glm::vec3(20)},
    {"subsurface_weight", glm::vec3(0)}, {"subsurface_color", glm::vec3(0.8f)}, {"subsurface_radius", glm::vec3(1)},
    {"subsurface_radius_scale", glm::vec3(1, 0.5f, 0.25f)}, {"subsurface_scatter_anisotropy", glm::vec3(0)},
    {"fuzz_weight", glm::vec3(0)}, {"fuzz_color", glm::vec3(1)}, {"fuzz_roughness", glm::vec3(0.5f)},
    {"coat_weight", glm::vec3(0)}, {"coat_color", glm::vec3(1)}, {"coat_roughness", glm::vec3(0)},
    {"coat_roughness_anisotropy", glm::vec3(0)}, {"coat_ior", glm::vec3(1.6f)}, {"coat_darkening", glm::vec3(1)},
    {"thin_film_weight", glm::vec3(0)}, {"thin_film_thickness", glm::vec3(0.5f)}, {"thin_film_ior", glm::vec3(1.4f)},
    {"emission_luminance", glm::vec3(0)}, {"emission_color", glm::vec3(1)}, {"geometry_opacity", glm::vec3(1)},
    {"geometry_thin_walled", glm::vec3(0)}, {"geometry_normal", glm::vec3(0)}, {"geometry_coat_normal", glm::vec3(0)},
    {"geometry_tangent", glm::vec3(0)}, {"geometry_coat_tangent", glm::vec3(0)},
};

const Defaults kStandardSurfaceDefaults = {
    {"base", glm::vec3(0.8f)}, {"base_color", glm::vec3(1)}, {"diffuse_roughness", glm::vec3(0)}, {"metalness", glm::vec3(0)},
    {"specular", glm::vec3(1)}, {"specular_color", glm::vec3(1)}, {"specular_roughness", glm::vec3(0.2f)},
    {"specular_IOR", glm::vec3(1.5f)}, {"specular_anisotropy", glm::vec3(0)}, {"specular_rotation", glm::vec3(0)},
    {"transmission", glm::vec3(0)}, {"transmission_color", glm::vec3(1)}, {"transmission_depth", glm::vec3(0)},
    {"transmission_scatter", glm::vec3(0)}, {"transmission_scatter_anisotropy", glm::vec3(0)},
    {"transmission_dispersion", glm::vec3(0)}, {"transmission_extra_roughness", glm::vec3(0)},
    {"subsurface", glm::vec3(0)}, {"subsurface_color", glm::vec3(1)}, {"subsurface_radius", glm::vec3(1)},
    {"subsurface_scale", glm::vec3(1)}, {"subsurface_anisotropy", glm::vec3(0)}, {"sheen", glm::vec3(0)},
    {"sheen_color", glm::vec3(1)}, {"sheen_roughness", glm::vec3(0.3f)}, {"coat", glm::vec3(0)}, {"coat_color", glm::vec3(1)},
    {"coat_roughness", glm::vec3(0.1f)}, {"coat_anisotropy", glm::vec3(0)}, {"coat_rotation", glm::vec3(0)},
    {"coat_IOR", glm::vec3(1.5f)}, {"coat_normal", glm::vec3(0)}, {"coat_affect_color", glm::vec3(0)},
    {"coat_affect_roughness", glm::vec3(0)}, {"thin_film_thickness", glm::vec3(0)}, {"thin_film_IOR", glm::vec3(1.5f)},
    {"emission", glm::vec3(0)}, {"emission_color", glm::vec3(1)}, {"opacity", glm::vec3(1)}, {"thin_walled", glm::vec3(0)},
    {"normal", glm::vec3(0)}, {"tangent", glm::vec3(0)},
};

const Defaults kGltfPbrDefaults = {
    {"base_color", glm::vec3(1)}, {"metallic", glm::vec3(1)}, {"roughness", glm::vec3(1)}, {"normal", glm::vec3(0)},
    {"tangent", glm::vec3(0)}, {"occlusion", glm::vec3(1)}, {"transmission", glm::vec3(0)}, {"specular", glm::vec3(1)},
    {"specular_color", glm::vec3(1)}, {"ior", glm::vec3(1.5f)}, {"alpha", glm::vec3(1)}, {"alpha_mode", glm::vec3(0)},
    {"alpha_cutoff", glm::vec3(0.5f)}, {"iridescence", glm::vec3(0)}, {"iridescence_ior", glm::vec3(1.3f)},
    {"iridescence_thickness", glm::vec3(100)}, {"sheen_color", glm::vec3(0)}, {"sheen_roughness", glm::vec3(0)},
    {"clearcoat", glm::vec3(0)}, {"clearcoat_roughness", glm::vec3(0)}, {"clearcoat_normal", glm::vec3(0)},
    {"emissive", glm::vec3(0)}, {"emissive_strength", glm::vec3(1)}, {"thickness", glm::vec3(0)},
    {"attenuation_distance", glm::vec3(0)}, {"attenuation_color", glm::vec3(1)}, {"anisotropy_strength", glm::vec3(0)},
    {"anisotropy_rotation", glm::vec3(0)}, {"dispersion", glm::vec3(0)},
};

// One source shader's inputs with its defaults, and the OpenPBR inputs being built.
class Mapping {
public:
    Mapping(const MaterialXInputs& inputs, const Defaults& defaults, std::vector<Diagnostic>& warnings)
        : inputs_(inputs), defaults_(defaults), warnings_(warnings) {}

    glm::vec3 value(const std::string& name) const {
        const auto set = inputs_.find(name);
        if (set != inputs_.end() && !set->second.image) return set->second.value;
        return defaults_.at(name);
    }
    float scalar(const std::string& name) const { return value(name).x; }
    bool isSet(const std::string& name) const { return inputs_.count(name) > 0; }

    // `to` is `from` unchanged: a value or an image carries over.
    void copy(const std::string& from, const std::string& to) {
        const auto set = inputs_.find(from);
        MaterialXInput input{value(from), {}, {}};
        if (set != inputs_.end()) input = set->second;
        if (input.image) input.value = kOpenPbrDefaults.at(to);
        out_[to] = input;
    }
    // `to` is computed from `sources`: an image on any of them cannot carry over.
    void compute(const std::string& to, glm::vec3 value, std::initializer_list<const char*> sources) {
        MaterialXInput input{value, {}, {}};
        for (const char* source : sources) {
            const auto set = inputs_.find(source);
            if (set == inputs_.end()) continue;
            if (input.where.file.empty()) input.where = set->second.where;
            if (set->second.image)
                warnings_.push_back(makeError(std::string("warning: the image on '") + source + "' is dropped: '" + to +
                                                  "' is computed from it, which Glint's textures cannot do; its default is used",
                                              set->second.where));
        }
        out_[to] = input;
    }
    // `from`'s image as the surface map `to` (texture/material_texture.h), which has no constant
    // form: a constant `from` is dropped with `whyNotConstant`.
    void copyImage(const std::string& from, const std::string& to, const std::string& whyNotConstant) {
        const auto set = inputs_.find(from);
        if (set != inputs_.end() && set->second.image) out_[to] = set->second;
        else drop(from, whyNotConstant);
    }
    // A source input Glint has no counterpart for: a warning when the file sets it away from its default.
    void drop(const std::string& name, const std::string& why) {
        const auto set = inputs_.find(name);
        if (set == inputs_.end() || (!set->second.image && set->second.value == defaults_.at(name))) return;
        warnings_.push_back(makeError("warning: input '" + name + "' is dropped: " + why, set->second.where));
    }
    void warnUnknown(const std::string& category) {
        for (const auto& [name, input] : inputs_)
            if (!defaults_.count(name))
                warnings_.push_back(makeError("warning: '" + name + "' is not an input of " + category + " (ignored)", input.where));
    }
    MaterialXInputs take() { return std::move(out_); }

private:
    const MaterialXInputs& inputs_;
    const Defaults& defaults_;
    std::vector<Diagnostic>& warnings_;
    MaterialXInputs out_;
};

// MaterialX's NG_standard_surface_to_open_pbr_surface, node by node.
MaterialXInputs fromStandardSurface(const MaterialXInputs& inputs, std::vector<Diagnostic>& warnings) {
    Mapping m(inputs, kStandardSurfaceDefaults, warnings);
    m.warnUnknown("standard_surface");
    m.copy("base", "base_weight");
    // Standard Surface tints what lies under the coat by coat_color.
    const glm::vec3 coatTint = glm::mix(glm::vec3(1.0f), m.value("coat_color"), m.scalar("coat"));
    if (coatTint == glm::vec3(1.0f))
        m.copy("base_color", "base_color");
    else
        m.compute("base_color", m.value("base_color") * coatTint, {"base_color", "coat_color", "coat"});
    m.copy("diffuse_roughness", "base_diffuse_roughness");
    m.copy("metalness", "base_metalness");
    // specular has no effect on Standard Surface's metal; specular_weight scales OpenPBR's.
    m.compute("specular_weight", glm::vec3(m.scalar("metalness") > 0.0f ? 1.0f : m.scalar("specular")), {"metalness", "specular"});
    const glm::vec3 specularColor = m.value("specular_color");
    m.compute("specular_color", specularColor.r + specularColor.g + specularColor.b == 0.0f ? glm::vec3(1.0f) : specularColor,
              {"specular_color"});
    m.copy("specular_roughness", "specular_roughness");
    m.copy("specular_IOR", "specular_ior");
    m.copy("specular_anisotropy", "specular_roughness_anisotropy");
    m.drop("specular_rotation", "the anisotropy direction follows Glint's tangent frame");
    m.copy("transmission", "transmission_weight");
    m.copy("transmission_color", "transmission_color");
    m.copy("transmission_depth", "transmission_depth");
    m.copy("transmission_scatter", "transmission_scatter");
    m.copy("transmission_scatter_anisotropy", "transmission_scatter_anisotropy");
    m.copy("transmission_dispersion", "transmission_dispersion_scale");
    m.drop("transmission_extra_roughness", "OpenPBR has no counterpart");
    m.copy("subsurface", "subsurface_weight");
    m.copy("subsurface_color", "subsurface_color");
    m.copy("subsurface_scale", "subsurface_radius");
    m.copy("subsurface_radius", "subsurface_radius_scale");
    m.copy("subsurface_anisotropy", "subsurface_scatter_anisotropy");
    m.copy("sheen", "fuzz_weight");
    m.copy("sheen_color", "fuzz_color");
    // "approximated by eye" in the translation graph
    m.compute("fuzz_roughness", glm::vec3(std::pow(m.scalar("sheen_roughness"), 0.4f)), {"sheen_roughness"});
    // A coat on a metal is how Standard Surface colours metals: the tint went into base_color.
    m.compute("coat_weight", glm::vec3(m.scalar("coat") * m.scalar("metalness") > 0.0f ? 0.0f : m.scalar("coat")),
              {"coat", "metalness"});
    m.copy("coat_color", "coat_color");
    m.copy("coat_roughness", "coat_roughness");
    m.copy("coat_anisotropy", "coat_roughness_anisotropy");
    m.drop("coat_rotation", "the anisotropy direction follows Glint's tangent frame");
    m.copy("coat_IOR", "coat_ior");
    m.copy("coat_affect_roughness", "coat_darkening");
    m.drop("coat_affect_color", "OpenPBR's coat darkens the base by its own physics");
    const float thickness = m.scalar("thin_film_thickness") * 0.001f;  // nm → µm
    m.compute("thin_film_weight", glm::vec3(thickness > 0.0f ? 1.0f : 0.0f), {"thin_film_thickness"});
    m.compute("thin_film_thickness", glm::vec3(thickness), {"thin_film_thickness"});
    m.copy("thin_film_IOR", "thin_film_ior");
    // Standard Surface's emission scales radiance in the renderer's unit, as glTF's emissive does:
    // 1 is 1 W/(sr·m²) = 683 nit here, as in Glint's glTF reader (the translation graph copies the
    // number, its renderers having no photometric unit).
    m.compute("emission_luminance", glm::vec3(m.scalar("emission") * kLumensPerWatt), {"emission"});
    m.copy("emission_color", "emission_color");
    m.compute("geometry_opacity", glm::vec3(m.value("opacity").r), {"opacity"});
    m.copy("thin_walled", "geometry_thin_walled");
    m.copy("normal", "geometry_normal");
    m.copy("coat_normal", "geometry_coat_normal");
    m.copy("tangent", "geometry_tangent");
    return m.take();
}

// gltf_pbr after the glTF 2.0 core and KHR_materials_* definitions: both use perceptual
// roughness and F0 from the IOR, so most inputs map one to one.
MaterialXInputs fromGltfPbr(const MaterialXInputs& inputs, std::vector<Diagnostic>& warnings) {
    Mapping m(inputs, kGltfPbrDefaults, warnings);
    m.warnUnknown("gltf_pbr");
    m.copy("base_color", "base_color");
    m.copy("metallic", "base_metalness");
    m.copy("roughness", "specular_roughness");
    m.copy("ior", "specular_ior");
    m.copy("specular", "specular_weight");
    m.copy("specular_color", "specular_color");
    m.copy("transmission", "transmission_weight");
    // KHR_materials_volume: thickness 0 is a thin wall; attenuation over attenuation_distance.
    m.compute("geometry_thin_walled", glm::vec3(m.scalar("thickness") == 0.0f && m.scalar("transmission") > 0.0f ? 1.0f : 0.0f),
              {"thickness", "transmission"});
    if (m.isSet("attenuation_distance") && m.scalar("attenuation_distance") > 0.0f) {
        m.copy("attenuation_color", "transmission_color");
        m.copy("attenuation_distance", "transmission_depth");
    }
    // KHR_materials_sheen: the colour is the sheen's strength.
    m.compute("fuzz_weight", glm::vec3(m.isSet("sheen_color") ? 1.0f : 0.0f), {});
    m.copy("sheen_color", "fuzz_color");
    m.copy("sheen_roughness", "fuzz_roughness");
    m.copy("clearcoat", "coat_weight");
    m.copy("clearcoat_roughness", "coat_roughness");
    m.compute("coat_ior", glm::vec3(1.5f), {});  // KHR_materials_clearcoat: a fixed index of 1.5
    m.copy("iridescence", "thin_film_weight");
    m.compute("thin_film_thickness", glm::vec3(m.scalar("iridescence_thickness") * 0.001f), {"iridescence_thickness"});  // nm → µm
    m.copy("iridescence_ior", "thin_film_ior");
    // Emission: the colour times emissive_strength (KHR_materials_emissive_strength), a radiance
    // of 1 W/(sr·m²) = 683 nit for white at strength 1, as in Glint's glTF reader.
    m.copy("emissive", "emission_color");
    m.compute("emission_luminance", glm::vec3(m.scalar("emissive_strength") * kLumensPerWatt), {"emissive_strength"});
    m.copy("anisotropy_strength", "specular_roughness_anisotropy");
    m.compute("geometry_tangent_rotation", glm::vec3(m.scalar("anisotropy_rotation") * 180.0f / kPi), {"anisotropy_rotation"});
    m.copy("alpha", "geometry_opacity");
    const float dispersion = m.scalar("dispersion");  // KHR_materials_dispersion: 20 / Abbe number
    m.compute("transmission_dispersion_scale", glm::vec3(dispersion > 0.0f ? 1.0f : 0.0f), {"dispersion"});
    if (dispersion > 0.0f) m.compute("transmission_dispersion_abbe_number", glm::vec3(20.0f / dispersion), {"dispersion"});
    m.copyImage("occlusion", kOcclusionMapKey, "Glint reads an image on it (its occlusion map), not a constant");
    m.drop("alpha_mode", "Glint renders every material opaque");
    m.drop("alpha_cutoff", "Glint renders every material opaque");
    m.copy("normal", "geometry_normal");
    m.copy("clearcoat_normal", "geometry_coat_normal");
    m.copy("tangent", "geometry_tangent");
    return m.take();
}

// open_pbr_surface as it is; names outside its node definition are warnings.
MaterialXInputs fromOpenPbr(const MaterialXInputs& inputs, std::vector<Diagnostic>& warnings) {
    MaterialXInputs openPbr;
    for (const auto& [name, input] : inputs) {
        if (!kOpenPbrDefaults.count(name)) {
            warnings.push_back(makeError("warning: '" + name + "' is not an input of open_pbr_surface (ignored)", input.where));
            continue;
        }
        openPbr[name] = input;
        if (input.image) openPbr[name].value = kOpenPbrDefaults.at(name);
    }
    return openPbr;
}

// OpenPBR inputs Glint's table lacks: a warning each where it changes the look (a lobe's
// secondary inputs only matter when its weight is above 0), then removed.
void keepGlintInputs(MaterialXInputs& inputs, std::span<const ParamSpec> glintTable, std::vector<Diagnostic>& warnings) {
    for (auto it = inputs.begin(); it != inputs.end();) {
        const std::string& name = it->first;
        const MaterialXInput& input = it->second;
        const bool glint = findParam(glintTable, name) >= 0 || (surfaceMapOf(name) && input.image);
        // A lobe's secondary inputs: its weight's warning speaks for them.
        const bool secondary = (name.rfind("subsurface_", 0) == 0 && name != "subsurface_weight") ||
                               name == "transmission_dispersion_abbe_number" || name == "transmission_scatter_anisotropy";
        const auto standard = kOpenPbrDefaults.find(name);
        const bool matters = input.image || standard == kOpenPbrDefaults.end() || input.value != standard->second;
        if (!glint && !secondary && matters && !input.where.file.empty())
            warnings.push_back(makeError("warning: '" + name + "' is dropped: Glint's openpbr has no " +
                                             (name.rfind("subsurface", 0) == 0 ? "subsurface scattering"
                                              : name.rfind("transmission_", 0) == 0 ? "volume scattering or dispersion"
                                              : name == "geometry_opacity" ? "cut-outs (every material is opaque)"
                                                                           : "such input"),
                                         input.where));
        it = glint ? std::next(it) : inputs.erase(it);
    }
}

}  // namespace

const char* surfaceMapOf(const std::string& input) {
    return input == "geometry_normal"        ? kNormalMapKey
           : input == "geometry_coat_normal" ? kCoatNormalMapKey
           : input == kOcclusionMapKey       ? kOcclusionMapKey
                                             : nullptr;
}

bool isReadableMaterialXShader(const std::string& category) {
    return category == "open_pbr_surface" || category == "standard_surface" || category == "gltf_pbr";
}

MaterialXInputs toOpenPbrInputs(const std::string& category, const MaterialXInputs& inputs,
                                std::span<const ParamSpec> glintTable, std::vector<Diagnostic>& warnings) {
    MaterialXInputs openPbr = category == "standard_surface" ? fromStandardSurface(inputs, warnings)
                              : category == "gltf_pbr"       ? fromGltfPbr(inputs, warnings)
                                                             : fromOpenPbr(inputs, warnings);
    keepGlintInputs(openPbr, glintTable, warnings);
    return openPbr;
}

}  // namespace glint
