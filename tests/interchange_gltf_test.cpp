// glTF 2.0: KHR_lights_punctual units convert (cd, lx ↔ W, W/m²); the exported file is
// structurally valid (accessor counts, bufferView lengths, min/max, embedded buffer, UVs); the
// models other than openpbr export to their nearest glTF and lights round-trip; malformed files
// give located errors. The materials' mapping: interchange_gltf_openpbr_test.cpp.
#include <cmath>
#include <filesystem>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "brdf/fresnel.h"
#include "interchange/base64.h"
#include "interchange/gltf.h"
#include "interchange/material_values.h"
#include "light/photometry.h"
#include "math/constants.h"
#include "test_support.h"

namespace glint {
namespace {

using nlohmann::json;

ImportedFile parseGltfOk(const std::string& text) {
    auto parsed = parseGltf(text, "test.gltf");
    EXPECT_TRUE(parsed.ok()) << (parsed ? "" : parsed.error().format());
    return parsed ? *parsed : ImportedFile{};
}

std::string withMaterial(const json& material) {
    return json{{"asset", {{"version", "2.0"}}}, {"materials", json::array({material})}}.dump(2);
}

TEST(Gltf, PunctualLightUnitsConvertAt683LumensPerWatt) {
    const glm::vec3 warm(1.0f, 0.8f, 0.6f);
    const float luminanceWeight = kLumensPerWatt * relativeLuminance(warm);
    const ImportedFile file = parseGltfOk(json{
        {"asset", {{"version", "2.0"}}},
        {"extensions",
         {{"KHR_lights_punctual",
           {{"lights",
             {{{"type", "point"}, {"color", {1.0, 0.8, 0.6}}, {"intensity", 100.0}, {"name", "bulb"}},
              {{"type", "directional"}, {"intensity", 1000.0}},
              {{"type", "spot"}, {"intensity", 50.0}, {"spot", {{"innerConeAngle", 0.3}, {"outerConeAngle", 0.5}}}}}}}}}},
        {"nodes",
         {{{"translation", {1.0, 2.0, 3.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}},
          {{"rotation", {-0.7071068, 0.0, 0.0, 0.7071068}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}},
          {{"translation", {0.0, 1.0, 0.0}}, {"children", {3}}},
          {{"translation", {0.0, 1.0, 0.0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}}}}}.dump(2));
    ASSERT_EQ(file.lights.size(), 3u);
    const Light& bulb = file.lights[0];
    EXPECT_EQ(bulb.type, LightType::Point);
    EXPECT_EQ(bulb.name, "bulb");
    EXPECT_EQ(bulb.position, glm::vec3(1, 2, 3));
    EXPECT_NEAR(bulb.power, 4.0f * kPi * 100.0f / luminanceWeight, 1e-3f);
    EXPECT_NEAR(lightPhotometry(bulb).candelas, 100.0f, 1e-3f);  // the editor shows the same candelas back
    const Light& sun = file.lights[1];
    EXPECT_EQ(sun.type, LightType::Directional);
    EXPECT_NEAR(sun.irradiance, 1000.0f / kLumensPerWatt, 1e-4f);
    EXPECT_NEAR(sun.direction.y, -1.0f, 1e-5f);  // −Z rotated −90° about x points down
    const Light& spot = file.lights[2];
    EXPECT_EQ(spot.position, glm::vec3(0, 2, 0));  // parent and child translations compose
    EXPECT_NEAR(spot.coneHalfAngleDegrees, glm::degrees(0.5f), 1e-4f);
    EXPECT_NEAR(spot.edgeWidthDegrees, glm::degrees(0.2f), 1e-4f);
}

// The other models export to their nearest metallic-roughness material, read back as openpbr
// (gltf_openpbr.h has the openpbr round trips); lights keep their units, place and cone.
TEST(Gltf, RoundTripKeepsLightsAndTheModelsNearestGltf) {
    Material dielectric = test::materialWith("varnish", BrdfModel::CookTorrance,
        {{"diffuse_albedo", glm::vec3(0.3f, 0.2f, 0.1f)}, {"ior", 1.6f}, {"extinction", 0.0f}, {"roughness", 0.09f},
         {"fresnel", 0.0f}});
    Material metal = test::materialWith("gold", BrdfModel::CookTorrance,
        {{"diffuse_albedo", 0.0f}, {"ior", 1.0f}, {"extinction", glm::vec3(6.0f, 3.0f, 1.0f)}, {"roughness", 0.3f},
         {"fresnel", 0.0f}});
    Material glass = test::materialWith("bottle", BrdfModel::Glass,
        {{"ior", 1.52f}, {"absorption", glm::vec3(0.5f, 0.1f, 2.0f)}});

    std::vector<Light> lights(3);
    lights[0].name = "key";
    lights[0].type = LightType::Point;
    lights[0].color = {1.0f, 0.9f, 0.8f};
    lights[0].power = 250.0f;
    lights[0].position = {1, 3, 2};
    lights[1].name = "sun";
    lights[1].type = LightType::Directional;
    lights[1].irradiance = 4.5f;
    lights[1].direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    lights[2].name = "spot";
    lights[2].type = LightType::Spot;
    lights[2].power = 80.0f;
    lights[2].position = {0, 2, 0};
    lights[2].direction = {0, -1, 0};
    lights[2].coneHalfAngleDegrees = 40.0f;
    lights[2].edgeWidthDegrees = 10.0f;

    for (const Material& before : {dielectric, metal, glass}) {
        const ExportedText written = writeGltf({before, {}}, lights);
        EXPECT_TRUE(written.warnings.empty()) << before.name << ": " << written.warnings.front().format();
        const ImportedFile read = parseGltfOk(written.text);
        ASSERT_EQ(read.materials.size(), 1u);
        const Material& after = read.materials[0].material;
        EXPECT_EQ(after.name, before.name);
        ASSERT_EQ(after.analytic()->model, BrdfModel::OpenPbr);
        if (before.analytic()->model == BrdfModel::Glass) {
            EXPECT_FLOAT_EQ(paramScalar(after, "specular_ior"), 1.52f);
            EXPECT_EQ(paramScalar(after, "transmission_weight"), 1.0f);
            const glm::vec3 transmitted = glm::pow(paramValue(after, "transmission_color"), glm::vec3(1.0f / paramScalar(after, "transmission_depth")));
            const glm::vec3 expected = glm::exp(-paramValue(before, "absorption"));  // per metre
            EXPECT_LT(glm::length(transmitted - expected), 1e-5f);
        } else if (before.name == "gold") {
            EXPECT_EQ(paramScalar(after, "base_metalness"), 1.0f);
            EXPECT_LT(glm::length(paramValue(after, "base_color") - fresnelF0(paramValue(before, "ior"), paramValue(before, "extinction"))), 1e-6f);
            EXPECT_FLOAT_EQ(paramScalar(after, "specular_roughness"), std::sqrt(0.3f));
        } else {
            EXPECT_EQ(paramScalar(after, "base_metalness"), 0.0f);
            EXPECT_EQ(paramValue(after, "base_color"), paramValue(before, "diffuse_albedo"));
            EXPECT_FLOAT_EQ(paramScalar(after, "specular_ior"), 1.6f);
            EXPECT_FLOAT_EQ(paramScalar(after, "specular_roughness"), 0.3f);  // α = r²
        }
        ASSERT_EQ(read.lights.size(), lights.size());
        for (size_t i = 0; i < lights.size(); ++i) {
            const Light& a = lights[i];
            const Light& b = read.lights[i];
            EXPECT_EQ(b.name, a.name);
            EXPECT_EQ(b.type, a.type);
            EXPECT_LT(glm::length(b.color - a.color), 1e-6f);
            EXPECT_NEAR(b.power, a.power, 1e-4f * a.power);
            EXPECT_NEAR(b.irradiance, a.irradiance, 1e-4f * a.irradiance);
            if (a.type != LightType::Directional) {
                EXPECT_LT(glm::length(b.position - a.position), 1e-5f);
            }
            if (a.type != LightType::Point) {
                EXPECT_LT(glm::length(b.direction - a.direction), 1e-5f) << a.name;
            }
            EXPECT_NEAR(b.coneHalfAngleDegrees, a.coneHalfAngleDegrees, 1e-3f);
            if (a.type == LightType::Spot) {
                EXPECT_NEAR(b.edgeWidthDegrees, a.edgeWidthDegrees, 1e-3f);
            }
        }
    }
}

// What a viewer checks: counts, byte lengths, POSITION min/max, indices in range.
TEST(Gltf, ExportedSphereIsStructurallyValid) {
    const ExportedText written = writeGltf({Material::withDefaults("m", BrdfModel::CookTorrance), {}}, {});
    const json gltf = json::parse(written.text);
    EXPECT_EQ(gltf["asset"]["version"], "2.0");
    const std::string uri = gltf["buffers"][0]["uri"];
    const std::string prefix = "data:application/octet-stream;base64,";
    ASSERT_EQ(uri.rfind(prefix, 0), 0u);
    const auto bytes = decodeBase64(uri.substr(prefix.size()));
    ASSERT_TRUE(bytes.has_value());
    EXPECT_EQ(bytes->size(), gltf["buffers"][0]["byteLength"].get<size_t>());
    EXPECT_EQ(bytes->size() % 4, 0u);
    const size_t componentBytes[] = {4, 2};  // FLOAT, UNSIGNED_SHORT
    for (const json& accessor : gltf["accessors"]) {
        const json& view = gltf["bufferViews"][accessor["bufferView"].get<int>()];
        const size_t components = accessor["type"] == "VEC3" ? 3 : accessor["type"] == "VEC2" ? 2 : 1;
        const size_t size = componentBytes[accessor["componentType"] == 5126 ? 0 : 1];
        EXPECT_EQ(view["byteLength"].get<size_t>(), accessor["count"].get<size_t>() * components * size);
        EXPECT_LE(view["byteOffset"].get<size_t>() + view["byteLength"].get<size_t>(), bytes->size());
        EXPECT_EQ(view["byteOffset"].get<size_t>() % size, 0u);
    }
    const json& position = gltf["accessors"][0];
    const size_t vertexCount = position["count"];
    glm::vec3 low(1e9f), high(-1e9f);
    for (size_t i = 0; i < vertexCount; ++i) {
        glm::vec3 p;
        std::memcpy(&p, bytes->data() + i * 12, 12);
        EXPECT_NEAR(glm::length(p), 1.0f, 1e-5f);
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(position["min"][c].get<float>(), low[c]);
        EXPECT_EQ(position["max"][c].get<float>(), high[c]);
    }
    EXPECT_EQ(gltf["meshes"][0]["primitives"][0]["attributes"]["TEXCOORD_0"], 2);
    const json& indices = gltf["accessors"][3];
    const size_t indexOffset = gltf["bufferViews"][3]["byteOffset"];
    for (size_t i = 0; i < indices["count"].get<size_t>(); ++i) {
        uint16_t index;
        std::memcpy(&index, bytes->data() + indexOffset + 2 * i, 2);
        ASSERT_LT(index, vertexCount);
    }
    EXPECT_EQ(indices["count"].get<size_t>() % 3, 0u);
}

TEST(Gltf, Base64RoundTripsAndRefusesBadText) {
    for (size_t length = 0; length < 7; ++length) {
        std::vector<uint8_t> bytes;
        for (size_t i = 0; i < length; ++i) bytes.push_back(static_cast<uint8_t>(0xF0 + 7 * i));
        EXPECT_EQ(decodeBase64(encodeBase64(bytes)), bytes);
    }
    EXPECT_EQ(encodeBase64({'M', 'a', 'n'}), "TWFu");
    EXPECT_FALSE(decodeBase64("TWF").has_value());
    EXPECT_FALSE(decodeBase64("TW=u").has_value());
    EXPECT_FALSE(decodeBase64("TW!u").has_value());
}

TEST(Gltf, MalformedFilesGiveLocatedErrors) {
    test::expectParseErrors(parseGltf, "test.gltf", {
        {"", "test.gltf"},
        {"{\"asset\": {\"version\": \"2.0\"}", "test.gltf:1"},  // truncated
        {"[1, 2]", "test.gltf:1:1: glTF must be a JSON object"},
        {"{\"materials\": []}", "not a glTF file"},
        {"{\"asset\": {\"version\": \"1.0\"}, \"materials\": [{}]}", "glTF 1.0 is not supported"},
        {"{\"asset\": {\"version\": \"2.0\"}}", "no material and no light"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"extensionsRequired\": [\"KHR_draco_mesh_compression\"], \"materials\": [{}]}",
         "requires the extension \"KHR_draco_mesh_compression\""},
        {withMaterial({{"pbrMetallicRoughness", {{"roughnessFactor", 1.5}}}}), "'roughnessFactor'"},
        {withMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1}}}}}), "expected an array of 4 numbers"},
        {withMaterial({{"pbrMetallicRoughness", {{"baseColorFactor", {1, "x", 1, 1}}}}}), "baseColorFactor[1]"},
        {withMaterial({{"pbrMetallicRoughness", {{"metalicFactor", 1}}}}), "unknown key"},
        {withMaterial({{"extensions", {{"KHR_materials_ior", {{"ior", 0.5}}}}}}), "'ior'"},
        {withMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 3}}}}}}), "textures[3] does not exist"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"pbrMetallicRoughness\": {\"metallicFactor\": 1e999}}]}",
         "test.gltf:1"},
        {"{\"asset\": {\"version\": \"2.0\"}, \"materials\": [{\"name\": \"\xff\"}]}", "test.gltf"},
        {json{{"asset", {{"version", "2.0"}}},
              {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "area"}}}}}}}}}.dump(),
         "'type'"},
        {json{{"asset", {{"version", "2.0"}}},
              {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "spot"}, {"spot", {{"innerConeAngle", 0.6}, {"outerConeAngle", 0.5}}}}}}}}}},
              {"nodes", {{{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}}}.dump(),
         "must be less than outerConeAngle"},
        {json{{"asset", {{"version", "2.0"}}},
              {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}}}}}}}},
              {"nodes", {{{"extensions", {{"KHR_lights_punctual", {{"light", 4}}}}}}}}}.dump(),
         "no such light"},
        {json{{"asset", {{"version", "2.0"}}},
              {"extensions", {{"KHR_lights_punctual", {{"lights", {{{"type", "point"}}}}}}}},
              {"nodes", {{{"children", {1}}}, {{"children", {0}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}}}}}.dump(),
         "cycle"},
    });
}

}  // namespace
}  // namespace glint
