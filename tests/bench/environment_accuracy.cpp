// Environment light against its Monte-Carlo ground truth, the table of issue 21: for each map
// (smooth sky, small bright light, the shipped studio HDRI, the built-in studio) and material (Lambert ρ 0.8 and an
// F = 1 GGX conductor at α 0.05 … 1; with --all every model with an environment hook), the
// preview's image-based lighting (the CPU twin of the GPU's, equal to it to 79 dB and better)
// against the CPU reference's Monte-Carlo integral: PSNR over the sphere's interior and the ratio
// of means, and the reference's own noise (two seeds: PSNR between them − 3 dB).
// usage: environment_accuracy [--samples N] [--size S] [--all | --model ID | --material NAME] (NAME as the
// tests name it, e.g. "cook_torrance beckmann smith α 0.5"). Not run by ctest.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "environment/environment_source.h"
#include "environment_accuracy_support.h"
#include "render/reference_renderer.h"

using namespace glint;

int main(int argc, char** argv) {
    int samples = 4096, size = 64;
    bool all = false;
    std::string only;      // a model id: that model alone
    std::string material;  // a material's name: that material alone
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--samples" && i + 1 < argc) samples = std::atoi(argv[++i]);
        else if (argument == "--size" && i + 1 < argc) size = std::atoi(argv[++i]);
        else if (argument == "--all") all = true;
        else if (argument == "--model" && i + 1 < argc) only = argv[++i];
        else if (argument == "--material" && i + 1 < argc) material = argv[++i];
        else {
            std::fprintf(stderr, "usage: environment_accuracy [--samples N] [--size S] [--all | --model ID | --material NAME]\n");
            return 2;
        }
    }
    auto maps = test::accuracyMaps(std::string(GLINT_TEST_DATA_DIR) + "/environments/studio_small_01_256.exr");
    maps.push_back({"built-in studio", {}});  // the default stage's light (not one of the tests' maps)
    maps.back().environment.kind = EnvironmentKind::Studio;
    (void)loadEnvironment(maps.back().environment);
    for (const auto& map : maps)
        if (!map.environment.enabled()) {
            std::fprintf(stderr, "cannot load the map '%s'\n", map.name.c_str());
            return 2;
        }
    std::printf("%dx%d, %d samples per pixel; cells: preview dB, ratio (reference noise dB)\n", size, size, samples);
    std::printf("%-28s", "material");
    for (const auto& map : maps) std::printf(" | %-24s", map.name.c_str());
    std::printf("\n");
    const auto start = std::chrono::steady_clock::now();
    bool any = false;
    for (const auto& entry : test::accuracyMaterials()) {
        const BrdfModel model = entry.material.analytic()->model;
        if (!material.empty() ? material != entry.name
            : !only.empty() ? only != modelInfo(model).id
                            : !all && model != BrdfModel::Lambert && model != BrdfModel::CookTorrance)
            continue;
        any = true;
        std::printf("%-28s", entry.name.c_str());
        for (const auto& map : maps) {
            const Scene scene = test::accuracyScene(entry.material, map.environment);
            const RadianceImage preview = renderReference(scene, size, size);
            const RadianceImage truth = renderReference(scene, size, size, {true, samples, 0});
            const RadianceImage again = renderReference(scene, size, size, {true, samples, 1});
            const test::Accuracy accuracy = test::measureAccuracy(preview, truth);
            const double noise = test::measureAccuracy(again, truth).psnr + 3.0103;
            std::printf(" | %5.1f dB, %5.3f (%4.1f) ", accuracy.psnr, accuracy.ratio, noise);
            std::fflush(stdout);
        }
        std::printf("\n");
    }
    if (!any) {
        std::fprintf(stderr, "no material matches '%s'\n", !material.empty() ? material.c_str() : only.c_str());
        return 2;
    }
    std::printf("%.0f s\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
}
