// Environment textures and uniform block (see environment_textures.h).
#include "gl/environment_textures.h"

#include <cmath>
#include <vector>

#include "environment/environment_lighting.h"
#include "environment/environment_map.h"
#include "environment/lobe_albedo.h"
#include "math/constants.h"

namespace glint {
namespace {

void setNearestClamp(GLenum target) {
    glTexParameteri(target, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(target, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(target, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

std::vector<float> rgba(const EquirectImage& image) {
    std::vector<float> texels;
    texels.reserve(image.texels.size() * 4);
    for (const glm::vec3& texel : image.texels) texels.insert(texels.end(), {texel.r, texel.g, texel.b, 1.0f});
    return texels;
}

}  // namespace

EnvironmentTextures::EnvironmentTextures() {
    glGenTextures(1, &baseTexture_);
    glGenTextures(1, &prefilteredTexture_);
    glGenTextures(1, &lobeAlbedoTexture_);
    glGenBuffers(1, &uniformBuffer_);
    glBindBuffer(GL_UNIFORM_BUFFER, uniformBuffer_);
    glBufferData(GL_UNIFORM_BUFFER, sizeof(EnvironmentBlockStd140), nullptr, GL_DYNAMIC_DRAW);
    // Placeholders until a map arrives, so that every sampler has a complete texture.
    const float black[4] = {0, 0, 0, 1};
    glBindTexture(GL_TEXTURE_2D, baseTexture_);
    setNearestClamp(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, black);
    glBindTexture(GL_TEXTURE_2D_ARRAY, prefilteredTexture_);
    setNearestClamp(GL_TEXTURE_2D_ARRAY);
    glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, 1, 1, 1, 0, GL_RGBA, GL_FLOAT, black);
    // The lobes' albedo tables depend on no map: uploaded once.
    glBindTexture(GL_TEXTURE_2D, lobeAlbedoTexture_);
    setNearestClamp(GL_TEXTURE_2D);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, kLobeAlbedoSize, kLobeAlbedoTables * kLobeAlbedoSize, 0, GL_RG, GL_FLOAT,
                 lobeAlbedoTables().texels.data());
}

EnvironmentTextures::~EnvironmentTextures() {
    glDeleteTextures(1, &baseTexture_);
    glDeleteTextures(1, &prefilteredTexture_);
    glDeleteTextures(1, &lobeAlbedoTexture_);
    glDeleteBuffers(1, &uniformBuffer_);
}

void EnvironmentTextures::connect(const ShaderProgram& program) {
    program.bindBlock("EnvironmentBlock", kEnvironmentBinding);
    glUseProgram(program.id());
    glUniform1i(program.uniform("environmentBase"), kEnvironmentBaseUnit);
    glUniform1i(program.uniform("environmentPrefiltered"), kEnvironmentPrefilteredUnit);
    glUniform1i(program.uniform("environmentLobeTables"), kEnvironmentLobeAlbedoUnit);
    glUseProgram(0);
}

void EnvironmentTextures::prepare(const Environment& environment) {
    const EnvironmentMap* map = environment.enabled() ? environment.map.get() : nullptr;
    if (map && map != uploadedMap_) {
        glBindTexture(GL_TEXTURE_2D, baseTexture_);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, map->radiance.width, map->radiance.height, 0, GL_RGBA, GL_FLOAT,
                     rgba(map->radiance).data());
        // The prefiltered levels, the irradiance map, the residual's prefiltered levels.
        std::vector<const EquirectImage*> images;
        for (const EquirectImage& level : map->prefiltered) images.push_back(&level);
        images.push_back(&map->irradiance);
        for (const EquirectImage& level : map->residualPrefiltered) images.push_back(&level);
        std::vector<float> layers;
        for (const EquirectImage* image : images) {
            const std::vector<float> texels = rgba(*image);
            layers.insert(layers.end(), texels.begin(), texels.end());
        }
        glBindTexture(GL_TEXTURE_2D_ARRAY, prefilteredTexture_);
        glTexImage3D(GL_TEXTURE_2D_ARRAY, 0, GL_RGBA32F, kPrefilteredWidth, kPrefilteredHeight,
                     static_cast<GLsizei>(images.size()), 0, GL_RGBA, GL_FLOAT, layers.data());
        uploadedMap_ = map;
        keepAlive_ = environment.map;
    }
    EnvironmentBlockStd140 block{};
    const float angle = environment.rotationDegrees * (kPi / 180.0f);
    block.transform = {std::cos(angle), std::sin(angle), environment.intensity, map ? map->peakMinimumAlpha : 0.0f};
    const int peaks = map ? static_cast<int>(map->peaks.size()) : 0;
    block.flags = {map ? 1 : 0, map && environment.showAsBackground ? 1 : 0, peaks, 0};
    if (map) {
        block.sizes = {map->radiance.width, map->radiance.height, kPrefilteredWidth, kPrefilteredHeight};
        block.residualMean = glm::vec4(environmentResidualMeanRadiance(environment), 0.0f);
    }
    for (int k = 0; k < peaks; ++k) {
        block.peakDirections[k] = glm::vec4(environmentPeakDirection(environment, k), map->peaks[k].sinRadius);
        block.peakIrradiances[k] = glm::vec4(environmentPeakIrradiance(environment, k), 0.0f);
    }
    glBindBuffer(GL_UNIFORM_BUFFER, uniformBuffer_);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof block, &block);
    glBindBufferBase(GL_UNIFORM_BUFFER, kEnvironmentBinding, uniformBuffer_);
    glActiveTexture(GL_TEXTURE0 + kEnvironmentBaseUnit);
    glBindTexture(GL_TEXTURE_2D, baseTexture_);
    glActiveTexture(GL_TEXTURE0 + kEnvironmentPrefilteredUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, prefilteredTexture_);
    glActiveTexture(GL_TEXTURE0 + kEnvironmentLobeAlbedoUnit);
    glBindTexture(GL_TEXTURE_2D, lobeAlbedoTexture_);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace glint
