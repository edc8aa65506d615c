// What `glint render FILE`, `glint FILE` without a display and `glint info FILE` read: a scene or
// material .json, a BRDF Explorer .brdf or .bparam, an asset (an .obj, a .gltf or .glb with
// meshes: interchange/asset.h), an interchange file (.mtl, .gltf, .glb, .binary:
// interchange/import_formats.h) or a mesh (.ply, .stl, .fbx), everything but a scene placed on the
// preview stage.
#pragma once

#include <string>
#include <vector>

#include "geometry/mesh.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

struct RenderInputOptions {
    std::string material;               // --material NAME|INDEX: one of an interchange file's materials on the sphere (empty: an asset whole, else the first)
    MeshUpAxis upAxis = MeshUpAxis::Y;  // --up y|z: a mesh file's up axis
};

// The scene to render. `warnings` gets what the file could not carry over exactly (for the
// material chosen only), `notes` what was loaded ("3 materials; 'b' chosen", a mesh's counts and
// what was dropped and why). Custom BRDFs are not probed here.
Result<Scene> loadRenderInput(const std::string& path, const RenderInputOptions& options, std::vector<Diagnostic>& warnings,
                              std::vector<std::string>& notes);

// One line about an imported mesh: vertices, triangles, meshes merged, what was dropped and why,
// normals generated.
std::string meshStatisticsText(const MeshStatistics& statistics);

}  // namespace glint
