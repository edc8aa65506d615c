// glint: the command-line front. `glint render …` renders headless; `glint [FILE]` opens the
// editor on FILE (as File ▸ Open would), or, with no display, renders it headless and says where
// the image went.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "classroom/lessons.h"
#include "cli/bench_command.h"
#include "cli/cmf_command.h"
#include "cli/brdf_probe.h"
#include "cli/headless.h"
#include "cli/export_command.h"
#include "cli/lessons_command.h"
#include "cli/models_command.h"
#include "cli/presets_command.h"
#include "cli/render_command.h"
#include "cli/render_input.h"
#include "cli/info_command.h"
#include "cli/snapshot_command.h"
#include "cli/spectral_command.h"
#include "cli/thumbnails_command.h"
#include "editor/editor.h"
#include "scene/scene_json.h"

namespace {

constexpr const char* kUsage =
    "Glint " GLINT_VERSION ": a material editor for physically based shading.\n"
    "\n"
    "usage:\n"
    "  glint [FILE]                open the editor (the default scene when no file is given) and open\n"
    "                              FILE as File > Open does: a scene or material .json, a BRDF Explorer\n"
    "                              .brdf, a .mtl, .gltf or .glb material (glTF lights too), a MERL\n"
    "                              .binary, a .bparam, or a mesh .obj|.ply|.stl|.fbx (added as an object)\n"
    "  glint info FILE             list what a file holds (materials, meshes, lights, parameters) and its warnings\n"
    "  glint render SCENE.json -o OUT.png|OUT.exr [--size WxH] [--msaa N] [--reference [--samples N]]\n"
    "                              [--material NAME|INDEX]\n"
    "                              render headless (no display needed)\n"
    "  glint snapshot SUITE [--out DIR] [--update] [--update-case NAME] [--jobs N] [--shard I/N]\n"
    "                              compare a suite of scenes and materials with their goldens\n"
    "  glint thumbnails DIR -o OUTDIR [--size N] [--jobs N]\n"
    "                              one thumbnail per material and a labelled contact sheet\n"
    "  glint bench [--frames N] [--quick] [--json FILE] [--scene NAME]...\n"
    "                              time the standard scenes against the bare shading pass\n"
    "  glint export IN -o OUT.mtl|OUT.gltf\n"
    "                              write a material (file, scene, .mtl or .gltf) as .mtl or glTF\n"
    "  glint presets [NAME -o FILE.json]\n"
    "                              list the material presets, or write one as a material file\n"
    "  glint models [--markdown]   list the BRDF models, or write their parameter reference (docs/models.md)\n"
    "  glint present [LIST.json]   the editor in presentation mode (full screen, large type) on the first\n"
    "                              lesson of LIST (the shipped lessons when omitted); PageDown / PageUp step\n"
    "  glint lessons [LIST.json] [--check] [--render DIR]\n"
    "                              list the classroom lessons, check that they load, or render them\n"
    "  glint spectral SCENE.json -o OUT.png|OUT.exr [--band NM,FWHM] [--cauchy-b B] [--wavelengths N]\n"
    "                              render per wavelength (CPU) and convert through the CIE 1931 matching functions\n"
    "  glint cmf -o OUT.png [--size WxH]\n"
    "                              plot the CIE 1931 colour matching functions headless\n"
    "  glint --help | --version\n"
    "\n"
    "With no display, `glint [FILE]` renders the scene (a material on the preview stage) headless\n"
    "to glint-<name>.png.\n";

// No window could be opened: render `path` (the default scene when empty) offscreen instead, as
// `glint render` would, and say where it went.
int renderWithoutDisplay(const std::string& path, const std::string& reason) {
    glint::Scene scene = glint::defaultScene();
    if (!path.empty()) {
        std::vector<glint::Diagnostic> warnings;
        std::vector<std::string> notes;
        auto loaded = glint::loadRenderInput(path, {}, warnings, notes);
        for (const glint::Diagnostic& warning : warnings) std::fprintf(stderr, "glint: %s\n", warning.format().c_str());
        for (const std::string& note : notes) std::printf("glint: %s\n", note.c_str());
        // Custom .brdf shaders are proven to finish (in a child) before this process draws them.
        glint::Status usable = loaded ? glint::probeSceneBrdfs(*loaded, glint::brdfProbeTimeoutSeconds()) : loaded.error();
        if (!usable) {
            std::fprintf(stderr, "glint: %s\n", usable.error().format().c_str());
            return 2;
        }
        scene = std::move(*loaded);
    }
    const std::string sceneName = path.empty() ? "default" : std::filesystem::path(path).stem().string();
    const std::string output = "glint-" + sceneName + ".png";
    auto headless = glint::HeadlessRenderer::create();
    if (!headless) {
        std::fprintf(stderr, "glint: %s\n", headless.error().format().c_str());
        return 2;
    }
    auto images = (*headless)->render(scene, scene.width, scene.height);
    if (!images) {
        std::fprintf(stderr, "glint: %s\n", images.error().format().c_str());
        return 2;
    }
    if (glint::Status written = glint::writeRenderedImage(*images, output); !written) {
        std::fprintf(stderr, "glint: %s\n", written.error().format().c_str());
        return 2;
    }
    std::printf("glint: no display (%s).\nglint: rendered the %s scene headless (%dx%d, %s) to %s\n",
                reason.c_str(), sceneName.c_str(), scene.width, scene.height,
                (*headless)->renderer().description().c_str(),
                std::filesystem::absolute(output).string().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<std::string> arguments(argv + 1, argv + argc);
    if (!arguments.empty() && arguments[0] == "render")
        return glint::runRenderCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "probe-brdf")  // hidden: the custom-BRDF safety probe's child
        return glint::runProbeBrdfCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "snapshot")
        return glint::runSnapshotCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "thumbnails")
        return glint::runThumbnailsCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "bench")
        return glint::runBenchCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "info")
        return glint::runInfoCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "export")
        return glint::runExportCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "presets")
        return glint::runPresetsCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "models")
        return glint::runModelsCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "cmf")
        return glint::runCmfCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "spectral")
        return glint::runSpectralCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && arguments[0] == "lessons")
        return glint::runLessonsCommand({arguments.begin() + 1, arguments.end()});
    if (!arguments.empty() && (arguments[0] == "-h" || arguments[0] == "--help")) {
        std::printf("%s", kUsage);
        return 0;
    }
    if (!arguments.empty() && arguments[0] == "--version") {
        std::printf("glint %s\n", GLINT_VERSION);
        return 0;
    }
    // `glint present [LIST.json]`: presentation mode on the list's first lesson.
    if (!arguments.empty() && arguments[0] == "present") {
        if (arguments.size() > 2 || (arguments.size() == 2 && arguments[1].rfind("-", 0) == 0)) {
            std::fprintf(stderr, "glint: present takes one lesson list at most\n%s", kUsage);
            return 2;
        }
        const std::string presentList = arguments.size() == 2 ? arguments[1] : glint::defaultLessonListPath();
        if (auto list = glint::loadLessonList(presentList); !list) {
            std::fprintf(stderr, "glint: %s\n", list.error().format().c_str());
            return 2;
        }
        const char* display = std::getenv("DISPLAY");
        const char* wayland = std::getenv("WAYLAND_DISPLAY");
        if ((!display || !*display) && (!wayland || !*wayland)) {
            std::fprintf(stderr, "glint: present needs a display (DISPLAY is not set); `glint lessons --render DIR` renders the lessons headless\n");
            return 2;
        }
        auto platform = glint::GlfwPlatform::create(1280, 800, "Glint — presentation");
        if (!platform) {
            std::fprintf(stderr, "glint: present needs a window: %s\n", platform.error().message.c_str());
            return 2;
        }
        return glint::runEditor(std::move(*platform), "", presentList);
    }
    if (arguments.size() > 1 || (!arguments.empty() && arguments[0].rfind("-", 0) == 0)) {
        std::fprintf(stderr, "glint: unexpected arguments\n%s", kUsage);
        return 2;
    }

    const std::string openPath = arguments.empty() ? "" : arguments[0];
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    if ((!display || !*display) && (!wayland || !*wayland)) return renderWithoutDisplay(openPath, "DISPLAY is not set");
    const std::string title = openPath.empty() ? "untitled" : std::filesystem::path(openPath).filename().string();
    auto platform = glint::GlfwPlatform::create(1280, 800, "Glint — " + title);
    if (!platform) return renderWithoutDisplay(openPath, platform.error().message);
    // The file opens in the editor as File ▸ Open opens it; a failure shows there, located.
    return glint::runEditor(std::move(*platform), openPath);
}
