// Text labels drawn into 8-bit images with stb_truetype (anti-aliased coverage blended over the
// pixels), for contact sheets. One line of UTF-8 text; no shaping, wrapping or GL.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "util/diagnostic.h"

namespace glint {

inline constexpr const char* kDefaultFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

class LabelFont {
public:
    // Reads a TrueType file (Debian's fonts-dejavu-core by default).
    static Result<LabelFont> load(const std::string& path = kDefaultFontPath);

    // Width in pixels of `text` at `pixelHeight` (ascent to descent).
    int measure(const std::string& text, float pixelHeight) const;
    // Draws `text` with its top-left corner at (left, top), clipped to the image and cut with
    // "…" when wider than `maxWidth` pixels. `color` is 8-bit display RGB.
    void draw(DisplayImage& image, int left, int top, const std::string& text, float pixelHeight, glm::u8vec3 color,
              int maxWidth) const;

private:
    std::vector<unsigned char> data_;  // the font file; stb_truetype reads it in place
    std::vector<unsigned char> info_;  // an stbtt_fontinfo, kept opaque so this header needs no stb
};

}  // namespace glint
