// `glint bench` (see commands.h).
// Sections: options · statistics · child processes · scene timing · whole-program figures ·
// output · the command.
#include "cli/commands.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>

#include "cli/bench_scenes.h"
#include "cli/command_line.h"
#include "runtime/headless.h"
#include "geometry/mesh_import.h"
#include "geometry/shape_mesh.h"
#include "gl/bare_shading_pass.h"
#include "gl/textbook_floor_pass.h"
#include "scene/scene_json.h"
#include "util/file_io.h"

extern char** environ;

namespace glint {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// --- options ------------------------------------------------------------------------------------

struct BenchOptions {
    int frames = 0;  // 0: the default for the mode
    bool quick = false;
    bool generic = false;  // RendererOptions::specialisePrograms off
    bool radiance = false;  // RendererOptions::keepRadiance
    int width = 1280, height = 720;
    std::string jsonPath;
    std::vector<std::string> sceneNames;  // empty: every standard scene
    std::vector<std::string> sceneFiles;
    std::vector<BenchScene> fileScenes;  // --scene-file, loaded, in the order given
    bool scenesOnly() const { return !sceneNames.empty() || !sceneFiles.empty(); }
    int coldStarts() const { return quick ? 3 : 11; }
    int thumbnails() const { return quick ? 8 : 40; }
    int meshLoads() const { return quick ? 1 : 5; }
    int framesPerScene() const { return frames ? frames : quick ? 1 : 11; }
};

// --- statistics ---------------------------------------------------------------------------------

struct Timing {
    double median = 0, lowerQuartile = 0, upperQuartile = 0, min = 0, max = 0;  // [ms]
};

Timing summarize(std::vector<double> samples) {
    std::sort(samples.begin(), samples.end());
    const auto at = [&](double fraction) { return samples[static_cast<size_t>(fraction * (samples.size() - 1) + 0.5)]; };
    return {at(0.5), at(0.25), at(0.75), samples.front(), samples.back()};
}

json toJson(const Timing& timing) {
    return {{"median", timing.median}, {"q1", timing.lowerQuartile}, {"q3", timing.upperQuartile},
            {"min", timing.min}, {"max", timing.max}};
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// --- child processes ----------------------------------------------------------------------------

struct ChildRun {
    double wallMs = 0;
    double peakMegabytes = 0;  // the child's maximum resident set
    bool succeeded = false;
};

// Runs this executable with `arguments`, output discarded, and waits for it.
ChildRun runSelf(const std::vector<std::string>& arguments) {
    const std::string self = fs::read_symlink("/proc/self/exe").string();
    std::vector<std::string> storage = {self};
    storage.insert(storage.end(), arguments.begin(), arguments.end());
    std::vector<char*> argv;
    for (std::string& argument : storage) argv.push_back(argument.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    ChildRun run;
    const auto start = std::chrono::steady_clock::now();
    pid_t child = 0;
    if (posix_spawn(&child, self.c_str(), &actions, nullptr, argv.data(), environ) == 0) {
        int status = 0;
        rusage usage{};
        if (wait4(child, &status, 0, &usage) == child) {
            run.wallMs = millisecondsSince(start);
            run.peakMegabytes = usage.ru_maxrss / 1024.0;  // kB on Linux
            run.succeeded = WIFEXITED(status) && WEXITSTATUS(status) == 0;
        }
    }
    posix_spawn_file_actions_destroy(&actions);
    return run;
}

// --- scene timing -------------------------------------------------------------------------------

struct SceneResult {
    std::string name, family;
    Timing frame, radiance, display, bare, readback;
    double ratio = 0, radianceRatio = 0;  // 0 when the scene has no floor
    std::string floor;                    // "textbook", "generated" or "none"
    double firstFrameMs = 0;              // the untimed first frame: programs compiled, targets made
    MeshDetail detail = MeshDetail::Full;
    long long triangles = 0;           // submitted by the surface pass per frame
    double shadowMapsPerFrame = 0.0;   // shadow maps drawn per timed frame (0: kept from the first)
};

// The floor a scene's frames are compared with: the hand-written textbook program where it covers
// the scene (gl/textbook_floor_pass.h), else the generated shading of the first object's material
// alone (gl/bare_shading_pass.h), else none. Returns the kind and sets `draw`.
Result<std::string> makeFloor(const Renderer& renderer, const Scene& scene, int width, int height,
                              std::function<void()>& draw) {
    if (TextbookFloorPass::covers(scene)) {
        auto pass = TextbookFloorPass::create(renderer.sources(), scene);
        if (!pass) return pass.error();
        draw = [pass = std::shared_ptr<TextbookFloorPass>(std::move(*pass)), &scene, width, height] { pass->draw(scene, width, height); };
        return std::string("textbook");
    }
    const AnalyticMaterial* analytic = scene.objects.empty() ? nullptr : scene.materials.at(scene.objects[0].materialIndex).analytic();
    if (!analytic) return std::string("none");
    auto pass = BareShadingPass::create(renderer.sources(), *analytic);
    if (!pass) return pass.error();
    draw = [pass = std::shared_ptr<BareShadingPass>(std::move(*pass)), &scene, width, height] { pass->draw(scene, width, height); };
    return std::string("generated");
}

// Times `frames` frames of the scene (radiance pass, then display pass) and as many floor passes,
// interleaved frame by frame, alternating which goes first, each ended by glFinish; after each
// frame, the readback of its 8-bit picture, timed apart. A scene drawn with simplified stand-ins
// has them made first (the editor makes them ahead of a drag).
Result<SceneResult> timeScene(HeadlessRenderer& headless, const BenchScene& benchScene, const BenchOptions& options) {
    Renderer& renderer = headless.renderer();
    const int width = options.width, height = options.height, frames = options.framesPerScene();
    Scene scene = benchScene.build();
    if (benchScene.detail == MeshDetail::Simplified) {
        renderer.prepareSimplifiedMeshes(scene);
        renderer.finishSimplifiedMeshes();
    }
    std::function<void()> floorDraw;
    auto floor = makeFloor(renderer, scene, width, height, floorDraw);
    if (!floor) return floor.error();
    std::vector<double> frameMs, radianceMs, displayMs, bareMs, readbackMs;
    Status failure = success();
    const auto drawScene = [&] {
        if (benchScene.beforeEachFrame) benchScene.beforeEachFrame(scene);
        const auto start = std::chrono::steady_clock::now();
        if (Status status = renderer.renderRadiance(scene, width, height, benchScene.detail); !status) failure = status;
        glFinish();
        const double radiance = millisecondsSince(start);
        renderer.displayOffscreen(scene.display);
        glFinish();
        frameMs.push_back(millisecondsSince(start));
        radianceMs.push_back(radiance);
        displayMs.push_back(frameMs.back() - radiance);
        const auto readStart = std::chrono::steady_clock::now();
        (void)renderer.readDisplay();
        readbackMs.push_back(millisecondsSince(readStart));
    };
    const auto drawFloor = [&] {
        if (!floorDraw) return;
        const auto start = std::chrono::steady_clock::now();
        floorDraw();
        glFinish();
        bareMs.push_back(millisecondsSince(start));
    };
    drawScene();  // compiles the programs and allocates the targets: not counted
    const double firstFrameMs = frameMs.back();
    drawFloor();
    if (!failure) return failure.error();
    frameMs.clear(), radianceMs.clear(), displayMs.clear(), bareMs.clear(), readbackMs.clear();
    const long long shadowMapsBefore = renderer.shadowMapsDrawn();
    for (int i = 0; i < frames; ++i) {
        if (i % 2 == 0) drawScene(), drawFloor();
        else drawFloor(), drawScene();
    }
    if (!failure) return failure.error();
    SceneResult result{benchScene.name, benchScene.family, summarize(frameMs), summarize(radianceMs),
                       summarize(displayMs), bareMs.empty() ? Timing{} : summarize(bareMs), summarize(readbackMs)};
    result.floor = *floor;
    result.firstFrameMs = firstFrameMs;
    if (!bareMs.empty()) {
        result.ratio = result.frame.median / result.bare.median;
        result.radianceRatio = result.radiance.median / result.bare.median;
    }
    result.detail = benchScene.detail;
    result.triangles = renderer.trianglesDrawn();
    result.shadowMapsPerFrame = static_cast<double>(renderer.shadowMapsDrawn() - shadowMapsBefore) / frames;
    return result;
}

// --- whole-program figures ----------------------------------------------------------------------

struct ProgramFigures {
    Timing coldStart;
    double coldStartPeakMegabytes = 0;
    int thumbnailCount = 0;
    double thumbnailsPerSecond = 0;
    size_t meshTriangles = 0;
    Timing meshLoad;  // importMesh of a binary PLY, in this process
    Timing meshRead;  // bare Assimp::Importer::ReadFile(Triangulate) of the same file, interleaved
    double peakMegabytes = 0;  // this process: VmHWM
};

double peakResidentMegabytes() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // "VmHWM:  123 kB"
    return 0.0;
}

// A binary little-endian PLY of the sphere tessellated into 1000 × 500 segments and rings
// (1,000,000 triangles): positions only, so the importer also generates the normals.
Status writeBenchMeshPly(const std::string& path, size_t& triangleCount) {
    SphereShape sphere;
    sphere.segments = 1000, sphere.rings = 500;
    const Mesh mesh = worldMesh(sphere);
    triangleCount = mesh.triangleCount();
    std::string bytes = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(mesh.vertices.size()) +
                        "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
                        std::to_string(triangleCount) + "\nproperty list uchar uint vertex_indices\nend_header\n";
    bytes.reserve(bytes.size() + mesh.vertices.size() * 12 + triangleCount * 13);
    const auto append = [&bytes](const void* data, size_t size) { bytes.append(static_cast<const char*>(data), size); };
    for (const Vertex& vertex : mesh.vertices) append(&vertex.position, 12);
    for (size_t i = 0; i < mesh.indices.size(); i += 3) {
        const uint8_t three = 3;
        append(&three, 1);
        append(&mesh.indices[i], 12);
    }
    return writeFileAtomically(path, bytes);
}

// Cold start: `glint render` of the default scene at 512×512 in a fresh process, `runs` times.
// Thumbnails: one `glint thumbnails --jobs 1` process over `count` materials at 256×256, start-up
// and contact sheet included (as tests/bench/thumbnails_bench.sh).
Result<ProgramFigures> measureProgram(const BenchOptions& options, const fs::path& work) {
    ProgramFigures figures;
    const std::string scenePath = (work / "scene.json").string();
    if (Status saved = saveScene(defaultScene(), scenePath); !saved) return saved.error();
    std::vector<double> coldStartMs;
    for (int i = 0; i < options.coldStarts(); ++i) {
        const ChildRun run = runSelf({"render", scenePath, "-o", (work / "cold.png").string(), "--size", "512x512"});
        if (!run.succeeded) return makeError("glint render " + scenePath + " failed in the cold-start run");
        coldStartMs.push_back(run.wallMs);
        figures.coldStartPeakMegabytes = std::max(figures.coldStartPeakMegabytes, run.peakMegabytes);
    }
    figures.coldStart = summarize(coldStartMs);
    const fs::path materials = work / "materials";
    fs::create_directories(materials);
    for (int i = 0; i < options.thumbnails(); ++i) {
        Material material = Material::withDefaults("bench", i % 2 ? BrdfModel::BlinnPhong : BrdfModel::Lambert);
        material.analytic()->values[0] = 0.05f + 0.9f * static_cast<float>(i % 7) / 7.0f;
        const std::string path = (materials / ("material_" + std::to_string(i) + ".json")).string();
        if (Status saved = saveMaterial(material, path); !saved) return saved.error();
    }
    figures.thumbnailCount = options.thumbnails();
    const ChildRun thumbnails = runSelf({"thumbnails", materials.string(), "-o", (work / "thumbnails").string(), "--jobs", "1"});
    if (!thumbnails.succeeded) return makeError("glint thumbnails " + materials.string() + " failed");
    figures.thumbnailsPerSecond = 1000.0 * figures.thumbnailCount / thumbnails.wallMs;
    const std::string meshPath = (work / "sphere_1m.ply").string();
    if (Status written = writeBenchMeshPly(meshPath, figures.meshTriangles); !written) return written.error();
    std::vector<double> meshLoadMs, meshReadMs;
    for (int i = 0; i < options.meshLoads(); ++i) {
        auto start = std::chrono::steady_clock::now();
        auto imported = importMesh(meshPath);
        if (!imported) return imported.error();
        meshLoadMs.push_back(millisecondsSince(start));
        start = std::chrono::steady_clock::now();
        {
            Assimp::Importer importer;
            if (!importer.ReadFile(meshPath, aiProcess_Triangulate)) return makeError(importer.GetErrorString(), {meshPath});
        }  // the scene freed, as importMesh frees its own
        meshReadMs.push_back(millisecondsSince(start));
    }
    figures.meshLoad = summarize(meshLoadMs);
    figures.meshRead = summarize(meshReadMs);
    figures.peakMegabytes = peakResidentMegabytes();
    return figures;
}

// --- output -------------------------------------------------------------------------------------

void printTable(const std::vector<SceneResult>& scenes, const ProgramFigures& program, const BenchOptions& options,
                const std::string& rendererDescription) {
    std::printf("glint bench: %dx%d, median of %d frames per scene, interleaved with the floor pass, %s programs, %s (%s)\n",
                options.width, options.height, options.framesPerScene(), options.generic ? "generic" : "specialised",
                options.radiance ? "8-bit and float images" : "8-bit image only", rendererDescription.c_str());
    std::printf("%-27s %-15s %9s %9s %9s %9s %9s %-9s %7s %9s %9s %9s %10s %5s\n", "scene", "family", "frame ms", "IQR ms",
                "radiance", "display", "floor ms", "floor", "ratio", "rad.ratio", "readback", "first ms", "triangles", "maps");
    for (const SceneResult& scene : scenes)
        std::printf("%-27s %-15s %9.2f %9.2f %9.2f %9.2f %9.2f %-9s %7.3f %9.3f %9.2f %9.0f %10lld %5.1f\n", scene.name.c_str(),
                    scene.family.c_str(), scene.frame.median, scene.frame.upperQuartile - scene.frame.lowerQuartile,
                    scene.radiance.median, scene.display.median, scene.bare.median, scene.floor.c_str(), scene.ratio,
                    scene.radianceRatio, scene.readback.median, scene.firstFrameMs, scene.triangles, scene.shadowMapsPerFrame);
    if (options.scenesOnly()) return;  // --scene, --scene-file: the scenes only
    std::printf("cold start (glint render, 512x512, child process): median %.0f ms over %d runs (IQR %.0f ms), peak %.0f MB\n",
                program.coldStart.median, options.coldStarts(), program.coldStart.upperQuartile - program.coldStart.lowerQuartile,
                program.coldStartPeakMegabytes);
    std::printf("thumbnails (glint thumbnails --jobs 1, %d materials at 256x256, one process): %.1f per second\n",
                program.thumbnailCount, program.thumbnailsPerSecond);
    std::printf("mesh load (importMesh, binary PLY, %zu triangles, normals generated): median %.0f ms over %d loads, "
                "assimp ReadFile(Triangulate) %.0f ms, ratio %.2f\n",
                program.meshTriangles, program.meshLoad.median, options.meshLoads(), program.meshRead.median,
                program.meshLoad.median / program.meshRead.median);
    std::printf("peak memory of this bench process (VmHWM): %.0f MB\n", program.peakMegabytes);
}

json toJson(const std::vector<SceneResult>& scenes, const ProgramFigures& program, const BenchOptions& options,
            const std::string& rendererDescription) {
    json sceneRows = json::array();
    for (const SceneResult& scene : scenes)
        sceneRows.push_back({{"name", scene.name}, {"family", scene.family}, {"frame_ms", toJson(scene.frame)},
                             {"radiance_ms", toJson(scene.radiance)}, {"display_ms", toJson(scene.display)},
                             {"bare_ms", toJson(scene.bare)}, {"floor", scene.floor}, {"ratio", scene.ratio},
                             {"radiance_ratio", scene.radianceRatio}, {"readback_ms", toJson(scene.readback)},
                             {"first_frame_ms", scene.firstFrameMs},
                             {"mesh_detail", scene.detail == MeshDetail::Simplified ? "simplified" : "full"},
                             {"triangles", scene.triangles}, {"shadow_maps_per_frame", scene.shadowMapsPerFrame}});
    json figures = {{"format", "glint-bench"}, {"version", 1}, {"renderer", rendererDescription},
                    {"width", options.width}, {"height", options.height}, {"frames", options.framesPerScene()},
                    {"quick", options.quick}, {"generic_programs", options.generic}, {"float_radiance", options.radiance},
                    {"scenes", sceneRows}};
    if (options.scenesOnly()) return figures;  // --scene, --scene-file: the scenes only
    figures.update(json{{"cold_start_ms", toJson(program.coldStart)}, {"cold_start_runs", options.coldStarts()},
            {"cold_start_peak_mb", program.coldStartPeakMegabytes},
            {"thumbnails", program.thumbnailCount}, {"thumbnails_per_second", program.thumbnailsPerSecond},
            {"mesh_triangles", program.meshTriangles}, {"mesh_load_ms", toJson(program.meshLoad)},
            {"mesh_read_ms", toJson(program.meshRead)}, {"mesh_load_ratio", program.meshLoad.median / program.meshRead.median},
            {"peak_memory_mb", program.peakMegabytes}});
    return figures;
}

// --- the command --------------------------------------------------------------------------------

int runBench(const BenchOptions& options) {
    const std::vector<BenchScene>& fileScenes = options.fileScenes;
    if (std::find(options.sceneNames.begin(), options.sceneNames.end(), "list") != options.sceneNames.end()) {
        for (const BenchScene& scene : benchScenes()) std::printf("%-27s %s\n", scene.name.c_str(), scene.family.c_str());
        return 0;
    }

    auto headless = HeadlessRenderer::create();
    if (!headless) return commandFailed("bench", headless.error().format());
    (*headless)->renderer().options().specialisePrograms = !options.generic;
    (*headless)->renderer().options().keepRadiance = options.radiance;
    std::vector<const BenchScene*> timed;
    for (const BenchScene& benchScene : benchScenes()) {
        const auto& only = options.sceneNames;
        const bool chosen = only.empty() ? options.sceneFiles.empty()
                                         : std::find(only.begin(), only.end(), benchScene.name) != only.end();
        if (chosen) timed.push_back(&benchScene);
    }
    for (const BenchScene& fileScene : fileScenes) timed.push_back(&fileScene);
    std::vector<SceneResult> scenes;
    for (const BenchScene* benchScene : timed) {
        auto result = timeScene(**headless, *benchScene, options);
        if (!result) return commandFailed("bench", benchScene->name + ": " + result.error().format(), 1);
        scenes.push_back(std::move(*result));
    }
    const std::string description = (*headless)->renderer().description();
    ProgramFigures program;
    if (!options.scenesOnly()) {
        const fs::path work = fs::temp_directory_path() / ("glint-bench-" + std::to_string(getpid()));
        fs::create_directories(work);
        auto measured = measureProgram(options, work);
        std::error_code ignored;
        fs::remove_all(work, ignored);
        if (!measured) return commandFailed("bench", measured.error().format(), 1);
        program = *measured;
    }
    printTable(scenes, program, options, description);
    if (!options.jsonPath.empty()) {
        const Status written = writeFileAtomically(options.jsonPath, toJson(scenes, program, options, description).dump(2) + "\n");
        if (!written) return commandFailed("bench", written.error().format(), 1);
        std::printf("figures written to %s\n", options.jsonPath.c_str());
    }
    return 0;
}

}  // namespace

void addBenchCommand(CLI::App& glint) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* command = addCommand(glint, "bench", "time the standard scenes against the bare shading pass",
                                   [options] { return runBench(*options); });
    command->add_option("--frames", options->frames, "frames timed per scene, interleaved with the floor pass (default 11; --quick: 1)")
        ->check(needsWholeNumber("a number from 1 to 1000", 1, 1000))
        ->type_name("N");
    command->add_flag("--quick", options->quick, "fewer frames, cold starts and thumbnails: a smoke run, its ratios are noisy");
    command->add_option("--json", options->jsonPath, "also write the figures as JSON (\"format\": \"glint-bench\")")
        ->check(needs("a file in an existing folder", [](const std::string& value) {
            std::error_code error;  // the non-throwing forms: no exception escapes
            const fs::path folder = value.empty() ? fs::path() : fs::absolute(value, error).parent_path();
            return !value.empty() && !error && !fs::is_directory(value, error) && fs::is_directory(folder, error);
        }))
        ->type_name("FILE");
    command
        ->add_option("--scene", options->sceneNames,
                     "time only this standard scene, no program figures (repeatable; e.g. lambert/4; `--scene list` lists them)")
        ->allow_extra_args(false)  // one name per --scene
        ->each([](const std::string& value) {
            const auto& all = benchScenes();
            if (value != "list" && std::none_of(all.begin(), all.end(), [&](const BenchScene& scene) { return scene.name == value; }))
                refuse("no standard scene is named \"" + value + "\" (`--scene list` lists them)");
        })
        ->type_name("NAME");
    command
        ->add_option_function<std::vector<std::string>>(
            "--scene-file",
            [options](const std::vector<std::string>& paths) {
                for (const std::string& path : paths) {
                    auto scene = loadScene(path);  // a malformed file: its located message
                    if (!scene) refuse("--scene-file: " + scene.error().format());
                    options->fileScenes.push_back({fs::path(path).stem().string(), "file", [scene = *scene] { return scene; }});
                    options->sceneFiles.push_back(path);
                }
            },
            "time this scene file (repeatable), no program figures")
        ->allow_extra_args(false)
        ->type_name("FILE");
    addPixelSize(*command, options->width, options->height, 1, 8192, "frame size (default 1280x720)");
    command->add_flag("--generic", options->generic, "draw with the generic programs, not the specialised ones (for comparison)");
    command->add_flag("--radiance", options->radiance,
                      "also write the float radiance image, as an EXR render does (default: the 8-bit picture only)");
}

}  // namespace glint
