// glint: the command-line front. `glint render …` renders headless; `glint [FILE]` opens the
// editor on FILE (as File ▸ Open would), or, with no display, renders it headless and says where
// the image went.
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "classroom/lessons.h"
#include "cli/commands.h"
#include "cli/command_line.h"
#include "cli/render_input.h"
#include "editor/editor.h"
#include "runtime/brdf_probe.h"
#include "runtime/headless.h"
#include "runtime/precompute_report.h"
#include "scene/scene_json.h"

namespace {

bool hasDisplay() {
    const char* display = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (display && *display) || (wayland && *wayland);
}

// No window could be opened: render `path` (the default scene when empty) offscreen instead, as
// `glint render` would, and say where it went.
int renderWithoutDisplay(const std::string& path, const std::string& reason) {
    glint::Scene scene;  // the default one only when no file is named: its studio map takes a while
    if (path.empty()) {
        scene = glint::defaultScene();
    } else {
        std::vector<glint::Diagnostic> warnings;
        std::vector<std::string> notes;
        auto loaded = glint::loadRenderInput(path, {}, warnings, notes);
        for (const glint::Diagnostic& warning : warnings) std::fprintf(stderr, "glint: %s\n", warning.format().c_str());
        for (const std::string& note : notes) std::printf("glint: %s\n", note.c_str());
        // Custom .brdf shaders are proven to finish (in a child) before this process draws them.
        glint::Status usable = loaded ? glint::probeSceneBrdfs(*loaded, glint::brdfProbeTimeoutSeconds()) : loaded.error();
        if (!usable) return glint::commandFailed("", usable.error().format());
        scene = std::move(*loaded);
    }
    const std::string sceneName = path.empty() ? "default" : std::filesystem::path(path).stem().string();
    const std::string output = "glint-" + sceneName + ".png";
    auto headless = glint::HeadlessRenderer::create();
    if (!headless) return glint::commandFailed("", headless.error().format());
    auto images = (*headless)->render(scene, scene.width, scene.height);
    if (!images) return glint::commandFailed("", images.error().format());
    if (glint::Status written = glint::writeRenderedImage(*images, output); !written)
        return glint::commandFailed("", written.error().format());
    std::printf("glint: no display (%s).\nglint: rendered the %s scene headless (%dx%d, %s) to %s\n",
                reason.c_str(), sceneName.c_str(), scene.width, scene.height,
                (*headless)->renderer().description().c_str(),
                std::filesystem::absolute(output).string().c_str());
    return 0;
}

// `glint present [LIST.json]`: the editor in presentation mode on the list's first lesson.
int runPresentation(const std::string& presentList) {
    if (auto list = glint::loadLessonList(presentList); !list) return glint::commandFailed("", list.error().format());
    if (!hasDisplay())
        return glint::commandFailed("", "present needs a display (DISPLAY is not set); "
                                        "`glint lessons --render DIR` renders the lessons headless");
    auto platform = glint::GlfwPlatform::create(1280, 800, "Glint — presentation");
    if (!platform) return glint::commandFailed("", "present needs a window: " + platform.error().message);
    return glint::runEditor(std::move(*platform), "", presentList);
}

}  // namespace

int main(int argc, char** argv) {
    // A file-size limit (ulimit -f) makes a write fail with EFBIG, reported as any failed save, instead
    // of killing the process (the default for SIGXFSZ).
    std::signal(SIGXFSZ, SIG_IGN);
    glint::reportSlowEnvironmentPrecomputes();  // headless runs (the editor turns it off)
    CLI::App glint("Glint " GLINT_VERSION ": a material editor for physically based shading.", "glint");
    glint.set_version_flag("--version", "glint " GLINT_VERSION);
    std::string openPath;
    glint.add_option("FILE", openPath,
                     "open the editor (the default scene when no file is given) and open FILE as File > Open does: a "
                     "scene or material .json, a BRDF Explorer .brdf, a .mtl, .gltf or .glb material (glTF lights too), a "
                     "MERL .binary, a .bparam, or a mesh .obj|.ply|.stl|.fbx (added as an object)");
    glint.footer("With no display, `glint [FILE]` renders the scene (a material on the preview stage) headless to "
                 "glint-<name>.png.\n`glint COMMAND --help` lists a command's options.");
    glint::addInfoCommand(glint);
    glint::addRenderCommand(glint);
    glint::addSnapshotCommand(glint);
    glint::addThumbnailsCommand(glint);
    glint::addBenchCommand(glint);
    glint::addExportCommand(glint);
    glint::addPresetsCommand(glint);
    glint::addModelsCommand(glint);
    std::string presentList = glint::defaultLessonListPath();
    glint::addCommand(glint, "present",
                      "the editor in presentation mode (full screen, large type) on the first lesson of LIST; "
                      "PageDown / PageUp step",
                      [&] { return runPresentation(presentList); })
        ->add_option("LIST", presentList, "a lesson list (default: the lessons shipped with Glint)");
    glint::addLessonsCommand(glint);
    glint::addSpectralCommand(glint);
    glint::addCmfCommand(glint);
    std::string probeName, probeValues;  // hidden (no group): the custom-BRDF safety probe's child
    CLI::App* probe = glint::addCommand(glint, "probe-brdf", "", [&] { return glint::runProbeBrdfCommand(probeName, probeValues); });
    probe->group("");
    probe->add_option("NAME", probeName)->required();
    probe->add_option("--values", probeValues)->required();

    glint::addOutsideReferencesFlag(glint);  // the editor's FILE
    for (const char* opensFiles : {"info", "render", "snapshot", "thumbnails", "export", "present", "lessons", "spectral"})
        glint::addOutsideReferencesFlag(*glint.get_subcommand(opensFiles));

    bool chosen = false;
    const int exitCode = glint::runCommandLine(glint, argc, argv, chosen);
    if (chosen) return exitCode;
    if (!hasDisplay()) return renderWithoutDisplay(openPath, "DISPLAY is not set");
    const std::string title = openPath.empty() ? "untitled" : std::filesystem::path(openPath).filename().string();
    auto platform = glint::GlfwPlatform::create(1280, 800, "Glint — " + title);
    if (!platform) return renderWithoutDisplay(openPath, platform.error().message);
    // The file opens in the editor as File ▸ Open opens it; a failure shows there, located.
    return glint::runEditor(std::move(*platform), openPath);
}
