// Binary glTF (see glb.h). Layout (glTF 2.0 §4.4): uint32 magic 0x46546C67 ("glTF"), uint32
// version, uint32 length of the whole file; then chunks of uint32 chunkLength, uint32 chunkType
// ("JSON" 0x4E4F534A, "BIN\0" 0x004E4942, others ignored), chunkLength bytes of data. All little-endian.
#include "interchange/glb.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "interchange/gltf.h"
#include "util/file_io.h"

namespace glint {
namespace {

constexpr uint32_t kGlbMagic = 0x46546C67, kJsonChunk = 0x4E4F534A, kBinChunk = 0x004E4942;
constexpr size_t kGlbHeaderBytes = 12, kChunkHeaderBytes = 8;

uint32_t readLittleEndian32(std::string_view bytes, size_t offset) {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + offset);
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

Diagnostic atOffset(const std::string& file, size_t offset, const std::string& message) {
    return makeError("byte offset " + std::to_string(offset) + ": " + message, {file});
}

}  // namespace

Result<GlbChunks> glbChunks(std::string_view bytes, const std::string& file) {
    if (bytes.size() < kGlbHeaderBytes)
        return atOffset(file, 0, "not a .glb: " + std::to_string(bytes.size()) + " bytes is too short for the 12-byte header");
    if (readLittleEndian32(bytes, 0) != kGlbMagic) return atOffset(file, 0, "not a .glb: the file does not start with \"glTF\"");
    if (const uint32_t version = readLittleEndian32(bytes, 4); version != 2)
        return atOffset(file, 4, "binary glTF version " + std::to_string(version) + " is not supported (Glint reads version 2)");
    if (const uint32_t length = readLittleEndian32(bytes, 8); length != bytes.size())
        return atOffset(file, 8, "the header says the file is " + std::to_string(length) + " bytes, but it is " +
                                     std::to_string(bytes.size()) + (length > bytes.size() ? " (truncated)" : " (trailing data)"));
    GlbChunks chunks;
    bool sawJson = false, sawBin = false;
    for (size_t offset = kGlbHeaderBytes; offset < bytes.size();) {
        if (bytes.size() - offset < kChunkHeaderBytes)
            return atOffset(file, offset, std::to_string(bytes.size() - offset) + " bytes left: too few for a chunk header (8 bytes)");
        const uint32_t length = readLittleEndian32(bytes, offset), type = readLittleEndian32(bytes, offset + 4);
        const size_t dataStart = offset + kChunkHeaderBytes;
        if (length > bytes.size() - dataStart)
            return atOffset(file, offset, "the chunk says it holds " + std::to_string(length) + " bytes, but only " +
                                              std::to_string(bytes.size() - dataStart) + " follow");
        if (!sawJson && type != kJsonChunk) return atOffset(file, offset + 4, "the first chunk must be the JSON chunk");
        if (type == kJsonChunk) {
            if (sawJson) return atOffset(file, offset + 4, "a second JSON chunk (a .glb has exactly one)");
            sawJson = true;
            chunks.json.assign(bytes.data() + dataStart, length);
        } else if (type == kBinChunk) {
            if (sawBin) return atOffset(file, offset + 4, "a second BIN chunk (a .glb has at most one)");
            sawBin = true;
            chunks.bin = bytes.substr(dataStart, length);
        }  // chunks of other types are skipped, as the specification asks
        offset = dataStart + length;
    }
    if (!sawJson) return atOffset(file, kGlbHeaderBytes, "the file has no JSON chunk");
    return chunks;
}

Result<ImportedFile> parseGlb(std::string_view bytes, const std::string& file) {
    auto chunks = glbChunks(bytes, file);
    if (!chunks) return chunks.error();
    return parseGlbJson(chunks->json, file, chunks->bin);
}

Result<ImportedFile> loadGlb(const std::string& path) {
    auto bytes = readTextFile(path);  // reads bytes as they are
    if (!bytes) return bytes.error();
    return parseGlb(*bytes, path);
}

std::optional<std::string> readGlbJsonChunk(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string headers(kGlbHeaderBytes + kChunkHeaderBytes, '\0');
    if (!in.read(headers.data(), static_cast<std::streamsize>(headers.size()))) return std::nullopt;
    if (readLittleEndian32(headers, 0) != kGlbMagic || readLittleEndian32(headers, 16) != kJsonChunk) return std::nullopt;
    const uint32_t length = readLittleEndian32(headers, 12);
    std::error_code error;
    if (length > std::filesystem::file_size(path, error) || error) return std::nullopt;  // a damaged length
    std::string json(length, '\0');
    if (!in.read(json.data(), length)) return std::nullopt;
    return json;
}

}  // namespace glint
