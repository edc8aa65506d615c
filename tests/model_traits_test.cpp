// What the models declare they do (brdf/model_traits.h, brdf/model.h's hook list), as the code
// outside core/brdf asks it; and that no code outside core/brdf asks by comparing model ids.
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "brdf/fresnel.h"
#include "brdf/model_traits.h"
#include "interchange/material_values.h"
#include "render/transmission_backdrop.h"
#include "test_support.h"

namespace glint {
namespace {

std::vector<float> valuesOf(const Material& material) { return material.analytic()->values; }

TEST(ModelTraits, TextbookFormsAreLambertAndGgxSmithSchlickOnly) {
    Material lambert = Material::withDefaults("l", BrdfModel::Lambert);
    setParam(lambert, "albedo", glm::vec3(0.2f, 0.4f, 0.6f));
    const auto diffuse = textbookForm(BrdfModel::Lambert, valuesOf(lambert));
    ASSERT_TRUE(diffuse);
    EXPECT_EQ(diffuse->diffuseAlbedo, glm::vec3(0.2f, 0.4f, 0.6f));
    EXPECT_FALSE(diffuse->specular);

    Material ggx = Material::withDefaults("g", BrdfModel::CookTorrance);
    setParam(ggx, "distribution", 1.0f);  // ggx
    setParam(ggx, "geometry", 1.0f);      // smith
    setParam(ggx, "fresnel", 0.0f);       // schlick
    setParam(ggx, "roughness", 0.3f);
    const auto specular = textbookForm(BrdfModel::CookTorrance, valuesOf(ggx));
    ASSERT_TRUE(specular && specular->specular);
    EXPECT_EQ(specular->specular->f0, fresnelF0(paramValue(ggx, "ior"), paramValue(ggx, "extinction")));
    EXPECT_FLOAT_EQ(specular->specular->alpha, 0.3f);

    setParam(ggx, "fresnel", 1.0f);  // exact: not the textbook's Schlick
    EXPECT_FALSE(textbookForm(BrdfModel::CookTorrance, valuesOf(ggx)));
    setParam(ggx, "fresnel", 0.0f);
    setParam(ggx, "distribution", 0.0f);  // Beckmann
    EXPECT_FALSE(textbookForm(BrdfModel::CookTorrance, valuesOf(ggx)));
    EXPECT_FALSE(textbookForm(BrdfModel::OpenPbr, valuesOf(Material::withDefaults("o", BrdfModel::OpenPbr))));
}

TEST(ModelTraits, DeltaLobesConserveOrFollowFresnel) {
    const Material glass = Material::withDefaults("g", BrdfModel::Glass);
    for (float cosIncident : {1.0f, 0.5f, 0.05f}) {
        const auto lobes = deltaLobeWeights(BrdfModel::Glass, valuesOf(glass), cosIncident);
        ASSERT_TRUE(lobes && lobes->refractiveIndex);
        EXPECT_FLOAT_EQ(*lobes->refractiveIndex, paramScalar(glass, "ior"));
        EXPECT_FLOAT_EQ(lobes->reflected.x, fresnelDielectric(cosIncident, paramScalar(glass, "ior")));
        EXPECT_FLOAT_EQ(lobes->reflected.x + lobes->transmitted.x, 1.0f);
    }
    const Material mirror = Material::withDefaults("m", BrdfModel::Mirror);
    const auto reflected = deltaLobeWeights(BrdfModel::Mirror, valuesOf(mirror), 0.7f);
    ASSERT_TRUE(reflected);
    EXPECT_FALSE(reflected->refractiveIndex);
    EXPECT_EQ(reflected->transmitted, glm::vec3(0.0f));
    EXPECT_EQ(reflected->reflected, fresnelComplexIndex(0.7f, paramValue(mirror, "ior"), paramValue(mirror, "extinction")));
    EXPECT_FALSE(deltaLobeWeights(BrdfModel::Lambert, valuesOf(Material::withDefaults("l", BrdfModel::Lambert)), 1.0f));
    // Every model whose light leaves only by delta lobes says what those lobes weigh.
    for (const ModelInfo& info : allModels())
        EXPECT_TRUE(!info.onlyDeltaLobes || deltaLobeWeights(info.model, defaultValues(info.params), 1.0f)) << info.id;
}

TEST(ModelTraits, TransmissionFollowsTheWeightOrItsTexture) {
    EXPECT_TRUE(transmitsLight(Material::withDefaults("g", BrdfModel::Glass)));
    EXPECT_FALSE(transmitsLight(Material::withDefaults("l", BrdfModel::Lambert)));
    Material openPbr = Material::withDefaults("o", BrdfModel::OpenPbr);
    EXPECT_FALSE(transmitsLight(openPbr));
    openPbr.analytic()->textures.push_back({.parameter = "base_weight"});
    EXPECT_FALSE(transmitsLight(openPbr)) << "a texture on another weight lets no light through";
    openPbr.analytic()->textures.push_back({.parameter = "transmission_weight"});
    EXPECT_TRUE(transmitsLight(openPbr)) << "a texture may take the weight above 0";
    openPbr.analytic()->textures.clear();
    setParam(openPbr, "transmission_weight", 0.25f);
    EXPECT_TRUE(transmitsLight(openPbr));
}

// The layer weights that programs compile out at 0 are the *_weight scalars, marked in the tables.
TEST(ModelTraits, LayerWeightsAreMarkedInTheTables) {
    int marked = 0;
    for (const ModelInfo& info : allModels())
        for (const ParamSpec& spec : info.params) {
            const std::string name = spec.name;
            const bool weightName = name.size() > 7 && name.ends_with("_weight");
            EXPECT_EQ(spec.layerWeight, weightName) << info.id << " " << name;
            if (spec.layerWeight) {
                EXPECT_EQ(spec.kind, ParamKind::Scalar) << info.id << " " << name;
            }
            marked += spec.layerWeight;
        }
    EXPECT_EQ(marked, 6);  // OpenPBR's base, specular, transmission, fuzz, coat and thin film
}

// Code outside core/brdf asks what a model does (model_traits.h); it does not compare against a
// particular model or test a model's type (naming a model to build a material is fine).
TEST(ModelTraits, NoCodeOutsideTheModelsComparesModelIds) {
    const std::regex identity(R"(BrdfModel::\w+\s*[!=]=|[!=]=\s*BrdfModel::\w+|case\s+BrdfModel::|is_same_v<M\s*,)");
    int files = 0;
    for (const char* folder : {"core", "app"}) {
        for (const auto& entry : std::filesystem::recursive_directory_iterator(test::dataPath("../") + folder)) {
            const std::string path = entry.path().generic_string();
            if (!entry.is_regular_file() || path.find("/core/brdf/") != std::string::npos) continue;
            if (!path.ends_with(".cpp") && !path.ends_with(".h")) continue;
            ++files;
            std::ifstream in(entry.path());
            std::string line;
            for (int number = 1; std::getline(in, line); ++number)
                EXPECT_FALSE(std::regex_search(line, identity)) << path << ":" << number << ": " << line;
        }
    }
    EXPECT_GT(files, 100);
}

}  // namespace
}  // namespace glint
