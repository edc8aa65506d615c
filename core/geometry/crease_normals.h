// CreaseNormals: Glint's own vertex normals with a crease angle, the same for every file format.
// Each corner of a triangle gets the angle-weighted average of the normals of the faces around
// its position that lie within the crease angle of the corner's own face. It welds nothing
// itself: its input triangles index positions already welded (mesh_builder.h).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace glint {

// The corners of a triangle list grouped by the position they index (a counting sort, so each
// position's corners are in corner order): corner c is corner c % 3 of triangle c / 3.
struct CornersByPosition {
    CornersByPosition(const std::vector<uint32_t>& triangles, size_t positionCount);
    size_t positionCount() const { return first.size() - 1; }
    // The corners at position p are corners[first[p] .. first[p + 1]).
    std::vector<uint32_t> first, corners;
};

struct CornerNormal {
    uint32_t corner;
    glm::vec3 normal;  // unit
};

class CreaseNormals {
public:
    // `triangles`: three indices into `positions` per triangle, none of zero area, grouped in
    // `around` (which must outlive this object). `creaseAngleDegrees` in [0, 180]: 0 shades
    // every face flat, 180 smooths across every edge.
    CreaseNormals(const std::vector<glm::vec3>& positions, const std::vector<uint32_t>& triangles,
                  const CornersByPosition& around, float creaseAngleDegrees);

    // The normal of every corner at `position`, in the order of `around`, into `normals`.
    // Corners that smooth over the same faces get bit-identical normals.
    void normalsAt(uint32_t position, std::vector<CornerNormal>& normals) const;

private:
    const CornersByPosition& around_;
    std::vector<glm::vec3> faceNormals_;  // unit, one per triangle
    std::vector<float> cornerAngles_;     // the triangle's interior angle at each corner [radians]
    float cosineLimit_;      // faces whose normals' dot product reaches this are smoothed together
    float cosineHalfLimit_;  // the same for half the crease angle
};

}  // namespace glint
