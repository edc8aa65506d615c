// ParamSpec: the one declaration of a BRDF parameter (name, label, unit, ranges, default,
// scale, kind). The table drives the ImGui panel, the JSON reader and writer, the uniform
// packing and the documentation. It holds no values; ParamValues does.
#pragma once

#include <algorithm>
#include <array>
#include <limits>
#include <span>
#include <string_view>
#include <vector>

namespace glint {

// Color: linear RGB reflectance in [0, 1], shown with an sRGB picker. PerChannel: three linear
// numbers that are not a colour (an index of refraction, an absorption coefficient), shown as
// three numbers. Both are [r, g, b] or one number in files and a vec3 in GLSL.
enum class ParamKind { Scalar, Color, PerChannel, Bool, Enum };
enum class ParamScale { Linear, Log };

struct EnumOption {
    const char* id;     // as written in files
    const char* label;  // as shown in the panel
};

struct ParamSpec {
    const char* name;   // key in files and in GLSL (snake_case)
    const char* label;  // shown in the panel
    const char* unit;   // "" when dimensionless
    ParamKind kind = ParamKind::Scalar;
    float sliderMin = 0.0f;  // the slider's range...
    float sliderMax = 1.0f;
    float validMin = 0.0f;   // ...and what files and typed values may hold (may be wider)
    float validMax = 1.0f;
    std::array<float, 3> defaultValue{0, 0, 0};
    bool validMinExclusive = false;  // validMin itself is refused (an index of refraction > 0)
    ParamScale scale = ParamScale::Linear;
    std::span<const EnumOption> options{};  // Enum only
    const char* help = "";
    // A Scalar weighting a layer or lobe that adds nothing at 0: programs compile it out there.
    bool layerWeight = false;

    // Whether files and typed values may hold `value` (validMin, validMax and validMinExclusive).
    bool accepts(float value) const {
        return (validMinExclusive ? value > validMin : value >= validMin) && value <= validMax;
    }
};

inline constexpr float kUnbounded = std::numeric_limits<float>::infinity();

// The two common rows: a Color, and a dimensionless Scalar in [0, 1] (a weight, a roughness), each
// with the slider over its whole valid range [0, 1].
constexpr ParamSpec colorParam(const char* name, const char* label, std::array<float, 3> value, const char* help) {
    return {.name = name, .label = label, .unit = "", .kind = ParamKind::Color, .defaultValue = value, .help = help};
}
constexpr ParamSpec fractionParam(const char* name, const char* label, float value, const char* help) {
    return {.name = name, .label = label, .unit = "", .kind = ParamKind::Scalar, .defaultValue = {value, 0, 0}, .help = help};
}
// A row marked as a layer's weight.
constexpr ParamSpec layerWeight(ParamSpec spec) {
    spec.layerWeight = true;
    return spec;
}

// Floats one parameter occupies in the packed value array.
constexpr int componentCount(ParamKind kind) {
    return kind == ParamKind::Color || kind == ParamKind::PerChannel ? 3 : 1;
}

// Offset of each parameter in the packed array, and the total.
inline int packedSize(std::span<const ParamSpec> table) {
    int size = 0;
    for (const ParamSpec& spec : table) size += componentCount(spec.kind);
    return size;
}
inline int packedOffset(std::span<const ParamSpec> table, int paramIndex) {
    int offset = 0;
    for (int i = 0; i < paramIndex; ++i) offset += componentCount(table[i].kind);
    return offset;
}

// The table's defaults, packed.
inline std::vector<float> defaultValues(std::span<const ParamSpec> table) {
    std::vector<float> values;
    for (const ParamSpec& spec : table)
        for (int c = 0; c < componentCount(spec.kind); ++c) values.push_back(spec.defaultValue[c]);
    return values;
}

inline int findParam(std::span<const ParamSpec> table, std::string_view name) {
    for (size_t i = 0; i < table.size(); ++i)
        if (name == table[i].name) return static_cast<int>(i);
    return -1;
}

// Values for table `to`: its defaults, except that a parameter `from` has too (same name and kind,
// not an enum, whose options are the table's own) keeps its value in `values` where that lies in
// `to`'s valid range.
inline std::vector<float> carriedValues(std::span<const ParamSpec> from, std::span<const float> values, std::span<const ParamSpec> to) {
    std::vector<float> carried = defaultValues(to);
    for (size_t i = 0; i < to.size(); ++i) {
        const ParamSpec& spec = to[i];
        const int old = findParam(from, spec.name);
        if (spec.kind == ParamKind::Enum || old < 0 || from[old].kind != spec.kind) continue;
        const float* value = values.data() + packedOffset(from, old);
        if (std::all_of(value, value + componentCount(spec.kind), [&](float v) { return v >= spec.validMin && v <= spec.validMax; }))
            std::copy(value, value + componentCount(spec.kind), carried.begin() + packedOffset(to, static_cast<int>(i)));
    }
    return carried;
}

}  // namespace glint
