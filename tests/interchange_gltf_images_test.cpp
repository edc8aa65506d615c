// Images inside glTF files: Khronos' BoxTextured as a .glb (a bufferView image) and as a
// glTF-Embedded .gltf (a data URI) render the same texture; a material file keeps such an image
// by its glTF and index and reads it back; glTF export writes it as a data URI; JPEG decodes from
// memory as PNG does; damaged images (bad base64, a bufferView or buffer out of range, an unknown
// or missing MIME type) are located errors naming the image, an undecodable one a warning.
// Also: extensions a file requires or uses.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "image/image_io.h"
#include "interchange/base64.h"
#include "interchange/glb.h"
#include "interchange/gltf.h"
#include "interchange/gltf_images.h"
#include "scene/scene_json.h"
#include "test_support.h"
#include "util/file_io.h"

namespace glint {
namespace {

using nlohmann::json;

const std::string kKhronos = std::string(GLINT_TEST_DATA_DIR) + "/files/gltf/khronos/";

const MaterialTexture& baseColorTexture(const ImportedFile& file) {
    const auto& textures = file.materials.at(0).material.analytic()->textures;
    EXPECT_EQ(textures.size(), 1u);
    return textures.at(0);
}

TEST(GltfImages, GlbBufferViewAndDataUriImagesAreTheSameTexture) {
    auto glb = loadGlb(kKhronos + "BoxTextured.glb");
    auto gltf = loadGltf(kKhronos + "BoxTextured_embedded.gltf");
    ASSERT_TRUE(glb.ok()) << glb.error().format();
    ASSERT_TRUE(gltf.ok()) << gltf.error().format();
    EXPECT_TRUE(allWarnings(*glb).empty()) << allWarnings(*glb).front().format();
    EXPECT_TRUE(allWarnings(*gltf).empty()) << allWarnings(*gltf).front().format();
    const MaterialTexture &fromGlb = baseColorTexture(*glb), &fromGltf = baseColorTexture(*gltf);
    EXPECT_EQ(fromGlb.parameter, "base_color");
    EXPECT_EQ(fromGlb.gltfImage, 0);
    EXPECT_NE(fromGlb.file.find("BoxTextured.glb"), std::string::npos);
    ASSERT_TRUE(fromGlb.image && fromGltf.image);
    EXPECT_EQ(fromGlb.image->width, 211);
    EXPECT_EQ(fromGlb.image->height, 211);
    EXPECT_EQ(fromGlb.image->rgba, fromGltf.image->rgba);
    EXPECT_NE(fromGlb.image->path, fromGltf.image->path);  // two images to the GPU's texture cache
}

TEST(GltfImages, MaterialFilesKeepTheImageByItsGltfAndIndex) {
    auto glb = loadGlb(kKhronos + "BoxTextured.glb");
    ASSERT_TRUE(glb.ok()) << glb.error().format();
    const std::string materialFile = kKhronos + "box.material.json";  // never written: the JSON stays in memory
    const json written = materialToJson(glb->materials[0].material, materialFile);
    EXPECT_EQ(written["textures"]["base_color"]["file"], "BoxTextured.glb");
    EXPECT_EQ(written["textures"]["base_color"]["gltf_image"], 0);
    auto read = parseMaterial(written.dump(), materialFile);
    ASSERT_TRUE(read.ok()) << read.error().format();
    const MaterialTexture& texture = read->analytic()->textures.at(0);
    EXPECT_EQ(texture.gltfImage, 0);
    EXPECT_EQ(texture.image->rgba, baseColorTexture(*glb).image->rgba);

    json missing = written;
    missing["textures"]["base_color"]["gltf_image"] = 5;
    auto refused = parseMaterial(missing.dump(), materialFile);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().format().find("no image 5"), std::string::npos) << refused.error().format();
}

TEST(GltfImages, ExportWritesTheImageAsADataUri) {
    auto glb = loadGlb(kKhronos + "BoxTextured.glb");
    ASSERT_TRUE(glb.ok()) << glb.error().format();
    const std::string target = test::outputDirectory("gltf_images") + "/box.gltf";
    const ExportedText written = writeGltf(glb->materials[0], {}, target);
    const json gltf = json::parse(written.text);
    EXPECT_EQ(gltf["images"][0]["uri"].get<std::string>().rfind("data:image/png;base64,", 0), 0u);
    auto again = parseGltf(written.text, target);
    ASSERT_TRUE(again.ok()) << again.error().format();
    EXPECT_EQ(baseColorTexture(*again).image->rgba, baseColorTexture(*glb).image->rgba);
}

// A material whose base colour texture is images[0], as `image` describes it.
std::string withImage(const json& image, const json& more = json::object()) {
    json gltf = {{"asset", {{"version", "2.0"}}},
                 {"materials", {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}}},
                 {"textures", {{{"source", 0}}}},
                 {"images", {image}}};
    gltf.update(more);
    return gltf.dump(2);
}

