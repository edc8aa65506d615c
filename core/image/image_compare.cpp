// Golden-image comparison (see image_compare.h).
#include "image/image_compare.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace glint {

std::string CompareResult::summary() const {
    if (!sizesMatch) return "image sizes differ";
    char text[160];
    std::snprintf(text, sizeof text, "%ld of %ld pixels differ by more than the tolerance (%.3f%%), max difference %d/255",
                  failingPixels, totalPixels, 100.0 * failingFraction(), maxChannelDifference);
    return text;
}

CompareResult compareImages(const DisplayImage& actual, const DisplayImage& expected, CompareTolerance tolerance) {
    CompareResult result;
    result.totalPixels = static_cast<long>(expected.width) * expected.height;
    if (actual.width != expected.width || actual.height != expected.height) {
        result.sizesMatch = false;
        result.failingPixels = result.totalPixels;
        return result;
    }
    // The largest channel difference between actual pixel `pixel` and expected pixel `other`.
    auto worstChannel = [&](long pixel, long other) {
        int worst = 0;
        for (int c = 0; c < 3; ++c)
            worst = std::max(worst, std::abs(int(actual.pixels[pixel * 3 + c]) - int(expected.pixels[other * 3 + c])));
        return worst;
    };
    const int reach = tolerance.allowOnePixelShift ? 1 : 0;
    for (int y = 0; y < expected.height; ++y) {
        for (int x = 0; x < expected.width; ++x) {
            const long pixel = static_cast<long>(y) * expected.width + x;
            int best = worstChannel(pixel, pixel);
            for (int dy = -reach; dy <= reach && best > tolerance.channelTolerance; ++dy)
                for (int dx = -reach; dx <= reach; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= expected.width || ny >= expected.height) continue;
                    best = std::min(best, worstChannel(pixel, static_cast<long>(ny) * expected.width + nx));
                }
            result.maxChannelDifference = std::max(result.maxChannelDifference, best);
            if (best > tolerance.channelTolerance) ++result.failingPixels;
        }
    }
    result.passed = result.failingFraction() <= tolerance.failingFraction;
    return result;
}

DisplayImage differenceImage(const DisplayImage& actual, const DisplayImage& expected, int gain) {
    if (actual.width != expected.width || actual.height != expected.height) return {};
    DisplayImage difference(actual.width, actual.height);
    for (size_t i = 0; i < difference.pixels.size(); ++i)
        difference.pixels[i] = static_cast<uint8_t>(std::min(255, gain * std::abs(int(actual.pixels[i]) - int(expected.pixels[i]))));
    return difference;
}

}  // namespace glint
