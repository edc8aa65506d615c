// Material textures on the GPU (OSMesa): a textured quad and a mipmapped checker plane at
// grazing angles (trilinear and anisotropic) against goldens, GPU against the CPU reference per
// pixel for a procedural-marble sphere and an image-textured sphere at magnification, a normal
// map tilting a plane's shading by a known angle, clamped and mirrored wrap modes, an occlusion
// map that darkens only the ambient light, a coat normal map tilting the openpbr coat alone, and
// one upload per image. Images are written by the tests themselves; goldens update only with
// GLINT_UPDATE_GOLDENS=1.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "golden_support.h"
#include "gpu_test_support.h"
#include "image/image_io.h"
#include "test_support.h"

namespace glint {
namespace {

std::string textureDirectory() { return test::outputDirectory("texture_gpu"); }

// A scene file in the texture folder (so that texture paths resolve against it).
Scene sceneFrom(const std::string& camera, const std::string& light, const std::string& material,
                const std::string& object) {
    const std::string text = R"({"format": "glint-scene", "version": 1, "background": [0, 0, 0], "camera": )" + camera +
                             R"(, "lights": [)" + light + R"(], "materials": [)" + material + R"(], "objects": [)" + object + "]}";
    auto scene = parseScene(text, textureDirectory() + "/scene.json");
    if (!scene) ADD_FAILURE() << scene.error().format();
    return scene ? *scene : Scene{};
}

const char* kFrontOrtho = R"({"projection": "orthographic", "position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "ortho_height": 2.2})";
const char* kSun = R"({"type": "directional", "direction": [0, 0, -1], "irradiance": 3.14159265})";

// 8×8 sRGB PNG: a colour ramp in x, a second in y, and a white texel in the top-left corner.
std::string writeColourTexture() {
    DisplayImage image(8, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            uint8_t* p = &image.pixels[(y * 8 + x) * 3];
            p[0] = static_cast<uint8_t>(32 * x + 16), p[1] = static_cast<uint8_t>(255 - 32 * y), p[2] = static_cast<uint8_t>((x ^ y) & 1 ? 200 : 40);
        }
    image.pixels[0] = image.pixels[1] = image.pixels[2] = 255;
    const std::string path = textureDirectory() + "/colour.png";
    EXPECT_TRUE(writeDisplayImage(image, path).ok());
    return path;
}

// 64×64 black-and-white checker, 8 texels a square.
void writeCheckerTexture() {
    DisplayImage image(64, 64);
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x)
            for (int c = 0; c < 3; ++c) image.pixels[(y * 64 + x) * 3 + c] = ((x / 8 + y / 8) & 1) ? 230 : 20;
    EXPECT_TRUE(writeDisplayImage(image, textureDirectory() + "/checker.png").ok());
}

using test::expectMatchesGolden;

// Renders `scene` at size × size, writes the picture as NAME.png, and expects every pixel but the
// silhouettes within `relativeTolerance` of the CPU reference, at least `minimumCompared` of them.
RenderedImages expectAgreesWithCpu(const Scene& scene, int size, const std::string& name, float relativeTolerance,
                                   long minimumCompared) {
    Scene aliased = scene;  // as the CPU reference draws it: the sphere's edge on the picture's border is compared too
    aliased.msaaSamples = 1;
    auto images = test::sharedHeadless().render(aliased, size, size);
    if (!images) {
        ADD_FAILURE() << images.error().format();
        return {};
    }
    (void)writeDisplayImage(images->display, textureDirectory() + "/" + name + ".png");
    const auto agreement = test::compareWithReference(scene, images->radiance, relativeTolerance);
    std::printf("%s: %ld compared, %ld excluded, %ld disagreeing, worst relative %.2e\n", name.c_str(), agreement.compared,
                agreement.excluded, agreement.disagreeing, agreement.worstRelative);
    EXPECT_EQ(agreement.disagreeing, 0) << name << ": " << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, minimumCompared) << name;
    return std::move(*images);
}

