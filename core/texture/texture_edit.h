// Edits of a material's textures, for the editor and for files alike: a new texture of a kind
// with its defaults, putting one on a parameter (table order kept), taking one off, and
// pointing an image texture at a file (decoded first; on failure the material is unchanged).
#pragma once

#include <string>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// The table entry of a texturable parameter (for the occlusion map a scalar in [0, 1] of its own),
// nullptr for the normal maps; `error` says why neither (unknown name, or a kind that cannot be
// textured).
const ParamSpec* texturableParam(BrdfModel model, const std::string& parameter, std::string& error);

// A texture of `kind` for the parameter with Glint's defaults: colour images sRGB, everything
// else linear; procedural values b = the parameter's default and a = a fifth of it.
MaterialTexture defaultTexture(const std::string& parameter, const ParamSpec* spec, TextureKind kind);

// The texture on `parameter`, or nullptr.
MaterialTexture* findTexture(AnalyticMaterial& material, const std::string& parameter);
const MaterialTexture* findTexture(const AnalyticMaterial& material, const std::string& parameter);
// Puts `texture` on its parameter (replacing one there), keeping table order (then the coat
// normal map, the occlusion map, the normal map last).
void putTexture(AnalyticMaterial& material, MaterialTexture texture);
void removeTexture(AnalyticMaterial& material, const std::string& parameter);

// Checks that the texels a parameter reads lie in [0, 1] (reflectances and blend weights).
Status checkTexelRange(const TextureImage& image, const MaterialTexture& texture, const ParamSpec* spec);

// Points `parameter`'s texture at the image `path` (an image texture with defaults when it had
// none, else keeping its settings). The file is decoded and checked first: on failure the
// material is left exactly as it was and the Diagnostic names the file.
Status setTextureImage(AnalyticMaterial& material, const std::string& parameter, const std::string& path);

}  // namespace glint
