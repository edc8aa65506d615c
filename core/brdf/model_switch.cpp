// Model switching through the quantities models share (see model_switch.h): each model says
// what it holds (extract), each says what it takes (apply); a pair needs no code of its own.
#include "brdf/model_switch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "brdf/fresnel.h"
#include "interchange/material_values.h"

namespace glint {

float dielectricIorFromF0(float f0) {
    const float root = std::sqrt(std::clamp(f0, 0.0f, 0.99f));
    return (1.0f + root) / (1.0f - root);
}
float conductorExtinctionFromF0(float f0) {
    const float clamped = std::clamp(f0, 0.0f, 0.999f);
    return 2.0f * std::sqrt(clamped / (1.0f - clamped));
}
float blinnPhongExponentFromAlpha(float alpha) { return 2.0f / (alpha * alpha) - 2.0f; }
float alphaFromBlinnPhongExponent(float exponent) { return std::sqrt(2.0f / (std::max(exponent, 0.0f) + 2.0f)); }

namespace {

// A quantity and the source parameters it came from ("" for one the model implies, like a
// mirror's zero roughness, which is never reported as kept).
template <class T>
struct Held {
    std::optional<T> value;
    std::vector<std::string> from;
    explicit operator bool() const { return value.has_value(); }
    const T& operator*() const { return *value; }
};

// What a material holds, in physical terms shared between models.
struct Appearance {
    Held<glm::vec3> diffuse;       // diffuse albedo ρ_d (a dielectric's body colour)
    Held<glm::vec3> specular;      // a lobe's reflectance at normal incidence (Phong ρ_s, a metal's F0)
    Held<glm::vec2> alpha;         // linear roughness α along tangent and bitangent (equal: isotropic)
    Held<glm::vec3> ior;           // complex index n + iκ per channel
    Held<glm::vec3> extinction;
    Held<float> glassIor;          // a transparent dielectric's index...
    Held<glm::vec3> absorption;    // ...and its Beer-Lambert coefficient σ [1/m]
};

glm::vec3 color(const Material& m, const char* name) { return paramValue(m, name); }
float scalar(const Material& m, const char* name) { return paramScalar(m, name); }

Appearance extract(const Material& m) {
    Appearance a;
    const auto take = [](auto& held, auto value, std::vector<std::string> from) {
        held.value = value;
        held.from = std::move(from);
    };
    switch (m.model) {
        case BrdfModel::Lambert:
        case BrdfModel::OrenNayar:
        case BrdfModel::Retroreflective: take(a.diffuse, color(m, "albedo"), {"albedo"}); break;
        case BrdfModel::BlinnPhong:
        case BrdfModel::Phong: {
            take(a.diffuse, color(m, "diffuse_albedo"), {"diffuse_albedo"});
            take(a.specular, color(m, "specular"), {"specular"});
            // Phong's lobe about the mirror direction is about as wide as Blinn-Phong's with 4× the exponent.
            const float exponent = scalar(m, "exponent") * (m.model == BrdfModel::Phong ? 4.0f : 1.0f);
            take(a.alpha, glm::vec2(alphaFromBlinnPhongExponent(exponent)), {"exponent"});
            break;
        }
        case BrdfModel::CookTorrance:
            take(a.diffuse, color(m, "diffuse_albedo"), {"diffuse_albedo"});
            take(a.ior, color(m, "ior"), {"ior"});
            take(a.extinction, color(m, "extinction"), {"extinction"});
            take(a.alpha, glm::vec2(scalar(m, "roughness")), {"roughness"});
            break;
        case BrdfModel::GgxAnisotropic:
            take(a.diffuse, color(m, "diffuse_albedo"), {"diffuse_albedo"});
            take(a.ior, color(m, "ior"), {"ior"});
            take(a.extinction, color(m, "extinction"), {"extinction"});
            take(a.alpha, glm::vec2(scalar(m, "roughness_x"), scalar(m, "roughness_y")), {"roughness_x", "roughness_y"});
            break;
        case BrdfModel::Ward:  // Ward's α is the RMS slope, Beckmann's m, close to GGX's α
            take(a.diffuse, color(m, "diffuse_albedo"), {"diffuse_albedo"});
            take(a.specular, color(m, "specular"), {"specular"});
            take(a.alpha, glm::vec2(scalar(m, "roughness_x"), scalar(m, "roughness_y")), {"roughness_x", "roughness_y"});
            break;
        case BrdfModel::Mirror:
            take(a.diffuse, color(m, "diffuse_albedo"), {"diffuse_albedo"});
            take(a.ior, color(m, "ior"), {"ior"});
            take(a.extinction, color(m, "extinction"), {"extinction"});
            take(a.alpha, glm::vec2(0.0f), {});
            break;
        case BrdfModel::Glass:
            take(a.glassIor, scalar(m, "ior"), {"ior"});
            take(a.absorption, color(m, "absorption"), {"absorption"});
            take(a.alpha, glm::vec2(0.0f), {});
            break;
        case BrdfModel::OpenPbr: {
            const float metalness = scalar(m, "base_metalness");
            const glm::vec3 base = color(m, "base_color") * scalar(m, "base_weight");
            const float ior = scalar(m, "specular_ior");
            // OpenPBR's anisotropic mapping: α_t = r²·√(2/(1 + (1 − a)²)), α_b = (1 − a)·α_t.
            const float r = scalar(m, "specular_roughness"), anisotropy = scalar(m, "specular_roughness_anisotropy");
            const float alphaT = std::min(1.0f, r * r * std::sqrt(2.0f / (1.0f + (1.0f - anisotropy) * (1.0f - anisotropy))));
            take(a.alpha, glm::vec2(alphaT, (1.0f - anisotropy) * alphaT),
                 anisotropy > 0.0f ? std::vector<std::string>{"specular_roughness", "specular_roughness_anisotropy"}
                                   : std::vector<std::string>{"specular_roughness"});
            if (scalar(m, "transmission_weight") >= 0.5f) {
                take(a.glassIor, ior, {"specular_ior"});
                const float depth = scalar(m, "transmission_depth");
                const glm::vec3 tint = glm::max(color(m, "transmission_color"), glm::vec3(1e-4f));
                if (depth > 0.0f) take(a.absorption, -glm::log(tint) / depth, {"transmission_color", "transmission_depth"});
                a.alpha.from.clear();  // Glint's glass is smooth
            } else if (metalness >= 0.5f) {
                take(a.specular, base, {"base_color", "base_metalness"});
                const glm::vec3 f0 = glm::clamp(base, glm::vec3(0.0f), glm::vec3(0.999f));
                take(a.ior, glm::vec3(1.0f), {"base_metalness"});
                take(a.extinction, glm::vec3(conductorExtinctionFromF0(f0.r), conductorExtinctionFromF0(f0.g), conductorExtinctionFromF0(f0.b)),
                     {"base_color", "base_metalness"});
            } else {
                take(a.diffuse, base, scalar(m, "base_weight") != 1.0f ? std::vector<std::string>{"base_color", "base_weight"}
                                                                      : std::vector<std::string>{"base_color"});
                take(a.ior, glm::vec3(ior), {"specular_ior"});
                take(a.extinction, glm::vec3(0.0f), {});
            }
            break;
        }
    }
    return a;
}

// The target side: writes parameters from the appearance and records what it used.
class Applier {
public:
    Applier(Material& material, std::vector<std::string>& kept, std::set<std::string>& used)
        : material_(material), kept_(kept), used_(used) {}

