// `glint cmf`: one OSMesa context (HeadlessRenderer), one OverlayCanvas, drawCmfPlot into its
// background draw list, and the PNG written. The plot itself lives in app/classroom/cmf_plot.cpp.
#include "cli/cmf_command.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "classroom/cmf_plot.h"
#include "classroom/overlay_canvas.h"
#include "cli/command_options.h"
#include "cli/headless.h"
#include "image/image_io.h"

namespace glint {
namespace {

constexpr const char* kCmfUsage =
    "usage: glint cmf -o OUT.png [--size WxH]\n"
    "  the CIE 1931 2° colour matching functions x̄, ȳ, z̄ (Wyman, Sloan & Shirley 2013 fit) over 380-780 nm\n"
    "  --size WxH   image size in pixels (default 640x400)\n";

}  // namespace

int runCmfCommand(const std::vector<std::string>& arguments) {
    std::string outputPath;
    int width = 640, height = 400;
    const std::vector<CommandOption> options = {
        {{"-o", "--output"}, "a file name", [&](const std::string& value) { outputPath = value; return std::string(); }},
        {{"--size"}, "WIDTHxHEIGHT", pixelSizeOption(width, height, 128, 4096, "--size needs WIDTHxHEIGHT from 128x128 to 4096x4096")},
    };
    auto parsed = parseCommandOptions(arguments, options, "argument");
    if (!parsed || (!parsed->help && (outputPath.empty() || !parsed->positionals.empty()))) {
        std::fprintf(stderr, "glint cmf: %s\n%s", parsed ? "needs -o OUT.png and nothing else" : parsed.error().format().c_str(), kCmfUsage);
        return 2;
    }
    if (parsed->help) {
        std::printf("%s", kCmfUsage);
        return 0;
    }
    auto headless = HeadlessRenderer::create();  // makes the OSMesa context current
    if (!headless) {
        std::fprintf(stderr, "glint cmf: %s\n", headless.error().format().c_str());
        return 2;
    }
    const float fontSize = std::max(12.0f, height / 25.0f);
    auto canvas = OverlayCanvas::create(fontSize);
    if (!canvas) {
        std::fprintf(stderr, "glint cmf: %s\n", canvas.error().format().c_str());
        return 2;
    }
    (*canvas)->begin(width, height);
    drawCmfPlot(ImGui::GetBackgroundDrawList(), ImVec2(0.0f, 0.0f), ImVec2(static_cast<float>(width), static_cast<float>(height)), fontSize);
    auto image = (*canvas)->finish(DisplayImage{});
    if (!image) {
        std::fprintf(stderr, "glint cmf: %s\n", image.error().format().c_str());
        return 2;
    }
    if (Status written = writeDisplayImage(*image, outputPath); !written) {
        std::fprintf(stderr, "glint cmf: %s\n", written.error().format().c_str());
        return 2;
    }
    return 0;
}

}  // namespace glint
