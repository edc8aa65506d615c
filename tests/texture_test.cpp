// Material textures on the CPU: the "textures" JSON (round trip, located errors for a missing
// file, a corrupt or truncated PNG, NaN texels, an unknown parameter, an Enum parameter), image
// decoding (sRGB → linear, bottom-up rows), sampling, Perlin noise and the shapes' (u, v).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include "display/display_chain.h"
#include "geometry/mesh.h"
#include "image/image_io.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "texture/procedural.h"
#include "texture/texture_edit.h"
#include "texture/texture_eval.h"
#include "texture/texture_image.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// A 4×2 RGB PNG: top row red, green, blue, white; bottom row greys 0, 64, 128, 255.
std::string writeSmallPng(const std::string& directory, const std::string& name) {
    DisplayImage image(4, 2);
    const uint8_t pixels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255, 0, 0, 0, 64, 64, 64, 128, 128, 128, 255, 255, 255};
    std::copy(std::begin(pixels), std::end(pixels), image.pixels.begin());
    const std::string path = directory + "/" + name;
    EXPECT_TRUE(writeDisplayImage(image, path).ok());
    return path;
}

std::string materialJson(const std::string& textures, const std::string& model = "lambert") {
    return R"({"format": "glint-material", "version": 1, "name": "m", "model": ")" + model +
           R"(", "textures": )" + textures + "}";
}

TEST(TextureImage, DecodesSrgbToLinearWithRowsBottomUp) {
    const std::string path = writeSmallPng(test::outputDirectory("textures"), "small.png");
    auto image = loadTextureImage(path, TextureColorSpace::Srgb);
    ASSERT_TRUE(image.ok()) << image.error().format();
    EXPECT_EQ((*image)->width, 4);
    EXPECT_EQ((*image)->height, 2);
    // Row 0 is the picture's bottom row: grey 64/255 decodes to 0.0513 linear.
    EXPECT_NEAR((*image)->texel(1, 0).r, decodeSrgb(64.0f / 255.0f), 1e-6f);
    EXPECT_NEAR(decodeSrgb(64.0f / 255.0f), 0.0512694f, 1e-5f);
    EXPECT_EQ((*image)->texel(0, 1), glm::vec4(1, 0, 0, 1));  // top-left red
    auto linear = loadTextureImage(path, TextureColorSpace::Linear);
    ASSERT_TRUE(linear.ok());
    EXPECT_NEAR((*linear)->texel(1, 0).r, 64.0f / 255.0f, 1e-6f);
    // Decoded once per path, time and colour space.
    EXPECT_EQ(loadTextureImage(path, TextureColorSpace::Srgb)->get(), image->get());
}

TEST(TextureImage, SamplesBilinearWithRepeatLikeOpenGl) {
    TextureImage image;
    image.width = 2, image.height = 1;
    image.rgba = {0, 0, 0, 1, 1, 1, 1, 1};
    EXPECT_FLOAT_EQ(sampleImage(image, {0.25f, 0.5f}, true).r, 0.0f);  // texel centre
    EXPECT_FLOAT_EQ(sampleImage(image, {0.5f, 0.5f}, true).r, 0.5f);   // between the centres
    EXPECT_FLOAT_EQ(sampleImage(image, {0.0f, 0.5f}, true).r, 0.5f);   // wraps to the last texel
    EXPECT_FLOAT_EQ(sampleImage(image, {0.6f, 0.5f}, false).r, 1.0f);  // nearest
}

