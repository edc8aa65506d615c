// Switching a material between models (brdf/model_switch.h): every pair gives a valid material
// and keeps the diffuse colour, the roughness and the index where both models hold them; what
// a round trip through a model with the same quantities returns is what went in.
#include <gtest/gtest.h>

#include "brdf/fresnel.h"
#include "brdf/microfacet.h"
#include "brdf/model_switch.h"
#include "interchange/material_values.h"
#include "test_support.h"

namespace glint {
namespace {

bool holdsDiffuse(BrdfModel model) { return model != BrdfModel::Glass; }
bool holdsRoughness(BrdfModel model) {
    return model != BrdfModel::Lambert && model != BrdfModel::OrenNayar && model != BrdfModel::Retroreflective &&
           model != BrdfModel::Mirror && model != BrdfModel::Glass;
}
const char* diffuseName(BrdfModel model) {
    switch (model) {
        case BrdfModel::Lambert:
        case BrdfModel::OrenNayar:
        case BrdfModel::Retroreflective: return "albedo";
        case BrdfModel::OpenPbr: return "base_color";
        default: return "diffuse_albedo";
    }
}

// A material of `model` with a distinctive diffuse colour and, where it has one, a rough lobe
// of α = 0.25 on a dielectric.
Material sample(BrdfModel model) {
    Material material = Material::withDefaults("sample", model);
    const glm::vec3 colour(0.6f, 0.3f, 0.1f);
    switch (model) {
        case BrdfModel::Glass: setParam(material, "ior", 1.7f); break;
        case BrdfModel::OpenPbr:
            setParam(material, "base_color", colour);
            setParam(material, "specular_roughness", 0.5f);
            break;
        case BrdfModel::BlinnPhong:
        case BrdfModel::Phong:
            setParam(material, "diffuse_albedo", colour);
            setParam(material, "exponent", blinnPhongExponentFromAlpha(0.25f) / (model == BrdfModel::Phong ? 4.0f : 1.0f));
            break;
        case BrdfModel::CookTorrance:
        case BrdfModel::Ward:
        case BrdfModel::GgxAnisotropic:
        case BrdfModel::Mirror:
            setParam(material, "diffuse_albedo", colour);
            if (model == BrdfModel::CookTorrance) setParam(material, "roughness", 0.25f);
            if (model == BrdfModel::Ward || model == BrdfModel::GgxAnisotropic) setParam(material, "roughness_x", 0.25f), setParam(material, "roughness_y", 0.25f);
            if (model == BrdfModel::GgxAnisotropic || model == BrdfModel::Mirror)
                setParam(material, "ior", glm::vec3(1.5f)), setParam(material, "extinction", glm::vec3(0.0f));
            break;
        default: setParam(material, diffuseName(model), colour);
    }
    return material;
}

float roughnessAlpha(const Material& material) {
    switch (material.analytic()->model) {
        case BrdfModel::BlinnPhong: return alphaFromBlinnPhongExponent(paramScalar(material, "exponent"));
        case BrdfModel::Phong: return alphaFromBlinnPhongExponent(4.0f * paramScalar(material, "exponent"));
        case BrdfModel::CookTorrance: return paramScalar(material, "roughness");
        case BrdfModel::OpenPbr: return paramScalar(material, "specular_roughness") * paramScalar(material, "specular_roughness");
        default: return std::sqrt(paramScalar(material, "roughness_x") * paramScalar(material, "roughness_y"));
    }
}

TEST(ModelSwitch, EveryPairIsValidAndKeepsColourAndRoughness) {
    for (const ModelInfo& from : allModels()) {
        for (const ModelInfo& to : allModels()) {
            SCOPED_TRACE(std::string(from.id) + " → " + to.id);
            const Material source = sample(from.model);
            const ModelSwitch switched = switchModel(source, to.model);
            EXPECT_EQ(switched.material.analytic()->model, to.model);
            EXPECT_EQ(switched.material.name, "sample");
            EXPECT_FALSE(findOutOfRange(switched.material).has_value()) << *findOutOfRange(switched.material);
            if (holdsDiffuse(from.model) && holdsDiffuse(to.model)) {
                EXPECT_EQ(paramValue(switched.material, diffuseName(to.model)), paramValue(source, diffuseName(from.model)))
                    << switched.summary();
            }
            if (holdsRoughness(from.model) && holdsRoughness(to.model)) {
                EXPECT_NEAR(roughnessAlpha(switched.material), 0.25f, 1e-4f) << switched.summary();
            }
            EXPECT_FALSE(switched.kept.empty() && from.model != to.model && holdsDiffuse(from.model) && holdsDiffuse(to.model))
                << switched.summary();
        }
    }
}

TEST(ModelSwitch, SaysWhatWasKeptAndDropped) {
    Material phong = Material::withDefaults("plastic", BrdfModel::BlinnPhong);
    setParam(phong, "diffuse_albedo", glm::vec3(0.2f, 0.4f, 0.6f));
    setParam(phong, "specular", glm::vec3(0.3f));  // Lambert has no place for a specular lobe...
    setParam(phong, "form", 0.0f);                  // ...nor its form; the exponent, at its default, goes unsaid
    const ModelSwitch switched = switchModel(phong, BrdfModel::Lambert);
    EXPECT_EQ(switched.summary(), "kept diffuse_albedo → albedo; dropped specular, form");
}

TEST(ModelSwitch, MetalIndexBecomesMetalnessWithTheSameF0AndBack) {
    Material gold = test::materialWith("gold", BrdfModel::CookTorrance,
        {{"ior", glm::vec3(0.18f, 0.42f, 1.37f)}, {"extinction", glm::vec3(3.42f, 2.35f, 1.77f)},
         {"roughness", 0.09f}});
    const glm::vec3 f0 = fresnelF0(glm::vec3(0.18f, 0.42f, 1.37f), glm::vec3(3.42f, 2.35f, 1.77f));
    const Material openPbr = switchModel(gold, BrdfModel::OpenPbr).material;
    EXPECT_EQ(paramScalar(openPbr, "base_metalness"), 1.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(paramValue(openPbr, "base_color")[c], f0[c], 1e-6f);
    EXPECT_NEAR(paramScalar(openPbr, "specular_roughness"), 0.3f, 1e-6f);  // r = √α
    // Back: a conductor n = 1, κ = 2√(F0/(1 − F0)) with the same reflectance at normal incidence.
    const Material back = switchModel(openPbr, BrdfModel::CookTorrance).material;
    const glm::vec3 backF0 = fresnelF0(paramValue(back, "ior"), paramValue(back, "extinction"));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(backF0[c], f0[c], 1e-5f);
    EXPECT_NEAR(paramScalar(back, "roughness"), 0.09f, 1e-6f);
}

TEST(ModelSwitch, GlassAndOpenPbrTransmissionKeepIndexAndAbsorption) {
    Material glass = test::materialWith("green glass", BrdfModel::Glass,
        {{"ior", 1.52f}, {"absorption", glm::vec3(2.0f, 0.1f, 1.0f)}});
    const Material openPbr = switchModel(glass, BrdfModel::OpenPbr).material;
    EXPECT_EQ(paramScalar(openPbr, "transmission_weight"), 1.0f);
    EXPECT_EQ(paramScalar(openPbr, "specular_ior"), 1.52f);
    const Material back = switchModel(openPbr, BrdfModel::Glass).material;
    EXPECT_EQ(paramScalar(back, "ior"), 1.52f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(paramValue(back, "absorption")[c], glm::vec3(2.0f, 0.1f, 1.0f)[c], 1e-5f);
}

TEST(ModelSwitch, DielectricIndexCarriesIntoOpenPbrAndAnisotropyIntoGgx) {
    Material ggx = test::materialWith("brushed", BrdfModel::GgxAnisotropic,
        {{"ior", glm::vec3(1.45f)}, {"extinction", glm::vec3(0.0f)}, {"roughness_x", 0.4f}, {"roughness_y", 0.1f}});
    const Material openPbr = switchModel(ggx, BrdfModel::OpenPbr).material;
    EXPECT_EQ(paramScalar(openPbr, "base_metalness"), 0.0f);
    EXPECT_NEAR(paramScalar(openPbr, "specular_ior"), 1.45f, 1e-6f);
    EXPECT_NEAR(paramScalar(openPbr, "specular_roughness_anisotropy"), 0.75f, 1e-6f);
    const Material back = switchModel(openPbr, BrdfModel::GgxAnisotropic).material;
    EXPECT_NEAR(paramScalar(back, "roughness_x"), 0.4f, 1e-5f);
    EXPECT_NEAR(paramScalar(back, "roughness_y"), 0.1f, 1e-5f);
}

TEST(ModelSwitch, DiffuseTextureFollowsTheColourAndOthersAreReported) {
    Material lambert = Material::withDefaults("wood", BrdfModel::Lambert);
    MaterialTexture albedo;
    albedo.parameter = "albedo";
    MaterialTexture normal;
    normal.parameter = kNormalMapKey;
    lambert.analytic()->textures = {albedo, normal};
    const ModelSwitch toOpenPbr = switchModel(lambert, BrdfModel::OpenPbr);
    ASSERT_EQ(toOpenPbr.material.analytic()->textures.size(), 2u);
    EXPECT_EQ(toOpenPbr.material.analytic()->textures[0].parameter, "base_color");
    EXPECT_EQ(toOpenPbr.material.analytic()->textures[1].parameter, kNormalMapKey);
    Material coated = toOpenPbr.material;
    MaterialTexture coatNormal;
    coatNormal.parameter = kCoatNormalMapKey;
    coated.analytic()->textures.insert(coated.analytic()->textures.begin() + 1, coatNormal);
    const ModelSwitch back = switchModel(switchModel(coated, BrdfModel::CookTorrance).material, BrdfModel::OpenPbr);
    ASSERT_EQ(back.material.analytic()->textures.size(), 3u);  // the coat normal map survives a model without a coat
    EXPECT_EQ(back.material.analytic()->textures[1].parameter, kCoatNormalMapKey);
    const ModelSwitch toGlass = switchModel(lambert, BrdfModel::Glass);
    ASSERT_EQ(toGlass.material.analytic()->textures.size(), 1u);
    EXPECT_NE(toGlass.summary().find("dropped the texture on albedo"), std::string::npos) << toGlass.summary();
}

TEST(ModelSwitch, ExponentAndAlphaInvertEachOther) {
    for (float alpha : {0.01f, 0.1f, 0.5f, 1.0f}) EXPECT_NEAR(alphaFromBlinnPhongExponent(blinnPhongExponentFromAlpha(alpha)), alpha, 1e-5f);
    EXPECT_NEAR(fresnelF0(glm::vec3(dielectricIorFromF0(0.04f)), glm::vec3(0.0f)).x, 0.04f, 1e-6f);
    EXPECT_NEAR(fresnelF0(glm::vec3(1.0f), glm::vec3(conductorExtinctionFromF0(0.9f))).x, 0.9f, 1e-5f);
}

}  // namespace
}  // namespace glint
