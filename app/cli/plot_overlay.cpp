// The classroom plots in `glint render` (see plot_overlay.h): option parsing and drawing over the
// rendered image on the overlay canvas.
#include "cli/plot_overlay.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <imgui.h>

#include "classroom/brdf_plots.h"
#include "classroom/overlay_canvas.h"

namespace glint {
namespace {

constexpr int kPlotOverlayMaxMaterials = 6;

// The distinct materials the objects use, in object order, as plot materials in their colours.
std::vector<PlotMaterial> plotOverlayMaterials(const Scene& scene) {
    std::vector<int> seen;
    std::vector<PlotMaterial> materials;
    for (const SceneObject& object : scene.objects) {
        const int index = object.materialIndex;
        if (index < 0 || index >= static_cast<int>(scene.materials.size())) continue;
        if (std::find(seen.begin(), seen.end(), index) != seen.end()) continue;
        seen.push_back(index);
        if (auto material = plotMaterialFrom(scene.materials[index])) {
            if (static_cast<int>(materials.size()) < kPlotOverlayMaxMaterials) materials.push_back(*material);
        } else {
            std::fprintf(stderr, "glint render: material \"%s\" is a .brdf shader (GPU only) and is left out of the plot\n",
                         scene.materials[index].name.c_str());
        }
    }
    return materials;
}

}  // namespace

PlotOptionMatch parsePlotOverlayOption(const std::vector<std::string>& arguments, size_t& i,
                                       PlotOverlayOptions& options, std::string& error) {
    const std::string& argument = arguments[i];
    const bool hasValue = i + 1 < arguments.size();
    if (argument == "--overlay" && hasValue) {
        static const std::pair<const char*, PlotOverlayKind> kinds[] = {
            {"polar", PlotOverlayKind::Polar}, {"lobe", PlotOverlayKind::Lobe},
            {"albedo", PlotOverlayKind::Albedo}, {"fresnel", PlotOverlayKind::Fresnel}};
        for (const auto& [name, kind] : kinds)
            if (arguments[i + 1] == name) {
                if (options.kind != PlotOverlayKind::None) {
                    error = "one plot per image (--overlay " + arguments[i + 1] + " given after another plot)";
                    return PlotOptionMatch::Error;
                }
                options.kind = kind;
                ++i;
                return PlotOptionMatch::Taken;
            }
        return PlotOptionMatch::NotMine;
    }
    if (argument == "--incidence") {
        char* end = nullptr;
        const float degrees = hasValue ? std::strtof(arguments[i + 1].c_str(), &end) : NAN;
        if (!hasValue || end == arguments[i + 1].c_str() || *end != '\0' || !(degrees >= 0.0f && degrees <= 90.0f)) {
            error = "--incidence needs an angle in degrees from 0 to 90" + (hasValue ? " (got " + arguments[i + 1] + ")" : std::string());
            return PlotOptionMatch::Error;
        }
        options.incidenceDegrees = degrees;
        options.incidenceGiven = true;
        ++i;
        return PlotOptionMatch::Taken;
    }
    if (argument == "--from-inside") {
        options.fromInside = true;
        return PlotOptionMatch::Taken;
    }
    return PlotOptionMatch::NotMine;
}

std::string plotOverlayConflict(const PlotOverlayOptions& options, bool reference, const std::string& outputPath) {
    if (options.kind == PlotOverlayKind::None) {
        if (options.incidenceGiven) return "--incidence needs --overlay polar, lobe or albedo";
        if (options.fromInside) return "--from-inside needs --overlay fresnel";
        return "";
    }
    if (reference) return "--overlay plots are drawn with OpenGL, not with --reference";
    std::string extension = outputPath.size() >= 4 ? outputPath.substr(outputPath.size() - 4) : "";
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    if (extension != ".png") return "--overlay plots are drawn on the PNG (-o OUT.png), not into radiance";
    if (options.fromInside && options.kind != PlotOverlayKind::Fresnel) return "--from-inside needs --overlay fresnel";
    if (options.incidenceGiven && options.kind == PlotOverlayKind::Fresnel) return "--incidence is not used by --overlay fresnel";
    return "";
}

Status drawPlotOverlay(const Scene& scene, const PlotOverlayOptions& options, DisplayImage& image) {
    const std::vector<PlotMaterial> materials = plotOverlayMaterials(scene);
    if (materials.empty()) return makeError("the scene has no object with a built-in material to plot");
    std::optional<FresnelCurves> fresnel;
    std::string fresnelName;
    if (options.kind == PlotOverlayKind::Fresnel) {
        for (const PlotMaterial& material : materials)
            if (auto index = materialComplexIndex(material)) {
                fresnel = fresnelCurves(*index, options.fromInside);
                fresnelName = material.name;
                break;
            }
        if (!fresnel) return makeError("no material in the scene has an index of refraction (n, κ) for --overlay fresnel");
    }
    std::vector<PlottedMaterial> plotted;
    for (size_t i = 0; i < materials.size(); ++i)
        plotted.push_back(computePlottedMaterial(materials[i], plotSeriesColour(static_cast<int>(i)), options.incidenceDegrees));

    // Text 1/20 of the shorter side, 13 to 28 pixels.
    const float fontPixels = std::clamp(static_cast<float>(std::min(image.width, image.height)) / 20.0f, 13.0f, 28.0f);
    auto canvas = OverlayCanvas::create(fontPixels);
    if (!canvas) return canvas.error();
    (*canvas)->begin(image.width, image.height);
    ImDrawList* drawList = ImGui::GetBackgroundDrawList();
    const ImVec2 topLeft(2, 2), bottomRight(static_cast<float>(image.width) - 2, static_cast<float>(image.height) - 2);
    switch (options.kind) {
        case PlotOverlayKind::Polar: drawPolarPlot(drawList, topLeft, bottomRight, plotted); break;
        case PlotOverlayKind::Lobe: drawLobePlot(drawList, topLeft, bottomRight, plotted, -0.6f, 0.45f); break;
        case PlotOverlayKind::Albedo: drawAlbedoPlot(drawList, topLeft, bottomRight, plotted); break;
        case PlotOverlayKind::Fresnel: drawFresnelPlot(drawList, topLeft, bottomRight, *fresnel, fresnelName); break;
        case PlotOverlayKind::None: break;
    }
    auto composite = (*canvas)->finish(image);
    if (!composite) return composite.error();
    image = std::move(*composite);
    return success();
}

}  // namespace glint
