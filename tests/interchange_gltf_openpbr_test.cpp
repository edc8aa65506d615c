// glTF 2.0 materials ↔ the openpbr model: the factors and every KHR_materials_* extension map
// onto OpenPBR parameters; textures (with KHR_texture_transform) onto material textures; both
// round trips (glTF → Glint → glTF keeps the material's JSON values, Glint → glTF → Glint its
// parameters and textures), for each extension with textures; what cannot map is one located
// note or warning.
#include <cmath>
#include <functional>
#include <random>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "interchange/gltf.h"
#include "interchange/gltf_openpbr.h"
#include "interchange/gltf_textures.h"
#include "interchange/material_values.h"
#include "texture/texture_edit.h"
#include "texture/texture_eval.h"
#include "texture/texture_image.h"
#include "test_support.h"

namespace glint {
namespace {

using nlohmann::json;

std::string folder() { return test::outputDirectory("gltf_openpbr"); }

// Small PNGs beside the test's .gltf files.
void writeImages() {
    DisplayImage image(4, 4);
    for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = static_cast<uint8_t>(37 * i);
    for (const char* name : {"color.png", "data.png", "normal.png", "emissive.png", "occlusion.png"})
        ASSERT_TRUE(writeDisplayImage(image, folder() + "/" + name).ok());
}

ImportedFile parseOk(const json& gltf, const std::string& name = "test.gltf") {
    auto parsed = parseGltf(gltf.dump(2), folder() + "/" + name);
    EXPECT_TRUE(parsed.ok()) << (parsed ? "" : parsed.error().format());
    return parsed ? *parsed : ImportedFile{};
}

json withMaterials(const std::vector<json>& materials) {
    return {{"asset", {{"version", "2.0"}}},
            {"images", {{{"uri", "color.png"}}, {{"uri", "data.png"}}, {{"uri", "normal.png"}}, {{"uri", "emissive.png"}}, {{"uri", "occlusion.png"}}}},
            {"textures", {{{"source", 0}}, {{"source", 1}}, {{"source", 2}}, {{"source", 3}}, {{"source", 4}}}},
            {"materials", json(materials)}};
}

std::vector<std::string> warningTexts(const ImportedFile& file) {
    std::vector<std::string> texts;
    for (const Diagnostic& warning : allWarnings(file)) texts.push_back(warning.format());
    return texts;
}

bool mentions(const std::vector<std::string>& texts, const std::string& fragment) {
    for (const std::string& text : texts)
        if (text.find(fragment) != std::string::npos) return true;
    return false;
}

// One textureInfo with a transform, on texture `index`.
json info(int index, bool transformed = false) {
    json result = {{"index", index}};
    if (transformed)
        result["extensions"] = {{"KHR_texture_transform", {{"offset", {0.25, -0.5}}, {"rotation", 0.7}, {"scale", {2.0, -3.0}}}}};
    return result;
}

// glTF materials exercising the core and each extension, with textures (color 0, data 1,
// normal 2, emissive 3, occlusion 4).
std::vector<json> sampleMaterials() {
    return {
        {{"name", "core"},
         {"pbrMetallicRoughness",
          {{"baseColorFactor", {0.8, 0.4, 0.2, 1.0}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.6},
           {"baseColorTexture", info(0, true)}, {"metallicRoughnessTexture", info(1)}}},
         {"normalTexture", {{"index", 2}, {"scale", 0.75}}},
         {"occlusionTexture", {{"index", 4}, {"strength", 0.5}}},
         {"emissiveFactor", {1.0, 0.5, 0.25}},
         {"emissiveTexture", info(3)}},
        {{"name", "ior_specular"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.3}}},
         {"extensions",
          {{"KHR_materials_ior", {{"ior", 1.7}}},
           {"KHR_materials_specular",
            {{"specularFactor", 0.5}, {"specularColorFactor", {1.0, 0.5, 0.25}}, {"specularTexture", info(1)},
             {"specularColorTexture", info(0, true)}}}}}},
        {{"name", "clearcoat"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.02, 0.01, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.44}}},
         {"extensions",
          {{"KHR_materials_clearcoat",
            {{"clearcoatFactor", 0.9}, {"clearcoatRoughnessFactor", 0.03}, {"clearcoatTexture", info(1)},
             {"clearcoatRoughnessTexture", info(1, true)}, {"clearcoatNormalTexture", {{"index", 2}, {"scale", 0.5}}}}}}}},
        {{"name", "sheen"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
         {"extensions",
          {{"KHR_materials_sheen",
            {{"sheenColorFactor", {0.9, 0.3, 0.6}}, {"sheenRoughnessFactor", 0.4}, {"sheenColorTexture", info(0)},
             {"sheenRoughnessTexture", info(1)}}}}}},
        {{"name", "transmission_volume"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}, {"roughnessFactor", 0.1}}},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 0.95}, {"transmissionTexture", info(1)}}},
           {"KHR_materials_volume",
            {{"thicknessFactor", 0.3}, {"attenuationDistance", 0.2}, {"attenuationColor", {0.9, 0.5, 0.3}},
             {"thicknessTexture", info(1)}}},
           {"KHR_materials_ior", {{"ior", 1.45}}},
           {"KHR_materials_dispersion", {{"dispersion", 0.5}}}}}},
        {{"name", "thin_transmission"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.6, 0.9, 0.7, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.0}}},
         {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}}}}},
        {{"name", "iridescence"},
         {"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.2}}},
         {"extensions",
          {{"KHR_materials_iridescence",
            {{"iridescenceFactor", 1.0}, {"iridescenceIor", 1.8}, {"iridescenceThicknessMinimum", 200.0},
             {"iridescenceThicknessMaximum", 800.0}, {"iridescenceTexture", info(1)}, {"iridescenceThicknessTexture", info(1, true)}}}}}},
        {{"name", "iridescence_plain"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
         {"extensions",
          {{"KHR_materials_iridescence", {{"iridescenceFactor", 0.5}, {"iridescenceThicknessMinimum", 150.0}, {"iridescenceThicknessMaximum", 450.0}}}}}},
        {{"name", "anisotropy"},
         {"pbrMetallicRoughness", {{"metallicFactor", 1.0}, {"roughnessFactor", 0.5}}},
         {"extensions", {{"KHR_materials_anisotropy", {{"anisotropyStrength", 0.6}, {"anisotropyRotation", 1.2}}}}}},
        {{"name", "emissive_strength"},
         {"pbrMetallicRoughness", {{"metallicFactor", 0.0}}},
         {"emissiveFactor", {1.0, 0.8, 0.5}},
         {"emissiveTexture", info(3, true)},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 40.0}}}}}},
        {{"name", "unlit"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.2, 0.7, 0.3, 1.0}}, {"baseColorTexture", info(0)}}},
         {"extensions", {{"KHR_materials_unlit", json::object()}}}},
    };
}

