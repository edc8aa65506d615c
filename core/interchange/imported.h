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

// A texture the source file names that Glint's material textures do not carry (an MTL map), kept
// for the user and written back on export.
struct TextureReference {
    std::string slot;     // the source's name for it: "map_Kd", "baseColorTexture", ...
    std::string path;     // as written in the file (relative to it)
    std::string options;  // MTL map options before the path ("-s 2 2 1"), verbatim; else empty
};

struct ImportedMaterial {
    Material material;
    std::vector<TextureReference> textures;
    std::vector<Diagnostic> warnings;  // about this material only, located where the source allows
    // glTF values read but not rendered (dispersion, the iridescence minimum), as JSON text merged back into the material by writeGltf so that glTF →
    // Glint → glTF keeps them; a kept texture names its image by "uri" (absolute path or data
    // URI) instead of "index". Empty when none; not kept once the material is in a scene.
    std::string gltfKept;
};

struct ImportedFile {
    std::vector<ImportedMaterial> materials;
    std::vector<Light> lights;
    std::vector<std::string> meshNames;  // the meshes a glTF holds (read as meshes by geometry/mesh_import.h)
    std::vector<Diagnostic> warnings;  // about the file and its lights, located where the source allows
};

// The file's warnings and those of material `index` (the one used), or of every material.
std::vector<Diagnostic> warningsFor(const ImportedFile& file, size_t index);
std::vector<Diagnostic> allWarnings(const ImportedFile& file);

// The material `selector` names: its index (0 is the first) or its name; empty is the first.
// An unknown name or index is an error listing what the file holds.
Result<size_t> chooseMaterial(const ImportedFile& file, const std::string& selector, const std::string& path);

// Writers return the text and the warnings about what the target format cannot hold.
struct ExportedText {
    std::string text;
    std::vector<Diagnostic> warnings;
};

}  // namespace glint
