// `glint render` (see commands.h).
#include "cli/commands.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <regex>
#include <string>
#include <vector>

#include "runtime/brdf_probe.h"
#include "cli/classroom_options.h"
#include "cli/command_line.h"
#include "runtime/headless.h"
#include "runtime/progress_line.h"
#include "classroom/probe_text.h"
#include "classroom/surface_probe.h"
#include "cli/plot_overlay.h"
#include "cli/render_overlays.h"
#include "cli/render_input.h"
#include "display/display_chain.h"
#include "image/image_io.h"
#include "render/path_tracer.h"
#include "render/reference_renderer.h"

namespace glint {
namespace {

struct RenderOptions {
    std::string scenePath, outputPath;
    RenderInputOptions input;  // --material, --up
    int width = 0, height = 0, msaa = 0;
    bool reference = false;
    bool pathTrace = false;
    int samples = 0;  // --samples N: the reference's Monte-Carlo environment (0: the preview's), or the path tracer's per pixel
    std::optional<uint32_t> seed;   // --seed S, path tracer only
    std::optional<int> bounces;     // --bounces N, path tracer only
    bool wireframe = false, normals = false;
    std::optional<glm::ivec2> probePixel;          // --probe X,Y
    std::vector<const RenderOverlay*> overlays;  // --overlay NAME, in order (the plots among them)
    std::optional<PlotOverlayKind> plot;         // the one plot among the overlays
    PlotOverlayOptions plots;                    // --incidence, --from-inside
    ClassroomOptions classroom;                  // display lessons and compare views (classroom_options.h)
};

// The compare panes of `scene` rendered and composited (app/classroom/compare_render.h).
Result<RenderedImages> renderCompareView(const ClassroomOptions& classroom, const Scene& scene, Renderer& renderer, int width, int height) {
    auto panes = classroom.paneScenes(scene);
    if (!panes) return panes.error();
    return renderCompare(renderer, *panes, classroom.chosenLayout(), width, height, classroom.divider.value_or(0.5f));
}

int usageError(const std::string& message) { return glint::usageError("render", message); }

constexpr int kDefaultPathTraceSamples = 64;  // per pixel, when --path-trace has no --samples

// What contradicts itself among the options, before the scene is read; empty when nothing.
std::string optionConflict(const RenderOptions& options) {
    const ClassroomOptions& classroom = options.classroom;
    if (options.scenePath.empty()) return "no scene file given";
    if (options.outputPath.empty()) return "no output file given (-o OUT.png or -o OUT.exr)";
    if (options.reference && options.pathTrace) return "give --reference or --path-trace, not both";
    if (options.samples > 0 && !options.reference && !options.pathTrace)
        return "--samples needs --reference (its Monte-Carlo environment) or --path-trace (samples per pixel)";
    if ((options.seed || options.bounces) && !options.pathTrace) return std::string(options.seed ? "--seed" : "--bounces") + " needs --path-trace";
    if (options.pathTrace && (options.wireframe || options.normals || options.plot || classroom.comparing()))
        return "--wireframe, --normals, --overlay plots and the compare views are drawn by the OpenGL renderer, not with --path-trace";
    if (options.reference && (options.wireframe || options.normals))
        return "--wireframe and --normals are drawn by the OpenGL renderer, not with --reference";
    if (std::string conflict = plotOverlayConflict(options.plots, options.plot, options.reference, options.outputPath); !conflict.empty())
        return conflict;
    if (std::string contradiction = classroom.check(); !contradiction.empty()) return contradiction;
    if (options.reference && classroom.comparing()) return "the compare views are drawn by the OpenGL renderer, not with --reference";
    return "";
}

// What the probe and the overlays ask that a width×height image cannot give; empty when nothing.
std::string overlayConflict(const RenderOptions& options, int width, int height) {
    for (const RenderOverlay* overlay : options.overlays)
        if (overlay->needsProbePoint && !options.probePixel) return std::string("--overlay ") + overlay->name + " needs --probe X,Y";
    if (options.probePixel && (options.probePixel->x >= width || options.probePixel->y >= height))
        return "--probe " + std::to_string(options.probePixel->x) + "," + std::to_string(options.probePixel->y) + " lies outside the " +
               std::to_string(width) + "x" + std::to_string(height) + " image";
    if (!options.overlays.empty() && isFloatImagePath(options.outputPath))
        return "--overlay draws over the display-encoded image: write a PNG, not an EXR or HDR";
    return "";
}

// The scene as the options change it, with what its reading printed.
Result<Scene> renderedScene(RenderOptions& options) {
    std::vector<Diagnostic> warnings;  // what an interchange file could not carry over exactly
    std::vector<std::string> notes;    // what was loaded
    // A material, interchange, .brdf, .bparam or mesh file renders on the preview stage.
    auto scene = loadRenderInput(options.scenePath, options.input, warnings, notes);
    for (const Diagnostic& warning : warnings) std::fprintf(stderr, "glint render: %s\n", warning.format().c_str());
    for (const std::string& note : notes) std::printf("glint render: %s\n", note.c_str());
    if (!scene) return scene.error();
    if (options.msaa > 0) scene->msaaSamples = options.msaa;
    scene->display.overlays.wireframe |= options.wireframe;
    scene->display.overlays.normals |= options.normals;
    options.classroom.applyDisplay(*scene);
    return scene;
}

// The CPU reference's or path tracer's picture, with progress on stderr.
RenderedImages renderOnCpu(const RenderOptions& options, const Scene& scene, int width, int height) {
    RenderedImages images;
    if (options.reference) {
        ReferenceOptions reference;
        if (options.samples > 0) {
            reference.sampleEnvironment = true;
            reference.environmentSamples = options.samples;
            // Progress for renders long enough to wonder about (runtime/progress_line.h).
            reference.progress = [line = std::make_shared<ProgressLine>("glint render: reference")](float done) { line->update(done); };
        }
        images.radiance = renderReference(scene, width, height, reference);
    } else {
        PathTraceSettings settings;
        settings.seed = options.seed.value_or(settings.seed);
        settings.maxBounces = options.bounces.value_or(settings.maxBounces);
        ProgressLine line("glint render: path trace");
        images.radiance = renderPathTraced(scene, options.samples > 0 ? options.samples : kDefaultPathTraceSamples, width, height,
                                           settings, [&line](float done) { line.update(done); });
    }
    images.display = applyDisplayChain(images.radiance, scene.display);
    return images;
}

// The surface probe's report (printed) and the overlays drawn over the display image.
Status drawProbeAndOverlays(const RenderOptions& options, const Scene& scene, int width, int height, RenderedImages& images) {
    std::optional<ProbeResult> probe;
    if (options.probePixel) {
        probe = probeSurface(scene, options.probePixel->x, options.probePixel->y, width, height);
        std::printf("%s", probeReport(*probe).c_str());
    }
    if (options.overlays.empty()) return success();
    auto composite = drawRenderOverlays(options.overlays, {scene, width, height, probe, options.plots}, images.display);
    if (!composite) return composite.error();
    images.display = std::move(*composite);
    return success();
}

int render(RenderOptions& options) {
    if (const std::string conflict = optionConflict(options); !conflict.empty()) return usageError(conflict);
    auto scene = renderedScene(options);
    if (!scene) return commandFailed("render", scene.error().format());
    const int width = options.width > 0 ? options.width : scene->width;
    const int height = options.height > 0 ? options.height : scene->height;
    if (const std::string conflict = overlayConflict(options, width, height); !conflict.empty()) return usageError(conflict);
    // Custom .brdf shaders: GPU only, and proven to finish in a child process before drawing here.
    const bool onCpu = options.reference || options.pathTrace;
    if (Status gpuOnly = referenceCanRender(*scene); !gpuOnly && onCpu) return commandFailed("render", gpuOnly.error().format());
    if (Status probed = probeSceneBrdfs(*scene, brdfProbeTimeoutSeconds()); !probed) return commandFailed("render", probed.error().format());
    std::unique_ptr<HeadlessRenderer> headless;  // the GL context: for OpenGL renders and for overlays
    if (!onCpu || !options.overlays.empty()) {
        auto created = HeadlessRenderer::create();
        if (!created) return commandFailed("render", created.error().format());
        headless = std::move(*created);
    }
    RenderedImages images;
    if (onCpu) {
        images = renderOnCpu(options, *scene, width, height);
    } else {
        if (const std::string note = headless->renderer().samplesNote(scene->msaaSamples); !note.empty())
            std::fprintf(stderr, "glint render: note: %s\n", note.c_str());
        auto rendered = options.classroom.comparing() ? renderCompareView(options.classroom, *scene, headless->renderer(), width, height)
                                                      : headless->render(*scene, width, height, isFloatImagePath(options.outputPath));
        if (!rendered) return commandFailed("render", rendered.error().format());
        images = std::move(*rendered);
    }
    if (Status drawn = drawProbeAndOverlays(options, *scene, width, height, images); !drawn) return commandFailed("render", drawn.error().format());
    if (Status written = writeRenderedImage(images, options.outputPath); !written) return commandFailed("render", written.error().format());
    return 0;
}

// "X,Y" within 0..99999 each, or nothing.
std::optional<glm::ivec2> pixelPoint(const std::string& value) {
    static const std::regex pointPattern(R"((\d{1,5}),(\d{1,5}))");
    std::smatch match;
    if (!std::regex_match(value, match, pointPattern)) return std::nullopt;
    return glm::ivec2(std::stoi(match[1]), std::stoi(match[2]));
}

// --reference, --path-trace and what they take.
void addRendererOptions(CLI::App& command, const std::shared_ptr<RenderOptions>& options) {
    command.add_flag("--reference", options->reference, "render with the CPU reference ray caster instead of OpenGL");
    command.add_flag("--path-trace", options->pathTrace,
                      "render with the CPU path tracer instead of OpenGL: light bouncing between surfaces, glass "
                      "refracting the scene (docs/path-tracer.md); progress on stderr");
    command
        .add_option("--samples", options->samples,
                     "with --reference: integrate the environment light by Monte-Carlo with N samples per pixel (map, "
                     "cosine and GGX importance sampling, deterministic), not the preview's image-based lighting; progress "
                     "on stderr. With --path-trace: N paths per pixel (default " +
                         std::to_string(kDefaultPathTraceSamples) + ")")
        ->check(needs("a positive number of samples per pixel, e.g. 1024",
                      [](const std::string& value) { return std::regex_match(value, std::regex(R"(\d{1,7})")) && std::stoi(value) >= 1; }))
        ->type_name("N");
    command
        .add_option_function<std::string>(
            "--seed", [options](const std::string& value) { options->seed = static_cast<uint32_t>(std::stoul(value)); },
            "with --path-trace: another seed gives another, as deterministic, estimate (default 0)")
        ->check(needs("a whole number from 0 to 4294967295",
                      [](const std::string& value) {
                          return std::regex_match(value, std::regex(R"(\d{1,10})")) && std::stoull(value) <= 4294967295ull;
                      }))
        ->type_name("S");
    command
        .add_option_function<std::string>(
            "--bounces", [options](const std::string& value) { options->bounces = std::stoi(value); },
            "with --path-trace: surface interactions per path at most (default " +
                std::to_string(PathTraceSettings{}.maxBounces) + "; 1: direct light only)")
        ->check(needs("a whole number from 1 to 1000",
                      [](const std::string& value) {
                          return std::regex_match(value, std::regex(R"(\d{1,4})")) && std::stoi(value) >= 1 && std::stoi(value) <= 1000;
                      }))
        ->type_name("N");
}

// What is drawn over the picture: edges, normals, the probe and the classroom overlays.
void addOverlayOptions(CLI::App& command, const std::shared_ptr<RenderOptions>& options) {
    command.add_flag("--wireframe", options->wireframe, "draw the edges of the drawn triangles over the image (PNG only; not with --reference or --path-trace)");
    command.add_flag("--normals", options->normals, "draw vertex normals as short lines over the image (PNG only; not with --reference or --path-trace)");
    command
        .add_option_function<std::string>(
            "--probe", [options](const std::string& value) { options->probePixel = pixelPoint(value); },
            "print the surface probe at pixel (X, Y): the chain from each light to the pixel")
        ->check(needs("a pixel X,Y, e.g. 128,128", [](const std::string& value) { return pixelPoint(value).has_value(); }))
        ->type_name("X,Y");
    std::string overlayNames;
    for (const RenderOverlay& overlay : allRenderOverlays())
        overlayNames += std::string(overlayNames.empty() ? "" : "; ") + overlay.name + ": " + overlay.help;
    command
        .add_option_function<std::vector<std::string>>(
            "--overlay",
            [options](const std::vector<std::string>& names) {
                for (const std::string& name : names) {
                    const RenderOverlay* overlay = findRenderOverlay(name);
                    if (overlay->plot && options->plot) refuse("one plot per image (--overlay " + name + " given after another plot)");
                    if (overlay->plot) options->plot = overlay->plot;
                    options->overlays.push_back(overlay);
                }
            },
            "draw a classroom overlay over the PNG (repeatable; one plot per image): " + overlayNames)
        ->allow_extra_args(false)  // one name per --overlay
        ->each([](const std::string& value) {
            if (!findRenderOverlay(value)) refuse("unknown overlay '" + value + "'");
        })
        ->type_name("NAME");
}

}  // namespace

void addRenderCommand(CLI::App& glint) {
    auto options = std::make_shared<RenderOptions>();
    CLI::App* command = addCommand(glint, "render", "render headless (no display needed)", [options] { return render(*options); });
    command->footer("Classroom: docs/classroom.md (compare views, display chain, plots, surface probe).");
    command->add_option("SCENE", options->scenePath,
                        "a scene, or a material file (rendered on the preview stage, 256x256); also a Wavefront .mtl, a "
                        "glTF .gltf|.glb (a material and its lights on the stage), a MERL measured BRDF .binary (preview "
                        "stage), a BRDF Explorer .brdf or .bparam file (preview stage, GPU only), or a mesh "
                        ".obj|.ply|.stl|.fbx (on the stage in the sphere's place; what was loaded is printed)");
    command->add_option("--material", options->input.material,
                        "put one material of a .mtl, .gltf or .glb on the preview sphere (default: the first; a glTF with meshes renders whole without it; `glint info` lists them)")
        ->check(needs("a material's name or index", [](const std::string& value) { return !value.empty(); }))
        ->type_name("NAME|INDEX");
    command
        ->add_option_function<std::string>(
            "--up", [options](const std::string& value) { options->input.upAxis = value == "z" ? MeshUpAxis::Z : MeshUpAxis::Y; },
            "a mesh file's up axis (default y; z for Z-up files)")
        ->check(needs("y or z", [](const std::string& value) { return value == "y" || value == "z"; }))
        ->type_name("y|z");
    command->add_option("-o,--output", options->outputPath, "PNG (display-encoded, 8-bit) or EXR (linear radiance, W/(sr·m²))")
        ->type_name("FILE");
    addPixelSize(*command, options->width, options->height, 1, 16384, "output size in pixels (default: the scene's \"output\")");
    command->add_option("--msaa", options->msaa, "multisample anti-aliasing with N samples (1 = off; default: the scene file's \"msaa\", else 4)")
        ->check(needs("1, 2, 4, 8 or 16", [](const std::string& value) { return std::regex_match(value, std::regex("1|2|4|8|16")); }))
        ->type_name("N");
    addRendererOptions(*command, options);
    addOverlayOptions(*command, options);
    addPlotOverlayOptions(*command, options->plots);
    options->classroom.addTo(*command);
}

}  // namespace glint
