// MaterialX (.mtlx): open_pbr_surface read as it is, standard_surface and gltf_pbr through the
// published mappings, colour spaces, node graphs and images, a Glint → MaterialX → Glint round
// trip that keeps every value, and located errors for malformed documents.
#include <fstream>

#include <gtest/gtest.h>

#include "image/image_io.h"
#include "interchange/material_values.h"
#include "interchange/materialx.h"
#include "test_support.h"

namespace glint {
namespace {

ImportedFile parseMaterialXOk(const std::string& text, const std::string& file = "test.mtlx") {
    auto parsed = parseMaterialX(text, file);
    EXPECT_TRUE(parsed.ok()) << (parsed ? "" : parsed.error().format());
    return parsed ? *parsed : ImportedFile{};
}

std::string errorOf(const std::string& text) {
    auto parsed = parseMaterialX(text, "bad.mtlx");
    EXPECT_FALSE(parsed.ok());
    return parsed ? std::string() : parsed.error().format();
}

std::string document(const std::string& body) { return "<?xml version=\"1.0\"?>\n<materialx version=\"1.39\">\n" + body + "</materialx>\n"; }

// A document's lines for a shader node <category name="name" type="surfaceshader"> of constant
// inputs {name, value}: color3 where the value lists three numbers, float otherwise.
std::string shaderNode(const std::string& category, const std::string& name,
                       std::initializer_list<std::pair<std::string, std::string>> inputs) {
    std::string text = "  <" + category + " name=\"" + name + "\" type=\"surfaceshader\">\n";
    for (const auto& [input, value] : inputs) {
        const char* type = value.find(',') == std::string::npos ? "float" : "color3";
        text += "    <input name=\"" + input + "\" type=\"" + type + "\" value=\"" + value + "\" />\n";
    }
    return text + "  </" + category + ">\n";
}

std::string warningsText(const ImportedFile& file) {
    std::string text;
    for (const Diagnostic& warning : allWarnings(file)) text += warning.format() + "\n";
    return text;
}

void expectNear(glm::vec3 actual, glm::vec3 expected, float tolerance = 1e-6f) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

TEST(MaterialX, OpenPbrCarPaintFromTheMaterialXExamples) {
    auto file = loadMaterialX(test::dataPath("files/materialx/open_pbr_carpaint.mtlx"));
    ASSERT_TRUE(file.ok()) << file.error().format();
    ASSERT_EQ(file->materials.size(), 1u);
    const Material& m = file->materials[0].material;
    EXPECT_EQ(m.name, "Car_Paint");
    EXPECT_EQ(m.analytic()->model, BrdfModel::OpenPbr);
    expectNear(paramValue(m, "base_color"), {0.1f, 0.6f, 0.9f});
    EXPECT_EQ(paramScalar(m, "specular_ior"), 1.6f);
    EXPECT_EQ(paramScalar(m, "specular_roughness"), 0.3f);
    EXPECT_EQ(paramScalar(m, "coat_weight"), 1.0f);
    EXPECT_EQ(paramScalar(m, "coat_roughness"), 0.02f);
    EXPECT_EQ(paramScalar(m, "base_weight"), 1.0f);  // unset: OpenPBR's default
    EXPECT_EQ(warningsText(*file), "");
}

TEST(MaterialX, StandardSurfaceGoldThroughTheTranslationGraph) {
    const ImportedFile file = parseMaterialXOk(document(
        shaderNode("standard_surface", "SR_gold",
                   {{"base", "1"}, {"base_color", "0.944, 0.776, 0.373"}, {"specular", "0.5"}, {"specular_roughness", "0.02"},
                    {"metalness", "1"}, {"sheen_roughness", "0.5"}, {"thin_film_thickness", "250"}, {"emission", "0.5"}}) +
        R"(  <surfacematerial name="Gold" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR_gold" />
  </surfacematerial>
)"));
    ASSERT_EQ(file.materials.size(), 1u);
    const Material& m = file.materials[0].material;
    EXPECT_EQ(m.name, "Gold");
    expectNear(paramValue(m, "base_color"), {0.944f, 0.776f, 0.373f});
    EXPECT_EQ(paramScalar(m, "base_metalness"), 1.0f);
    EXPECT_EQ(paramScalar(m, "specular_weight"), 1.0f);  // specular does not act on Standard Surface's metal
    EXPECT_EQ(paramScalar(m, "specular_roughness"), 0.02f);
    EXPECT_NEAR(paramScalar(m, "fuzz_roughness"), std::pow(0.5f, 0.4f), 1e-6f);
    EXPECT_EQ(paramScalar(m, "thin_film_weight"), 1.0f);
    EXPECT_NEAR(paramScalar(m, "thin_film_thickness"), 0.25f, 1e-6f);  // nm → µm
    EXPECT_EQ(paramScalar(m, "coat_ior"), 1.5f);  // Standard Surface's default, not OpenPBR's 1.6
    EXPECT_EQ(paramScalar(m, "coat_roughness"), 0.1f);
    EXPECT_EQ(paramScalar(m, "emission_luminance"), 0.5f * 683.0f);
}

TEST(MaterialX, StandardSurfaceCoatOnMetalTintsTheBase) {
    const ImportedFile file = parseMaterialXOk(document(shaderNode(
        "standard_surface", "copper", {{"metalness", "1"}, {"base_color", "0.5, 0.5, 0.5"}, {"coat", "1"}, {"coat_color", "1, 0.5, 0.25"}})));
    ASSERT_EQ(file.materials.size(), 1u);
    expectNear(paramValue(file.materials[0].material, "base_color"), {0.5f, 0.25f, 0.125f});
    EXPECT_EQ(paramScalar(file.materials[0].material, "coat_weight"), 0.0f);
}

TEST(MaterialX, GltfPbrMapsOneToOneWithUnitsConverted) {
    const ImportedFile file = parseMaterialXOk(document(shaderNode(
        "gltf_pbr", "SR_glass",
        {{"base_color", "1, 1, 1"}, {"metallic", "0"}, {"roughness", "0.1"}, {"transmission", "1"}, {"ior", "1.45"},
         {"thickness", "0.02"}, {"attenuation_color", "0.5, 0.9, 0.5"}, {"attenuation_distance", "0.05"}, {"iridescence", "1"},
         {"iridescence_thickness", "400"}, {"sheen_color", "0.2, 0.2, 0.3"}, {"anisotropy_rotation", "1.5707964"},
         {"emissive", "1, 0.5, 0"}, {"emissive_strength", "2"}})));
    ASSERT_EQ(file.materials.size(), 1u);
    const Material& m = file.materials[0].material;
    EXPECT_EQ(paramScalar(m, "specular_roughness"), 0.1f);
    EXPECT_EQ(paramScalar(m, "base_metalness"), 0.0f);
    EXPECT_EQ(paramScalar(m, "transmission_weight"), 1.0f);
    EXPECT_EQ(paramScalar(m, "specular_ior"), 1.45f);
    expectNear(paramValue(m, "transmission_color"), {0.5f, 0.9f, 0.5f});
    EXPECT_EQ(paramScalar(m, "transmission_depth"), 0.05f);
    EXPECT_EQ(paramScalar(m, "geometry_thin_walled"), 0.0f);
    EXPECT_NEAR(paramScalar(m, "thin_film_thickness"), 0.4f, 1e-6f);
    EXPECT_EQ(paramScalar(m, "thin_film_ior"), 1.3f);  // gltf_pbr's default
    EXPECT_EQ(paramScalar(m, "fuzz_weight"), 1.0f);
    expectNear(paramValue(m, "fuzz_color"), {0.2f, 0.2f, 0.3f});
    EXPECT_EQ(paramScalar(m, "fuzz_roughness"), 0.0f);
    EXPECT_NEAR(paramScalar(m, "geometry_tangent_rotation"), 90.0f, 1e-4f);
    expectNear(paramValue(m, "emission_color"), {1.0f, 0.5f, 0.0f});
    EXPECT_EQ(paramScalar(m, "emission_luminance"), 2.0f * 683.0f);  // 1 W/(sr·m²) = 683 nit, as Glint's glTF reader
}

TEST(MaterialX, ColourSpacesNodeGraphConstantsAndDotsResolve) {
    const ImportedFile file = parseMaterialXOk(R"(<?xml version="1.0"?>
<materialx version="1.39" colorspace="srgb_texture">
  <nodegraph name="NG_constants">
    <constant name="tint" type="color3">
      <input name="value" type="color3" value="0.5, 0.5, 0.5" colorspace="lin_rec709" />
    </constant>
    <dot name="passed" type="color3"><input name="in" type="color3" nodename="tint" /></dot>
    <output name="out" type="color3" nodename="passed" />
  </nodegraph>
  <open_pbr_surface name="SR" type="surfaceshader">
    <input name="base_color" type="color3" value="0.5, 0.5, 0.5" />
    <input name="coat_color" type="color3" nodegraph="NG_constants" output="out" />
    <input name="fuzz_color" type="color3" value="0.5, 0.5, 0.5" colorspace="g22_rec709" />
  </open_pbr_surface>
  <surfacematerial name="M" type="material">
    <input name="surfaceshader" type="surfaceshader" nodename="SR" />
  </surfacematerial>
</materialx>
)");
    ASSERT_EQ(file.materials.size(), 1u);
    const Material& m = file.materials[0].material;
    expectNear(paramValue(m, "base_color"), glm::vec3(0.21404114f));  // sRGB 0.5 decoded (document colour space)
    expectNear(paramValue(m, "coat_color"), glm::vec3(0.5f));         // its own lin_rec709
    expectNear(paramValue(m, "fuzz_color"), glm::vec3(std::pow(0.5f, 2.2f)));
    EXPECT_EQ(warningsText(file), "");
}

// MaterialX's gltf_pbr_boombox.mtlx: its four images on base colour, metalness and roughness (one
// image's blue and green), occlusion (its red: the occlusion map), emission and the normal map, in
// table order; nothing is called dropped or not rendered.
TEST(MaterialX, GltfPbrBoomboxRendersEveryImage) {
    auto file = loadMaterialX(std::string(GLINT_TEST_DATA_DIR) + "/files/materialx/gltf_pbr_boombox.mtlx");
    ASSERT_TRUE(file.ok()) << file.error().format();
    std::vector<std::string> parameters;
    for (const MaterialTexture& texture : file->materials[0].material.analytic()->textures) parameters.push_back(texture.parameter);
    EXPECT_EQ(parameters, (std::vector<std::string>{"base_color", "base_metalness", "specular_roughness", "emission_color",
                                                    kOcclusionMapKey, kNormalMapKey}));
    const MaterialTexture& occlusion = file->materials[0].material.analytic()->textures[4];
    EXPECT_EQ(occlusion.channel, TextureChannel::R);
    EXPECT_EQ(occlusion.range, glm::vec2(0.0f, 1.0f));
    EXPECT_TRUE(file->materials[0].textures.empty());
    EXPECT_EQ(warningsText(*file).find("occlusion"), std::string::npos) << warningsText(*file);
}

TEST(MaterialX, ImageNodesBecomeTexturesAndProceduralGraphsAreWarnings) {
    const std::string directory = test::outputDirectory("materialx_images");
    DisplayImage image(2, 2);
    std::fill(image.pixels.begin(), image.pixels.end(), uint8_t(200));
    ASSERT_TRUE(writeDisplayImage(image, directory + "/textures/colour.png").ok() ||
                (std::filesystem::create_directories(directory + "/textures"), writeDisplayImage(image, directory + "/textures/colour.png").ok()));
    const std::string path = directory + "/images.mtlx";
    std::ofstream(path) << R"(<?xml version="1.0"?>
<materialx version="1.39" fileprefix="textures/">
  <nodegraph name="NG">
    <tiledimage name="colour" type="color3">
      <input name="file" type="filename" value="colour.png" colorspace="srgb_texture" />
      <input name="uvtiling" type="vector2" value="4, 2" />
    </tiledimage>
    <image name="rough" type="color3"><input name="file" type="filename" value="colour.png" /></image>
    <extract name="rough_g" type="float">
      <input name="in" type="color3" nodename="rough" />
      <input name="index" type="integer" value="1" />
    </extract>
    <image name="bumps" type="vector3"><input name="file" type="filename" value="colour.png" /></image>
    <normalmap name="normals" type="vector3"><input name="in" type="vector3" nodename="bumps" /></normalmap>
    <noise2d name="noise" type="float" />
    <output name="base" type="color3" nodename="colour" />
    <output name="roughness" type="float" nodename="rough_g" />
    <output name="normal" type="vector3" nodename="normals" />
    <output name="noisy" type="float" nodename="noise" />
  </nodegraph>
  <open_pbr_surface name="SR" type="surfaceshader">
    <input name="base_color" type="color3" nodegraph="NG" output="base" />
    <input name="specular_roughness" type="float" nodegraph="NG" output="roughness" />
    <input name="geometry_normal" type="vector3" nodegraph="NG" output="normal" />
    <input name="coat_weight" type="float" nodegraph="NG" output="noisy" />
    <input name="geometry_coat_normal" type="vector3" nodegraph="NG" output="normal" />
  </open_pbr_surface>
</materialx>
)";
    auto file = loadMaterialX(path);
    ASSERT_TRUE(file.ok()) << file.error().format();
    const Material& m = file->materials[0].material;
    ASSERT_EQ(m.analytic()->textures.size(), 4u) << warningsText(*file);
    EXPECT_EQ(m.analytic()->textures[0].parameter, "base_color");
    EXPECT_EQ(m.analytic()->textures[0].colorSpace, TextureColorSpace::Srgb);
    EXPECT_EQ(m.analytic()->textures[0].tiling, glm::vec2(4, 2));
    EXPECT_EQ(m.analytic()->textures[0].file, directory + "/textures/colour.png");
    EXPECT_TRUE(m.analytic()->textures[0].image != nullptr);
    EXPECT_EQ(m.analytic()->textures[1].parameter, "specular_roughness");  // table order, the normal map last
    EXPECT_EQ(m.analytic()->textures[1].channel, TextureChannel::G);
    EXPECT_EQ(m.analytic()->textures[1].colorSpace, TextureColorSpace::Linear);
    EXPECT_EQ(m.analytic()->textures[2].parameter, kCoatNormalMapKey);
    EXPECT_EQ(m.analytic()->textures[3].parameter, kNormalMapKey);
    EXPECT_TRUE(file->materials[0].textures.empty());  // every image is rendered: none is only named
    EXPECT_NE(warningsText(*file).find("images.mtlx:25:5: warning: input 'coat_weight' is driven by a 'noise2d' node"), std::string::npos)
        << warningsText(*file);
}

TEST(MaterialX, GlintMaterialsRoundTripThroughOpenPbrSurface) {
    Material openPbr = test::materialWith("car paint", BrdfModel::OpenPbr,
        {{"base_color", glm::vec3(0.05f, 0.1f, 0.6f)}, {"specular_roughness", 0.37f}, {"coat_weight", 1.0f},
         {"coat_ior", 1.55f}, {"fuzz_color", glm::vec3(0.123456789f, 0.3f, 1.0f)}, {"geometry_thin_walled", 1.0f},
         {"emission_luminance", 1500.0f}});
    Material lambert = Material::withDefaults("car paint", BrdfModel::Lambert);  // same name: written unique
    setParam(lambert, "albedo", glm::vec3(0.7f, 0.2f, 0.1f));
    const std::vector<ImportedMaterial> materials = {{openPbr, {}, {}}, {lambert, {}, {}}};
    const ExportedText written = writeMaterialX(materials, "");
    EXPECT_NE(written.text.find("<open_pbr_surface name=\"SR_car_paint\" type=\"surfaceshader\">"), std::string::npos) << written.text;
    EXPECT_NE(written.text.find("<surfacematerial name=\"car_paint_2\" type=\"material\">"), std::string::npos) << written.text;
    EXPECT_NE(written.text.find("<input name=\"geometry_thin_walled\" type=\"boolean\" value=\"true\" />"), std::string::npos);
    ASSERT_EQ(written.warnings.size(), 0u) << written.warnings[0].format();  // Lambert → OpenPBR drops nothing
    const ImportedFile back = parseMaterialXOk(written.text);
    ASSERT_EQ(back.materials.size(), 2u);
    EXPECT_EQ(back.materials[0].material.analytic()->values, openPbr.analytic()->values);
    expectNear(paramValue(back.materials[1].material, "base_color"), {0.7f, 0.2f, 0.1f}, 0.0f);
    EXPECT_EQ(warningsText(back), "");
}

TEST(MaterialX, WritingAnotherModelSaysWhatTheConversionDropped) {
    Material phong = Material::withDefaults("old", BrdfModel::Phong);
    setParam(phong, "form", paramScalar(phong, "form") == 0.0f ? 1.0f : 0.0f);  // how the lobe is normalised: OpenPBR has no choice
    const ExportedText written = writeMaterialX(std::vector<ImportedMaterial>{{phong, {}, {}}}, "");
    ASSERT_EQ(written.warnings.size(), 1u);
    EXPECT_NE(written.warnings[0].message.find("converted from Phong"), std::string::npos) << written.warnings[0].message;
    EXPECT_NE(written.warnings[0].message.find("dropped form"), std::string::npos) << written.warnings[0].message;
}

TEST(MaterialX, MalformedDocumentsGiveLocatedErrors) {
    EXPECT_EQ(errorOf("<materialx version=\"1.39\">\n  <open_pbr_surface name=\"a\">\n</materialx>\n"),
              "bad.mtlx:3:3: not well-formed XML: mismatched tag");
    EXPECT_EQ(errorOf("<?xml version=\"1.0\"?>\n<scene/>\n"), "bad.mtlx:2:1: the root element is <scene>, not <materialx>: not a MaterialX document");
    EXPECT_EQ(errorOf(document(shaderNode("open_pbr_surface", "a", {{"base_color", "0.1, x, 0.3"}}))),
              "bad.mtlx:4:5: '0.1, x, 0.3' is not a color3 (3 comma-separated numbers)");
    EXPECT_EQ(errorOf(document(shaderNode("open_pbr_surface", "a", {{"base_color", "0.1, 0.3"}}))),
              "bad.mtlx:4:5: '0.1, 0.3' is not a color3: 3 numbers expected, 2 found");
    EXPECT_EQ(errorOf(document("  <open_pbr_surface name=\"a\" type=\"surfaceshader\">\n"
                               "    <input name=\"base_color\" type=\"color3\" nodegraph=\"NG\" output=\"out\" />\n  </open_pbr_surface>\n")),
              "bad.mtlx:4:5: input 'base_color' connects to node graph 'NG', which the document does not hold");
    EXPECT_EQ(errorOf(document("  <UsdPreviewSurface name=\"u\" type=\"surfaceshader\" />\n"
                               "  <surfacematerial name=\"M\" type=\"material\">\n"
                               "    <input name=\"surfaceshader\" type=\"surfaceshader\" nodename=\"u\" />\n  </surfacematerial>\n")),
              "bad.mtlx:2:1: no open_pbr_surface, standard_surface or gltf_pbr material (it holds UsdPreviewSurface)");
    // A connection loop ends in a message, not a stack overflow.
    EXPECT_NE(errorOf(document("  <dot name=\"d1\" type=\"float\"><input name=\"in\" type=\"float\" nodename=\"d2\" /></dot>\n"
                               "  <dot name=\"d2\" type=\"float\"><input name=\"in\" type=\"float\" nodename=\"d1\" /></dot>\n"
                               "  <open_pbr_surface name=\"a\" type=\"surfaceshader\">\n"
                               "    <input name=\"coat_weight\" type=\"float\" nodename=\"d1\" />\n  </open_pbr_surface>\n"))
                  .find("(a loop?)"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(100, '<')).find("bad.mtlx:1:2: not well-formed XML"), std::string::npos);
    std::string deep = "<materialx>";
    for (int i = 0; i < 1000; ++i) deep += "<a>";
    EXPECT_NE(errorOf(deep).find("nested more than 64 deep"), std::string::npos);
}

TEST(MaterialX, ValuesOutsideGlintsRangesAreReadAsTheNearestWithAWarning) {
    // MaterialX's velvet example has specular_IOR 0 under specular 0: valid there, harmless.
    auto file = loadMaterialX(test::dataPath("files/materialx/standard_surface_velvet.mtlx"));
    ASSERT_TRUE(file.ok()) << file.error().format();
    EXPECT_EQ(paramScalar(file->materials[0].material, "specular_ior"), 1.0f);
    EXPECT_EQ(paramScalar(file->materials[0].material, "specular_weight"), 0.0f);
    EXPECT_NE(warningsText(*file).find("standard_surface_velvet.mtlx:9:5: warning: 'specular_ior' is outside Glint's range [1, inf]"),
              std::string::npos) << warningsText(*file);
}

TEST(MaterialX, UnknownInputsAndDroppedLobesAreLocatedWarnings) {
    const ImportedFile file =
        parseMaterialXOk(document(shaderNode("open_pbr_surface", "a", {{"subsurface_weight", "0.5"}, {"base_colour", "1, 0, 0"}})));
    EXPECT_EQ(warningsText(file),
              "test.mtlx:5:5: warning: 'base_colour' is not an input of open_pbr_surface (ignored)\n"
              "test.mtlx:4:5: warning: 'subsurface_weight' is dropped: Glint's openpbr has no subsurface scattering\n");
}

}  // namespace
}  // namespace glint