TEST(GltfImages, JpegDataUrisDecodeFromMemory) {
    DisplayImage picture(8, 4);
    for (size_t i = 0; i < picture.pixels.size(); ++i) picture.pixels[i] = static_cast<uint8_t>(i * 7);
    const std::string jpeg = test::outputDirectory("gltf_images") + "/ramp.jpg";
    ASSERT_TRUE(writeDisplayImage(picture, jpeg).ok());
    auto bytes = readTextFile(jpeg);
    ASSERT_TRUE(bytes.ok());
    const std::string uri = "data:image/jpeg;base64," + encodeBase64({bytes->begin(), bytes->end()});
    auto imported = parseGltf(withImage({{"uri", uri}}), "jpeg.gltf");
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    const MaterialTexture& texture = baseColorTexture(*imported);
    EXPECT_EQ(texture.image->width, 8);
    EXPECT_EQ(texture.image->height, 4);
}

TEST(GltfImages, DamagedImagesAreLocatedErrorsNamingTheImage) {
    auto located = parseGltf(withImage({{"uri", "data:image/png;base64,@@@@"}}), "images.gltf");
    ASSERT_FALSE(located.ok());
    EXPECT_GT(located.error().where.line, 0);
    const json oneBuffer = {{"buffers", {{{"byteLength", 4}, {"uri", "data:application/octet-stream;base64,AAECAw=="}}}}};
    json views = oneBuffer;
    views["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 2}, {"byteLength", 4}}};
    test::expectParseErrors(parseGltf, "images.gltf", {
        {withImage({{"uri", "data:image/png;base64,iVBOR*w0KGgo="}}), "image 0 'uri': the data URI is not valid base64"},
        {withImage({{"uri", "data:image/png,rawbytes"}}), "image 0 'uri': a data URI must be base64"},
        {withImage({{"uri", "data:image/webp;base64,AAAA"}}), "image 0 'uri': the image is of type \"image/webp\", which Glint does not read"},
        {withImage({{"bufferView", 0}}), "image 0: an image in a bufferView needs a \"mimeType\""},
        {withImage({{"bufferView", 0}, {"mimeType", "image/ktx2"}}, views), "image 0 'mimeType': the image is of type \"image/ktx2\""},
        {withImage({{"bufferView", 3}, {"mimeType", "image/png"}}, views), "image 0 'bufferView': bufferView 3 does not exist"},
        {withImage({{"bufferView", 0}, {"mimeType", "image/png"}}, views),
         "image 0's bufferView 0: bytes 2 to 6 lie outside buffer 0 (4 bytes)"},
        {withImage({{"bufferView", 0}, {"mimeType", "image/png"}}, {{"bufferViews", {{{"buffer", 1}, {"byteLength", 4}}}}}),
         "image 0's bufferView 0 'buffer': buffer 1 does not exist"},
        {withImage({{"bufferView", 0}, {"mimeType", "image/png"}}, {{"bufferViews", {{{"buffer", 0}, {"byteLength", 4}}}}, {"buffers", {{{"byteLength", 4}}}}}),
         "image 0's bufferView 0's buffer 0: it has no \"uri\" and is not the BIN chunk of a .glb"},
        {withImage(json::object()), "image 0: an image needs a \"uri\" or a \"bufferView\""},
    });
}

TEST(GltfImages, AnUndecodableImageIsAWarningAndTheTextureIsLeftOut) {
    // Four bytes that are no PNG: the file is well formed, the picture is not.
    auto imported = parseGltf(withImage({{"uri", "data:image/png;base64,AAECAw=="}}), "broken_png.gltf");
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    EXPECT_TRUE(imported->materials[0].material.analytic()->textures.empty());
    const auto warnings = allWarnings(*imported);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].format().find("image 0 (image/png, 4 bytes inside the file): cannot read texture image"), std::string::npos)
        << warnings[0].format();
}

TEST(GltfImages, RequiredExtensionsGlintLacksAreRefusedAndUsedOnesNamedOnce) {
    const json required = {{"asset", {{"version", "2.0"}}},
                           {"extensionsUsed", {"KHR_texture_transform", "KHR_draco_mesh_compression"}},
                           {"extensionsRequired", {"KHR_texture_transform", "KHR_draco_mesh_compression"}},
                           {"materials", {json::object()}}};
    auto refused = parseGltf(required.dump(2), "draco.gltf");
    ASSERT_FALSE(refused.ok());
    EXPECT_GT(refused.error().where.line, 0);  // at the name in extensionsRequired
    EXPECT_NE(refused.error().message.find("the file requires the extension \"KHR_draco_mesh_compression\", which Glint does not support"),
              std::string::npos)
        << refused.error().format();

    json used = required;
    used.erase("extensionsRequired");
    used["materials"] = {{{"extensions", {{"KHR_draco_mesh_compression", json::object()}}}},
                         {{"extensions", {{"KHR_draco_mesh_compression", json::object()}}}}};
    auto imported = parseGltf(used.dump(2), "draco.gltf");
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    const auto warnings = allWarnings(*imported);
    ASSERT_EQ(warnings.size(), 1u);  // once, though two materials carry it
    EXPECT_NE(warnings[0].format().find("extension KHR_draco_mesh_compression is not supported by Glint"), std::string::npos)
        << warnings[0].format();
}

}  // namespace
}  // namespace glint
