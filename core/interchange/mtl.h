// Wavefront .mtl material libraries: reading them into Glint materials (illum 0-2 → Lambert /
// Blinn-Phong, 3/5/8 → mirror, 4/6/7/9 → glass) and writing Glint materials back. Texture maps
// are kept as references (imported.h); they are not rendered. Geometry (.obj) is not read.
#pragma once

#include <span>
#include <string>

#include "interchange/imported.h"

namespace glint {

// Parses .mtl text; `file` names it in messages (file:line). Malformed lines, numbers, unknown
// statements and values out of Glint's ranges are errors; valid MTL that Glint does not use
// (Ke, Tf, sharpness, PBR extensions, ...) gives a warning. At least one newmtl is required.
Result<ImportedFile> parseMtl(const std::string& text, const std::string& file);
Result<ImportedFile> loadMtl(const std::string& path);

// Writes one newmtl per material. Models MTL cannot hold exactly are written as their nearest
// illum model, with a warning saying what was lost.
ExportedText writeMtl(std::span<const ImportedMaterial> materials);

}  // namespace glint
