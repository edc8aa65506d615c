// Crease-angle vertex normals (see crease_normals.h). Weights: each face's normal counts with
// the angle of the face at the vertex, Thürmer & Wüthrich, "Computing vertex normals from
// polygonal facets", JGT 3(1), 1998: unlike area or equal weights, the result does not depend on
// how a polygon was cut into triangles (a cube's smoothed corner points exactly along the diagonal).
#include "geometry/crease_normals.h"

#include <algorithm>
#include <cmath>

#include "math/constants.h"

namespace glint {
namespace {

// Below this much the dot product of two unit normals is rounding, not an angle: faces in one
// plane whose computed normals differ in the last bits still count as within a 0° crease.
constexpr float kCosineRounding = 1e-6f;

}  // namespace

CornersByPosition::CornersByPosition(const std::vector<uint32_t>& triangles, size_t positionCount)
    : first(positionCount + 1, 0), corners(triangles.size()) {
    for (const uint32_t position : triangles) ++first[position + 1];
    for (size_t p = 0; p < positionCount; ++p) first[p + 1] += first[p];
    std::vector<uint32_t> next(first.begin(), first.end() - 1);
    for (size_t corner = 0; corner < triangles.size(); ++corner) corners[next[triangles[corner]]++] = static_cast<uint32_t>(corner);
}

CreaseNormals::CreaseNormals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& triangles,
                             const CornersByPosition& around, float creaseAngleDegrees)
    : around_(around),
      cosineLimit_(std::cos(creaseAngleDegrees * (kPi / 180.0f)) - kCosineRounding),
      cosineHalfLimit_(std::cos(0.5f * creaseAngleDegrees * (kPi / 180.0f)) - kCosineRounding) {
    faceNormals_.resize(triangles.size() / 3);
    cornerAngles_.resize(triangles.size());
    for (size_t t = 0; t < faceNormals_.size(); ++t) {
        const glm::vec3 p0 = positions[triangles[3 * t]], p1 = positions[triangles[3 * t + 1]],
                        p2 = positions[triangles[3 * t + 2]];
        const glm::vec3 edge01 = p1 - p0, edge02 = p2 - p0, edge12 = p2 - p1;
        const glm::vec3 cross = glm::cross(edge01, edge02);
        const float doubleArea = glm::length(cross);  // |a × b| of any two edges leaving a corner
        faceNormals_[t] = cross / doubleArea;
        // Interior angles as atan2(|a × b|, a · b), robust for tiny and obtuse ones; they sum to π.
        cornerAngles_[3 * t] = std::atan2(doubleArea, glm::dot(edge01, edge02));
        cornerAngles_[3 * t + 1] = std::atan2(doubleArea, -glm::dot(edge12, edge01));
        cornerAngles_[3 * t + 2] = std::max(0.0f, kPi - cornerAngles_[3 * t] - cornerAngles_[3 * t + 1]);
    }
}

void CreaseNormals::normalsAt(uint32_t position, std::vector<CornerNormal>& normals) const {
    normals.clear();
    glm::vec3 all(0.0f);  // the sum over every face: each corner's where no crease divides them
    for (uint32_t i = around_.first[position]; i < around_.first[position + 1]; ++i) {
        const uint32_t corner = around_.corners[i];
        const glm::vec3 face = faceNormals_[corner / 3];
        normals.push_back({corner, face});
        all += cornerAngles_[corner] * face;
    }
    // No crease divides the faces when each lies within half the crease angle of their mean
    // (then any two lie within the angle: the triangle inequality on the sphere). That costs one
    // pass, where comparing every corner's face with every other's costs the square of the count.
    bool creased = false;
    if (cosineLimit_ > -1.0f) {
        const float meanLength = glm::length(all);
        const glm::vec3 mean = meanLength > 0.0f ? all / meanLength : glm::vec3(0.0f);
        for (const CornerNormal& entry : normals) creased = creased || glm::dot(entry.normal, mean) < cosineHalfLimit_;
    }
    // Sums in the order of `around` for every corner: equal sets of faces give equal bits.
    for (CornerNormal& entry : normals) {
        glm::vec3 sum = all;
        if (creased) {
            sum = glm::vec3(0.0f);
            for (uint32_t i = around_.first[position]; i < around_.first[position + 1]; ++i) {
                const uint32_t corner = around_.corners[i];
                const glm::vec3 face = faceNormals_[corner / 3];
                if (glm::dot(entry.normal, face) >= cosineLimit_) sum += cornerAngles_[corner] * face;
            }
        }
        const float length = glm::length(sum);
        if (length > 0.0f && std::isfinite(length)) entry.normal = sum / length;  // else its face's own
    }
}

}  // namespace glint
