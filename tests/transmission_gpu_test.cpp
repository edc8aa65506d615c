// Screen-space transmission (render/transmission_backdrop.h, gl/transmission_pass.h): a glass ball
// and an openpbr transmission ball in front of an orange wall show the wall, on the GPU and in
// the CPU reference given the GPU's opaque pass, pixel by pixel; bands and MSAA see it too; a
// tilted openpbr slab with a thickness absorbs over it (Beer-Lambert) on both.
#include <gtest/gtest.h>

#include "brdf/param_table.h"
#include "gpu_test_support.h"

namespace glint {
namespace {

constexpr int kWidth = 128, kHeight = 96;
const glm::vec3 kWallAlbedo{0.6f, 0.3f, 0.1f};
const glm::vec3 kTint{0.5f, 1.0f, 0.5f};  // the openpbr ball's transmission_color (a tint: depth 0)

void setParam(Material& material, const char* name, std::initializer_list<float> values) {
    const auto table = modelInfo(material.analytic()->model).params;
    std::copy(values.begin(), values.end(), material.analytic()->values.begin() + packedOffset(table, findParam(table, name)));
}

// Black background, no environment: what the balls show of the wall is all they transmit. The
// light comes from above, so the balls' highlights stay off their centres.
Scene glassBeforeAWall() {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 4.0f};
    scene.background = Background{BackgroundKind::Constant, {0.0f, 0.0f, 0.0f}};
    Light sun;
    sun.direction = glm::normalize(glm::vec3(0.2f, -1.0f, -0.6f));
    sun.irradiance = 3.0f;
    scene.lights = {sun};
    Material wall = Material::withDefaults("wall", BrdfModel::Lambert);
    wall.analytic()->values = {kWallAlbedo.r, kWallAlbedo.g, kWallAlbedo.b};
    Material glass = Material::withDefaults("glass", BrdfModel::Glass);
    Material openpbr = Material::withDefaults("openpbr glass", BrdfModel::OpenPbr);
    setParam(openpbr, "transmission_weight", {1.0f});
    setParam(openpbr, "transmission_color", {kTint.r, kTint.g, kTint.b});
    setParam(openpbr, "specular_roughness", {0.2f});  // blurred: a level between 1 and 2 of the chain
    scene.materials = {wall, glass, openpbr};
    scene.objects.push_back({"wall", PlaneShape{{0.0f, 0.0f, -1.5f}, {0.0f, 0.0f, 1.0f}, {8.0f, 8.0f}}, 0});
    scene.objects.push_back({"glass ball", SphereShape{{-0.65f, 0.0f, 0.0f}, 0.5f}, 1});
    scene.objects.push_back({"openpbr ball", SphereShape{{0.65f, 0.0f, 0.0f}, 0.5f}, 2});
    return scene;
}

// Mean radiance of the 5×5 pixels around the centre of the ball at `center`.
glm::vec3 ballCentre(const Scene& scene, const RadianceImage& image, glm::vec3 center) {
    const glm::vec4 clip = scene.camera.viewProjection(static_cast<float>(image.width) / image.height) * glm::vec4(center, 1.0f);
    const int x = static_cast<int>((0.5f * clip.x / clip.w + 0.5f) * image.width);
    const int y = static_cast<int>((0.5f - 0.5f * clip.y / clip.w) * image.height);
    glm::vec3 sum(0.0f);
    for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) sum += image.at(x + dx, y + dy);
    return sum / 25.0f;
}

// Each ball's centre shows the wall behind it: the glass ball (1 − F)² ≈ 0.92 of it, the openpbr
// ball about that times its tint; without the backdrop both would be black.
void expectTheWallSeenThrough(const Scene& scene, const RadianceImage& image) {
    const glm::vec3 wall = image.at(4, kHeight / 2);
    EXPECT_NEAR(wall.r / wall.g, kWallAlbedo.r / kWallAlbedo.g, 1e-3f);
    const glm::vec3 glass = ballCentre(scene, image, {-0.65f, 0.0f, 0.0f});
    const glm::vec3 openpbr = ballCentre(scene, image, {0.65f, 0.0f, 0.0f});
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(glass[c] / wall[c], 0.92f, 0.03f) << "glass ball, channel " << c;
        EXPECT_NEAR(openpbr[c] / (wall[c] * kTint[c]), 0.92f, 0.05f) << "openpbr ball, channel " << c;
    }
}

