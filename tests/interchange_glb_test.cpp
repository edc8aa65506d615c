// Binary glTF (.glb): the JSON chunk is read for materials and lights as a .gltf is, unknown
// chunks are skipped, and every broken layout (short header, wrong magic or version, lying total
// or chunk lengths, a first chunk that is not JSON, no JSON chunk) is refused at its byte offset.
#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "interchange/glb.h"
#include "interchange/import_formats.h"

namespace glint {
namespace {

std::string glbWord(uint32_t value) {
    return {char(value & 0xFF), char(value >> 8 & 0xFF), char(value >> 16 & 0xFF), char(value >> 24 & 0xFF)};
}

std::string glbChunk(uint32_t type, std::string data) {
    while (data.size() % 4) data += type == 0x4E4F534Au ? ' ' : '\0';  // §4.4.3: padded to 4 bytes
    return glbWord(uint32_t(data.size())) + glbWord(type) + data;
}

// Header + chunks, with the true total length unless `length` overrides it.
std::string glbFile(const std::string& chunks, int64_t length = -1) {
    return glbWord(0x46546C67u) + glbWord(2) + glbWord(uint32_t(length >= 0 ? length : 12 + int64_t(chunks.size()))) + chunks;
}

constexpr const char* kGlbMaterialJson =
    R"({"asset": {"version": "2.0"},
 "materials": [{"name": "copper", "pbrMetallicRoughness": {"baseColorFactor": [0.95, 0.64, 0.54, 1], "metallicFactor": 1, "roughnessFactor": 0.4}}],
 "buffers": [{"byteLength": 8}]})";

TEST(Glb, JsonChunkIsReadLikeAGltfAndOtherChunksAreSkipped) {
    const std::string file = glbFile(glbChunk(0x4E4F534Au, kGlbMaterialJson) + glbChunk(0x004E4942u, std::string(8, '\x7f')) +
                                     glbChunk(0x12345678u, "extra"));
    auto imported = parseGlb(file, "copper.glb");
    ASSERT_TRUE(imported.ok()) << imported.error().format();
    ASSERT_EQ(imported->materials.size(), 1u);
    EXPECT_EQ(imported->materials[0].material.name, "copper");
    EXPECT_EQ(imported->materials[0].material.analytic()->model, BrdfModel::OpenPbr);
    EXPECT_EQ(findImportFormat("x/Y.GLB")->load, &loadGlb);
}

TEST(Glb, BrokenLayoutsAreRefusedAtTheirByteOffset) {
    const std::string json = glbChunk(0x4E4F534Au, kGlbMaterialJson), bin = glbChunk(0x004E4942u, std::string(8, '\0'));
    std::string wrongMagic = glbFile(json);
    wrongMagic[0] = 'x';
    std::string version1 = glbFile(json);
    version1[4] = 1;
    std::string lyingChunk = glbFile(json + bin);
    lyingChunk[12 + json.size()] = 100;  // the BIN chunk claims 100 bytes
    struct Case {
        std::string bytes;
        std::string expected;
    };
    const Case cases[] = {
        {"glTF", "byte offset 0: not a .glb: 4 bytes is too short"},
        {wrongMagic, "byte offset 0: not a .glb: the file does not start with \"glTF\""},
        {version1, "byte offset 4: binary glTF version 1 is not supported"},
        {glbFile(json, 4000), "byte offset 8: the header says the file is 4000 bytes"},
        {glbFile(json) + "tail", "byte offset 8:"},
        {lyingChunk, ("byte offset " + std::to_string(12 + json.size()) + ": the chunk says it holds 100 bytes, but only 8 follow")},
        {glbFile(bin + json), "byte offset 16: the first chunk must be the JSON chunk"},
        {glbFile(json + json), "a second JSON chunk"},
        {glbFile(""), "byte offset 12: the file has no JSON chunk"},
        {glbFile(json + "abc"), "3 bytes left: too few for a chunk header"},
    };
    for (const Case& testCase : cases) {
        auto imported = parseGlb(testCase.bytes, "broken.glb");
        ASSERT_FALSE(imported.ok()) << testCase.expected;
        EXPECT_EQ(imported.error().where.file, "broken.glb");
        EXPECT_NE(imported.error().message.find(testCase.expected), std::string::npos) << imported.error().format();
    }
}

TEST(Glb, JsonErrorsAreLocatedInTheJsonChunk) {
    auto imported = parseGlb(glbFile(glbChunk(0x4E4F534Au, "{\"asset\": {\"version\": \"2.0\"},\n \"materials\": [{\"alphaMode\": 3}]}")),
                             "broken.glb");
    ASSERT_FALSE(imported.ok());
    EXPECT_EQ(imported.error().where.file, "broken.glb (JSON chunk)");
    EXPECT_EQ(imported.error().where.line, 2) << imported.error().format();
}

}  // namespace
}  // namespace glint
