// Every combination of image textures on one openpbr material, GPU against the CPU reference per
// pixel: each subset of the slots base colour, normal map, roughness, metalness, occlusion and
// emission, put on the material in reverse table order (as an importer may build it), and the two
// MaterialX files that once showed their normal map as the base colour and rendered dark on the GPU.
// Images are tests/files/materialx/boombox/*.png (16×16, written for Glint).
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "gpu_test_support.h"
#include "image/image_io.h"
#include "interchange/material_values.h"
#include "interchange/materialx.h"
#include "test_support.h"
#include "texture/texture_image.h"

namespace glint {
namespace {

const std::string kImages = std::string(GLINT_TEST_DATA_DIR) + "/files/materialx/boombox/";

struct Slot {
    const char* parameter;
    const char* image;
    TextureColorSpace colorSpace;
    TextureChannel channel;
};

// In table order (normal map last); the roughness, metalness and occlusion share one image, as
// glTF's and the boombox's do.
constexpr Slot kSlots[] = {
    {"base_color", "BoomBox_baseColor.png", TextureColorSpace::Srgb, TextureChannel::R},
    {"base_metalness", "BoomBox_occlusionRoughnessMetallic.png", TextureColorSpace::Linear, TextureChannel::B},
    {"specular_roughness", "BoomBox_occlusionRoughnessMetallic.png", TextureColorSpace::Linear, TextureChannel::G},
    {"emission_color", "BoomBox_emissive.png", TextureColorSpace::Srgb, TextureChannel::R},
    {kOcclusionMapKey, "BoomBox_occlusionRoughnessMetallic.png", TextureColorSpace::Linear, TextureChannel::R},
    {kNormalMapKey, "BoomBox_normal.png", TextureColorSpace::Linear, TextureChannel::R},
};
constexpr int kSlotCount = static_cast<int>(std::size(kSlots));

MaterialTexture imageTexture(const Slot& slot) {
    MaterialTexture texture;
    texture.parameter = slot.parameter;
    texture.kind = TextureKind::Image;
    texture.file = kImages + slot.image;
    texture.colorSpace = slot.colorSpace;
    texture.channel = slot.channel;
    texture.filter = TextureFilter::Bilinear;
    auto image = loadTextureImage(texture.file, texture.colorSpace);
    EXPECT_TRUE(image.ok()) << image.error().format();
    if (image) texture.image = *image;
    return texture;
}

// The preview stage under its key light and an ambient light (which the occlusion map scales).
Scene stageFor(const Material& material, int size) {
    Scene scene = test::keyLitPreviewStage(material, size, size);
    Light ambient;
    ambient.type = LightType::Ambient;
    ambient.ambientRadiance = 0.3f;
    scene.lights.push_back(ambient);
    return scene;
}

// Every pixel but the silhouettes within 1 % of the CPU reference: the GGX highlight over an 8-bit
// normal map amplifies the twins' rounding to about 0.5 %, while an image in another slot's place
// is off by far more.
void expectGpuMatchesCpu(const Material& material, const std::string& name) {
    constexpr int kSize = 64;
    const Scene scene = stageFor(material, kSize);
    auto images = test::sharedHeadless().render(scene, kSize, kSize);
    ASSERT_TRUE(images.ok()) << images.error().format();
    (void)writeDisplayImage(images->display, test::outputDirectory("texture_slots_gpu") + "/" + name + ".png");
    const auto agreement = test::compareWithReference(scene, images->radiance, 1e-2f, 1e-4f);
    std::printf("%s: %ld compared, %ld disagreeing, worst relative %.2e\n", name.c_str(), agreement.compared,
                agreement.disagreeing, agreement.worstRelative);
    EXPECT_EQ(agreement.disagreeing, 0) << name << ": " << agreement.firstDisagreement;
    EXPECT_GT(agreement.compared, 1000) << name;
}

// The subset's name, e.g. "base_color+normal"; "none" for the empty one.
std::string subsetName(int subset) {
    std::string name;
    for (int i = 0; i < kSlotCount; ++i)
        if (subset >> i & 1) name += (name.empty() ? "" : "+") + std::string(kSlots[i].parameter);
    return name.empty() ? "none" : name;
}

class TextureSlotSubsets : public testing::TestWithParam<int> {};

// The textures go into material.textures against table order, so a renderer that bound them by
// their place there instead of the slot its program reads would show one slot's image in another.
TEST_P(TextureSlotSubsets, GpuMatchesCpu) {
    const int subset = GetParam();
    Material material = Material::withDefaults("slots", BrdfModel::OpenPbr);
    setParam(material, "emission_luminance", 200.0f);
    for (int i = kSlotCount - 1; i >= 0; --i)
        if (subset >> i & 1) material.analytic()->textures.push_back(imageTexture(kSlots[i]));
    expectGpuMatchesCpu(material, subsetName(subset));
}

INSTANTIATE_TEST_SUITE_P(EverySubset, TextureSlotSubsets, testing::Range(1, 1 << kSlotCount),
                         [](const testing::TestParamInfo<int>& info) { return "subset" + std::to_string(info.param); });

// The MaterialX files of issue 36: four images (base colour, occlusion-roughness-metalness,
// normal, emission) and three (no emission).
TEST(TextureSlotsMaterialX, BoomboxMatchesCpu) {
    for (const char* file : {"gltf_pbr_boombox.mtlx", "gltf_pbr_boombox_three_images.mtlx"}) {
        auto imported = loadMaterialX(std::string(GLINT_TEST_DATA_DIR) + "/files/materialx/" + file);
        ASSERT_TRUE(imported.ok()) << imported.error().format();
        ASSERT_EQ(imported->materials.size(), 1u);
        const Material& material = imported->materials[0].material;
        EXPECT_GE(material.analytic()->textures.size(), 4u) << file;  // three images: four parameters at least
        expectGpuMatchesCpu(material, file);
    }
}

}  // namespace
}  // namespace glint
