// Image files through OpenImageIO: EXR keeps linear radiance as float; PNG (and other 8-bit
// formats) hold display-encoded values. Errors name the file. Writes are atomic (util/file_io.h):
// a temporary beside the file, renamed over it, so a full disk never leaves half an image.
#pragma once

#include <string>

#include "image/image.h"
#include "util/diagnostic.h"

namespace glint {

Status writeRadianceImage(const RadianceImage& image, const std::string& path);
// `pngCompression` is zlib's level for PNG files: 0 (fastest, largest) to 9; OpenImageIO's default 6.
Status writeDisplayImage(const DisplayImage& image, const std::string& path, int pngCompression = 6);
Result<RadianceImage> readRadianceImage(const std::string& path);
Result<DisplayImage> readDisplayImage(const std::string& path);

// True when the path's extension names a float format (.exr, .hdr).
bool isFloatImagePath(const std::string& path);

}  // namespace glint
