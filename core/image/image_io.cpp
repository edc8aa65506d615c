// Image files through OpenImageIO (see image_io.h).
#include "image/image_io.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <algorithm>
#include <vector>

#include "util/file_io.h"
#include "util/text.h"

namespace glint {
namespace {

// OpenImageIO's writers do not all check their own writes (its PNG writer leaves an empty file on
// a full disk and reports success), so an image is encoded in memory where the format's writer
// takes an IOProxy (PNG, EXR, ...) and saved by writeFileAtomically (util/file_io.h), which checks
// every byte. A format that cannot be encoded in memory is written to a temporary beside `path`,
// read back whole to prove it complete, and renamed over `path`.
template <class Pixel>
Status writeImage(const std::string& path, int width, int height, const Pixel* pixels, OIIO::TypeDesc type, int pngCompression = 6) {
    OIIO::ImageSpec spec(width, height, 3, type);
    if (type == OIIO::TypeDesc::FLOAT) spec.attribute("compression", "zip");
    spec.attribute("png:compressionLevel", pngCompression);
    // Writes the image to `file`, or into `memory` when given.
    const auto encode = [&](const std::string& file, OIIO::Filesystem::IOProxy* memory) -> Status {
        auto output = OIIO::ImageOutput::create(path);
        if (!output) return makeError("cannot write this image format: " + OIIO::geterror(), {path});
        if (memory && !output->set_ioproxy(memory)) return makeError("cannot encode in memory: " + output->geterror(), {path});
        if (!output->open(file, spec)) return makeError("cannot write: " + output->geterror(), {path});
        const bool written = output->write_image(type, pixels);
        if (!output->close() || !written) return makeError("write failed: " + output->geterror(), {path});
        return success();
    };
    const auto probe = OIIO::ImageOutput::create(path);
    if (!probe) return makeError("cannot write this image format: " + OIIO::geterror(), {path});
    if (probe->supports("ioproxy")) {
        std::vector<unsigned char> bytes;
        OIIO::Filesystem::IOVecOutput memory(bytes);
        if (Status encoded = encode(path, &memory); !encoded) return encoded;
        return writeFileAtomically(path, std::string(bytes.begin(), bytes.end()));
    }
    return replaceFileAtomically(path, [&](const std::string& temporary) -> Status {
        if (Status written = encode(temporary, nullptr); !written) return written;
        auto input = OIIO::ImageInput::open(temporary);
        std::vector<float> texels(static_cast<size_t>(width) * height * 3);
        if (!input || !input->read_image(0, 0, 0, 3, OIIO::TypeDesc::FLOAT, texels.data()))
            return makeError("write failed: the image written cannot be read back whole (is the disk full?)");
        return success();
    });
}

// An image file as RGB pixels of `Image` (RadianceImage or DisplayImage): grey repeats its one
// channel, channels past the third are dropped.
template <class Image>
Result<Image> readImage(const std::string& path, OIIO::TypeDesc type) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) return makeError("cannot read image: " + OIIO::geterror(), {path});
    const OIIO::ImageSpec& spec = input->spec();
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    if (image.width <= 0 || image.height <= 0 || spec.nchannels < 1)
        return makeError("image has no pixels", {path});
    const size_t count = static_cast<size_t>(image.width) * image.height;
    decltype(image.pixels) all(count * spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, type, all.data()))
        return makeError("cannot read image: " + input->geterror(), {path});
    image.pixels.resize(count * 3);
    for (size_t i = 0; i < count; ++i)
        for (int c = 0; c < 3; ++c) image.pixels[i * 3 + c] = all[i * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return image;
}

}  // namespace

bool isFloatImagePath(const std::string& path) {
    const std::string extension = lowerExtension(path);
    return extension == "exr" || extension == "hdr";
}

Status writeRadianceImage(const RadianceImage& image, const std::string& path) {
    return writeImage(path, image.width, image.height, image.pixels.data(), OIIO::TypeDesc::FLOAT);
}

Status writeDisplayImage(const DisplayImage& image, const std::string& path, int pngCompression) {
    return writeImage(path, image.width, image.height, image.pixels.data(), OIIO::TypeDesc::UINT8, pngCompression);
}

Result<RadianceImage> readRadianceImage(const std::string& path) { return readImage<RadianceImage>(path, OIIO::TypeDesc::FLOAT); }

Result<DisplayImage> readDisplayImage(const std::string& path) { return readImage<DisplayImage>(path, OIIO::TypeDesc::UINT8); }

}  // namespace glint
