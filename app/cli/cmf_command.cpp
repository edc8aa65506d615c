// `glint cmf`: one OSMesa context (HeadlessRenderer), one OverlayCanvas, drawCmfPlot into its
// background draw list, and the PNG written. The plot itself lives in app/classroom/cmf_plot.cpp.
#include "cli/commands.h"

#include <imgui.h>

#include <algorithm>
#include <memory>
#include <string>
#include <utility>

#include "classroom/cmf_plot.h"
#include "classroom/overlay_canvas.h"
#include "cli/command_line.h"
#include "runtime/headless.h"
#include "image/image_io.h"

namespace glint {
namespace {

int plotCmf(const std::string& outputPath, int width, int height) {
    auto headless = HeadlessRenderer::create();  // makes the OSMesa context current
    if (!headless) return commandFailed("cmf", headless.error().format());
    const float fontSize = std::max(12.0f, height / 25.0f);
    auto canvas = OverlayCanvas::create(fontSize);
    if (!canvas) return commandFailed("cmf", canvas.error().format());
    (*canvas)->begin(width, height);
    drawCmfPlot(ImGui::GetBackgroundDrawList(), ImVec2(0.0f, 0.0f), ImVec2(static_cast<float>(width), static_cast<float>(height)), fontSize);
    auto image = (*canvas)->finish(DisplayImage{});
    if (!image) return commandFailed("cmf", image.error().format());
    if (Status written = writeDisplayImage(*image, outputPath); !written) return commandFailed("cmf", written.error().format());
    return 0;
}

}  // namespace

void addCmfCommand(CLI::App& glint) {
    auto outputPath = std::make_shared<std::string>();
    auto size = std::make_shared<std::pair<int, int>>(640, 400);
    CLI::App* command = addCommand(glint, "cmf", "plot the CIE 1931 colour matching functions headless",
                                   [=] { return plotCmf(*outputPath, size->first, size->second); });
    command->footer("The CIE 1931 2° colour matching functions x̄, ȳ, z̄ (Wyman, Sloan & Shirley 2013 fit) over 380-780 nm.");
    command->add_option("-o,--output", *outputPath, "the PNG to write")->required()->type_name("OUT.png");
    addPixelSize(*command, size->first, size->second, 128, 4096, "image size in pixels (default 640x400)");
}

}  // namespace glint
