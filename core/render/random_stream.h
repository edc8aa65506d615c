// A small deterministic random-number stream for Monte-Carlo rendering: PCG32 (O'Neill, "PCG: A
// Family of Simple Fast Space-Efficient Statistically Good Algorithms for Random Number
// Generation", 2014), one independent stream per (seed, pass, pixel), so a picture does not
// depend on how its rows are split among threads. Not for anything that needs secrecy.
#pragma once

#include <cstdint>

#include <glm/glm.hpp>

namespace glint {

class RandomStream {
public:
    // The stream `sequence` (e.g. a pixel's index) of the generator started from `seed`.
    RandomStream(uint64_t seed, uint64_t sequence) : increment_((sequence << 1u) | 1u) {
        nextWord();
        state_ += seed;
        nextWord();
    }

    // Uniform in [0, 1): the top 24 bits, so that the float never rounds up to 1.
    float uniform() { return static_cast<float>(nextWord() >> 8u) * 0x1p-24f; }
    glm::vec2 uniform2() {
        const float first = uniform();
        return {first, uniform()};
    }

private:
    uint32_t nextWord() {
        const uint64_t previous = state_;
        state_ = previous * 6364136223846793005ull + increment_;
        const uint32_t xorShifted = static_cast<uint32_t>(((previous >> 18u) ^ previous) >> 27u);
        const uint32_t rotation = static_cast<uint32_t>(previous >> 59u);
        return (xorShifted >> rotation) | (xorShifted << ((32u - rotation) & 31u));
    }

    uint64_t state_ = 0;
    uint64_t increment_;
};

}  // namespace glint
