// libFuzzer target: MERL .binary validation must refuse any malformed bytes with a message, and
// lookups must stay finite for any pair of directions (fuzzed as six floats) on a valid table.
// Full 35 MB files are beyond -max_len, so the table itself is built once, not fuzzed.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "interchange/merl.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    glint::fuzz::readOrExplained(glint::parseMerl(glint::fuzz::text(data, size), "fuzz.binary"));
    static const glint::MerlTable table = glint::parseMerl(glint::makeConstantMerl(glm::vec3(0.1f, 0.2f, 0.3f)), "t").value();
    if (size >= 6 * sizeof(float)) {
        float raw[6];
        std::memcpy(raw, data, sizeof raw);
        const glm::vec3 wi(raw[0], raw[1], raw[2]), wo(raw[3], raw[4], raw[5]);
        const float lengthIn = glm::length(wi), lengthOut = glm::length(wo);
        if (!(lengthIn > 1e-3f && lengthOut > 1e-3f && std::isfinite(lengthIn) && std::isfinite(lengthOut))) return 0;
        const glint::ShadingFrame frame;
        for (const glm::vec3 value : {glint::lookupMerlNearest(table, wi / lengthIn, wo / lengthOut, frame),
                                      glint::lookupMerlTrilinear(table, wi / lengthIn, wo / lengthOut, frame)})
            for (int c = 0; c < 3; ++c)
                if (!std::isfinite(value[c]) || value[c] < 0.0f) __builtin_trap();
    }
    return 0;
}
