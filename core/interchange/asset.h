// Opening a glTF 2.0 / GLB or an OBJ + MTL as the asset it is: one scene object per part (a glTF
// primitive under its node, an OBJ `usemtl` group: geometry/mesh_import.h) with the material the
// file gives it, parts that share a material sharing one scene material; and the asset on the
// preview stage. Textures, cameras and animation are not read here.
#pragma once

#include <string>
#include <vector>

#include "geometry/mesh_import.h"
#include "interchange/imported.h"
#include "scene/scene.h"

namespace glint {

struct Asset {
    std::vector<Material> materials;   // those the parts use, each once, in order of first use, with unique names
    std::vector<SceneObject> objects;  // one mesh part each, centred at the origin in the unit sphere
    std::vector<Light> lights;         // a glTF's KHR_lights_punctual lights, moved and scaled with the asset
    std::vector<Diagnostic> warnings;  // about the file and the materials used
    MeshStatistics statistics;         // of the whole file (geometry/mesh_import.h)
};

// Whether `path` opens as an asset: an .obj, or a .gltf / .glb whose JSON lists meshes (one that
// lists none, or whose JSON cannot be parsed, is an interchange file: interchange/import_formats.h).
bool isAssetFile(const std::string& path);

// Reads the file's parts and materials: each glTF material maps onto `openpbr` (gltf_openpbr.h),
// each MTL material as interchange/mtl.h reads it; a part without one gets a Lambert "default".
// Any problem with the geometry, or a glTF whose materials cannot be read, is an error naming the
// file; a missing MTL library or material is a warning.
Result<Asset> loadAsset(const std::string& path, const MeshImportOptions& options = {}, const MeshImportProgress& progress = {});

// The asset on the preview stage (scene/preview_stage.h) in the sphere's place: its bounding
// sphere is the ball's (radius 1 m), it rests on the floor and the camera looks at its centre.
Scene assetStage(const Asset& asset, int width, int height);

// "3 parts, 2 materials, 1 light".
std::string assetSummary(const Asset& asset);

}  // namespace glint