TEST(TextureGpu, TexturedQuadMatchesGoldenAndCpu) {
    writeColourTexture();
    // The quad fills the 88×88 frame: 11 pixels a texel, so pixel (5, 5) sits on the centre of
    // the top-left texel.
    const Scene scene = sceneFrom(
        R"({"projection": "orthographic", "position": [0, 0, 5], "target": [0, 0, 0], "up": [0, 1, 0], "ortho_height": 2})",
        kSun, R"({"name": "m", "model": "lambert", "textures": {"albedo": {"type": "image", "file": "colour.png"}}})",
        R"({"shape": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [2, 2], "material": "m"})");
    auto images = test::sharedHeadless().render(scene, 88, 88);
    ASSERT_TRUE(images.ok()) << images.error().format();
    expectMatchesGolden("textured_quad", images->display);
    // E⊥ = π and f_r = ρ/π: the radiance is the albedo. The top-left texel is white (1, 1, 1); its
    // right-hand neighbour has red 48/255 sRGB-encoded, linear 0.0296.
    EXPECT_NEAR(images->radiance.at(5, 5).r, 1.0f, 1e-4f);
    EXPECT_NEAR(images->radiance.at(16, 5).r, 0.0295568f, 1e-4f);
    const auto agreement = test::compareWithReference(scene, images->radiance);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 7000);
}

// Standard deviation of the green radiance over rows [firstRow, lastRow): the checker's contrast.
float rowContrast(const RadianceImage& image, int firstRow, int lastRow) {
    double sum = 0, squares = 0;
    int count = 0;
    for (int y = firstRow; y < lastRow; ++y)
        for (int x = 0; x < image.width; ++x) {
            const double value = image.at(x, y).g;
            sum += value, squares += value * value, ++count;
        }
    const double mean = sum / count;
    return static_cast<float>(std::sqrt(std::max(0.0, squares / count - mean * mean)));
}

TEST(TextureGpu, GrazingCheckerTrilinearAndAnisotropic) {
    writeCheckerTexture();
    const char* camera = R"({"position": [0, 0.25, 3], "target": [0, 0, -6], "up": [0, 1, 0], "fov_degrees": 50})";
    const auto scene = [&](const char* filter) {
        return sceneFrom(camera, R"({"type": "directional", "direction": [0, -1, 0], "irradiance": 3.14159265})",
                         std::string(R"({"name": "m", "model": "lambert", "textures": {"albedo": {"type": "image", "file": "checker.png", "color_space": "linear", "tiling": [12, 12], "filter": ")") +
                             filter + R"("}}})",
                         R"({"shape": "plane", "center": [0, 0, -25], "normal": [0, 1, 0], "size": [60, 60], "material": "m"})");
    };
    auto trilinear = test::sharedHeadless().render(scene("trilinear"), 128, 96);
    ASSERT_TRUE(trilinear.ok()) << trilinear.error().format();
    auto anisotropic = test::sharedHeadless().render(scene("anisotropic"), 128, 96);
    ASSERT_TRUE(anisotropic.ok()) << anisotropic.error().format();
    expectMatchesGolden("checker_grazing_trilinear", trilinear->display);
    expectMatchesGolden("checker_grazing_anisotropic", anisotropic->display);
    // Trilinear picks the mip level of the footprint's long axis and blurs the distant squares
    // to uniform grey; anisotropic filtering keeps some of their contrast. Rows 46-50 lie just
    // below the far edge (measured here: trilinear 0.0000, anisotropic 0.015-0.045).
    const float maxAnisotropy = test::sharedHeadless().renderer().textureCache().maxAnisotropy();
    const float trilinearContrast = rowContrast(trilinear->radiance, 46, 50);
    const float anisotropicContrast = rowContrast(anisotropic->radiance, 46, 50);
    std::printf("checker contrast below the far edge: trilinear %.4f, anisotropic %.4f (max anisotropy %.0f)\n",
                trilinearContrast, anisotropicContrast, maxAnisotropy);
    if (maxAnisotropy > 1.0f) EXPECT_GT(anisotropicContrast, 3.0f * trilinearContrast + 0.01f);
    else EXPECT_NEAR(anisotropicContrast, trilinearContrast, 1e-6f);  // the fallback is trilinear
    // Near the camera both are the same magnified checker.
    EXPECT_NEAR(rowContrast(trilinear->radiance, 88, 96), rowContrast(anisotropic->radiance, 88, 96), 0.02f);
}

const char* kCloseSphereCamera = R"({"position": [0, 0.3, 2.6], "target": [0, 0, 0], "up": [0, 1, 0], "fov_degrees": 45})";
const char* kSphere = R"({"shape": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"})";
const char* kTwoLights = R"({"type": "directional", "direction": [-0.3, -0.5, -1], "irradiance": 3},
                           {"type": "point", "position": [2, 2, 3], "power": 300})";

