// The files assimp may open while it imports one mesh: the mesh file itself, and the files it
// names (a glTF's buffers) confined to its folder (util/reference_confinement.h). An OBJ's
// material libraries are never opened here: Glint reads them itself (interchange/obj_material.h),
// and assimp's parse errors would quote their bytes. It remembers refusals and referenced files
// opened, so that the importer's message can name them instead of quoting them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <assimp/DefaultIOSystem.h>

#include "util/diagnostic.h"

namespace glint {

class MeshIoSystem : public Assimp::DefaultIOSystem {
public:
    // `meshFile`: the file imported; "" for bytes in memory, which may open no other file.
    explicit MeshIoSystem(std::string meshFile);

    bool Exists(const char* file) const override;
    Assimp::IOStream* Open(const char* file, const char* mode = "rb") override;

    // The first refusal, located in the mesh file.
    const std::optional<Diagnostic>& refusal() const { return refusal_; }
    // Files other than the mesh file that were opened, in order.
    const std::vector<std::string>& referencedFilesOpened() const { return referencedOpened_; }

private:
    // Whether `file` may be opened; a refused one is remembered.
    bool mayOpen(const char* file) const;

    std::string meshFile_;
    bool isObj_;
    mutable std::optional<Diagnostic> refusal_;
    std::vector<std::string> referencedOpened_;
};

}  // namespace glint
