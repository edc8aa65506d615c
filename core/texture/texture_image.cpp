// Image textures through OpenImageIO (see texture_image.h).
#include "texture/texture_image.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <new>
#include <string>
#include <tuple>

#include "display/display_chain.h"
#include "util/file_io.h"
#include "util/text.h"

namespace glint {
namespace {

using CacheKey = std::tuple<std::string, long long, TextureColorSpace>;

std::mutex cacheMutex;
std::map<CacheKey, std::weak_ptr<const TextureImage>> cache;  // weak: unused images are freed

// The image cached under `key`, else `decodeImage()`'s, cached from then on.
template <class Decode>
Result<std::shared_ptr<const TextureImage>> cached(const CacheKey& key, Decode decodeImage) {
    {
        std::lock_guard lock(cacheMutex);
        if (auto found = cache.find(key); found != cache.end())
            if (auto image = found->second.lock()) return image;
    }
    auto decoded = decodeImage();
    if (!decoded) return decoded.error();
    std::lock_guard lock(cacheMutex);
    cache[key] = *decoded;
    return decoded;
}

// OpenImageIO's errors can run to several lines (each library's own account): the first says it.
std::string firstLine(const std::string& text) { return text.substr(0, text.find('\n')); }

// Decodes the opened `input`; `path` names the image (a file, or an image inside one).
Result<std::shared_ptr<const TextureImage>> decode(std::unique_ptr<OIIO::ImageInput> input, const std::string& path,
                                                   long long modifiedAt, TextureColorSpace colorSpace) {
    if (!input) return makeError("cannot read texture image: " + firstLine(OIIO::geterror()), {path});
    const OIIO::ImageSpec spec = input->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.nchannels < 1)
        return makeError("texture image has no pixels (" + std::to_string(spec.width) + "×" +
                             std::to_string(spec.height) + ")", {path});
    const std::string size = std::to_string(spec.width) + "×" + std::to_string(spec.height);
    if (spec.width > kMaxTextureSize || spec.height > kMaxTextureSize)
        return makeError("texture image is " + size + " texels, larger than Glint's limit of " + std::to_string(kMaxTextureSize) +
                             " a side (OpenGL 4.1's least GL_MAX_TEXTURE_SIZE); the texture is refused: scale the image down",
                         {path});
    const int channels = spec.nchannels;
    std::vector<float> all;
    auto image = std::make_shared<TextureImage>();
    try {
        all.resize(static_cast<size_t>(spec.width) * spec.height * channels);
        image->rgba.resize(static_cast<size_t>(spec.width) * spec.height * 4);
    } catch (const std::bad_alloc&) {
        const double gibibytes = static_cast<double>(spec.width) * spec.height * (channels + 4) * sizeof(float) / (1 << 30);
        return makeError("texture image is " + size + " texels: decoding it needs " + formatNumber(gibibytes, "%.1f") +
                             " GiB of memory (linear float texels), more than is free; scale the image down",
                         {path});
    }
    if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, all.data()))
        return makeError("texture image is truncated or corrupt: " + firstLine(input->geterror()), {path});
    image->path = path;
    image->modifiedAt = modifiedAt;
    image->colorSpace = colorSpace;
    image->width = spec.width;
    image->height = spec.height;
    // Grey images fill r, g and b; a missing alpha is 1. Rows are flipped to bottom-up.
    for (int y = 0; y < spec.height; ++y) {
        for (int x = 0; x < spec.width; ++x) {
            const float* source = &all[(static_cast<size_t>(y) * spec.width + x) * channels];
            float* target = &image->rgba[(static_cast<size_t>(spec.height - 1 - y) * spec.width + x) * 4];
            for (int c = 0; c < 4; ++c) {
                float value = c < 3 ? source[channels >= 3 ? c : 0] : (channels == 4 || channels == 2 ? source[channels - 1] : 1.0f);
                if (!std::isfinite(value))
                    return makeError("texture image has a non-finite value (NaN or infinity) at texel (" +
                                         std::to_string(x) + ", " + std::to_string(y) + ")", {path});
                if (c < 3 && colorSpace == TextureColorSpace::Srgb) value = decodeSrgb(value);
                target[c] = value;
            }
        }
    }
    return std::shared_ptr<const TextureImage>(std::move(image));
}

}  // namespace

Result<std::shared_ptr<const TextureImage>> loadTextureImage(const std::string& path, TextureColorSpace colorSpace) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        return makeError("texture image file not found", {path});
    const long long modifiedAt = fileModificationTime(path);
    return cached({path, modifiedAt, colorSpace}, [&] { return decode(OIIO::ImageInput::open(path), path, modifiedAt, colorSpace); });
}

Result<std::shared_ptr<const TextureImage>> decodeTextureImage(std::span<const uint8_t> encoded, const std::string& format,
                                                               const std::string& name, long long modifiedAt,
                                                               TextureColorSpace colorSpace) {
    // Keyed by the bytes too: a name without a file (text parsed in memory) may hold other bytes each time.
    const std::string_view bytes(reinterpret_cast<const char*>(encoded.data()), encoded.size());
    const std::string key = name + "@" + std::to_string(std::hash<std::string_view>{}(bytes)) + "/" + std::to_string(bytes.size());
    return cached({key, modifiedAt, colorSpace}, [&] {
        // OpenImageIO picks the reader by the name's extension and reads the bytes through the proxy.
        OIIO::Filesystem::IOMemReader reader(encoded.data(), encoded.size());
        return decode(OIIO::ImageInput::open("image." + format, nullptr, &reader), name, modifiedAt, colorSpace);
    });
}

}  // namespace glint
