// Vertex tangents from UVs: the direction of increasing u on the surface, per vertex, for
// anisotropic BRDFs and normal maps. It does not touch normals, positions or UVs.
#pragma once

#include "geometry/mesh.h"

namespace glint {

// Gives every vertex a unit tangent ⟂ its (unit) normal. A vertex whose tangent is zero gets
// the sum of its triangles' unit ∂p/∂u (Lengyel, "Computing Tangent Space Basis Vectors for an
// Arbitrary Mesh", 2001); one with a tangent (from the file) keeps it. Both are then made ⟂ the
// normal (Gram-Schmidt); where that leaves nothing (no UVs, UVs of zero area) the tangent is any
// unit vector ⟂ the normal (Duff et al. 2017, ShadingFrame::fromNormal).
void completeTangents(Mesh& mesh);

}  // namespace glint