// Whether two JSON values are equal, numbers within single-precision rounding.
bool sameJson(const json& a, const json& b) {
    if (a.is_number() && b.is_number()) return std::abs(a.get<double>() - b.get<double>()) <= 2e-6 * std::max(1.0, std::abs(a.get<double>()));
    if (a.type() != b.type() || a.size() != b.size()) return false;
    if (a.is_array()) {
        for (size_t i = 0; i < a.size(); ++i)
            if (!sameJson(a[i], b[i])) return false;
        return true;
    }
    if (a.is_object()) {
        for (const auto& [key, value] : a.items())
            if (!b.contains(key) || !sameJson(value, b[key])) return false;
        return true;
    }
    return a == b;
}

// A material's JSON with every {"index": n} textureInfo naming its image file instead, the
// material's "name" dropped, and members equal to the specification's defaults (which a writer
// may spell out or leave out) removed.
json comparable(const json& gltf, json material) {
    static const json kDefaults = {
        {"", {{"emissiveFactor", {0, 0, 0}}}},
        {"pbrMetallicRoughness", {{"baseColorFactor", {1, 1, 1, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 1}}},
        {"KHR_materials_ior", {{"ior", 1.5}}},
        {"KHR_materials_specular", {{"specularFactor", 1}, {"specularColorFactor", {1, 1, 1}}}},
        {"KHR_materials_clearcoat", {{"clearcoatFactor", 0}, {"clearcoatRoughnessFactor", 0}}},
        {"KHR_materials_sheen", {{"sheenColorFactor", {0, 0, 0}}, {"sheenRoughnessFactor", 0}}},
        {"KHR_materials_transmission", {{"transmissionFactor", 0}}},
        {"KHR_materials_volume", {{"thicknessFactor", 0}, {"attenuationColor", {1, 1, 1}}}},
        {"KHR_materials_iridescence",
         {{"iridescenceFactor", 0}, {"iridescenceIor", 1.3}, {"iridescenceThicknessMinimum", 100}, {"iridescenceThicknessMaximum", 400}}},
        {"KHR_materials_anisotropy", {{"anisotropyStrength", 0}, {"anisotropyRotation", 0}}},
        {"KHR_materials_emissive_strength", {{"emissiveStrength", 1}}},
        {"KHR_materials_dispersion", {{"dispersion", 0}}},
        {"normalTexture", {{"scale", 1}}},
        {"occlusionTexture", {{"strength", 1}}}};
    std::function<void(json&, const std::string&)> normalise = [&](json& node, const std::string& key) {
        if (!node.is_object()) return;
        if (node.contains("index") && node["index"].is_number()) {
            const json& texture = gltf["textures"][node["index"].get<int>()];
            const std::string uri = gltf["images"][texture["source"].get<int>()]["uri"];
            node.erase("index");
            node["image"] = uri.substr(uri.rfind('/') + 1);
            if (node.contains("texCoord") && node["texCoord"] == 0) node.erase("texCoord");
        }
        if (kDefaults.contains(key))
            for (const auto& [member, value] : kDefaults[key].items())
                if (node.contains(member) && sameJson(node[member], value)) node.erase(member);
        for (auto& [child, value] : node.items()) normalise(value, child);
    };
    material.erase("name");
    normalise(material, "");
    return material;
}

// Equal structure, numbers within single-precision rounding.
void expectSameJson(const json& expected, const json& actual, const std::string& where) {
    if (expected.is_number() && actual.is_number()) {
        const double a = expected.get<double>(), b = actual.get<double>();
        EXPECT_NEAR(a, b, 2e-6 * std::max(1.0, std::abs(a))) << where;
        return;
    }
    ASSERT_EQ(expected.type(), actual.type()) << where << ": expected " << expected.dump() << ", got " << actual.dump();
    if (expected.is_object()) {
        for (const auto& [key, value] : expected.items()) {
            ASSERT_TRUE(actual.contains(key)) << where << ": missing " << key << " in " << actual.dump();
            expectSameJson(value, actual[key], where + "/" + key);
        }
        for (const auto& [key, value] : actual.items())
            EXPECT_TRUE(expected.contains(key)) << where << ": extra " << key << " = " << value.dump();
    } else if (expected.is_array()) {
        ASSERT_EQ(expected.size(), actual.size()) << where;
        for (size_t i = 0; i < expected.size(); ++i) expectSameJson(expected[i], actual[i], where + "/" + std::to_string(i));
    } else {
        EXPECT_EQ(expected, actual) << where;
    }
}

TEST(GltfOpenPbr, CoreFactorsMapOntoOpenPbrNames) {
    writeImages();
    const ImportedFile file = parseOk(withMaterials({{{"name", "blue plastic"},
                                                      {"pbrMetallicRoughness",
                                                       {{"baseColorFactor", {0.1, 0.2, 0.8, 1.0}}, {"metallicFactor", 0.3}, {"roughnessFactor", 0.5}}},
                                                      {"extensions", {{"KHR_materials_ior", {{"ior", 1.4}}}}}}}));
    ASSERT_EQ(file.materials.size(), 1u);
    const Material& m = file.materials[0].material;
    ASSERT_EQ(m.analytic()->model, BrdfModel::OpenPbr);
    EXPECT_EQ(m.name, "blue plastic");
    EXPECT_EQ(paramValue(m, "base_color"), glm::vec3(0.1f, 0.2f, 0.8f));
    EXPECT_FLOAT_EQ(paramScalar(m, "base_metalness"), 0.3f);
    EXPECT_FLOAT_EQ(paramScalar(m, "specular_roughness"), 0.5f);  // both perceptual
    EXPECT_FLOAT_EQ(paramScalar(m, "specular_ior"), 1.4f);
    EXPECT_FLOAT_EQ(paramScalar(m, "base_weight"), 1.0f);
    EXPECT_FLOAT_EQ(paramScalar(m, "coat_weight"), 0.0f);
    EXPECT_FLOAT_EQ(paramScalar(m, "emission_luminance"), 0.0f);
    EXPECT_TRUE(allWarnings(file).empty());
    // glTF's defaults: metallic 1, roughness 1, white.
    const ImportedFile empty = parseOk(withMaterials({json::object()}));
    EXPECT_FLOAT_EQ(paramScalar(empty.materials[0].material, "base_metalness"), 1.0f);
    EXPECT_FLOAT_EQ(paramScalar(empty.materials[0].material, "specular_roughness"), 1.0f);
    EXPECT_EQ(paramValue(empty.materials[0].material, "base_color"), glm::vec3(1.0f));
}

TEST(GltfOpenPbr, EachExtensionMapsOntoItsParameters) {
    writeImages();
    const ImportedFile file = parseOk(withMaterials(sampleMaterials()));
    const auto material = [&](const std::string& name) -> const Material& {
        for (const ImportedMaterial& m : file.materials)
            if (m.material.name == name) return m.material;
        ADD_FAILURE() << name;
        return file.materials[0].material;
    };
    const Material& specular = material("ior_specular");
    EXPECT_FLOAT_EQ(paramScalar(specular, "specular_ior"), 1.7f);
    EXPECT_FLOAT_EQ(paramScalar(specular, "specular_weight"), 0.5f);
    EXPECT_EQ(paramValue(specular, "specular_color"), glm::vec3(1.0f, 0.5f, 0.25f));
    const Material& coat = material("clearcoat");
    EXPECT_FLOAT_EQ(paramScalar(coat, "coat_weight"), 0.9f);
    EXPECT_FLOAT_EQ(paramScalar(coat, "coat_roughness"), 0.03f);
    EXPECT_FLOAT_EQ(paramScalar(coat, "coat_ior"), 1.5f);       // glTF's coat index
    EXPECT_FLOAT_EQ(paramScalar(coat, "coat_darkening"), 0.0f);  // glTF's coat does not darken
    const Material& sheen = material("sheen");
    EXPECT_FLOAT_EQ(paramScalar(sheen, "fuzz_weight"), 1.0f);
    EXPECT_EQ(paramValue(sheen, "fuzz_color"), glm::vec3(0.9f, 0.3f, 0.6f));
    EXPECT_FLOAT_EQ(paramScalar(sheen, "fuzz_roughness"), 0.4f);
    const Material& volume = material("transmission_volume");
    EXPECT_FLOAT_EQ(paramScalar(volume, "transmission_weight"), 0.95f);
    EXPECT_EQ(paramValue(volume, "transmission_color"), glm::vec3(0.9f, 0.5f, 0.3f));
    EXPECT_FLOAT_EQ(paramScalar(volume, "transmission_depth"), 0.2f);
    EXPECT_EQ(paramScalar(volume, "geometry_thin_walled"), 0.0f);
    EXPECT_FLOAT_EQ(paramScalar(volume, "specular_ior"), 1.45f);
    const Material& thin = material("thin_transmission");
    EXPECT_EQ(paramScalar(thin, "geometry_thin_walled"), 1.0f);  // no volume: a thin wall
    EXPECT_EQ(paramValue(thin, "transmission_color"), glm::vec3(0.6f, 0.9f, 0.7f));  // glTF tints by the base colour
    EXPECT_EQ(paramScalar(thin, "transmission_depth"), 0.0f);
    const Material& film = material("iridescence_plain");
    EXPECT_FLOAT_EQ(paramScalar(film, "thin_film_weight"), 0.5f);
    EXPECT_FLOAT_EQ(paramScalar(film, "thin_film_thickness"), 0.45f);  // nm → µm, the maximum without a texture
    EXPECT_FLOAT_EQ(paramScalar(film, "thin_film_ior"), 1.3f);         // the extension's default
    const Material& anisotropic = material("anisotropy");
    EXPECT_FLOAT_EQ(paramScalar(anisotropic, "specular_roughness_anisotropy"), 0.6f);
    EXPECT_NEAR(paramScalar(anisotropic, "geometry_tangent_rotation"), glm::degrees(1.2f), 1e-4f);
    // Emission: emissiveFactor × strength is a radiance in W/(m²·sr); 683 nits per unit.
    const Material& glow = material("emissive_strength");
    EXPECT_EQ(paramValue(glow, "emission_color"), glm::vec3(1.0f, 0.8f, 0.5f));
    EXPECT_FLOAT_EQ(paramScalar(glow, "emission_luminance"), 683.0f * 40.0f);
    // Unlit: the closest form, no reflection and the base colour emitted.
    const Material& unlit = material("unlit");
    EXPECT_EQ(paramScalar(unlit, "base_weight"), 0.0f);
    EXPECT_EQ(paramScalar(unlit, "specular_weight"), 0.0f);
    EXPECT_EQ(paramValue(unlit, "emission_color"), glm::vec3(0.2f, 0.7f, 0.3f));
    EXPECT_FLOAT_EQ(paramScalar(unlit, "emission_luminance"), 683.0f);
    ASSERT_NE(findTexture(*unlit.analytic(), "emission_color"), nullptr);
    EXPECT_EQ(findTexture(*unlit.analytic(), "base_color"), nullptr);

    // Only what cannot map exactly speaks: one located line each, and no warning for the rest.
    const std::vector<std::string> texts = warningTexts(file);
    for (const std::string& text : texts) EXPECT_EQ(text.find("warning"), std::string::npos) << text;
    EXPECT_TRUE(mentions(texts, "/materials/10/extensions/KHR_materials_unlit: unlit is imported as"));
    EXPECT_TRUE(mentions(texts, "/materials/4/extensions/KHR_materials_dispersion: dispersion 0.5"));
    EXPECT_EQ(texts.size(), 2u) << ::testing::PrintToString(texts);
}

TEST(GltfOpenPbr, TexturesDriveTheirParametersWithFactorsChannelsAndTransforms) {
    writeImages();
    const ImportedFile file = parseOk(withMaterials(sampleMaterials()));
    const Material& core = file.materials[0].material;
    const MaterialTexture* base = findTexture(*core.analytic(), "base_color");
    ASSERT_NE(base, nullptr);
    EXPECT_EQ(base->file, folder() + "/color.png");
    EXPECT_EQ(base->colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(base->colorFactor, glm::vec3(0.8f, 0.4f, 0.2f));
    EXPECT_EQ(base->tiling, glm::vec2(2.0f, -3.0f));
    EXPECT_FLOAT_EQ(base->rotation, 0.7f);
    const MaterialTexture* rough = findTexture(*core.analytic(), "specular_roughness");
    const MaterialTexture* metal = findTexture(*core.analytic(), "base_metalness");
    ASSERT_TRUE(rough && metal);
    EXPECT_EQ(rough->channel, TextureChannel::G);
    EXPECT_EQ(rough->range, glm::vec2(0.0f, 0.6f));
    EXPECT_EQ(metal->channel, TextureChannel::B);
    EXPECT_EQ(metal->range, glm::vec2(0.0f, 0.25f));
    EXPECT_EQ(rough->colorSpace, TextureColorSpace::Linear);
    const MaterialTexture* normal = findTexture(*core.analytic(), kNormalMapKey);
    ASSERT_NE(normal, nullptr);
    EXPECT_FLOAT_EQ(normal->normalScale, 0.75f);
    EXPECT_EQ(core.analytic()->textures.back().parameter, kNormalMapKey);  // last, as the shader expects
    const MaterialTexture* emission = findTexture(*core.analytic(), "emission_color");
    ASSERT_NE(emission, nullptr);
    EXPECT_EQ(emission->colorFactor, glm::vec3(1.0f, 0.5f, 0.25f));
    // The occlusion map: red, 1 + strength·(texel − 1), just before the normal map.
    const MaterialTexture* occlusion = findTexture(*core.analytic(), kOcclusionMapKey);
    ASSERT_NE(occlusion, nullptr);
    EXPECT_EQ(occlusion->file, folder() + "/occlusion.png");
    EXPECT_EQ(occlusion->channel, TextureChannel::R);
    EXPECT_EQ(occlusion->colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(occlusion->range, glm::vec2(0.5f, 1.0f));
    EXPECT_EQ(core.analytic()->textures[core.analytic()->textures.size() - 2].parameter, kOcclusionMapKey);
    EXPECT_TRUE(file.materials[0].textures.empty());  // nothing left only for export
    // The coat normal map with its scale, rendered (nothing left only for export).
    const MaterialTexture* coatNormal = findTexture(*file.materials[2].material.analytic(), kCoatNormalMapKey);
    ASSERT_NE(coatNormal, nullptr);
    EXPECT_EQ(coatNormal->file, folder() + "/normal.png");
    EXPECT_EQ(coatNormal->colorSpace, TextureColorSpace::Linear);
    EXPECT_FLOAT_EQ(coatNormal->normalScale, 0.5f);
    EXPECT_TRUE(file.materials[2].textures.empty());
    // The volume's thickness: thicknessFactor × G [m], rendered (nothing left only for export).
    EXPECT_FLOAT_EQ(paramScalar(file.materials[4].material, "geometry_thickness"), 0.3f);
    const MaterialTexture* volumeThickness = findTexture(*file.materials[4].material.analytic(), "geometry_thickness");
    ASSERT_NE(volumeThickness, nullptr);
    EXPECT_EQ(volumeThickness->channel, TextureChannel::G);
    EXPECT_EQ(volumeThickness->range, glm::vec2(0.0f, 0.3f));
    EXPECT_TRUE(file.materials[4].textures.empty());
    // Iridescence thickness: mix(minimum, maximum, G) in µm.
    const MaterialTexture* thickness = findTexture(*file.materials[6].material.analytic(), "thin_film_thickness");
    ASSERT_NE(thickness, nullptr);
    EXPECT_EQ(thickness->channel, TextureChannel::G);
    EXPECT_FLOAT_EQ(thickness->range.x, 0.2f);
    EXPECT_FLOAT_EQ(thickness->range.y, 0.8f);
    // Sheen roughness reads alpha; clearcoat R, clearcoat roughness G; specular A.
    EXPECT_EQ(findTexture(*file.materials[3].material.analytic(), "fuzz_roughness")->channel, TextureChannel::A);
    EXPECT_EQ(findTexture(*file.materials[2].material.analytic(), "coat_weight")->channel, TextureChannel::R);
    EXPECT_EQ(findTexture(*file.materials[2].material.analytic(), "coat_roughness")->channel, TextureChannel::G);
    EXPECT_EQ(findTexture(*file.materials[1].material.analytic(), "specular_weight")->channel, TextureChannel::A);
}

// KHR_texture_transform in glTF's UV (v down) and MaterialTexture's in Glint's (v up) are the
// same mapping: Glint's transformedUv(u, v) = F(T·R·S·F(u, v)) with F(u, v) = (u, 1 − v).
TEST(GltfOpenPbr, TextureTransformConvertsExactlyBetweenUvConventions) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> any(-2.0f, 2.0f);
    for (int trial = 0; trial < 50; ++trial) {
        GltfUvTransform gltf;
        gltf.offset = {any(random), any(random)};
        gltf.scale = {any(random), any(random)};
        gltf.rotation = any(random);
        MaterialTexture texture;
        applyGltfUvTransform(texture, gltf);
        const glm::vec2 uv{any(random), any(random)};
        const glm::vec2 flipped{uv.x, 1.0f - uv.y};
        const float c = std::cos(gltf.rotation), s = std::sin(gltf.rotation);
        const glm::vec2 scaled = flipped * gltf.scale;
        const glm::vec2 transformed = glm::vec2(c * scaled.x + s * scaled.y, -s * scaled.x + c * scaled.y) + gltf.offset;
        const glm::vec2 expected{transformed.x, 1.0f - transformed.y};
        const glm::vec2 actual = transformedUv(texture, uv);
        EXPECT_NEAR(actual.x, expected.x, 1e-5f);
        EXPECT_NEAR(actual.y, expected.y, 1e-5f);
        const GltfUvTransform back = gltfUvTransformOf(texture);
        EXPECT_NEAR(back.offset.x, gltf.offset.x, 1e-5f);
        EXPECT_NEAR(back.offset.y, gltf.offset.y, 1e-5f);
        EXPECT_EQ(back.scale, gltf.scale);
        EXPECT_EQ(back.rotation, gltf.rotation);
    }
    MaterialTexture identity;
    applyGltfUvTransform(identity, {});
    EXPECT_EQ(identity.offset, glm::vec2(0.0f));  // no transform in glTF: none in Glint
}

// glTF → Glint → glTF: each material's JSON comes back with the same values (textures compared by
// image file, with their transforms, scales and strengths).
TEST(GltfOpenPbr, GltfToGlintToGltfKeepsTheJsonValues) {
    writeImages();
    const json source = withMaterials(sampleMaterials());
    const ImportedFile file = parseOk(source);
    ASSERT_EQ(file.materials.size(), source["materials"].size());
    for (size_t i = 0; i < file.materials.size(); ++i) {
        const ExportedText written = writeGltf(file.materials[i], {}, folder() + "/out/written.gltf");
        const std::string name = file.materials[i].material.name;
        EXPECT_TRUE(written.warnings.empty()) << name << ": " << written.warnings.front().format();
        const json back = json::parse(written.text);
        expectSameJson(comparable(source, source["materials"][i]), comparable(back, back["materials"][0]), name);
        for (const json& image : back.value("images", json::array())) EXPECT_EQ(image["uri"].get<std::string>().rfind("../", 0), 0u) << image;  // relative
        // The written file reads back (its images resolve from its own folder).
        auto again = parseGltf(written.text, folder() + "/out/written.gltf");
        ASSERT_TRUE(again.ok()) << again.error().format();
        EXPECT_EQ(again->materials[0].material.analytic()->values, file.materials[i].material.analytic()->values) << name;
    }
}

// Glint → glTF → Glint: openpbr parameters and textures come back.
TEST(GltfOpenPbr, GlintToGltfToGlintKeepsParametersAndTextures) {
    writeImages();
    auto image = [&](const std::string& parameter, const char* file, TextureColorSpace space) {
        const auto table = modelInfo(BrdfModel::OpenPbr).params;
        MaterialTexture texture =
            defaultTexture(parameter, isNormalMapKey(parameter) ? nullptr : &table[findParam(table, parameter)], TextureKind::Image);
        texture.file = folder() + "/" + file;
        texture.colorSpace = space;
        auto decoded = loadTextureImage(texture.file, space);
        EXPECT_TRUE(decoded.ok());
        if (decoded) texture.image = *decoded;
        return texture;
    };
    // A scalar parameter read from one channel of data.png, mapped onto `range`.
    auto dataImage = [&](const std::string& parameter, TextureChannel channel, glm::vec2 range) {
        MaterialTexture texture = image(parameter, "data.png", TextureColorSpace::Linear);
        texture.channel = channel;
        texture.range = range;
        return texture;
    };
    std::vector<Material> materials;
    Material paint = test::materialWith("car paint", BrdfModel::OpenPbr,
        {{"base_color", glm::vec3(0.6f, 0.05f, 0.04f)}, {"base_metalness", 0.4f}, {"specular_roughness", 0.35f},
         {"specular_ior", 1.6f}, {"coat_weight", 1.0f}, {"coat_roughness", 0.05f}, {"coat_ior", 1.5f},
         {"coat_darkening", 0.0f}});
    MaterialTexture color = image("base_color", "color.png", TextureColorSpace::Srgb);
    color.colorFactor = paramValue(paint, "base_color");
    color.tiling = {3.0f, 2.0f};
    color.rotation = 0.4f;
    color.offset = {0.1f, 0.2f};
    putTexture(*paint.analytic(), color);
    putTexture(*paint.analytic(), dataImage("specular_roughness", TextureChannel::G, {0.0f, 0.35f}));
    putTexture(*paint.analytic(), dataImage("base_metalness", TextureChannel::B, {0.0f, 0.4f}));
    MaterialTexture normal = image(kNormalMapKey, "normal.png", TextureColorSpace::Linear);
    normal.normalScale = 0.6f;
    putTexture(*paint.analytic(), normal);
    MaterialTexture coatNormal = image(kCoatNormalMapKey, "normal.png", TextureColorSpace::Linear);
    coatNormal.normalScale = 0.8f;
    putTexture(*paint.analytic(), coatNormal);
    putTexture(*paint.analytic(), dataImage("coat_roughness", TextureChannel::G, {0.0f, 0.05f}));
    materials.push_back(paint);

    Material velvet = test::materialWith("velvet", BrdfModel::OpenPbr,
        {{"base_color", glm::vec3(0.3f, 0.02f, 0.1f)}, {"base_metalness", 0.0f}, {"fuzz_weight", 1.0f},
         {"fuzz_color", glm::vec3(0.9f, 0.4f, 0.6f)}, {"fuzz_roughness", 0.7f}});
    MaterialTexture fuzz = image("fuzz_color", "color.png", TextureColorSpace::Srgb);
    fuzz.colorFactor = paramValue(velvet, "fuzz_color");
    putTexture(*velvet.analytic(), fuzz);
    materials.push_back(velvet);

    Material bubble = test::materialWith("soap bubble", BrdfModel::OpenPbr,
        {{"base_color", glm::vec3(1.0f)}, {"base_metalness", 0.0f}, {"specular_roughness", 0.0f},
         {"specular_ior", 1.33f}, {"transmission_weight", 1.0f}, {"transmission_color", glm::vec3(1.0f)},
         {"geometry_thin_walled", 1.0f}, {"thin_film_weight", 1.0f}, {"thin_film_thickness", 0.38f},
         {"thin_film_ior", 1.33f}});
    materials.push_back(bubble);

    Material glass = Material::withDefaults("frosted glass", BrdfModel::OpenPbr);
    setParam(glass, "base_color", glm::vec3(1.0f));  // glTF would tint the transmitted light by it as well
    setParam(glass, "base_metalness", 0.0f);
    setParam(glass, "specular_roughness", 0.4f);
    setParam(glass, "transmission_weight", 1.0f);
    setParam(glass, "transmission_color", glm::vec3(0.7f, 0.9f, 0.8f));
    setParam(glass, "transmission_depth", 0.05f);
    setParam(glass, "geometry_thickness", 0.02f);  // glTF's volume needs one (0 is written as the sphere's diameter)
    putTexture(*glass.analytic(), dataImage("transmission_weight", TextureChannel::R, {0.0f, 1.0f}));
    putTexture(*glass.analytic(), dataImage("geometry_thickness", TextureChannel::G, {0.0f, 0.02f}));
    materials.push_back(glass);

    Material brushed = test::materialWith("brushed steel", BrdfModel::OpenPbr,
        {{"base_color", glm::vec3(0.56f, 0.57f, 0.58f)}, {"base_metalness", 1.0f}, {"specular_roughness", 0.4f},
         {"specular_roughness_anisotropy", 0.8f}, {"geometry_tangent_rotation", 30.0f}, {"specular_weight", 0.7f},
         {"specular_color", glm::vec3(0.9f, 0.8f, 1.0f)}});
    materials.push_back(brushed);

    Material lamp = test::materialWith("lamp", BrdfModel::OpenPbr,
        {{"emission_luminance", 1500.0f}, {"emission_color", glm::vec3(1.0f, 0.85f, 0.6f)}});
    MaterialTexture glow = image("emission_color", "emissive.png", TextureColorSpace::Srgb);
    glow.colorFactor = paramValue(lamp, "emission_color");
    glow.filter = TextureFilter::Nearest;
    putTexture(*lamp.analytic(), glow);
    materials.push_back(lamp);

    for (const Material& before : materials) {
        const ExportedText written = writeGltf({before, {}, {}, ""}, {}, folder() + "/roundtrip.gltf");
        EXPECT_TRUE(written.warnings.empty()) << before.name << ": " << written.warnings.front().format();
        auto read = parseGltf(written.text, folder() + "/roundtrip.gltf");
        ASSERT_TRUE(read.ok()) << read.error().format();
        EXPECT_TRUE(allWarnings(*read).empty()) << before.name;
        const Material& after = read->materials.at(0).material;
        ASSERT_EQ(after.analytic()->model, BrdfModel::OpenPbr);
        for (const ParamSpec& spec : modelInfo(BrdfModel::OpenPbr).params) {
            const glm::vec3 a = paramValue(before, spec.name), b = paramValue(after, spec.name);
            EXPECT_LT(glm::length(a - b), 2e-5f * std::max(1.0f, glm::length(a))) << before.name << " " << spec.name;
        }
        ASSERT_EQ(after.analytic()->textures.size(), before.analytic()->textures.size()) << before.name;
        for (size_t i = 0; i < before.analytic()->textures.size(); ++i) {
            const MaterialTexture &x = before.analytic()->textures[i], &y = after.analytic()->textures[i];
            EXPECT_EQ(y.parameter, x.parameter);
            EXPECT_EQ(y.file, x.file);
            EXPECT_EQ(y.colorSpace, x.colorSpace);
            EXPECT_EQ(y.filter, x.filter);
            EXPECT_EQ(y.channel, x.channel) << x.parameter;
            EXPECT_EQ(y.range, x.range) << x.parameter;
            EXPECT_EQ(y.colorFactor, x.colorFactor);
            EXPECT_EQ(y.normalScale, x.normalScale);
            EXPECT_EQ(y.tiling, x.tiling);
            EXPECT_NEAR(y.rotation, x.rotation, 1e-6f);
            EXPECT_LT(glm::length(y.offset - x.offset), 1e-5f) << x.parameter;
        }
    }
}

// What glTF cannot say is a warning naming the parameter, on export.
TEST(GltfOpenPbr, ExportReportsWhatGltfCannotHold) {
    Material coat = Material::withDefaults("lacquer", BrdfModel::OpenPbr);
    setParam(coat, "coat_weight", 1.0f);  // OpenPBR's default coat: ior 1.6, darkening 1
    setParam(coat, "base_diffuse_roughness", 0.5f);
    const ExportedText written = writeGltf({coat, {}, {}, ""}, {});
    std::string all;
    for (const Diagnostic& warning : written.warnings) all += warning.format() + "\n";
    EXPECT_NE(all.find("coat_ior"), std::string::npos) << all;
    EXPECT_NE(all.find("coat_darkening"), std::string::npos) << all;
    EXPECT_NE(all.find("base_diffuse_roughness"), std::string::npos) << all;
}

// Samplers: wrapS/wrapT and magFilter/minFilter reach the material texture and come back
// unchanged in the written glTF; a value glTF does not allow is refused at the textureInfo.
TEST(GltfOpenPbr, SamplersCarryWrapAndFilterBothWays) {
    writeImages();
    json gltf = withMaterials({{{"name", "sampled"},
                                {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 1}}}}},
                                {"emissiveFactor", {1.0, 1.0, 1.0}},
                                {"emissiveTexture", {{"index", 3}}}}});
    const json samplers = {{{"magFilter", 9729}, {"minFilter", 9986}, {"wrapS", 33071}, {"wrapT", 33648}},
                           {{"magFilter", 9728}, {"minFilter", 9987}, {"wrapS", 33648}},
                           {{"magFilter", 9729}, {"minFilter", 9729}, {"wrapT", 33071}}};
    gltf["samplers"] = samplers;
    gltf["textures"][0]["sampler"] = 0;
    gltf["textures"][1]["sampler"] = 1;
    gltf["textures"][3]["sampler"] = 2;
    const ImportedFile file = parseOk(gltf);
    EXPECT_TRUE(allWarnings(file).empty()) << warningTexts(file)[0];
    const auto expectSampling = [&](const char* parameter, TextureFilter filter, TextureMinFilter minFilter, TextureWrap u, TextureWrap v) {
        const MaterialTexture* texture = findTexture(*file.materials[0].material.analytic(), parameter);
        ASSERT_NE(texture, nullptr) << parameter;
        EXPECT_EQ(texture->filter, filter) << parameter;
        EXPECT_EQ(texture->minFilter, minFilter) << parameter;
        EXPECT_EQ(texture->wrapU, u) << parameter;
        EXPECT_EQ(texture->wrapV, v) << parameter;
    };
    expectSampling("base_color", TextureFilter::Trilinear, TextureMinFilter::NearestMipmapLinear, TextureWrap::ClampToEdge,
                   TextureWrap::MirroredRepeat);
    expectSampling("specular_roughness", TextureFilter::Nearest, TextureMinFilter::LinearMipmapLinear, TextureWrap::MirroredRepeat,
                   TextureWrap::Repeat);
    // LINEAR minification is what bilinear implies: no minFilter of its own.
    expectSampling("emission_color", TextureFilter::Bilinear, TextureMinFilter::Default, TextureWrap::Repeat, TextureWrap::ClampToEdge);

    const json written = json::parse(writeGltf(file.materials[0], {}, folder() + "/sampled_out.gltf").text);
    const auto samplerOf = [&](const json& info) { return written["samplers"][written["textures"][info["index"].get<int>()]["sampler"].get<int>()]; };
    const json& material = written["materials"][0];
    expectSameJson(samplers[0], samplerOf(material["pbrMetallicRoughness"]["baseColorTexture"]), "baseColorTexture");
    expectSameJson(samplers[1], samplerOf(material["pbrMetallicRoughness"]["metallicRoughnessTexture"]), "metallicRoughnessTexture");
    expectSameJson(samplers[2], samplerOf(material["emissiveTexture"]), "emissiveTexture");

    json bad = gltf;
    bad["samplers"][0]["wrapS"] = 10496;
    auto refused = parseGltf(bad.dump(2), folder() + "/bad_sampler.gltf");
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().format().find("samplers[0].wrapS 10496 is not a value glTF 2.0 allows"), std::string::npos)
        << refused.error().format();
    EXPECT_NE(refused.error().format().find("bad_sampler.gltf:"), std::string::npos) << refused.error().format();
}

// UV-set limits and unreadable images are located warnings; the material still loads.
TEST(GltfOpenPbr, UnsupportedTextureSettingsAreLocatedWarnings) {
    writeImages();
    json gltf = withMaterials({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}, {"texCoord", 1}}}}},
                                {"extensions", {{"VENDOR_sparkle", json::object()}}}}});
    gltf["images"][1] = {{"uri", "data:image/png;base64,AAAA"}};
    gltf["materials"][0]["normalTexture"] = {{"index", 1}};
    const ImportedFile file = parseOk(gltf);
    const std::vector<std::string> texts = warningTexts(file);
    EXPECT_TRUE(mentions(texts, "/materials/0/pbrMetallicRoughness/baseColorTexture: texCoord 1"));
    EXPECT_TRUE(mentions(texts, "/materials/0/normalTexture: texture not rendered"));
    EXPECT_TRUE(mentions(texts, "/materials/0/extensions/VENDOR_sparkle: extension not supported"));
    EXPECT_NE(findTexture(*file.materials[0].material.analytic(), "base_color"), nullptr);
    EXPECT_EQ(findTexture(*file.materials[0].material.analytic(), kNormalMapKey), nullptr);
}

}  // namespace
}  // namespace glint
