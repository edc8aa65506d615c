// Text labels with stb_truetype (see text_label.h). Debian's libstb carries the implementation.
#include "image/text_label.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>

#include <stb/stb_truetype.h>

namespace glint {
namespace {

// Decodes UTF-8 into code points; a malformed byte becomes U+FFFD.
std::vector<int> decodeUtf8(const std::string& text) {
    std::vector<int> codepoints;
    for (size_t i = 0; i < text.size();) {
        const unsigned char lead = static_cast<unsigned char>(text[i]);
        const int length = lead < 0x80 ? 1 : (lead >> 5) == 0x6 ? 2 : (lead >> 4) == 0xE ? 3 : (lead >> 3) == 0x1E ? 4 : 0;
        if (length == 0 || i + length > text.size()) {
            codepoints.push_back(0xFFFD);
            ++i;
            continue;
        }
        int codepoint = length == 1 ? lead : lead & (0x3F >> (length - 1));
        for (int k = 1; k < length; ++k) codepoint = (codepoint << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
        codepoints.push_back(codepoint);
        i += length;
    }
    return codepoints;
}

}  // namespace

Result<LabelFont> LabelFont::load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return makeError("cannot open the font (is fonts-dejavu-core installed?)", {path});
    auto data = std::make_shared<const std::vector<unsigned char>>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
    auto info = std::make_shared<stbtt_fontinfo>();
    if (data->size() < 12 || stbtt_GetFontOffsetForIndex(data->data(), 0) < 0 ||
        !stbtt_InitFont(info.get(), data->data(), stbtt_GetFontOffsetForIndex(data->data(), 0)))
        return makeError("not a TrueType font", {path});
    LabelFont font;
    font.data_ = std::move(data);
    font.info_ = std::move(info);
    return font;
}

int LabelFont::measure(const std::string& text, float pixelHeight) const {
    const stbtt_fontinfo* info = info_.get();
    const float scale = stbtt_ScaleForPixelHeight(info, pixelHeight);
    float width = 0.0f;
    const std::vector<int> codepoints = decodeUtf8(text);
    for (size_t i = 0; i < codepoints.size(); ++i) {
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(info, codepoints[i], &advance, &bearing);
        width += advance * scale;
        if (i + 1 < codepoints.size()) width += scale * stbtt_GetCodepointKernAdvance(info, codepoints[i], codepoints[i + 1]);
    }
    return static_cast<int>(std::ceil(width));
}

void LabelFont::draw(DisplayImage& image, int left, int top, const std::string& text, float pixelHeight, glm::u8vec3 color,
                     int maxWidth) const {
    std::string shown = text;
    if (measure(shown, pixelHeight) > maxWidth) {
        // Cut whole code points from the end until the text and the ellipsis fit.
        while (!shown.empty() && measure(shown + "…", pixelHeight) > maxWidth) {
            while (!shown.empty() && (static_cast<unsigned char>(shown.back()) & 0xC0) == 0x80) shown.pop_back();
            if (!shown.empty()) shown.pop_back();  // the lead byte (or an ASCII character)
        }
        shown += "…";
    }
    const stbtt_fontinfo* info = info_.get();
    const float scale = stbtt_ScaleForPixelHeight(info, pixelHeight);
    int ascent = 0, descent = 0, lineGap = 0;
    stbtt_GetFontVMetrics(info, &ascent, &descent, &lineGap);
    const int baseline = top + static_cast<int>(std::lround(ascent * scale));
    float penX = static_cast<float>(left);
    const std::vector<int> codepoints = decodeUtf8(shown);
    for (size_t i = 0; i < codepoints.size(); ++i) {
        int glyphWidth = 0, glyphHeight = 0, offsetX = 0, offsetY = 0;
        const float shift = penX - std::floor(penX);
        unsigned char* coverage = stbtt_GetCodepointBitmapSubpixel(info, scale, scale, shift, 0.0f, codepoints[i], &glyphWidth,
                                                                   &glyphHeight, &offsetX, &offsetY);
        const int originX = static_cast<int>(std::floor(penX)) + offsetX, originY = baseline + offsetY;
        for (int y = 0; y < glyphHeight; ++y) {
            for (int x = 0; x < glyphWidth; ++x) {
                const int px = originX + x, py = originY + y;
                if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
                const int alpha = coverage[y * glyphWidth + x];
                uint8_t* pixel = &image.pixels[(static_cast<size_t>(py) * image.width + px) * 3];
                for (int c = 0; c < 3; ++c) pixel[c] = static_cast<uint8_t>((color[c] * alpha + pixel[c] * (255 - alpha) + 127) / 255);
            }
        }
        stbtt_FreeBitmap(coverage, nullptr);
        int advance = 0, bearing = 0;
        stbtt_GetCodepointHMetrics(info, codepoints[i], &advance, &bearing);
        penX += advance * scale;
        if (i + 1 < codepoints.size()) penX += scale * stbtt_GetCodepointKernAdvance(info, codepoints[i], codepoints[i + 1]);
    }
}

}  // namespace glint
