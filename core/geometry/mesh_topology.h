// Mesh topology: whether a triangle mesh is closed (every edge shared by exactly two triangles
// that run along it in opposite directions, once vertices at the same position are welded: UV
// seams and split normals duplicate vertices) and which way its faces turn. The GL renderer culls
// the back faces of closed meshes seen from outside. It neither repairs nor changes the mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/mesh.h"

namespace glint {

enum class MeshClosure {
    Open,           // an edge with one triangle, or more than two, or two running the same way;
                    // or a closed part that encloses no volume (a two-sided sheet), or parts that disagree
    ClosedOutward,  // closed, every part counter-clockwise seen from outside (positive volume)
    ClosedInward,   // closed, every part turned inside out (negative volume)
};

// The closure of `mesh`, its vertices welded by position. Linear in the triangles: about 0.1 s
// for a million triangles.
MeshClosure meshClosure(const Mesh& mesh);

// Per vertex, the index of the first vertex at exactly the same position (−0 = +0; itself when
// none came before): the welded vertex ids. The importer (mesh_builder.h) and the procedural
// shapes give every copy of a position (at a crease, a UV seam) the same coordinates.
std::vector<uint32_t> weldPositions(const Mesh& mesh);

}  // namespace glint
