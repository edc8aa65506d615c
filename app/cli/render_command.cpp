// `glint render` (see render_command.h).
#include "cli/render_command.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <regex>

#include "cli/brdf_probe.h"
#include "cli/classroom_options.h"
#include "cli/headless.h"
#include "classroom/probe_text.h"
#include "classroom/surface_probe.h"
#include "cli/plot_overlay.h"
#include "cli/render_overlays.h"
#include "cli/render_input.h"
#include "display/display_chain.h"
#include "image/image_io.h"
#include "render/reference_renderer.h"

namespace glint {
namespace {

constexpr const char* kUsage =
    "usage: glint render SCENE.json -o OUT.png|OUT.exr [--size WxH] [--msaa N] [--reference [--samples N]] [--wireframe] [--normals]\n"
    "  SCENE.json         a scene, or a material file (rendered on the preview stage, 256x256);\n"
    "                     also a Wavefront .mtl, a glTF .gltf|.glb (a material and its lights on the stage),\n"
    "                     a MERL measured BRDF .binary (preview stage), a BRDF Explorer .brdf or\n"
    "                     .bparam file (preview stage, GPU only), or a mesh .obj|.ply|.stl|.fbx\n"
    "                     (on the stage in the sphere's place; what was loaded is printed)\n"
    "  --material NAME|INDEX  which material of a .mtl, .gltf or .glb (default: the first; `glint info` lists them)\n"
    "  --up y|z           a mesh file's up axis (default y; z for Z-up files)\n"
    "  -o, --output FILE  PNG (display-encoded, 8-bit) or EXR (linear radiance, W/(sr·m²))\n"
    "  --size WxH         output size in pixels (default: the scene's \"output\")\n"
    "  --msaa N           multisample anti-aliasing with N samples (1 = off)\n"
    "  --reference        render with the CPU reference ray caster instead of OpenGL\n"
    "  --samples N        with --reference: integrate the environment light by Monte-Carlo with N samples\n"
    "                     per pixel (map, cosine and GGX importance sampling, deterministic), not the\n"
    "                     preview's image-based lighting; progress on stderr\n"
    "  --wireframe        draw the edges of the drawn triangles over the image (PNG only; not with --reference)\n"
    "  --normals          draw vertex normals as short lines over the image (PNG only; not with --reference)\n"
    "  --probe X,Y        print the surface probe at pixel (X, Y): the chain from each light to the pixel\n"
    "  --overlay NAME     draw a classroom overlay over the PNG (repeatable; one plot per image); NAME is one of:\n";

struct RenderOptions {
    std::string scenePath, outputPath;
    RenderInputOptions input;  // --material, --up
    int width = 0, height = 0, msaa = 0;
    bool reference = false;
    int environmentSamples = 0;  // --samples N: the Monte-Carlo environment (0: the preview's)
    bool wireframe = false, normals = false;
    std::optional<glm::ivec2> probePixel;          // --probe X,Y
    std::vector<const RenderOverlay*> overlays;  // --overlay NAME, in order (the plots among them)
    std::optional<PlotOverlayKind> plot;         // the one plot among the overlays
    PlotOverlayOptions plots;                    // --incidence, --from-inside
};

// Classroom plots' options (cli/plot_overlay.h), after the overlay names.
constexpr const char* kPlotOptionsUsage =
    "  --incidence DEG    incidence angle θ_i of the polar plot, lobe and albedo marker (default 45)\n"
    "  --from-inside      Fresnel plot with the light inside the material (critical angle)\n";

void printUsage(std::FILE* stream) {
    std::fprintf(stream, "%s", kUsage);
    for (const RenderOverlay& overlay : allRenderOverlays()) std::fprintf(stream, "    %-16s %s\n", overlay.name, overlay.help);
    std::fprintf(stream, "%s", kPlotOptionsUsage);
    std::fprintf(stream, "Classroom (README \"Classroom: compare and display chain\"):\n%s", kClassroomUsage);
}

// The compare panes of `scene` rendered and composited (app/classroom/compare_render.h).
Result<RenderedImages> renderCompareView(const ClassroomOptions& classroom, const Scene& scene, Renderer& renderer, int width, int height) {
    auto panes = classroom.paneScenes(scene);
    if (!panes) return panes.error();
    return renderCompare(renderer, *panes, classroom.chosenLayout(), width, height, classroom.divider.value_or(0.5f));
}

int usageError(const std::string& message) {
    std::fprintf(stderr, "glint render: %s\n", message.c_str());
    printUsage(stderr);
    return 2;
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& arguments) {
    RenderOptions options;
    ClassroomOptions classroom;  // display lessons and compare views (classroom_options.h)
    std::string classroomError;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        auto next = [&]() -> const std::string* { return i + 1 < arguments.size() ? &arguments[++i] : nullptr; };
        std::string plotError;  // classroom plots' options first
        if (const PlotOptionMatch plot = parsePlotOverlayOption(arguments, i, options.plots, plotError);
            plot != PlotOptionMatch::NotMine) {
            if (plot == PlotOptionMatch::Error) return usageError(plotError);
            continue;
        }
        if (argument == "-h" || argument == "--help") {
            printUsage(stdout);
            return 0;
        } else if (argument == "-o" || argument == "--output") {
            const std::string* value = next();
            if (!value) return usageError("-o needs a file name");
            options.outputPath = *value;
        } else if (argument == "--size") {
            const std::string* value = next();
            static const std::regex sizePattern(R"((\d{1,5})x(\d{1,5}))");
            std::smatch match;
            if (!value || !std::regex_match(*value, match, sizePattern))
                return usageError("--size needs WIDTHxHEIGHT, e.g. 512x512");
            options.width = std::stoi(match[1]);
            options.height = std::stoi(match[2]);
            if (options.width < 1 || options.height < 1 || options.width > 16384 || options.height > 16384)
                return usageError("--size must be between 1x1 and 16384x16384");
        } else if (argument == "--msaa") {
            const std::string* value = next();
            if (!value || !std::regex_match(*value, std::regex("1|2|4|8|16")))
                return usageError("--msaa needs 1, 2, 4, 8 or 16");
            options.msaa = std::stoi(*value);
        } else if (argument == "--material") {
            const std::string* value = next();
            if (!value || value->empty()) return usageError("--material needs a material's name or index");
            options.input.material = *value;
        } else if (argument == "--up") {
            const std::string* value = next();
            if (!value || (*value != "y" && *value != "z")) return usageError("--up needs y or z");
            options.input.upAxis = *value == "z" ? MeshUpAxis::Z : MeshUpAxis::Y;
        } else if (argument == "--reference") {
            options.reference = true;
        } else if (argument == "--samples") {
            const std::string* value = next();
            if (!value || !std::regex_match(*value, std::regex(R"(\d{1,7})")) || std::stoi(*value) < 1)
                return usageError("--samples needs a positive number of samples per pixel, e.g. 1024");
            options.environmentSamples = std::stoi(*value);
        } else if (argument == "--wireframe") {
            options.wireframe = true;
        } else if (argument == "--normals") {
            options.normals = true;
        } else if (argument == "--probe") {
            const std::string* value = next();
            static const std::regex pointPattern(R"((\d{1,5}),(\d{1,5}))");
            std::smatch match;
            if (!value || !std::regex_match(*value, match, pointPattern))
                return usageError("--probe needs a pixel X,Y, e.g. 128,128");
            options.probePixel = glm::ivec2(std::stoi(match[1]), std::stoi(match[2]));
        } else if (argument == "--overlay") {
            const std::string* value = next();
            const RenderOverlay* overlay = value ? findRenderOverlay(*value) : nullptr;
            if (!overlay) return usageError(value ? "unknown overlay '" + *value + "'" : "--overlay needs a name");
            if (overlay->plot && options.plot)
                return usageError("one plot per image (--overlay " + *value + " given after another plot)");
            if (overlay->plot) options.plot = overlay->plot;
            options.overlays.push_back(overlay);
        } else if (const auto parsed = classroom.parse(arguments, i, classroomError);
                   parsed != ClassroomOptions::Parsed::NotClassroom) {
            if (parsed == ClassroomOptions::Parsed::Refused) return usageError(classroomError);
        } else if (!argument.empty() && argument[0] == '-') {
            return usageError("unknown option " + argument);
        } else if (options.scenePath.empty()) {
            options.scenePath = argument;
        } else {
            return usageError("one scene at a time (got " + options.scenePath + " and " + argument + ")");
        }
    }
    if (options.scenePath.empty()) return usageError("no scene file given");
    if (options.outputPath.empty()) return usageError("no output file given (-o OUT.png or -o OUT.exr)");
    if (options.environmentSamples > 0 && !options.reference)
        return usageError("--samples sets the CPU reference's Monte-Carlo environment: give it with --reference");
    if (options.reference && (options.wireframe || options.normals))
        return usageError("--wireframe and --normals are drawn by the OpenGL renderer, not with --reference");
    if (const std::string conflict = plotOverlayConflict(options.plots, options.plot, options.reference, options.outputPath);
        !conflict.empty())
        return usageError(conflict);
    if (const std::string contradiction = classroom.check(); !contradiction.empty()) return usageError(contradiction);
    if (options.reference && classroom.comparing()) return usageError("the compare views are drawn by the OpenGL renderer, not with --reference");

