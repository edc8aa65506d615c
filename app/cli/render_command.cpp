// `glint render` (see render_command.h).
#include "cli/render_command.h"

#include <cstdio>
#include <regex>

#include "cli/brdf_probe.h"
#include "cli/headless.h"
#include "display/display_chain.h"
#include "render/reference_renderer.h"
#include "snapshot/case_source.h"

namespace glint {
namespace {

constexpr const char* kUsage =
    "usage: glint render SCENE.json -o OUT.png|OUT.exr [--size WxH] [--msaa N] [--reference] [--wireframe] [--normals]\n"
    "  SCENE.json         a scene, or a material file (rendered on the preview stage, 256x256);\n"
    "                     also a Wavefront .mtl, a glTF .gltf (its first material on the stage),\n"
    "                     a MERL measured BRDF .binary (preview stage)\n"
    "                     or a BRDF Explorer .brdf file (preview stage, GPU only)\n"
    "  -o, --output FILE  PNG (display-encoded, 8-bit) or EXR (linear radiance, W/(sr·m²))\n"
    "  --size WxH         output size in pixels (default: the scene's \"output\")\n"
    "  --msaa N           multisample anti-aliasing with N samples (1 = off)\n"
    "  --reference        render with the CPU reference ray caster instead of OpenGL\n"
    "  --wireframe        draw the edges of the drawn triangles over the image (PNG only; not with --reference)\n"
    "  --normals          draw vertex normals as short lines over the image (PNG only; not with --reference)\n";

struct RenderOptions {
    std::string scenePath, outputPath;
    int width = 0, height = 0, msaa = 0;
    bool reference = false;
    bool wireframe = false, normals = false;
};

int usageError(const std::string& message) {
    std::fprintf(stderr, "glint render: %s\n%s", message.c_str(), kUsage);
    return 2;
}

}  // namespace

int runRenderCommand(const std::vector<std::string>& arguments) {
    RenderOptions options;
    for (size_t i = 0; i < arguments.size(); ++i) {
        const std::string& argument = arguments[i];
        auto next = [&]() -> const std::string* { return i + 1 < arguments.size() ? &arguments[++i] : nullptr; };
        if (argument == "-h" || argument == "--help") {
            std::printf("%s", kUsage);
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
        } else if (argument == "--reference") {
            options.reference = true;
        } else if (argument == "--wireframe") {
            options.wireframe = true;
        } else if (argument == "--normals") {
            options.normals = true;
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
    if (options.reference && (options.wireframe || options.normals))
        return usageError("--wireframe and --normals are drawn by the OpenGL renderer, not with --reference");

    std::vector<Diagnostic> warnings;  // what an interchange file could not carry over exactly
    // A material, interchange or .brdf file renders on the preview stage.
    auto scene = isBrdfFilePath(options.scenePath) ? loadBrdfPreviewStage(options.scenePath)
                                                   : loadRenderable(options.scenePath, 0, 0, &warnings);
    for (const Diagnostic& warning : warnings) std::fprintf(stderr, "glint render: %s\n", warning.format().c_str());
    if (!scene) {
        std::fprintf(stderr, "glint render: %s\n", scene.error().format().c_str());
        return 2;
    }
    if (options.msaa > 0) scene->msaaSamples = options.msaa;
    scene->display.overlays.wireframe |= options.wireframe;
    scene->display.overlays.normals |= options.normals;
    const int width = options.width > 0 ? options.width : scene->width;
    const int height = options.height > 0 ? options.height : scene->height;

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
    if (options.reference) {
        images.radiance = renderReference(*scene, width, height);
        images.display = applyDisplayChain(images.radiance, scene->display);
    } else {
        auto headless = HeadlessRenderer::create();
        if (!headless) {
            std::fprintf(stderr, "glint render: %s\n", headless.error().format().c_str());
            return 2;
        }
        auto rendered = (*headless)->render(*scene, width, height);
        if (!rendered) {
            std::fprintf(stderr, "glint render: %s\n", rendered.error().format().c_str());
            return 2;
        }
        images = std::move(*rendered);
    }
    if (Status written = writeRenderedImage(images, options.outputPath); !written) {
        std::fprintf(stderr, "glint render: %s\n", written.error().format().c_str());
        return 2;
    }
    return 0;
}

}  // namespace glint