// Tolerance of the GPU-vs-CPU texture comparisons, silhouettes excluded (compareWithReference):
// procedural textures 1e-3 relative + 1e-5 absolute per channel, as for the untextured models;
// image textures 5e-3 relative: llvmpipe filters with weights of 8 bits (1/256 of a texel; the
// CPU's are float), which moves a value between two texels that differ by 100% by up to 0.4%
// (measured: 4.2e-3 worst, with bilinear and trilinear alike).
TEST(TextureGpu, MarbleSphereMatchesCpuReference) {
    const Scene scene = sceneFrom(kCloseSphereCamera, kTwoLights,
                                  R"({"name": "m", "model": "cook_torrance", "roughness": 0.3, "textures": {
        "diffuse_albedo": {"type": "marble", "a": [0.9, 0.88, 0.8], "b": [0.15, 0.12, 0.1], "frequency": 3, "turbulence": 5, "octaves": 5},
        "roughness": {"type": "wood", "a": 0.15, "b": 0.6, "frequency": 2, "turbulence": 2}}})",
                                  kSphere);
    expectAgreesWithCpu(scene, 128, "marble_sphere", 1e-3f, 8000);
}

TEST(TextureGpu, ImageSphereMatchesCpuReferenceAtMagnification) {
    writeColourTexture();
    const Scene scene = sceneFrom(kCloseSphereCamera, kTwoLights,
                                  R"({"name": "m", "model": "cook_torrance", "textures": {
        "diffuse_albedo": {"type": "image", "file": "colour.png", "tiling": [2, 1]},
        "roughness": {"type": "image", "file": "colour.png", "channel": "g", "min": 0.1, "max": 0.6, "filter": "bilinear"}}})",
                                  kSphere);
    expectAgreesWithCpu(scene, 128, "image_sphere", 5e-3f, 8000);
}

// The UV transform (offset, rotation, a mirroring tiling), a colour factor and a scaled normal map
// (glTF's KHR_texture_transform, baseColorFactor, normalTexture.scale) agree with the CPU, on a
// plane (a rotated texture is discontinuous across a sphere's u seam, on both).
TEST(TextureGpu, TransformedFactoredImageMatchesCpuReference) {
    writeColourTexture();
    DisplayImage bumps(8, 8);  // tangent-space normals tilted by up to about 17° in x and y
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            uint8_t* p = &bumps.pixels[(y * 8 + x) * 3];
            p[0] = static_cast<uint8_t>(88 + 11 * x), p[1] = static_cast<uint8_t>(88 + 11 * y), p[2] = 250;
        }
    ASSERT_TRUE(writeDisplayImage(bumps, textureDirectory() + "/bumps.png").ok());
    const Scene scene = sceneFrom(kFrontOrtho, kTwoLights,
                                  R"({"name": "m", "model": "cook_torrance", "textures": {
        "diffuse_albedo": {"type": "image", "file": "colour.png", "tiling": [2, -1.5], "offset": [0.3, -0.2], "rotation": 0.6,
                           "factor": [0.9, 0.5, 0.7], "filter": "bilinear"},
        "normal": {"type": "image", "file": "bumps.png", "scale": 1.5, "rotation": -0.3, "filter": "bilinear"}}})",
                                  R"({"shape": "plane", "center": [0, 0, 0], "normal": [0.2, 0.3, 1], "size": [2, 2], "material": "m"})");
    expectAgreesWithCpu(scene, 128, "transformed_plane", 5e-3f, 8000);
}

// Wrap modes (glTF samplers' wrapS/wrapT): a plane whose UV runs from −1 to 2 clamps along u and
// mirrors along v, and its roughness (with a minification filter of its own) mirrors along u;
// GPU sampler objects against the CPU's OpenGL addressing, per pixel.
TEST(TextureGpu, ClampedAndMirroredImagesMatchCpuReference) {
    writeColourTexture();
    const Scene scene = sceneFrom(kFrontOrtho, kTwoLights,
                                  R"({"name": "m", "model": "cook_torrance", "textures": {
        "diffuse_albedo": {"type": "image", "file": "colour.png", "tiling": [3, 3], "offset": [-1, -1], "filter": "bilinear",
                           "wrap_u": "clamp_to_edge", "wrap_v": "mirrored_repeat"},
        "roughness": {"type": "image", "file": "colour.png", "channel": "r", "min": 0.1, "max": 0.6, "tiling": [3, 3],
                      "offset": [-1, -1], "filter": "bilinear", "min_filter": "nearest_mipmap_linear", "wrap_u": "mirrored_repeat"}}})",
                                  R"({"shape": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [2, 2], "material": "m"})");
    expectAgreesWithCpu(scene, 128, "wrapped_plane", 5e-3f, 8000);
}