// OpenGL 4.6 Table 8.20 along each axis: CLAMP_TO_EDGE holds the edge texel, MIRRORED_REPEAT
// runs the image backwards in every other repetition.
TEST(TextureImage, ClampsAndMirrorsLikeOpenGl) {
    TextureImage image;
    image.width = 4, image.height = 1;
    image.rgba = {0, 0, 0, 1, 1, 1, 1, 1, 2, 2, 2, 1, 3, 3, 3, 1};  // texel i holds i
    const auto nearest = [&](float u, TextureWrap wrap) { return sampleImage(image, {u, 0.5f}, false, wrap, wrap).r; };
    EXPECT_EQ(nearest(1.1f, TextureWrap::Repeat), 0.0f);
    EXPECT_EQ(nearest(1.1f, TextureWrap::ClampToEdge), 3.0f);
    EXPECT_EQ(nearest(-0.4f, TextureWrap::ClampToEdge), 0.0f);
    EXPECT_EQ(nearest(1.1f, TextureWrap::MirroredRepeat), 3.0f);   // 1.1: texel 4 → the mirrored 3
    EXPECT_EQ(nearest(1.6f, TextureWrap::MirroredRepeat), 1.0f);   // texel 6 → 1
    EXPECT_EQ(nearest(2.1f, TextureWrap::MirroredRepeat), 0.0f);   // texel 8: forwards again
    EXPECT_EQ(nearest(-0.1f, TextureWrap::MirroredRepeat), 0.0f);  // texel −1 → 0
    EXPECT_EQ(nearest(-0.6f, TextureWrap::MirroredRepeat), 2.0f);  // texel −3 → 2
    // Bilinear at u = 0 blends the last and first texels (repeat), the first with itself
    // (clamp) or with its mirror image, itself (mirror).
    EXPECT_FLOAT_EQ(sampleImage(image, {0.0f, 0.5f}, true).r, 1.5f);
    EXPECT_FLOAT_EQ(sampleImage(image, {0.0f, 0.5f}, true, TextureWrap::ClampToEdge, TextureWrap::Repeat).r, 0.0f);
    EXPECT_FLOAT_EQ(sampleImage(image, {0.0f, 0.5f}, true, TextureWrap::MirroredRepeat, TextureWrap::Repeat).r, 0.0f);
    EXPECT_FLOAT_EQ(sampleImage(image, {1.0f, 0.5f}, true, TextureWrap::MirroredRepeat, TextureWrap::Repeat).r, 3.0f);
    // u and v wrap independently.
    TextureImage column;
    column.width = 1, column.height = 2;
    column.rgba = {0, 0, 0, 1, 1, 1, 1, 1};
    EXPECT_EQ(sampleImage(column, {1.9f, 1.2f}, false, TextureWrap::ClampToEdge, TextureWrap::Repeat).r, 0.0f);
    EXPECT_EQ(sampleImage(column, {1.9f, 1.2f}, false, TextureWrap::Repeat, TextureWrap::ClampToEdge).r, 1.0f);
}

TEST(TextureImage, RefusesCorruptTruncatedAndNonFiniteFiles) {
    const std::string directory = test::outputDirectory("textures");
    const std::string corrupt = directory + "/corrupt.png";
    std::ofstream(corrupt, std::ios::binary) << "\x89PNG\r\n\x1a\nthis is not a png";
    auto image = loadTextureImage(corrupt, TextureColorSpace::Srgb);
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().where.file, corrupt);

    DisplayImage big(64, 64);
    for (size_t i = 0; i < big.pixels.size(); ++i) big.pixels[i] = static_cast<uint8_t>(i * 7919 % 251);
    const std::string whole = directory + "/whole.png", truncated = directory + "/truncated.png";
    ASSERT_TRUE(writeDisplayImage(big, whole, 0).ok());
    const auto size = fs::file_size(whole);
    fs::copy_file(whole, truncated, fs::copy_options::overwrite_existing);
    fs::resize_file(truncated, size / 2);
    auto cut = loadTextureImage(truncated, TextureColorSpace::Srgb);
    ASSERT_FALSE(cut.ok());
    EXPECT_NE(cut.error().format().find("truncated.png"), std::string::npos);

    RadianceImage withNan(2, 2);
    withNan.pixels[4] = std::nanf("");
    const std::string nanPath = directory + "/nan.exr";
    ASSERT_TRUE(writeRadianceImage(withNan, nanPath).ok());
    auto nan = loadTextureImage(nanPath, TextureColorSpace::Linear);
    ASSERT_FALSE(nan.ok());
    EXPECT_NE(nan.error().message.find("non-finite"), std::string::npos) << nan.error().format();

    auto missing = loadTextureImage(directory + "/nowhere.png", TextureColorSpace::Srgb);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("not found"), std::string::npos);
}

