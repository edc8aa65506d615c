// Binds a material's textures for the surface program: each texture's slot (table order, the
// normal map last, as material_glsl.h numbers them) gets a texture unit and its uniforms from
// common/textures.glsl. Uploading and filtering are texture_cache.h.
#pragma once

#include "gl/shader_program.h"
#include "gl/texture_cache.h"
#include "scene/scene.h"

namespace glint {

// First texture unit of the material textures (unit 0 stays with the display pass).
inline constexpr int kFirstMaterialTextureUnit = 1;

// Error: an image the context cannot take (TextureCache::bind).
Status bindMaterialTextures(const ShaderProgram& program, const AnalyticMaterial& material, const Shape& shape, TextureCache& cache);

}  // namespace glint
