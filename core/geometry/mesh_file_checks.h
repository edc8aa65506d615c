// Checks on mesh files before assimp reads them, for what assimp 5.2.5 (Debian 12) gets wrong
// silently or never returns from, and counts too large to hold (PLY triangle strips, which it reads as one polygon, are rewritten
// as faces instead: ply_strips.h): PLY headers that hang its reader, OBJ files cut short (a face of fewer than three corners, a corner cut in half,
// indices past the vertices), glTF indices past a primitive's vertices (assimp drops the
// triangle). Each finding is a Diagnostic naming the file and, where the format has them, the
// line (OBJ, PLY header) or the JSON key (glTF). Nothing here builds a mesh.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "util/diagnostic.h"

namespace glint {

// Most vertices or faces a PLY header may declare (an element's count): a larger declared count is
// refused before anything is allocated, naming the count and this limit. Fifty million is ten
// times the densest meshes a material preview is for (a 3D scan), and well past what fits in a
// workstation's memory once imported, welded and uploaded.
inline constexpr long long kMaxMeshElements = 50'000'000;

// `start`: the file's first bytes; `whole`: whether they are all of it. Also refuses an element
// count above kMaxMeshElements.
std::optional<Diagnostic> checkPlyHeader(std::string_view start, bool whole, const std::string& name);
std::optional<Diagnostic> checkObjText(std::string_view text, const std::string& name);
// `bytes`: a .gltf's JSON text or a .glb's bytes (`binary`) of `meshFile`, whose folder holds its
// external buffers (confined to it: util/reference_confinement.h; "": they are not checked).
// A file that requires an extension Glint lacks is refused first (interchange/gltf.h).
std::optional<Diagnostic> checkGltfIndices(std::string_view bytes, bool binary, const std::string& meshFile,
                                           const std::string& name);

}  // namespace glint
