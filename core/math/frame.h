// ShadingFrame: an orthonormal tangent frame (tangent, bitangent, normal) at a surface point,
// and the conversions between world and local (z = normal) coordinates.
// It does not decide which side a normal faces; callers orient it first.
#pragma once

#include <glm/glm.hpp>

namespace glint {

struct ShadingFrame {
    glm::vec3 tangent{1, 0, 0};
    glm::vec3 bitangent{0, 1, 0};
    glm::vec3 normal{0, 0, 1};
    // The coat's normal where a coat normal map tilts it (openpbr's geometry_coat_normal), zero
    // when the coat shares `normal`; only the openpbr coat lobe reads it (through coatFrame).
    glm::vec3 coatNormal{0, 0, 0};

    // A frame around a unit normal with no preferred tangent: the branchless construction of
    // Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
    static ShadingFrame fromNormal(glm::vec3 n) {
        const float sign = n.z >= 0.0f ? 1.0f : -1.0f;
        const float a = -1.0f / (sign + n.z);
        const float b = n.x * n.y * a;
        ShadingFrame frame;
        frame.tangent = {1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x};
        frame.bitangent = {b, sign + n.y * n.y * a, -n.y};
        frame.normal = n;
        return frame;
    }

    // A frame around a unit normal whose tangent follows `tangentHint` (Gram-Schmidt); falls
    // back to fromNormal when the hint is parallel to the normal.
    static ShadingFrame fromNormalAndTangent(glm::vec3 n, glm::vec3 tangentHint) {
        const glm::vec3 t = tangentHint - n * glm::dot(n, tangentHint);
        const float length = glm::length(t);
        if (length < 1e-6f) return fromNormal(n);
        ShadingFrame frame;
        frame.normal = n;
        frame.tangent = t / length;
        frame.bitangent = glm::cross(n, frame.tangent);
        return frame;
    }

    glm::vec3 toLocal(glm::vec3 world) const {
        return {glm::dot(world, tangent), glm::dot(world, bitangent), glm::dot(world, normal)};
    }
    glm::vec3 toWorld(glm::vec3 local) const {
        return tangent * local.x + bitangent * local.y + normal * local.z;
    }
    float cosTheta(glm::vec3 world) const { return glm::dot(world, normal); }
    // The frame of the coat: around coatNormal with the same tangent, or this frame.
    ShadingFrame coatFrame() const {
        return coatNormal == glm::vec3(0.0f) ? *this : fromNormalAndTangent(coatNormal, tangent);
    }
};

}  // namespace glint
