// Frame timing for the benchmarks: one draw timed to glFinish, and the median of a series.
// Nothing else; the benchmarks interleave their cases themselves.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

#include <glad/gl.h>

namespace glint {

inline double medianMs(std::vector<double> times) {
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

template <typename Draw>
double timeFrame(Draw draw) {
    const auto start = std::chrono::steady_clock::now();
    draw();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace glint
