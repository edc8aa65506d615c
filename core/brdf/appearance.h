// What a material holds in terms that models share, for switching it to another model
// (model_switch.h): diffuse albedo, a lobe's normal-incidence reflectance, roughness α, the
// complex index n + iκ, glass's index and absorption. A model says what it holds with
// `appearance(Params)` and what it takes with `takeAppearance(AppearanceWriter&)` (model.h);
// a model without them keeps nothing in a switch. No Material here: the writer fills packed values.
#pragma once

#include <map>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "brdf/param_table.h"

namespace glint {

// A quantity and the source parameters it came from (none for one the model implies, like a
// mirror's zero roughness, which is never reported as kept).
template <class T>
struct Held {
    std::optional<T> value;
    std::vector<std::string> from;
    explicit operator bool() const { return value.has_value(); }
    const T& operator*() const { return *value; }
};

struct Appearance {
    Held<glm::vec3> diffuse;     // diffuse albedo ρ_d (a dielectric's body colour)
    Held<glm::vec3> specular;    // a lobe's reflectance at normal incidence (Phong ρ_s, a metal's F0)
    Held<glm::vec2> alpha;       // linear roughness α along tangent and bitangent (equal: isotropic)
    Held<glm::vec3> ior;         // complex index n + iκ per channel
    Held<glm::vec3> extinction;
    Held<float> glassIor;        // a transparent dielectric's index...
    Held<glm::vec3> absorption;  // ...and its Beer-Lambert coefficient σ [1/m]
};

// "a, b, c": the source parameters a description of what was kept names.
std::string joinedNames(const std::vector<std::string>& names);

// The target side of a switch: writes the target model's parameters (clamped to their valid
// ranges) from the source's appearance, and records what it used and how ("albedo → base_color").
class AppearanceWriter {
public:
    AppearanceWriter(const Appearance& source, std::span<const ParamSpec> table, std::vector<float>& values)
        : source_(source), table_(table), values_(values) {}

    const Appearance& source() const { return source_; }
    float isotropicAlpha() const;  // √(α_x α_y), 0 without roughness
    bool metal() const;            // a conductor's extinction

    void set(const char* name, glm::vec3 value);
    void set(const char* name, float value) { set(name, glm::vec3(value)); }
    template <class T>
    void use(const Held<T>& held, const std::string& description) {
        if (held.from.empty()) return;
        used.insert(held.from.begin(), held.from.end());
        kept.push_back(description);
    }

    // The shared quantities written to the target's parameters of those names.
    void diffuseTo(const char* name);
    void indexTo(const char* iorName, const char* extinctionName);
    void reflectanceTo(const char* name);  // a lobe's colour, or F0 of n + iκ
    void alphaTo(const char* name, float alpha, const std::string& how);
    void anisotropicAlphaTo(const char* nameX, const char* nameY);

    std::vector<std::string> kept;
    std::set<std::string> used;
    std::map<std::string, std::string> unchanged;  // source → target parameter copied as it was (textures follow)

private:
    const Appearance& source_;
    std::span<const ParamSpec> table_;
    std::vector<float>& values_;
};

}  // namespace glint