TEST(TextureJson, MissingFileIsALocatedErrorNamingTheFile) {
    const std::string file = test::outputDirectory("textures") + "/missing.material.json";
    auto material = parseMaterial(materialJson(R"({
  "albedo": {"type": "image", "file": "no_such_texture.png"}})"), file);
    ASSERT_FALSE(material.ok());
    const Diagnostic& error = material.error();
    EXPECT_EQ(error.where.file, file);
    EXPECT_EQ(error.where.line, 2);
    EXPECT_NE(error.message.find("no_such_texture.png"), std::string::npos) << error.format();
    EXPECT_NE(error.message.find("not found"), std::string::npos) << error.format();
}

TEST(TextureJson, CorruptPngIsALocatedError) {
    const std::string directory = test::outputDirectory("textures");
    std::ofstream(directory + "/bad.png", std::ios::binary) << "\x89PNG\r\n\x1a\ngarbage";
    auto material = parseMaterial(materialJson(R"({"albedo": {"type": "image", "file": "bad.png"}})"), directory + "/m.json");
    ASSERT_FALSE(material.ok());
    EXPECT_NE(material.error().message.find("bad.png"), std::string::npos) << material.error().format();
    EXPECT_EQ(material.error().where.line, 1);
}

TEST(TextureJson, RefusesUnknownParametersAndNonTexturableKinds) {
    auto unknown = parseMaterial(materialJson(R"({"shininess": {"type": "checker"}})"), "m.json");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("'shininess' is not a parameter of the model 'lambert'"), std::string::npos)
        << unknown.error().format();
    EXPECT_NE(unknown.error().message.find("albedo"), std::string::npos);

    auto enumParam = parseMaterial(materialJson(R"({"distribution": {"type": "checker"}})", "cook_torrance"), "m.json");
    ASSERT_FALSE(enumParam.ok());
    EXPECT_NE(enumParam.error().message.find("is a choice; only scalar and colour parameters can be textured"),
              std::string::npos) << enumParam.error().format();

    auto perChannel = parseMaterial(materialJson(R"({"ior": {"type": "checker"}})", "cook_torrance"), "m.json");
    ASSERT_FALSE(perChannel.ok());

    auto outOfRange = parseMaterial(materialJson(R"({"roughness": {"type": "marble", "a": 0.1, "b": 7}})", "cook_torrance"), "m.json");
    ASSERT_FALSE(outOfRange.ok());
    EXPECT_NE(outOfRange.error().format().find("b'"), std::string::npos) << outOfRange.error().format();

    auto proceduralNormal = parseMaterial(materialJson(R"({"normal": {"type": "checker"}})"), "m.json");
    ASSERT_FALSE(proceduralNormal.ok());
    EXPECT_NE(proceduralNormal.error().message.find("normal map must be an image"), std::string::npos);
}

