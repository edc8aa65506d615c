// Parameter values in JSON (see param_values_json.h).
#include "scene/param_values_json.h"

#include <limits>

namespace glint {

std::vector<float> readParamValues(ObjectReader& reader, std::span<const ParamSpec> table) {
    std::vector<float> values = defaultValues(table);
    for (size_t i = 0; i < table.size(); ++i) {
        const ParamSpec& spec = table[i];
        float* value = values.data() + packedOffset(table, static_cast<int>(i));
        Bounds bounds = Bounds::between(spec.validMin, spec.validMax == kUnbounded ? std::numeric_limits<double>::max()
                                                                             : spec.validMax);
        bounds.minExclusive = spec.validMinExclusive;
        switch (spec.kind) {
            case ParamKind::Scalar: value[0] = static_cast<float>(reader.number(spec.name, value[0], bounds)); break;
            case ParamKind::Color:
            case ParamKind::PerChannel: {
                // A colour or per-channel quantity may be written as [r, g, b] or as one number for all three.
                if (reader.has(spec.name) && reader.take(spec.name).is_number()) {
                    const float grey = static_cast<float>(reader.number(spec.name, 0, bounds));
                    value[0] = value[1] = value[2] = grey;
                } else {
                    const glm::vec3 color = reader.vec3(spec.name, {value[0], value[1], value[2]}, bounds);
                    value[0] = color.r, value[1] = color.g, value[2] = color.b;
                }
                break;
            }
            case ParamKind::Bool: value[0] = reader.boolean(spec.name, value[0] != 0.0f) ? 1.0f : 0.0f; break;
            case ParamKind::Enum: {
                std::vector<const char*> ids;
                for (const EnumOption& option : spec.options) ids.push_back(option.id);
                value[0] = static_cast<float>(reader.choice(spec.name, ids, static_cast<int>(value[0])));
                break;
            }
        }
    }
    return values;
}

void writeParamValues(nlohmann::json& out, std::span<const ParamSpec> table, const std::vector<float>& values) {
    for (size_t i = 0; i < table.size(); ++i) {
        const ParamSpec& spec = table[i];
        const float* value = values.data() + packedOffset(table, static_cast<int>(i));
        switch (spec.kind) {
            case ParamKind::Scalar: out[spec.name] = value[0]; break;
            case ParamKind::Color:
            case ParamKind::PerChannel: out[spec.name] = {value[0], value[1], value[2]}; break;
            case ParamKind::Bool: out[spec.name] = value[0] != 0.0f; break;
            case ParamKind::Enum: out[spec.name] = spec.options[static_cast<int>(value[0])].id; break;
        }
    }
}

}  // namespace glint
