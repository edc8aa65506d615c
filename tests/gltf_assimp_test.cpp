// Another viewer's importer opens what Glint exports: the .gltf from writeGltf is loaded by
// Open Asset Import Library (assimp) with validation on, and its mesh, material factors and
// lights are what Glint wrote. Needs libassimp-dev; nothing of assimp is linked into Glint.
#include <cmath>
#include <fstream>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <gtest/gtest.h>

#include "interchange/gltf.h"
#include "interchange/material_values.h"
#include "test_support.h"

namespace glint {
namespace {

TEST(GltfAssimp, ExportedSphereAndLightsLoadInAssimp) {
    Material material = test::materialWith("varnish", BrdfModel::CookTorrance,
        {{"diffuse_albedo", glm::vec3(0.3f, 0.2f, 0.1f)}, {"extinction", 0.0f}, {"roughness", 0.25f},
         {"fresnel", 0.0f}});
    Light point;
    point.name = "bulb";
    point.type = LightType::Point;
    point.position = {1, 2, 3};
    const std::string path = test::outputDirectory("gltf_assimp") + "/varnish.gltf";
    std::ofstream(path) << writeGltf({material, {}}, std::vector<Light>{point}).text;

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, aiProcess_ValidateDataStructure);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_EQ(scene->mNumMeshes, 1u);
    const aiMesh* mesh = scene->mMeshes[0];
    EXPECT_EQ(mesh->mNumVertices, 49u * 25u);  // (segments + 1) × (rings + 1)
    EXPECT_GT(mesh->mNumFaces, 0u);
    EXPECT_TRUE(mesh->HasNormals());
    for (unsigned i = 0; i < mesh->mNumVertices; ++i) ASSERT_NEAR(mesh->mVertices[i].Length(), 1.0f, 1e-5f);
    const aiMaterial* loaded = scene->mMaterials[mesh->mMaterialIndex];
    aiColor4D baseColor;
    ASSERT_EQ(loaded->Get(AI_MATKEY_BASE_COLOR, baseColor), aiReturn_SUCCESS);
    EXPECT_NEAR(baseColor.r, 0.3f, 1e-6f);
    EXPECT_NEAR(baseColor.b, 0.1f, 1e-6f);
    float roughness = -1;
    ASSERT_EQ(loaded->Get(AI_MATKEY_ROUGHNESS_FACTOR, roughness), aiReturn_SUCCESS);
    EXPECT_NEAR(roughness, 0.5f, 1e-6f);  // √α
    ASSERT_EQ(scene->mNumLights, 1u);
    EXPECT_EQ(scene->mLights[0]->mType, aiLightSource_POINT);
}

}  // namespace
}  // namespace glint