TEST(TextureJson, RoundTripsWithPathsRelativeToTheSavedFile) {
    const std::string directory = test::outputDirectory("textures/roundtrip");
    fs::create_directories(directory + "/maps");
    writeSmallPng(directory + "/maps", "colour.png");
    const std::string text = materialJson(R"({
        "albedo": {"type": "image", "file": "maps/colour.png", "filter": "anisotropic", "tiling": [2, 3]},
        "normal": {"type": "image", "file": "maps/colour.png"}})");
    auto material = parseMaterial(text, directory + "/a.material.json");
    ASSERT_TRUE(material.ok()) << material.error().format();
    ASSERT_EQ(material->analytic()->textures.size(), 2u);
    EXPECT_EQ(material->analytic()->textures[0].parameter, "albedo");
    EXPECT_EQ(material->analytic()->textures[0].colorSpace, TextureColorSpace::Srgb);     // colour default
    EXPECT_EQ(material->analytic()->textures[1].colorSpace, TextureColorSpace::Linear);   // normal map default
    EXPECT_EQ(material->analytic()->textures[0].filter, TextureFilter::Anisotropic);
    EXPECT_EQ(material->analytic()->textures[0].wrapU, TextureWrap::Repeat);  // files without wrap keys repeat
    EXPECT_EQ(material->analytic()->textures[0].minFilter, TextureMinFilter::Default);
    EXPECT_FALSE(materialToJson(*material)["textures"]["albedo"].contains("wrap_u"));  // written only when not repeat

    // Wrap modes and a minification filter other than the filter's survive the file.
    auto sampled = parseMaterial(materialJson(R"({"albedo": {"type": "image", "file": "maps/colour.png", "filter": "bilinear",
        "min_filter": "nearest_mipmap_linear", "wrap_u": "clamp_to_edge", "wrap_v": "mirrored_repeat"}})"), directory + "/s.json");
    ASSERT_TRUE(sampled.ok()) << sampled.error().format();
    EXPECT_EQ(sampled->analytic()->textures[0].wrapU, TextureWrap::ClampToEdge);
    EXPECT_EQ(sampled->analytic()->textures[0].wrapV, TextureWrap::MirroredRepeat);
    EXPECT_EQ(sampled->analytic()->textures[0].minFilter, TextureMinFilter::NearestMipmapLinear);
    auto resampled = parseMaterial(materialToJson(*sampled, directory + "/s.json").dump(), directory + "/s.json");
    ASSERT_TRUE(resampled.ok()) << resampled.error().format();
    EXPECT_EQ(materialToJson(*resampled), materialToJson(*sampled));
    auto badWrap = parseMaterial(materialJson(R"({"albedo": {"type": "image", "file": "maps/colour.png", "wrap_u": "clamp"}})"),
                                 directory + "/w.json");
    ASSERT_FALSE(badWrap.ok());
    EXPECT_NE(badWrap.error().format().find("wrap_u"), std::string::npos) << badWrap.error().format();

    // The occlusion map is a scalar texture of its own: channel and range, slot before the normal map.
    auto occluded = parseMaterial(materialJson(R"({"normal": {"type": "image", "file": "maps/colour.png"},
        "occlusion": {"type": "image", "file": "maps/colour.png", "channel": "g", "min": 0.25}})"), directory + "/o.json");
    ASSERT_TRUE(occluded.ok()) << occluded.error().format();
    ASSERT_EQ(occluded->analytic()->textures.size(), 2u);
    EXPECT_EQ(occluded->analytic()->textures[0].parameter, kOcclusionMapKey);
    EXPECT_EQ(occluded->analytic()->textures[0].range, glm::vec2(0.25f, 1.0f));
    EXPECT_EQ(materialToJson(*occluded, directory + "/o.json")["textures"]["occlusion"]["channel"], "g");
    auto reoccluded = parseMaterial(materialToJson(*occluded, directory + "/o.json").dump(), directory + "/o.json");
    ASSERT_TRUE(reoccluded.ok()) << reoccluded.error().format();
    EXPECT_EQ(materialToJson(*reoccluded), materialToJson(*occluded));
    TexturePoint bottomLeft;
    bottomLeft.uv = {0.125f, 0.25f};  // the centre of the bottom row's first texel: grey 0
    EXPECT_FLOAT_EQ(ambientOcclusion(*occluded->analytic(), bottomLeft), 0.25f);
    EXPECT_FLOAT_EQ(ambientOcclusion(*material->analytic(), bottomLeft), 1.0f);  // none: unoccluded

    // The coat normal map: its scale saved, slot before the occlusion map; it sets the frame's coat normal and leaves the surface's normal to the normal map.
    auto coated = parseMaterial(materialJson(R"({"normal": {"type": "image", "file": "maps/colour.png"},
        "occlusion": {"type": "image", "file": "maps/colour.png"},
        "coat_normal": {"type": "image", "file": "maps/colour.png", "scale": 0.5}})", "openpbr"), directory + "/c.json");
    ASSERT_TRUE(coated.ok()) << coated.error().format();
    ASSERT_EQ(coated->analytic()->textures.size(), 3u);
    EXPECT_EQ(coated->analytic()->textures[0].parameter, kCoatNormalMapKey);
    EXPECT_EQ(materialToJson(*coated, directory + "/c.json")["textures"]["coat_normal"]["scale"], 0.5);
    auto recoated = parseMaterial(materialToJson(*coated, directory + "/c.json").dump(), directory + "/c.json");
    ASSERT_TRUE(recoated.ok()) << recoated.error().format();
    EXPECT_EQ(materialToJson(*recoated), materialToJson(*coated));
    const ShadingFrame flat;
    const ShadingFrame mapped = normalMappedFrame(*coated->analytic(), bottomLeft, flat);
    EXPECT_NE(mapped.coatNormal, glm::vec3(0.0f));
    EXPECT_NE(mapped.coatNormal, mapped.normal);  // coat scale 0.5, base scale 1
    EXPECT_EQ(normalMappedFrame(*occluded->analytic(), bottomLeft, flat).coatNormal, glm::vec3(0.0f));  // none: the coat shares the normal

    const std::string saved = directory + "/maps/b.material.json";  // another folder
    ASSERT_TRUE(saveMaterial(*material, saved).ok());
    EXPECT_EQ(materialToJson(*material, saved)["textures"]["albedo"]["file"], "colour.png");
    auto reread = loadMaterial(saved);
    ASSERT_TRUE(reread.ok()) << reread.error().format();
    EXPECT_EQ(materialToJson(*reread), materialToJson(*material));

    Material procedural = Material::withDefaults("p", BrdfModel::CookTorrance);
    auto marble = parseMaterial(materialJson(R"({"roughness": {"type": "marble", "a": 0.1, "b": 0.7, "frequency": 3},
        "diffuse_albedo": {"type": "checker", "a": [0.1, 0.2, 0.3], "b": 0.9, "tiling": [4, 4]}})", "cook_torrance"), "m.json");
    ASSERT_TRUE(marble.ok()) << marble.error().format();
    auto again = parseMaterial(materialToJson(*marble).dump(), "m.json");
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(materialToJson(*again), materialToJson(*marble));
    EXPECT_EQ(again->analytic()->textures[0].parameter, "diffuse_albedo");  // table order
}

