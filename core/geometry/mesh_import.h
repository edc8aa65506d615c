// Mesh import through assimp: OBJ (its .mtl materials: interchange/obj_material.h), PLY, STL, glTF 2.0
// (.gltf, .glb) and FBX, merged into one indexed triangle Mesh centred and scaled into the unit
// sphere, or kept as the file's parts in that same frame, with statistics. It loads geometry only
// (which material each part names, but no materials, textures, animation, cameras).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "util/diagnostic.h"

namespace glint {

struct MeshImportOptions {
    // Vertex normals are generated where the file has none (crease_normals.h), the same for
    // every format; faces whose normals differ by more than this angle keep separate normals
    // [degrees, in [0, 180]: 0 is flat shading, 180 smooth across every edge].
    float smoothingAngleDegrees = 60.0f;
    MeshUpAxis upAxis = MeshUpAxis::Y;
};

// Called with the fraction done, in [0, 1], from the thread that imports; returning false
// cancels the import, which then fails with a Diagnostic for which isImportCancellation() is
// true. Assimp reports progress while it parses OBJ text; other formats are parsed in one step,
// so a cancel there takes effect after the parse, at Glint's next report while it merges, welds
// and makes normals.
using MeshImportProgress = std::function<bool(float fraction)>;

struct ImportedMesh {
    std::shared_ptr<const Mesh> mesh;  // centred at the origin, bounding radius 1
    MeshStatistics statistics;
};

// Loads a mesh file. Nothing is returned half-loaded: any problem (missing, empty, truncated
// or malformed file, NaN coordinates, indices out of range, no triangles) is a Diagnostic
// naming the file, and the line where assimp reports one.
Result<ImportedMesh> importMesh(const std::string& path, const MeshImportOptions& options = {},
                                const MeshImportProgress& progress = {});

// The same from bytes in memory; `formatHint` is the file extension without the dot ("obj",
// "ply", "glb", ...); `name` names the data in messages.
Result<ImportedMesh> importMeshFromMemory(const void* data, size_t size, const std::string& formatHint,
                                          const std::string& name, const MeshImportOptions& options = {},
                                          const MeshImportProgress& progress = {});

// One placed mesh of a file's node tree: a glTF primitive under its node, an OBJ `usemtl` group.
struct ImportedPart {
    std::string name;            // its mesh's name, else its node's, else "mesh N"
    unsigned materialIndex = 0;  // the file's material as assimp numbers them (a glTF file's own order)
    std::string materialName;    // the material's name in the file (an OBJ's `usemtl`), else empty
    ImportedMesh mesh;           // in the frame of the whole file: the parts fit together in the unit sphere
};

struct ImportedParts {
    std::vector<ImportedPart> parts;  // in the order of a depth-first walk of the node tree
    MeshStatistics statistics;        // of the whole file: the parts' counts summed, with what was dropped
    glm::vec3 fileCentre{0.0f};       // what centring took out, in the file's units (after the up-axis turn)
    float fileRadius = 1.0f;          // what scaling divided by: the file's bounding radius in its units
};

// Loads a file as its parts, each with its own welded mesh, all centred and scaled together as
// importMesh centres and scales the whole. Parts whose triangles all have zero area are left out.
Result<ImportedParts> importMeshParts(const std::string& path, const MeshImportOptions& options = {},
                                      const MeshImportProgress& progress = {});
// Part `part` of importMeshParts(path, options). Asked for the parts of one file in turn (a scene
// file's objects), it reads the file once while the parts already handed out are alive.
Result<ImportedMesh> importMeshPart(const std::string& path, const MeshImportOptions& options, int part);

bool isImportCancellation(const Diagnostic& diagnostic);

// The extensions Glint offers to import, lower case without the dot.
const std::vector<std::string>& meshFileExtensions();
// Whether a path ends in one of meshFileExtensions() (case-insensitive).
bool isMeshFile(const std::string& path);

}  // namespace glint
