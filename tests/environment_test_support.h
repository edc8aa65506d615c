// Scenes and HDR files for the environment tests: a sphere of one material under an environment
// and no lights, and a smooth equirectangular HDR image written through OpenImageIO.
#pragma once

#include <cmath>
#include <string>

#include <OpenImageIO/imageio.h>

#include "environment/environment_source.h"
#include "environment_accuracy_support.h"
#include "image/image.h"
#include "scene/scene.h"

namespace glint::test {

// A unit sphere of `material` seen from +z (orthographic, filling most of the frame).
inline Scene sphereUnderEnvironment(const Material& material, EnvironmentKind kind, const std::string& file = {}) {
    Scene scene = accuracyScene(material, Environment{});
    scene.environment.kind = kind;
    scene.environment.file = file;
    if (Status loaded = loadEnvironment(scene.environment); !loaded) ADD_FAILURE() << loaded.error().format();
    return scene;
}

// Calls check(x, y, μ) for the pixels of sphereUnderEnvironment's 2.2-high orthographic view that
// lie inside the unit sphere's disc, within `radius` of its centre, and have μ = cos θ_o ≥ minCosine.
template <class Check>
void forDiscPixels(const RadianceImage& image, float minCosine, Check check, float radius = 1.0f) {
    const float pixelSize = 2.2f / image.height;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float px = -1.1f + (x + 0.5f) * pixelSize, py = 1.1f - (y + 0.5f) * pixelSize;
            const float r2 = px * px + py * py;
            if (r2 >= radius * radius) continue;
            const float cosine = std::sqrt(1.0f - r2);
            if (cosine >= minCosine) check(x, y, cosine);
        }
}

// Writes a width×(width/2) float image: a smooth sky (bluish above, brown below) with a bright warm
// blob towards (0.5, 0.6, 0.6), so reflections and refractions have structure.
inline void writeTestHdr(const std::string& path, int width, float poisonValue = 0.0f, bool poison = false) {
    const int height = width / 2;
    std::vector<float> texels(static_cast<size_t>(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height});
            const glm::vec3 sun = glm::normalize(glm::vec3(0.5f, 0.6f, 0.6f));
            const float blob = std::exp(8.0f * (glm::dot(d, sun) - 1.0f));
            glm::vec3 radiance = d.y > 0 ? glm::mix(glm::vec3(0.8f, 0.85f, 0.9f), glm::vec3(0.2f, 0.35f, 0.8f), d.y)
                                         : glm::mix(glm::vec3(0.8f, 0.85f, 0.9f), glm::vec3(0.25f, 0.2f, 0.15f), -d.y);
            radiance += glm::vec3(6.0f, 5.0f, 3.5f) * blob + glm::vec3(0.3f * (0.5f + 0.5f * std::sin(3.0f * d.x)));
            float* texel = &texels[(static_cast<size_t>(y) * width + x) * 3];
            texel[0] = radiance.r, texel[1] = radiance.g, texel[2] = radiance.b;
        }
    if (poison) texels[(static_cast<size_t>(height / 2) * width + 3) * 3 + 1] = poisonValue;
    auto output = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(output) << OIIO::geterror();
    ASSERT_TRUE(output->open(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT)));
    ASSERT_TRUE(output->write_image(OIIO::TypeDesc::FLOAT, texels.data()));
    ASSERT_TRUE(output->close());
}

}  // namespace glint::test
