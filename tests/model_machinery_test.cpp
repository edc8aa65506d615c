// The generic model machinery (brdf/model.h) on Glint's models and on a test-only model, and the
// models reference docs/models.md against the code.
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "brdf/model_docs.h"
#include "brdf/model_registry.h"
#include "gl/material_glsl.h"
#include "test_support.h"
#include "toy_model.h"

namespace glint {
namespace {

using test::ToyFalloff;
using test::ToySheen;

TEST(ModelMachinery, UnpacksATestModelInTableOrder) {
    const std::vector<float> values = defaultValues(ToySheen::params);
    const ToySheen::Params p = unpack<ToySheen>(values.data());
    EXPECT_EQ(p.tint, glm::vec3(0.25f, 0.5f, 0.75f));
    EXPECT_EQ(p.strength, 1.5f);
    EXPECT_EQ(p.falloff, ToyFalloff::Squared);
    EXPECT_TRUE(p.doubleSided);
}

TEST(ModelMachinery, DispatchesARunTimeIndexToItsType) {
    using List = ModelList<Lambert, ToySheen>;
    EXPECT_STREQ(dispatch(List{}, 0, []<class M>(M) { return M::id; }), "lambert");
    EXPECT_STREQ(dispatch(List{}, 1, []<class M>(M) { return M::id; }), "toy_sheen");
    int visited = 0;
    forEachModel(List{}, [&]<class M>(M) { visited += HasAmbient<M> ? 1 : 0; });
    EXPECT_EQ(visited, 2);
    EXPECT_EQ(dispatch(BrdfModel::Glass, []<class M>(M) { return std::string(M::id); }), "glass");
}

TEST(ModelMachinery, NamesGlslHooksAndOptionsByConvention) {
    const ModelInfo info = describeModel<ToySheen>(BrdfModel{});
    EXPECT_STREQ(info.glslFile, "brdf/toy_sheen.glsl");
    EXPECT_STREQ(info.glslEval, "evalToySheen");
    EXPECT_STREQ(info.glslAmbient, "ambientReflectanceToySheen");
    EXPECT_EQ(info.glslEnvironment, nullptr);
    EXPECT_EQ(info.glslTransport, nullptr);
    const std::string glsl = generateMaterialGlsl(info);
    EXPECT_NE(glsl.find("const int FALLOFF_LINEAR = 0;\nconst int FALLOFF_SQUARED = 1;\n"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("#define GLINT_EVAL_BRDF evalToySheen\n"), std::string::npos) << glsl;
    EXPECT_NE(generateMaterialGlsl(modelInfo(BrdfModel::CookTorrance)).find("const int DISTRIBUTION_GGX = 1;"),
              std::string::npos);
}

// Image textures alone give a program without Perlin noise (llvmpipe compiles it several times
// faster); a procedural texture brings it in, and the flag takes no texture slot.
TEST(ModelMachinery, ProceduralTextureCodeOnlyWhereAMaterialHasOne) {
    Material material = Material::withDefaults("m", BrdfModel::CookTorrance);
    MaterialTexture image;
    image.parameter = "roughness", image.kind = TextureKind::Image;
    MaterialTexture marble;
    marble.parameter = "diffuse_albedo", marble.kind = TextureKind::Marble;
    material.analytic()->textures = {image};
    const TexturedParams imagesOnly = TexturedParams::of(*material.analytic());
    EXPECT_EQ(generateMaterialGlsl(modelInfo(material.analytic()->model), imagesOnly).find("PERLIN_PERMUTATION"), std::string::npos);
    material.analytic()->textures = {marble, image};
    const TexturedParams withMarble = TexturedParams::of(*material.analytic());
    EXPECT_TRUE(withMarble.hasProcedural());
    EXPECT_NE(generateMaterialGlsl(modelInfo(material.analytic()->model), withMarble).find("#define GLINT_PROCEDURAL_TEXTURES"), std::string::npos);
    EXPECT_EQ(withMarble.slotOf(TexturedParams::kNormalMapBit), 2);
}

TEST(ModelMachinery, WritesTheReferenceOfATestModel) {
    const ModelInfo info = describeModel<ToySheen>(BrdfModel{});
    const std::string markdown = modelsMarkdown({&info, 1});
    EXPECT_NE(markdown.find("## Toy sheen (`toy_sheen`)"), std::string::npos) << markdown;
    EXPECT_NE(markdown.find("| `strength` | Strength | number |  | [0, 2] | 1.5 | Scale on ρ |"), std::string::npos)
        << markdown;
    EXPECT_NE(markdown.find("`linear`: cos θ_o; `squared`: cos² θ_o"), std::string::npos) << markdown;
}

// docs/models.md is `glint models --markdown`: regenerate it when a model changes.
TEST(ModelMachinery, DocsModelsMdMatchesTheCode) {
    std::ifstream file(test::dataPath("../docs/models.md"));
    ASSERT_TRUE(file) << "docs/models.md is missing";
    std::stringstream committed;
    committed << file.rdbuf();
    EXPECT_EQ(committed.str(), modelsMarkdown(allModels()))
        << "docs/models.md differs from the code: run `glint models --markdown > docs/models.md`";
}

}  // namespace
}  // namespace glint