    std::vector<Diagnostic> warnings;  // what an interchange file could not carry over exactly
    std::vector<std::string> notes;    // what was loaded
    // A material, interchange, .brdf, .bparam or mesh file renders on the preview stage.
    auto scene = loadRenderInput(options.scenePath, options.input, warnings, notes);
    for (const Diagnostic& warning : warnings) std::fprintf(stderr, "glint render: %s\n", warning.format().c_str());
    for (const std::string& note : notes) std::printf("glint render: %s\n", note.c_str());
    if (!scene) {
        std::fprintf(stderr, "glint render: %s\n", scene.error().format().c_str());
        return 2;
    }
    if (options.msaa > 0) scene->msaaSamples = options.msaa;
    scene->display.overlays.wireframe |= options.wireframe;
    scene->display.overlays.normals |= options.normals;
    classroom.applyDisplay(*scene);
    const int width = options.width > 0 ? options.width : scene->width;
    const int height = options.height > 0 ? options.height : scene->height;
    for (const RenderOverlay* overlay : options.overlays)
        if (overlay->needsProbePoint && !options.probePixel)
            return usageError(std::string("--overlay ") + overlay->name + " needs --probe X,Y");
    if (options.probePixel && (options.probePixel->x >= width || options.probePixel->y >= height))
        return usageError("--probe " + std::to_string(options.probePixel->x) + "," + std::to_string(options.probePixel->y) +
                          " lies outside the " + std::to_string(width) + "x" + std::to_string(height) + " image");
    if (!options.overlays.empty() && isFloatImagePath(options.outputPath))
        return usageError("--overlay draws over the display-encoded image: write a PNG, not an EXR or HDR");

