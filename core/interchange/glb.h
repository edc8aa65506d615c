// glTF 2.0 binary files (.glb, glTF 2.0 spec §4.4 "Binary glTF Layout"): the 12-byte header
// (magic "glTF", version 2, total length) and the chunks (JSON first, then an optional BIN),
// each length checked against the file with its byte offset. The JSON chunk is read for
// materials and lights as a .gltf is (gltf.h), the BIN chunk for the images it holds (gltf_images.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "interchange/imported.h"

namespace glint {

struct GlbChunks {
    std::string json;
    std::string_view bin;  // into the bytes given; empty when the file has no BIN chunk
};
// The chunks, or an error naming the byte offset where the layout goes wrong.
Result<GlbChunks> glbChunks(std::string_view bytes, const std::string& file);
// Materials and lights of a .glb; JSON errors are located in the JSON chunk as
// "FILE (JSON chunk):line:column".
Result<ImportedFile> parseGlb(std::string_view bytes, const std::string& file);
Result<ImportedFile> loadGlb(const std::string& path);
// The JSON chunk of the .glb at `path`, read without the rest of the file; none when the file
// does not start as a .glb does (loadGlb says why).
std::optional<std::string> readGlbJsonChunk(const std::string& path);

}  // namespace glint
