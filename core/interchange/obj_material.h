// The material a Wavefront .obj file gives its faces: its `mtllib` libraries (relative to the
// .obj, confined to its folder: util/reference_confinement.h) read with Glint's own MTL reader
// (interchange/mtl.h) and its first `usemtl` looked up in them, for a mesh loaded into the editor;
// or every material of those libraries, for an asset (interchange/asset.h). Geometry is not read
// here (geometry/mesh_import.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "interchange/imported.h"

namespace glint {

struct ObjMaterial {
    std::optional<ImportedMaterial> material;  // none: the file names no material Glint could read
    std::vector<Diagnostic> warnings;          // a missing or broken library, an unknown name, …
};

// Never fails: the geometry is usable whatever its materials, so every problem (a library
// refused, missing or malformed: said without quoting it) is a warning located in the .obj or the
// .mtl. A mesh has one material in Glint: an .obj that uses several gets its first, with a warning
// naming how many it uses. Other files (not .obj) give nothing.
ObjMaterial readObjMaterial(const std::string& objPath);

struct ObjMaterialLibraries {
    std::vector<ImportedMaterial> materials;  // of every library, in the order of the file's `mtllib` statements
    std::vector<Diagnostic> warnings;         // about the libraries (refused, missing, malformed)
};
// Never fails, as readObjMaterial; a name defined twice keeps its first definition (as lookup does).
ObjMaterialLibraries readObjMaterialLibraries(const std::string& objPath);

}  // namespace glint