    // Source parameter → target parameter for values copied unchanged (their textures follow).
    std::map<std::string, std::string> unchanged;

    template <class T>
    void use(const Held<T>& held, const std::string& description) {
        if (held.from.empty()) return;
        used_.insert(held.from.begin(), held.from.end());
        kept_.push_back(description);
    }
    void set(const char* name, glm::vec3 value) {
        const auto table = modelInfo(material_.model).params;
        const ParamSpec& spec = table[findParam(table, name)];
        setParam(material_, name, glm::clamp(value, glm::vec3(spec.validMin), glm::vec3(spec.validMax)));
    }
    void set(const char* name, float value) { set(name, glm::vec3(value)); }

private:
    Material& material_;
    std::vector<std::string>& kept_;
    std::set<std::string>& used_;
};

std::string joined(const std::vector<std::string>& names) {
    std::string text;
    for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
    return text;
}

// The reflectance at normal incidence the appearance implies (a lobe's colour, or F0 of n + iκ).
std::optional<glm::vec3> normalReflectance(const Appearance& a) {
    if (a.specular) return *a.specular;
    if (a.ior) return fresnelF0(*a.ior, a.extinction ? *a.extinction : glm::vec3(0.0f));
    return std::nullopt;
}
const std::vector<std::string>& reflectanceSources(const Appearance& a) { return a.specular ? a.specular.from : a.ior.from; }

// A reflectance as a complex index: grey → a dielectric (κ = 0), coloured → a conductor (n = 1).
std::pair<glm::vec3, glm::vec3> indexForReflectance(glm::vec3 f0) {
    const bool grey = std::abs(f0.r - f0.g) < 1e-3f && std::abs(f0.g - f0.b) < 1e-3f;
    if (grey) return {glm::vec3(dielectricIorFromF0(f0.g)), glm::vec3(0.0f)};
    return {glm::vec3(1.0f), glm::vec3(conductorExtinctionFromF0(f0.r), conductorExtinctionFromF0(f0.g), conductorExtinctionFromF0(f0.b))};
}

void apply(const Appearance& a, Applier& to, BrdfModel target) {
    const float isotropicAlpha = a.alpha ? std::sqrt((*a.alpha).x * (*a.alpha).y) : 0.0f;
    const bool metal = a.extinction && glm::length(*a.extinction) > 0.1f;
    const auto diffuseTo = [&](const char* name) {
        if (!a.diffuse) return;
        to.set(name, *a.diffuse);
        to.use(a.diffuse, joined(a.diffuse.from) + " → " + name);
        if (a.diffuse.from.size() == 1) to.unchanged[a.diffuse.from.front()] = name;
    };
    const auto indexTo = [&](const char* iorName, const char* extinctionName) {
        if (a.ior) {
            to.set(iorName, *a.ior);
            to.use(a.ior, joined(a.ior.from) + " → " + iorName);
            if (a.extinction) to.set(extinctionName, *a.extinction), to.use(a.extinction, joined(a.extinction.from) + " → " + extinctionName);
        } else if (a.glassIor) {
            to.set(iorName, *a.glassIor);
            to.use(a.glassIor, joined(a.glassIor.from) + " → " + iorName);
        } else if (a.specular) {
            const auto [n, k] = indexForReflectance(*a.specular);
            to.set(iorName, n), to.set(extinctionName, k);
            to.use(a.specular, joined(a.specular.from) + " → " + iorName + ", " + extinctionName + " (same F0)");
        }
    };
    const auto reflectanceTo = [&](const char* name) {
        const auto f0 = normalReflectance(a);
        if (!f0) return;
        to.set(name, *f0);
        if (a.specular) to.use(a.specular, joined(a.specular.from) + " → " + name);
        else to.use(a.ior, joined(reflectanceSources(a)) + " → " + name + " (F0 of n + iκ)"), to.use(a.extinction, "");
    };
    const auto alphaTo = [&](const char* name, float alpha, const std::string& how) {
        if (!a.alpha) return;
        to.set(name, alpha);
        to.use(a.alpha, joined(a.alpha.from) + " → " + name + how);
    };
    switch (target) {
        case BrdfModel::Lambert:
        case BrdfModel::OrenNayar:
        case BrdfModel::Retroreflective: diffuseTo("albedo"); break;
        case BrdfModel::BlinnPhong:
        case BrdfModel::Phong: {
            diffuseTo("diffuse_albedo");
            reflectanceTo("specular");
            const float exponent = blinnPhongExponentFromAlpha(std::max(isotropicAlpha, 0.01f)) / (target == BrdfModel::Phong ? 4.0f : 1.0f);
            alphaTo("exponent", exponent, target == BrdfModel::Phong ? " (n = (2/α² − 2)/4)" : " (n = 2/α² − 2)");
            break;
        }
        case BrdfModel::CookTorrance:
            diffuseTo("diffuse_albedo");
            indexTo("ior", "extinction");
            alphaTo("roughness", isotropicAlpha, " (α = √(α_x α_y))");
            break;
        case BrdfModel::GgxAnisotropic:
            diffuseTo("diffuse_albedo");
            indexTo("ior", "extinction");
            if (a.alpha) to.set("roughness_x", (*a.alpha).x);
            alphaTo("roughness_y", a.alpha ? (*a.alpha).y : 0.0f, " and roughness_x");
            break;
        case BrdfModel::Ward:
            diffuseTo("diffuse_albedo");
            reflectanceTo("specular");
            if (a.alpha) to.set("roughness_x", (*a.alpha).x);
            alphaTo("roughness_y", a.alpha ? (*a.alpha).y : 0.0f, " and roughness_x");
            break;
        case BrdfModel::Mirror:
            diffuseTo("diffuse_albedo");
            indexTo("ior", "extinction");
            break;
        case BrdfModel::Glass:
            if (a.glassIor) {
                to.set("ior", *a.glassIor);
                to.use(a.glassIor, joined(a.glassIor.from) + " → ior");
            } else if (a.ior && !metal) {
                to.set("ior", (*a.ior).g);
                to.use(a.ior, joined(a.ior.from) + " → ior (green channel)");
            }
            if (a.absorption) to.set("absorption", *a.absorption), to.use(a.absorption, joined(a.absorption.from) + " → absorption");
            break;
        case BrdfModel::OpenPbr: {
            if (a.glassIor) {
                to.set("transmission_weight", 1.0f);
                to.set("specular_ior", *a.glassIor);
                to.use(a.glassIor, joined(a.glassIor.from) + " → specular_ior, transmission_weight 1");
                if (a.absorption) {
                    // Beer-Lambert over 1 m: transmission_color = e^(−σ·1 m) at transmission_depth 1 m.
                    to.set("transmission_depth", 1.0f);
                    to.set("transmission_color", glm::exp(-*a.absorption));
                    to.use(a.absorption, joined(a.absorption.from) + " → transmission_color at transmission_depth 1 m");
                }
            } else if (metal || (a.specular && !a.diffuse && !a.ior)) {
                to.set("base_metalness", 1.0f);
                reflectanceTo("base_color");
            } else {
                diffuseTo("base_color");
                if (a.ior) {
                    to.set("specular_ior", std::max((*a.ior).g, 1.0f));
                    to.use(a.ior, joined(a.ior.from) + " → specular_ior (green channel)");
                } else if (a.specular) {
                    to.set("specular_ior", dielectricIorFromF0((*a.specular).g));
                    to.use(a.specular, joined(a.specular.from) + " → specular_ior (same F0)");
                }
            }
            if (a.alpha && !a.glassIor) {
                // Inverting OpenPBR's mapping: a = 1 − α_b/α_t, r = √(α_t / √(2/(1 + (1 − a)²))).
                const float alphaT = std::max((*a.alpha).x, (*a.alpha).y), alphaB = std::min((*a.alpha).x, (*a.alpha).y);
                const float anisotropy = alphaT > 0.0f ? 1.0f - alphaB / alphaT : 0.0f;
                const float stretch = std::sqrt(2.0f / (1.0f + (1.0f - anisotropy) * (1.0f - anisotropy)));
                if (anisotropy > 1e-3f) to.set("specular_roughness_anisotropy", anisotropy);
                alphaTo("specular_roughness", std::sqrt(alphaT / stretch), anisotropy > 1e-3f ? " (r = √α, with anisotropy)" : " (r = √α)");
            }
            break;
        }
    }
}

}  // namespace

std::string ModelSwitch::summary() const {
    std::string text = kept.empty() ? "kept nothing" : "kept " + joined(kept);
    if (!dropped.empty()) text += "; dropped " + joined(dropped);
    return text;
}

ModelSwitch switchModel(const Material& source, BrdfModel target) {
    ModelSwitch result;
    result.material = Material::withDefaults(source.name, target);
    if (source.custom) {
        result.dropped.push_back("the .brdf shader and its parameters");
        return result;
    }
    std::set<std::string> used;
    std::vector<std::string> kept;
    Applier applier(result.material, kept, used);
    apply(extract(source), applier, target);
    std::erase(kept, std::string());
    result.kept = std::move(kept);
    // Textures follow the parameter they drove where it was copied unchanged; the normal map always.
    for (const MaterialTexture& texture : source.textures) {
        const auto copied = applier.unchanged.find(texture.parameter);
        if (texture.parameter != kNormalMapKey && copied == applier.unchanged.end()) {
            result.dropped.push_back("the texture on " + texture.parameter);
            continue;
        }
        result.material.textures.push_back(texture);
        if (texture.parameter != kNormalMapKey) result.material.textures.back().parameter = copied->second;
    }
    const auto table = modelInfo(source.model).params;
    for (size_t i = 0; i < table.size(); ++i) {
        const ParamSpec& spec = table[i];
        if (used.count(spec.name)) continue;
        const glm::vec3 value = paramValue(source, spec.name);
        const glm::vec3 standard(spec.defaultValue[0], componentCount(spec.kind) == 3 ? spec.defaultValue[1] : spec.defaultValue[0],
                                 componentCount(spec.kind) == 3 ? spec.defaultValue[2] : spec.defaultValue[0]);
        if (value != standard) result.dropped.push_back(spec.name);
    }
    return result;
}

}  // namespace glint
