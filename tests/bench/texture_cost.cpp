// Texture cost benchmark: the radiance pass of a 1280×720 frame filled by a Cook-Torrance (GGX)
// sphere under 2 lights, untextured, with procedural marble albedo + wood roughness, and with a
// 1024² image albedo (anisotropic) + image roughness + a normal map; interleaved frame by frame,
// medians and ratios to the untextured sphere. Writes its images to a temporary folder. Not run by ctest.
// usage: texture_cost [FRAMES]   (DISPLAY unset)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "runtime/headless.h"
#include "frame_timing.h"
#include "image/image_io.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

constexpr int kWidth = 1280, kHeight = 720;

Scene sphereScene(const std::string& directory, const std::string& textures) {
    const std::string text = R"({"format": "glint-scene", "version": 1,
      "camera": {"position": [0, 0, 2.2], "target": [0, 0, 0], "up": [0, 1, 0], "fov_degrees": 40},
      "lights": [{"type": "directional", "direction": [-0.3, -0.5, -1], "irradiance": 3},
                 {"type": "point", "position": [2, 2, 3], "power": 300}],
      "materials": [{"name": "m", "model": "cook_torrance", "distribution": "ggx", "roughness": 0.3)" +
                             (textures.empty() ? "" : ", \"textures\": " + textures) + R"(}],
      "objects": [{"shape": "sphere", "center": [0, 0, 0], "radius": 1, "material": "m"}]})";
    auto scene = parseScene(text, directory + "/bench.json");
    if (!scene) {
        std::fprintf(stderr, "texture_cost: %s\n", scene.error().format().c_str());
        std::exit(1);
    }
    return *scene;
}

int run(int frames) {
    const std::string directory = (std::filesystem::temp_directory_path() / "glint_texture_cost").string();
    std::filesystem::create_directories(directory);
    DisplayImage image(1024, 1024), normals(1024, 1024);
    for (int y = 0; y < 1024; ++y)
        for (int x = 0; x < 1024; ++x) {
            uint8_t* p = &image.pixels[(y * 1024 + x) * 3];
            p[0] = static_cast<uint8_t>(x / 4), p[1] = static_cast<uint8_t>(y / 4), p[2] = static_cast<uint8_t>((x ^ y) & 255);
            uint8_t* n = &normals.pixels[(y * 1024 + x) * 3];
            n[0] = static_cast<uint8_t>(128 + 60 * std::sin(x * 0.05)), n[1] = 128, n[2] = 230;
        }
    if (!writeDisplayImage(image, directory + "/albedo.png").ok() || !writeDisplayImage(normals, directory + "/normal.png").ok())
        return 1;
    auto headless = HeadlessRenderer::create();
    if (!headless) {
        std::fprintf(stderr, "texture_cost: %s\n", headless.error().format().c_str());
        return 1;
    }
    Renderer& renderer = (*headless)->renderer();
    const Scene scenes[] = {
        sphereScene(directory, ""),
        sphereScene(directory, R"({"diffuse_albedo": {"type": "marble", "a": [0.9, 0.88, 0.8], "b": [0.15, 0.12, 0.1], "frequency": 3},
                                   "roughness": {"type": "wood", "a": 0.15, "b": 0.6, "frequency": 2}})"),
        sphereScene(directory, R"({"diffuse_albedo": {"type": "image", "file": "albedo.png", "filter": "anisotropic", "tiling": [2, 1]},
                                   "roughness": {"type": "image", "file": "albedo.png", "channel": "g", "min": 0.1, "max": 0.6},
                                   "normal": {"type": "image", "file": "normal.png", "tiling": [2, 1]}})")};
    const char* names[] = {"untextured", "marble + wood", "3 images"};
    std::vector<double> times[3];
    for (const Scene& scene : scenes) (void)renderer.renderRadiance(scene, kWidth, kHeight);  // compile, upload
    for (int frame = 0; frame < frames; ++frame)
        for (int i = 0; i < 3; ++i)
            times[i].push_back(timeFrame([&] { (void)renderer.renderRadiance(scenes[i], kWidth, kHeight); }));
    const double baseline = medianMs(times[0]);
    for (int i = 0; i < 3; ++i)
        std::printf("%-14s radiance pass %7.2f ms   ratio to untextured %.3f\n", names[i], medianMs(times[i]),
                    medianMs(times[i]) / baseline);
    return 0;
}

}  // namespace
}  // namespace glint

int main(int argc, char** argv) { return glint::run(argc > 1 ? std::max(1, std::atoi(argv[1])) : 9); }