    // Custom .brdf shaders: GPU only, and proven to finish in a child process before drawing here.
    if (Status gpuOnly = referenceCanRender(*scene); !gpuOnly && options.reference) {
        std::fprintf(stderr, "glint render: %s\n", gpuOnly.error().format().c_str());
        return 2;
    }
    if (Status probed = probeSceneBrdfs(*scene, brdfProbeTimeoutSeconds()); !probed) {
        std::fprintf(stderr, "glint render: %s\n", probed.error().format().c_str());
        return 2;
    }
    RenderedImages images;
    std::unique_ptr<HeadlessRenderer> headless;  // the GL context: for OpenGL renders and for overlays
    if (!options.reference || !options.overlays.empty()) {
        auto created = HeadlessRenderer::create();
        if (!created) {
            std::fprintf(stderr, "glint render: %s\n", created.error().format().c_str());
            return 2;
        }
        headless = std::move(*created);
        if (!options.reference)
            if (const std::string note = headless->renderer().samplesNote(scene->msaaSamples); !note.empty())
                std::fprintf(stderr, "glint render: note: %s\n", note.c_str());
    }
    if (options.reference) {
        ReferenceOptions reference;
        if (options.environmentSamples > 0) {
            reference.sampleEnvironment = true;
            reference.environmentSamples = options.environmentSamples;
            // Progress for renders long enough to wonder about: whole percents, one line at the end.
            reference.progress = [lastPercent = -1](float done) mutable {
                const int percent = static_cast<int>(done * 100.0f);
                if (percent == lastPercent) return;
                lastPercent = percent;
                std::fprintf(stderr, "\rglint render: reference %3d%%%s", percent, percent == 100 ? "\n" : "");
                std::fflush(stderr);
            };
        }
        images.radiance = renderReference(*scene, width, height, reference);
        images.display = applyDisplayChain(images.radiance, scene->display);
    } else {
        auto rendered = classroom.comparing() ? renderCompareView(classroom, *scene, headless->renderer(), width, height)
                                              : headless->render(*scene, width, height, isFloatImagePath(options.outputPath));
        if (!rendered) {
            std::fprintf(stderr, "glint render: %s\n", rendered.error().format().c_str());
            return 2;
        }
        images = std::move(*rendered);
    }
    // The classroom surface probe (core/classroom/surface_probe.h) and the overlays drawn over the PNG.
    std::optional<ProbeResult> probe;
    if (options.probePixel) {
        probe = probeSurface(*scene, options.probePixel->x, options.probePixel->y, width, height);
        std::printf("%s", probeReport(*probe).c_str());
    }
    if (!options.overlays.empty()) {
        auto composite = drawRenderOverlays(options.overlays, {*scene, width, height, probe, options.plots}, images.display);
        if (!composite) {
            std::fprintf(stderr, "glint render: %s\n", composite.error().format().c_str());
            return 2;
        }
        images.display = std::move(*composite);
    }
    if (Status written = writeRenderedImage(images, options.outputPath); !written) {
        std::fprintf(stderr, "glint render: %s\n", written.error().format().c_str());
        return 2;
    }
    return 0;
}

}  // namespace glint
