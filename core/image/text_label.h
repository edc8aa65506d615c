// Text labels drawn into 8-bit images with stb_truetype (anti-aliased coverage blended over the
// pixels), for contact sheets. One line of UTF-8 text; no shaping, wrapping or GL.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "util/diagnostic.h"

struct stbtt_fontinfo;

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
    // The font file and stb_truetype's view into it (which points into the file's bytes);
    // shared, so copies of a LabelFont stay valid.
    std::shared_ptr<const std::vector<unsigned char>> data_;
    std::shared_ptr<stbtt_fontinfo> info_;
};

}  // namespace glint
