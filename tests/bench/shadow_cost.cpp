// Shadow cost benchmark: the frame time (radiance + display pass, OSMesa) of the default scene
// with its key light's shadow off, on with the map cached (camera or material edits), and on with
// the map drawn again every frame (the light moving). Prints medians and their ratios to "off";
// short blocks interleaved so that machine noise hits all three alike. Not run by ctest.
// usage: shadow_cost [FRAMES] [WIDTH HEIGHT]   (DISPLAY unset; LP_NUM_THREADS as you like)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "runtime/headless.h"

namespace glint {
namespace {

double medianMs(std::vector<double> times) {
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

int run(int frames, int width, int height) {
    auto headless = HeadlessRenderer::create();
    if (!headless) {
        std::fprintf(stderr, "shadow_cost: %s\n", headless.error().format().c_str());
        return 2;
    }
    Scene shadowed = defaultScene(), unshadowed = defaultScene(), moving = defaultScene();
    shadowed.lights[0].castsShadows = moving.lights[0].castsShadows = true;  // the key light
    std::vector<double> off, cached, redrawn;
    const auto timeRender = [&](const Scene& scene) {
        const auto start = std::chrono::steady_clock::now();
        auto images = (*headless)->render(scene, width, height);  // reads back: waits for the GPU
        if (!images) std::fprintf(stderr, "shadow_cost: %s\n", images.error().format().c_str());
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    };
    // Rounds of three short blocks (off, cached, redrawn), so that machine noise hits all three
    // alike; each block starts with an untimed frame that leaves the cache as the block needs it.
    constexpr int kBlock = 3;
    long long cachedMapPasses = 0;
    int step = 0;
    for (int round = 0; round * kBlock < frames; ++round) {
        timeRender(unshadowed);
        for (int i = 0; i < kBlock; ++i) off.push_back(timeRender(unshadowed));
        timeRender(shadowed);
        const long long before = (*headless)->renderer().shadowMapRenders();
        for (int i = 0; i < kBlock; ++i) cached.push_back(timeRender(shadowed));
        cachedMapPasses += (*headless)->renderer().shadowMapRenders() - before;
        for (int i = 0; i <= kBlock; ++i) {
            moving.lights[0].direction.x = -0.5f + 0.001f * static_cast<float>(++step);  // a new map each frame
            const double milliseconds = timeRender(moving);
            if (i > 0) redrawn.push_back(milliseconds);
        }
    }
    const double offMs = medianMs(off), cachedMs = medianMs(cached), redrawnMs = medianMs(redrawn);
    std::printf("default scene %dx%d, median of %d frames (%s)\n", width, height, frames,
                (*headless)->renderer().description().c_str());
    std::printf("  shadows off:             %8.2f ms\n", offMs);
    std::printf("  shadow on, map cached:   %8.2f ms  (x%.3f)\n", cachedMs, cachedMs / offMs);
    std::printf("  shadow on, map redrawn:  %8.2f ms  (x%.3f)\n", redrawnMs, redrawnMs / offMs);
    std::printf("  shadow-map passes during the cached frames: %lld\n", cachedMapPasses);
    return 0;
}

}  // namespace
}  // namespace glint

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    const int width = argc > 3 ? std::max(1, std::atoi(argv[2])) : 960;
    const int height = argc > 3 ? std::max(1, std::atoi(argv[3])) : 720;
    return glint::run(frames, width, height);
}
