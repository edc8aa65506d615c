// Base64 (RFC 4648, standard alphabet, padded) for the data URIs of self-contained .gltf files.
// Encoding and strict decoding only; no line breaks, no URL-safe alphabet.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace glint {

std::string encodeBase64(const std::vector<uint8_t>& bytes);
// Nothing when `text` is not padded base64 of the standard alphabet.
std::optional<std::vector<uint8_t>> decodeBase64(std::string_view text);

}  // namespace glint
