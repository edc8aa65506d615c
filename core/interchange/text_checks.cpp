// UTF-8 validation (see text_checks.h), after the well-formed table in Unicode §3.9, table 3-7.
#include "interchange/text_checks.h"

namespace glint {

std::optional<TextPosition> findInvalidUtf8(std::string_view text) {
    int line = 1;
    size_t i = 0;
    while (i < text.size()) {
        const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
        const unsigned char lead = byte(i);
        if (lead == '\n') ++line;
        if (lead < 0x80) { ++i; continue; }
        int length = 0;
        unsigned char low = 0x80, high = 0xBF;  // the allowed range of the second byte
        if (lead >= 0xC2 && lead <= 0xDF) length = 2;
        else if (lead >= 0xE0 && lead <= 0xEF) {
            length = 3;
            if (lead == 0xE0) low = 0xA0;        // no overlongs
            if (lead == 0xED) high = 0x9F;       // no surrogates
        } else if (lead >= 0xF0 && lead <= 0xF4) {
            length = 4;
            if (lead == 0xF0) low = 0x90;
            if (lead == 0xF4) high = 0x8F;       // nothing above U+10FFFF
        } else {
            return TextPosition{i, line};
        }
        if (i + length > text.size()) return TextPosition{i, line};
        if (byte(i + 1) < low || byte(i + 1) > high) return TextPosition{i, line};
        for (int k = 2; k < length; ++k)
            if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return TextPosition{i, line};
        i += length;
    }
    return std::nullopt;
}

}  // namespace glint