TEST(GpuTransmission, BallsShowTheWallBehindThemAsTheCpuReferenceDoes) {
    const Scene scene = glassBeforeAWall();
    const RadianceImage gpu = test::renderGpu(scene, kWidth, kHeight);
    const auto agreement = test::compareWithReference(scene, gpu);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
    EXPECT_GT(agreement.compared, kWidth * kHeight / 2);
    expectTheWallSeenThrough(scene, gpu);
    // The CPU reference without the backdrop sees only the black background through the balls.
    const RadianceImage alone = renderReference(scene, kWidth, kHeight);
    EXPECT_LT(ballCentre(scene, alone, {-0.65f, 0.0f, 0.0f}).r, 1e-3f);
}

TEST(GpuTransmission, BandsAndMsaaSeeTheWallToo) {
    Scene scene = glassBeforeAWall();
    const RadianceImage whole = test::renderGpu(scene, kWidth, kHeight);
    // The editor's refinement, over a frame without the balls: the top band captures the
    // backdrop, the band below reuses it.
    Scene wallOnly = scene;
    wallOnly.objects.resize(1);
    test::renderGpu(wallOnly, kWidth, kHeight);
    Renderer& renderer = test::sharedHeadless().renderer();
    ASSERT_TRUE(renderer.renderRadiance(scene, kWidth, kHeight, MeshDetail::Full, {kHeight / 2, kHeight - kHeight / 2}).ok());
    ASSERT_TRUE(renderer.renderRadiance(scene, kWidth, kHeight, MeshDetail::Full, {0, kHeight / 2}).ok());
    const RadianceImage banded = renderer.readRadiance();
    float worst = 0.0f;
    for (size_t i = 0; i < whole.pixels.size(); ++i) worst = std::max(worst, std::abs(whole.pixels[i] - banded.pixels[i]));
    EXPECT_LT(worst, 1e-6f);
    scene.msaaSamples = 4;
    expectTheWallSeenThrough(scene, test::renderGpu(scene, kWidth, kHeight));
}

// A plane with geometry_thickness d (glTF's thicknessFactor) is a slab: the wall seen through it is
// absorbed over d, transmission_color^(d/depth) (here the square of the tint, where thickness 0
// tints once), and shifted by the refraction over d; GPU = CPU per pixel.
TEST(GpuTransmission, ASlabAbsorbsOverItsThickness) {
    Scene scene = glassBeforeAWall();
    Material& slab = scene.materials[2];
    setParam(slab, "geometry_thickness", {0.4f});
    setParam(slab, "transmission_depth", {0.2f});
    setParam(slab, "specular_roughness", {0.0f});
    scene.objects.resize(1);
    scene.objects.push_back({"slab", PlaneShape{{0.0f, 0.0f, 0.0f}, glm::normalize(glm::vec3(0.4f, 0.2f, 1.0f)), {1.6f, 1.6f}}, 2});
    const RadianceImage gpu = test::renderGpu(scene, kWidth, kHeight);
    const auto agreement = test::compareWithReference(scene, gpu);
    EXPECT_EQ(agreement.disagreeing, 0) << agreement.firstDisagreement << " (worst relative " << agreement.worstRelative << ")";
    EXPECT_GT(agreement.compared, kWidth * kHeight / 2);
    const glm::vec3 wall = gpu.at(4, kHeight / 2);
    const glm::vec3 through = ballCentre(scene, gpu, {0.0f, 0.0f, 0.0f});
    // Green passes (tint 1), red is absorbed to 0.5² of it: the ratio of red to green says which.
    EXPECT_NEAR((through.r / through.g) / (wall.r / wall.g), kTint.r * kTint.r, 0.02f);
}

}  // namespace
}  // namespace glint