TEST(Procedural, PerlinNoiseVanishesOnTheLatticeAndStaysBounded) {
    EXPECT_FLOAT_EQ(perlinNoise({3, -2, 7}), 0.0f);
    float largest = 0.0f;
    for (int i = 0; i < 2000; ++i) {
        const glm::vec3 point{i * 0.0137f, i * 0.0291f - 5.0f, std::sin(i * 0.1f) * 3.0f};
        largest = std::max(largest, std::abs(perlinNoise(point)));
        const float marble = marbleWeight(point, 2.0f, 5.0f, 5);
        ASSERT_GE(marble, 0.0f);
        ASSERT_LE(marble, 1.0f);
        ASSERT_GE(turbulence(point, 4), 0.0f);
    }
    EXPECT_GT(largest, 0.3f);
    EXPECT_LE(largest, 1.0f);
    EXPECT_EQ(checkerWeight({0.5f, 0.5f}), 0.0f);
    EXPECT_EQ(checkerWeight({1.5f, 0.5f}), 1.0f);
    EXPECT_EQ(checkerWeight({-0.5f, 0.5f}), 1.0f);
}

// The analytic (u, v) of the reference renderer and the GPU equals the proxy mesh's vertex UVs.
TEST(TexturePoint, SphereUvMatchesTheMeshConvention) {
    const SphereShape sphere{{0.5f, -0.2f, 1.0f}, 2.0f};
    const Mesh mesh = makeUvSphere(sphere.center, sphere.radius, 16, 8);
    int checked = 0;
    for (const Vertex& vertex : mesh.vertices) {
        if (vertex.uv.x < 1e-3f || vertex.uv.x > 1.0f - 1e-3f || vertex.uv.y < 1e-3f || vertex.uv.y > 1.0f - 1e-3f) continue;
        const TexturePoint point = texturePointOn(sphere, vertex.position);
        EXPECT_NEAR(point.uv.x, vertex.uv.x, 1e-4f);
        EXPECT_NEAR(point.uv.y, vertex.uv.y, 1e-4f);
        ++checked;
    }
    EXPECT_GT(checked, 50);
    const PlaneShape plane{{0, -1, 0}, {0, 1, 0}, {4, 2}};
    const Mesh quad = makePlane(plane.center, plane.normal, plane.size);
    for (const Vertex& vertex : quad.vertices) {
        const TexturePoint point = texturePointOn(plane, vertex.position);
        EXPECT_NEAR(point.uv.x, vertex.uv.x, 1e-5f);
        EXPECT_NEAR(point.uv.y, vertex.uv.y, 1e-5f);
    }
}

