// What a snapshot case or thumbnail renders: a scene file as it is, or a material file
// ("format": "glint-material") on the standard preview stage. Also lists the JSON files of a
// directory in a stable order. Loading only: rendering and comparing live elsewhere.
#pragma once

#include <string>
#include <vector>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

inline constexpr int kDefaultMaterialPreviewSize = 256;  // pixels, square

// A scene file, or a material file placed on previewStage(). A width/height above 0 overrides
// the scene's "output" size; a material without one is rendered at 256×256. An asset (an .obj,
// a .gltf or .glb with meshes: interchange/asset.h) is placed on the stage whole; another
// interchange file (interchange/import_formats.h: .mtl, .gltf) puts its first material on the
// stage; what did not map exactly is added to `warnings` when given.
Result<Scene> loadRenderable(const std::string& path, int width = 0, int height = 0,
                             std::vector<Diagnostic>* warnings = nullptr);

// The *.json regular files directly inside `directory`, sorted by name, leaving out the file
// names in `excluded`. An unreadable directory gives a Diagnostic naming it.
Result<std::vector<std::string>> listJsonFiles(const std::string& directory, const std::vector<std::string>& excluded = {});

}  // namespace glint