// The occlusion map (glTF's occlusionTexture) scales the ambient light and no other: under a sun
// alone the plane is the same with or without it, under ambient light it agrees with the CPU.
TEST(TextureGpu, OcclusionMapDarkensOnlyTheAmbientLight) {
    writeColourTexture();
    const std::string occluded = R"({"name": "m", "model": "lambert", "textures": {
        "occlusion": {"type": "image", "file": "colour.png", "channel": "g", "min": 0.1, "filter": "bilinear"}}})";
    const char* plane = R"({"shape": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [2, 2], "material": "m"})";
    const char* ambient = R"({"type": "ambient", "radiance": 0.5}, {"type": "directional", "direction": [0.3, 0, -1], "irradiance": 2})";
    const Scene lit = sceneFrom(kFrontOrtho, ambient, occluded, plane);
    const RenderedImages images = expectAgreesWithCpu(lit, 64, "occluded_plane", 5e-3f, 3000);
    // The colour texture's green falls from 1 at the top to 0.03 at the bottom: so does the ambient part.
    auto unoccluded = test::sharedHeadless().render(sceneFrom(kFrontOrtho, ambient, R"({"name": "m", "model": "lambert"})", plane), 64, 64);
    ASSERT_TRUE(unoccluded.ok());
    EXPECT_LT(images.radiance.at(32, 56).g, unoccluded->radiance.at(32, 56).g - 0.05f);
    EXPECT_NEAR(images.radiance.at(32, 6).g, unoccluded->radiance.at(32, 6).g, 0.02f);
    auto sunOnly = test::sharedHeadless().render(sceneFrom(kFrontOrtho, kSun, occluded, plane), 64, 64);
    auto plain = test::sharedHeadless().render(sceneFrom(kFrontOrtho, kSun, R"({"name": "m", "model": "lambert"})", plane), 64, 64);
    ASSERT_TRUE(sunOnly.ok() && plain.ok());
    EXPECT_EQ(sunOnly->display.pixels, plain->display.pixels);
}

// A normal map of one tangent-space normal tilted 30° towards +tangent (+x on this plane):
// lit from that direction the plane reflects as if facing the light, from straight on cos 30°.
TEST(TextureGpu, NormalMapTiltsTheShadingNormal) {
    const float tilt = glm::radians(30.0f);
    const glm::vec3 tangentSpace{std::sin(tilt), 0.0f, std::cos(tilt)};
    RadianceImage normalMap(2, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x) normalMap.set(x, y, 0.5f * tangentSpace + 0.5f);
    ASSERT_TRUE(writeRadianceImage(normalMap, textureDirectory() + "/tilted_normal.exr").ok());
    const auto render = [&](glm::vec3 towardsLight, bool mapped) {
        const std::string direction = "[" + std::to_string(-towardsLight.x) + ", " + std::to_string(-towardsLight.y) + ", " +
                                      std::to_string(-towardsLight.z) + "]";
        const std::string textures = mapped ? R"(, "textures": {"normal": {"type": "image", "file": "tilted_normal.exr"}})" : "";
        const Scene scene = sceneFrom(kFrontOrtho, R"({"type": "directional", "irradiance": 3.14159265, "direction": )" + direction + "}",
                                      R"({"name": "m", "model": "lambert", "albedo": 0.5)" + textures + "}",
                                      R"({"shape": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [2, 2], "material": "m"})");
        auto images = test::sharedHeadless().render(scene, 32, 32);
        EXPECT_TRUE(images.ok()) << images.error().format();
        const glm::vec3 cpu = renderReference(scene, 32, 32).at(16, 16);
        const glm::vec3 gpu = images.ok() ? images->radiance.at(16, 16) : glm::vec3(-1.0f);
        EXPECT_NEAR(gpu.g, cpu.g, 1e-4f);
        return gpu.g;
    };
    // L = ρ/π · E⊥ · cos θ with ρ = 0.5, E⊥ = π: 0.5 cos θ.
    EXPECT_NEAR(render(tangentSpace, true), 0.5f, 2e-4f);
    EXPECT_NEAR(render(tangentSpace, false), 0.5f * std::cos(tilt), 2e-4f);
    EXPECT_NEAR(render({0, 0, 1}, true), 0.5f * std::cos(tilt), 2e-4f);
    EXPECT_NEAR(render({-std::sin(tilt), 0, std::cos(tilt)}, true), 0.5f * std::cos(2 * tilt), 2e-4f);
}

