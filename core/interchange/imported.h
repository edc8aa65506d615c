// What an interchange importer hands back: Glint materials (with the texture references the
// source named, kept as paths), lights, and warnings for what did not map exactly. Plain data;
// the parsers live in mtl.h, gltf_material.h and merl.h.
#pragma once

#include <string>
#include <vector>

#include "light/light.h"
#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// A texture the source file names. Glint does not render material textures yet, so the path is
// kept for the user and written back on export, but the material uses its constant values.
struct TextureReference {
    std::string slot;     // the source's name for it: "map_Kd", "baseColorTexture", ...
    std::string path;     // as written in the file (relative to it)
    std::string options;  // MTL map options before the path ("-s 2 2 1"), verbatim; else empty
};

struct ImportedMaterial {
    Material material;
    std::vector<TextureReference> textures;
};

struct ImportedFile {
    std::vector<ImportedMaterial> materials;
    std::vector<Light> lights;
    std::vector<Diagnostic> warnings;  // located where the source allows
};

// Writers return the text and the warnings about what the target format cannot hold.
struct ExportedText {
    std::string text;
    std::vector<Diagnostic> warnings;
};

}  // namespace glint