TEST(TextureEval, TexturedValuesReplaceTheConstants) {
    auto material = parseMaterial(materialJson(R"({"roughness": {"type": "checker", "a": 0.2, "b": 0.6, "tiling": [2, 2]}})",
                                               "cook_torrance"), "m.json");
    ASSERT_TRUE(material.ok()) << material.error().format();
    const auto table = modelInfo(BrdfModel::CookTorrance).params;
    const int roughness = packedOffset(table, findParam(table, "roughness"));
    EXPECT_FLOAT_EQ(texturedValues(*material->analytic(), {{0.25f, 0.25f}, {}})[roughness], 0.2f);
    EXPECT_FLOAT_EQ(texturedValues(*material->analytic(), {{0.75f, 0.25f}, {}})[roughness], 0.6f);
}

// The editor's path: a file that fails leaves the material exactly as it was.
TEST(TextureEdit, AFailingImageLeavesTheMaterialAsItWas) {
    const std::string directory = test::outputDirectory("textures");
    Material material = Material::withDefaults("m", BrdfModel::CookTorrance);
    putTexture(*material.analytic(), defaultTexture("roughness", &modelInfo(material.analytic()->model).params[3], TextureKind::Marble));
    const nlohmann::json before = materialToJson(material);
    Status missing = setTextureImage(*material.analytic(), "diffuse_albedo", directory + "/absent.png");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().format().find("absent.png"), std::string::npos);
    std::ofstream(directory + "/broken.png", std::ios::binary) << "\x89PNG\r\n\x1a\n";
    EXPECT_FALSE(setTextureImage(*material.analytic(), "diffuse_albedo", directory + "/broken.png").ok());
    EXPECT_FALSE(setTextureImage(*material.analytic(), "distribution", writeSmallPng(directory, "ok.png")).ok());
    EXPECT_EQ(materialToJson(material), before);
    ASSERT_TRUE(setTextureImage(*material.analytic(), "diffuse_albedo", directory + "/ok.png").ok());
    ASSERT_EQ(material.analytic()->textures.size(), 2u);
    EXPECT_EQ(material.analytic()->textures[0].parameter, "diffuse_albedo");  // table order kept
    EXPECT_EQ(material.analytic()->textures[0].colorSpace, TextureColorSpace::Srgb);
}

}  // namespace
}  // namespace glint
