// Measured materials on the GPU (see measured_brdf_gpu.h).
#include "gl/measured_brdf_gpu.h"

#include <vector>

#include <glad/gl.h>

#include "gl/environment_textures.h"
#include "gl/uniform_blocks.h"

namespace glint {
namespace {

// generated/material.glsl for measured materials: no parameters, the hooks of merl.glsl.
constexpr const char* kMeasuredMaterialGlsl =
    "// Generated for measured (MERL) materials by core/gl/measured_brdf_gpu.cpp: the table is a texture.\n"
    "struct MaterialParams { float unused; };\n"
    "MaterialParams loadMaterialParams() { MaterialParams p; p.unused = 0.0; return p; }\n"
    "#include \"brdf/merl.glsl\"\n"
    "#define GLINT_EVAL_BRDF evalMerl\n"
    "#define GLINT_AMBIENT_REFLECTANCE ambientReflectanceMerl\n"
    "#ifdef GLINT_HAS_ENVIRONMENT\n#define GLINT_ENVIRONMENT_LIGHTING environmentLightingMerl\n#endif\n";

// The table interleaved as RGB texels, φ_d fastest (the file's order within a channel).
std::vector<float> interleavedTexels(const MerlTable& table) {
    std::vector<float> texels(3 * kMerlSamplesPerChannel);
    for (size_t i = 0; i < kMerlSamplesPerChannel; ++i)
        for (size_t channel = 0; channel < 3; ++channel)
            texels[3 * i + channel] = table.reflectance[channel * kMerlSamplesPerChannel + i];
    return texels;
}

}  // namespace

MeasuredBrdfGpu::~MeasuredBrdfGpu() {
    for (auto& [key, upload] : textures_) glDeleteTextures(1, &upload.texture);
}

Result<const ShaderProgram*> MeasuredBrdfGpu::program(const ShaderSources& sources, SurfaceVariant variant,
                                                      std::uint64_t frame) {
    if (ShaderProgram* found = programs_.use(variant, frame)) return found;
    auto built = ShaderProgram::build(sources, "surface.vert", "surface.frag", variant.prelude(),
                                      {{"generated/material.glsl", kMeasuredMaterialGlsl}});
    if (!built) return built.error();
    built->bindBlock("FrameBlock", kFrameBinding);
    built->bindBlock("LightBlock", kLightBinding);
    built->bindBlock("MaterialBlock", kMaterialBinding);
    EnvironmentTextures::connect(*built);
    return &programs_.insert(variant, std::move(*built), frame);
}

void MeasuredBrdfGpu::bind(const ShaderProgram& program, const std::shared_ptr<const MeasuredBrdf>& brdf) {
    for (auto it = textures_.begin(); it != textures_.end();) {  // tables no material holds any more
        if (it->second.owner.expired()) {
            glDeleteTextures(1, &it->second.texture);
            it = textures_.erase(it);
        } else {
            ++it;
        }
    }
    glActiveTexture(GL_TEXTURE0 + kMeasuredTableUnit);
    Upload& upload = textures_[brdf.get()];
    if (upload.texture == 0) {
        upload.owner = brdf;
        glGenTextures(1, &upload.texture);
        glBindTexture(GL_TEXTURE_3D, upload.texture);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);  // read by texelFetch only
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_3D, GL_TEXTURE_MAX_LEVEL, 0);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
        const std::vector<float> texels = interleavedTexels(brdf->table);
        glTexImage3D(GL_TEXTURE_3D, 0, GL_RGB32F, kMerlPhiDifferenceBins, kMerlThetaDifferenceBins, kMerlThetaHalfBins, 0,
                     GL_RGB, GL_FLOAT, texels.data());
        ++uploads_;
    }
    glBindTexture(GL_TEXTURE_3D, upload.texture);
    glActiveTexture(GL_TEXTURE0);
    glUniform1i(program.uniform("merlTable"), kMeasuredTableUnit);
    glUniform3fv(program.uniform("merlAlbedo"), kMeasuredAlbedoSamples, &brdf->directionalAlbedo[0].x);
}

}  // namespace glint