// A coat normal map (OpenPBR's geometry_coat_normal, glTF's clearcoatNormalTexture) over a base
// normal map of its own, each one tangent-space normal (exact float images, so that no 8-bit
// filter weights enter): the coat's highlight follows the coat's normal, GPU = CPU per pixel
// (1e-3), and the picture differs from the same material without the coat normal map.
TEST(TextureGpu, CoatNormalMapTiltsTheCoatOnly) {
    const auto writeNormal = [](glm::vec3 tangentSpace, const std::string& name) {
        RadianceImage image(2, 2);
        for (int y = 0; y < 2; ++y)
            for (int x = 0; x < 2; ++x) image.set(x, y, 0.5f * glm::normalize(tangentSpace) + 0.5f);
        EXPECT_TRUE(writeRadianceImage(image, textureDirectory() + "/" + name).ok());
    };
    writeNormal({0.0f, 0.35f, 1.0f}, "base_tilt.exr");
    writeNormal({0.45f, -0.1f, 1.0f}, "coat_tilt.exr");
    const auto material = [](bool coatMapped) {
        return std::string(R"({"name": "m", "model": "openpbr", "base_color": [0.6, 0.2, 0.1], "coat_weight": 1, "coat_roughness": 0.3,
            "specular_roughness": 0.7, "textures": {"normal": {"type": "image", "file": "base_tilt.exr", "color_space": "linear"})") +
               (coatMapped ? R"(, "coat_normal": {"type": "image", "file": "coat_tilt.exr", "color_space": "linear", "scale": 1.2})" : "") +
               "}}";
    };
    const char* plane = R"({"shape": "plane", "center": [0, 0, 0], "normal": [0.1, -0.2, 1], "size": [2, 2], "material": "m"})";
    const char* lights = R"({"type": "point", "position": [1.5, 1, 2], "power": 200}, {"type": "ambient", "radiance": 0.1})";
    const Scene scene = sceneFrom(kFrontOrtho, lights, material(true), plane);
    const RenderedImages images = expectAgreesWithCpu(scene, 64, "coat_normal_plane", 1e-3f, 3000);
    const RadianceImage unmapped = renderReference(sceneFrom(kFrontOrtho, lights, material(false), plane), 64, 64);
    float largest = 0.0f;
    for (int y = 0; y < 64; ++y)
        for (int x = 0; x < 64; ++x) largest = std::max(largest, glm::length(images.radiance.at(x, y) - unmapped.at(x, y)));
    std::printf("coat normal plane: largest change by the coat normal map %.3f\n", largest);
    EXPECT_GT(largest, 0.05f) << "the coat normal map changes nothing";
}

TEST(TextureGpu, AnImageIsUploadedOnce) {
    writeColourTexture();
    const Scene scene = sceneFrom(kFrontOrtho, kSun,
                                  R"({"name": "m", "model": "lambert", "textures": {"albedo": {"type": "image", "file": "colour.png", "tiling": [3, 3]}}})",
                                  R"({"shape": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [2, 2], "material": "m"})");
    ASSERT_TRUE(test::sharedHeadless().render(scene, 16, 16).ok());
    const int uploads = test::sharedHeadless().renderer().textureCache().uploads();
    ASSERT_TRUE(test::sharedHeadless().render(scene, 16, 16).ok());
    ASSERT_TRUE(test::sharedHeadless().render(sceneFrom(kFrontOrtho, kSun,
                    R"({"name": "m", "model": "lambert", "textures": {"albedo": {"type": "image", "file": "colour.png", "filter": "nearest"}}})",
                    R"({"shape": "plane", "center": [0, 0, 0], "normal": [0, 0, 1], "size": [2, 2], "material": "m"})"), 16, 16).ok());
    EXPECT_EQ(test::sharedHeadless().renderer().textureCache().uploads(), uploads);
}

}  // namespace
}  // namespace glint
