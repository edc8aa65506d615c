// The environment precomputation on load, timed: reads an equirectangular EXR of the size asked
// for (written first, a smooth sky with a sun), then makes its irradiance map and GGX-prefiltered
// levels. usage: environment_prefilter WIDTH DIRECTORY. Prints milliseconds; not run by ctest.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include <OpenImageIO/imageio.h>

#include "environment/environment_source.h"

using namespace glint;

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: environment_prefilter WIDTH DIRECTORY\n");
        return 2;
    }
    const int width = std::atoi(argv[1]), height = width / 2;
    const std::string path = std::string(argv[2]) + "/prefilter_bench.exr";
    std::vector<float> texels(static_cast<size_t>(width) * height * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height});
            const float sun = 50.0f * std::exp(200.0f * (glm::dot(d, glm::normalize(glm::vec3(1, 1, 1))) - 1.0f));
            for (int c = 0; c < 3; ++c) texels[(static_cast<size_t>(y) * width + x) * 3 + c] = 0.5f + 0.4f * d.y + sun;
        }
    auto output = OIIO::ImageOutput::create(path);
    if (!output || !output->open(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::FLOAT)) ||
        !output->write_image(OIIO::TypeDesc::FLOAT, texels.data()) || !output->close()) {
        std::fprintf(stderr, "cannot write %s\n", path.c_str());
        return 2;
    }
    const auto start = std::chrono::steady_clock::now();
    auto image = readEquirectFile(path);
    if (!image) {
        std::fprintf(stderr, "%s\n", image.error().format().c_str());
        return 2;
    }
    const auto read = std::chrono::steady_clock::now();
    const auto map = makeEnvironmentMap(std::move(*image));
    const auto done = std::chrono::steady_clock::now();
    const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    std::printf("%dx%d: read and check %.0f ms, precompute (irradiance + %d prefiltered levels %dx%d, %d samples) %.0f ms\n",
                width, height, ms(start, read), kPrefilteredLevels, kPrefilteredWidth, kPrefilteredHeight,
                kPrefilterSamples, ms(read, done));
    return 0;
}
