// Images stored inside a glTF file (see gltf_images.h).
#include "interchange/gltf_images.h"

#include "interchange/base64.h"
#include "interchange/glb.h"
#include "scene/json_object_reader.h"
#include "texture/texture_image.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"

namespace glint {
namespace {

using nlohmann::json;

// The MIME types glTF 2.0 allows for images (§5.18) and the file extension OpenImageIO reads them by.
const char* formatOf(const std::string& mimeType) {
    return mimeType == "image/png" ? "png" : mimeType == "image/jpeg" ? "jpg" : nullptr;
}

// `uri`'s bytes when it is a base64 data URI ("data:[MIME][;base64],DATA"), with its MIME type;
// nothing when it is not a data URI. Other data URIs and malformed base64 fail at `key`.
std::optional<EmbeddedImage> dataUri(const ObjectReader& reader, const std::string& key, const std::string& uri) {
    if (uri.rfind("data:", 0) != 0) return std::nullopt;
    const size_t comma = uri.find(',');
    const std::string header = uri.substr(5, comma == std::string::npos ? std::string::npos : comma - 5);
    const std::string base64Suffix = ";base64";
    if (comma == std::string::npos || header.size() < base64Suffix.size() ||
        header.compare(header.size() - base64Suffix.size(), base64Suffix.size(), base64Suffix) != 0)
        reader.fail(key, "a data URI must be base64 (\"data:MIME;base64,...\")");
    auto bytes = decodeBase64(std::string_view(uri).substr(comma + 1));
    if (!bytes) reader.fail(key, "the data URI is not valid base64 (RFC 4648, padded, no line breaks)");
    return EmbeddedImage{std::move(*bytes), header.substr(0, header.size() - base64Suffix.size())};
}

// The bytes of buffers[index]: a .glb's BIN chunk (buffer 0 without a "uri": viewed, not copied),
// or a data URI's or a file's beside the glTF (confined to its folder), held in `storage`.
// `what` names the bufferView in messages.
std::string_view bufferBytes(const GltfSource& source, const ObjectReader& view, size_t index, const std::string& what,
                             std::string& storage) {
    const json& root = source.document.root();
    if (!root.contains("buffers") || !root["buffers"].is_array() || index >= root["buffers"].size() || !root["buffers"][index].is_object())
        view.fail("buffer", "buffer " + std::to_string(index) + " does not exist");
    const json& buffer = root["buffers"][index];
    const std::string bufferName = what + "'s buffer " + std::to_string(index);
    ObjectReader reader(source.document, buffer, "/buffers/" + std::to_string(index), bufferName);
    if (!buffer.contains("uri")) {
        if (index != 0 || source.bin.data() == nullptr) reader.failHere(bufferName + ": it has no \"uri\" and is not the BIN chunk of a .glb");
        return source.bin;
    }
    if (!buffer["uri"].is_string()) reader.fail("uri", "expected a string");
    const std::string uri = buffer["uri"].get<std::string>();
    if (auto embedded = dataUri(reader, "uri", uri)) {
        storage.assign(embedded->bytes.begin(), embedded->bytes.end());
        return storage;
    }
    auto confined = confinedReference(uri, {source.file});
    if (!confined) reader.fail("uri", confined.error().message);
    auto bytes = readTextFile(confined->string());  // reads bytes as they are
    if (!bytes) reader.fail("uri", bytes.error().message);
    storage = std::move(*bytes);
    return storage;
}

// The bytes bufferViews[index] spans, checked against its buffer; `what` names the image in messages.
std::vector<uint8_t> bufferViewBytes(const GltfSource& source, const ObjectReader& image, size_t index, const std::string& what) {
    const json& root = source.document.root();
    if (!root.contains("bufferViews") || !root["bufferViews"].is_array() || index >= root["bufferViews"].size() ||
        !root["bufferViews"][index].is_object())
        image.fail("bufferView", "bufferView " + std::to_string(index) + " does not exist");
    const std::string pointer = "/bufferViews/" + std::to_string(index);
    const json& view = root["bufferViews"][index];
    const std::string viewName = what + "'s bufferView " + std::to_string(index);
    ObjectReader reader(source.document, view, pointer, viewName);
    if (!view.contains("buffer") || !view["buffer"].is_number_unsigned()) reader.failHere(viewName + ": a bufferView needs a \"buffer\" index");
    if (!view.contains("byteLength") || !view["byteLength"].is_number_unsigned()) reader.failHere(viewName + ": a bufferView needs a \"byteLength\"");
    const uint64_t offset = view.contains("byteOffset") && view["byteOffset"].is_number_unsigned() ? view["byteOffset"].get<uint64_t>() : 0;
    const uint64_t length = view["byteLength"].get<uint64_t>();
    std::string storage;
    const std::string_view buffer = bufferBytes(source, reader, view["buffer"].get<size_t>(), viewName, storage);
    if (offset > buffer.size() || length > buffer.size() - offset)
        reader.failHere(viewName + ": bytes " + std::to_string(offset) + " to " + std::to_string(offset + length) + " lie outside buffer " +
                        std::to_string(view["buffer"].get<size_t>()) + " (" + std::to_string(buffer.size()) + " bytes)");
    const std::string_view bytes = buffer.substr(offset, length);
    return {bytes.begin(), bytes.end()};
}

}  // namespace

std::optional<EmbeddedImage> embeddedGltfImage(const GltfSource& source, size_t index) {
    const json& image = source.document.root()["images"][index];
    const std::string what = "image " + std::to_string(index);
    ObjectReader reader(source.document, image, "/images/" + std::to_string(index), what);
    // The MIME type, from "mimeType" or else the data URI (`key` locates it), before any bytes are read.
    const auto knownType = [&](const std::string& key, const std::string& mimeType) {
        if (!formatOf(mimeType))
            reader.fail(key, "the image is of type \"" + mimeType + "\", which Glint does not read (glTF images are image/png or image/jpeg)");
        return mimeType;
    };
    const bool typed = image.contains("mimeType") && image["mimeType"].is_string();
    if (image.contains("mimeType") && !typed) reader.fail("mimeType", "expected a string");
    if (image.contains("uri")) {
        if (!image["uri"].is_string()) reader.fail("uri", "expected a string");
        auto embedded = dataUri(reader, "uri", image["uri"].get<std::string>());
        if (embedded)
            embedded->mimeType = typed ? knownType("mimeType", image["mimeType"].get<std::string>()) : knownType("uri", embedded->mimeType);
        return embedded;
    }
    if (!image.contains("bufferView")) reader.failHere(what + ": an image needs a \"uri\" or a \"bufferView\"");
    if (!image["bufferView"].is_number_unsigned()) reader.fail("bufferView", "expected the index of a bufferView");
    if (!typed) reader.failHere(what + ": an image in a bufferView needs a \"mimeType\" (image/png or image/jpeg)");
    const std::string mimeType = knownType("mimeType", image["mimeType"].get<std::string>());
    return EmbeddedImage{bufferViewBytes(source, reader, image["bufferView"].get<size_t>(), what), mimeType};
}

Result<std::shared_ptr<const TextureImage>> decodeEmbeddedGltfImage(const EmbeddedImage& image, const std::string& file,
                                                                    int index, TextureColorSpace colorSpace) {
    const std::string name = file + "#/images/" + std::to_string(index);
    auto decoded = decodeTextureImage(image.bytes, formatOf(image.mimeType), name, fileModificationTime(file), colorSpace);
    if (!decoded) return makeError("image " + std::to_string(index) + " (" + image.mimeType + ", " + std::to_string(image.bytes.size()) +
                                       " bytes inside the file): " + decoded.error().message,
                                   {file});
    return decoded;
}

Result<EmbeddedImage> readGltfImage(const std::string& file, int index) {
    auto bytes = readTextFile(file);  // reads bytes as they are
    if (!bytes) return bytes.error();
    std::string jsonText = *bytes;
    std::string_view bin;
    const bool binary = bytes->rfind("glTF", 0) == 0;
    if (binary) {
        auto chunks = glbChunks(*bytes, file);
        if (!chunks) return chunks.error();
        jsonText = std::move(chunks->json);
        bin = chunks->bin;
    }
    auto document = JsonDocument::parse(jsonText, binary ? file + " (JSON chunk)" : file);
    if (!document) return document.error();
    const json& root = document->root();
    if (index < 0 || !root.contains("images") || !root["images"].is_array() || static_cast<size_t>(index) >= root["images"].size() ||
        !root["images"][index].is_object())
        return makeError("the file has no image " + std::to_string(index) + " among its images", {file});
    try {
        auto embedded = embeddedGltfImage({*document, file, bin}, static_cast<size_t>(index));
        if (!embedded) return makeError("image " + std::to_string(index) + " is a file beside the glTF, not inside it", {file});
        return std::move(*embedded);
    } catch (const JsonReadError& error) {
        return error.diagnostic;
    }
}

Result<std::shared_ptr<const TextureImage>> loadGltfImage(const std::string& file, int index, TextureColorSpace colorSpace) {
    auto embedded = readGltfImage(file, index);
    if (!embedded) return embedded.error();
    return decodeEmbeddedGltfImage(*embedded, file, index, colorSpace);
}

Result<std::shared_ptr<const TextureImage>> loadMaterialTextureImage(const std::string& file, int gltfImage,
                                                                     TextureColorSpace colorSpace) {
    return gltfImage >= 0 ? loadGltfImage(file, gltfImage, colorSpace) : loadTextureImage(file, colorSpace);
}

}  // namespace glint
