// Named access to packed material values (see material_values.h).
#include "interchange/material_values.h"

#include <cmath>
#include <sstream>

namespace glint {
namespace {

// Where parameter `name` starts in the material's packed values; its component count in `count`.
int slot(const Material& material, std::string_view name, int* count) {
    const auto table = paramTable(material);
    const int index = findParam(table, name);
    GLINT_CHECK(index >= 0);
    *count = componentCount(table[index].kind);
    return packedOffset(table, index);
}

}  // namespace

glm::vec3 paramValue(const Material& material, std::string_view name) {
    int count = 0;
    const float* value = paramValues(material).data() + slot(material, name, &count);
    return count == 3 ? glm::vec3(value[0], value[1], value[2]) : glm::vec3(value[0]);
}

float paramScalar(const Material& material, std::string_view name) { return paramValue(material, name).x; }

void setParam(Material& material, std::string_view name, glm::vec3 value) {
    int count = 0;
    float* target = paramValues(material).data() + slot(material, name, &count);
    for (int c = 0; c < count; ++c) target[c] = value[c];
}

void setParam(Material& material, std::string_view name, float value) { setParam(material, name, glm::vec3(value)); }

std::optional<std::string> findOutOfRange(const Material& material) {
    const AnalyticMaterial* analytic = material.analytic();
    if (!analytic) return std::nullopt;  // a .brdf file's own ranges are checked as it is read
    const auto table = modelInfo(analytic->model).params;
    for (size_t i = 0; i < table.size(); ++i) {
        const ParamSpec& spec = table[i];
        const float* value = analytic->values.data() + packedOffset(table, static_cast<int>(i));
        for (int c = 0; c < componentCount(spec.kind); ++c) {
            const float v = value[c];
            if (std::isfinite(v) && spec.accepts(v)) continue;
            std::ostringstream message;
            message << "'" << spec.name << "'";
            if (componentCount(spec.kind) == 3) message << "[" << c << "]";
            message << ": " << v << " is out of range for " << modelInfo(analytic->model).id << ": must be ";
            if (spec.validMax == kUnbounded)
                message << (spec.validMinExclusive ? "greater than " : "at least ") << spec.validMin;
            else
                message << "in [" << spec.validMin << ", " << spec.validMax << "]";
            return message.str();
        }
    }
    return std::nullopt;
}

}  // namespace glint
