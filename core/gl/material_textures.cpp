// Binds a material's textures for the surface program (see material_textures.h).
#include "gl/material_textures.h"

#include <string>

#include "texture/texture_eval.h"

namespace glint {

Status bindMaterialTextures(const ShaderProgram& program, const AnalyticMaterial& material, const Shape& shape, TextureCache& cache) {
    const glm::vec3 center = shapeCenter(shape);
    glUniform3f(program.uniform("objectCenter"), center.x, center.y, center.z);
    // material.textures is in table order with the normal map last: its index is the slot.
    for (size_t slot = 0; slot < material.textures.size(); ++slot) {
        const MaterialTexture& texture = material.textures[slot];
        const auto uniform = [&](const char* name) {
            return program.uniform((std::string(name) + "[" + std::to_string(slot) + "]").c_str());
        };
        const int unit = kFirstMaterialTextureUnit + static_cast<int>(slot);
        if (texture.kind == TextureKind::Image)
            if (Status bound = cache.bind(GL_TEXTURE0 + unit, texture); !bound) {
                glActiveTexture(GL_TEXTURE0);
                return bound;
            }
        glUniform1i(uniform("textureImages"), unit);
        glUniform4i(uniform("textureSettings"), static_cast<int>(texture.kind), static_cast<int>(texture.channel),
                    texture.octaves, 0);
        glUniform4f(uniform("textureValueA"), texture.valueA.r, texture.valueA.g, texture.valueA.b, 0.0f);
        glUniform4f(uniform("textureValueB"), texture.valueB.r, texture.valueB.g, texture.valueB.b, 0.0f);
        glUniform4f(uniform("textureScale"), texture.tiling.x, texture.tiling.y, texture.frequency, texture.turbulence);
        glUniform4f(uniform("textureRange"), texture.range.x, texture.range.y, 0.0f, 0.0f);
        glUniform4f(uniform("textureTransform"), texture.offset.x, texture.offset.y, texture.rotation, texture.normalScale);
        glUniform3f(uniform("textureColorFactor"), texture.colorFactor.r, texture.colorFactor.g, texture.colorFactor.b);
    }
    glActiveTexture(GL_TEXTURE0);
    return success();
}

}  // namespace glint
