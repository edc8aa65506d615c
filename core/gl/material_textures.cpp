// Binds a material's textures for the surface program (see material_textures.h).
#include "gl/material_textures.h"

#include <string>

#include "gl/material_glsl.h"
#include "texture/texture_eval.h"

namespace glint {

Status bindMaterialTextures(const ShaderProgram& program, const AnalyticMaterial& material, const Shape& shape, TextureCache& cache) {
    const glm::vec3 center = shapeCenter(shape);
    glUniform3f(program.uniform("objectCenter"), center.x, center.y, center.z);
    // Each texture goes to the slot the program reads it from (material_glsl.h), not to its place
    // in material.textures: a material built in another order still shades right.
    const TexturedParams textured = TexturedParams::of(material);
    for (const MaterialTexture& texture : material.textures) {
        const int slot = textured.slotOf(TexturedParams::bitOf(material.model, texture));
        const auto uniform = [&](const char* name) {
            return program.uniform((std::string(name) + "[" + std::to_string(slot) + "]").c_str());
        };
        const int unit = kFirstMaterialTextureUnit + slot;
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
