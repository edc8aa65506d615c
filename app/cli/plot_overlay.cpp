// The classroom plots in `glint render` (see plot_overlay.h): their options and checks, and
// drawing on the overlay canvas's ImGui context.
#include "cli/plot_overlay.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

#include <imgui.h>

#include "classroom/brdf_plots.h"
#include "classroom/plot_materials.h"
#include "cli/command_line.h"
#include "util/text.h"

namespace glint {
namespace {

constexpr int kPlotOverlayMaxMaterials = 6;

// The distinct materials the objects use, in object order, as plot materials (.brdf ones sampled
// through `sampler`).
std::vector<PlotMaterial> plotOverlayMaterials(const Scene& scene, BrdfSampler& sampler) {
    std::vector<int> seen;
    std::vector<PlotMaterial> materials;
    for (const SceneObject& object : scene.objects) {
        const int index = object.materialIndex;
        if (index < 0 || index >= static_cast<int>(scene.materials.size())) continue;
        if (std::find(seen.begin(), seen.end(), index) != seen.end()) continue;
        seen.push_back(index);
        if (auto material = plotMaterialFor(scene.materials[index], sampler)) {
            if (static_cast<int>(materials.size()) < kPlotOverlayMaxMaterials) materials.push_back(std::move(*material));
        } else {
            std::fprintf(stderr, "glint render: material \"%s\" is left out of the plot: %s\n",
                         scene.materials[index].name.c_str(), material.error().format().c_str());
        }
    }
    return materials;
}

}  // namespace

void addPlotOverlayOptions(CLI::App& command, PlotOverlayOptions& options) {
    command
        .add_option_function<std::string>(
            "--incidence",
            [&options](const std::string& value) {
                options.incidenceDegrees = std::strtof(value.c_str(), nullptr);
                options.incidenceGiven = true;
            },
            "incidence angle θ_i of the polar plot, lobe and albedo marker (default 45)")
        ->check(needs("an angle in degrees from 0 to 90", [](const std::string& value) {
            char* end = nullptr;
            const float degrees = std::strtof(value.c_str(), &end);
            return end != value.c_str() && *end == '\0' && degrees >= 0.0f && degrees <= 90.0f;
        }))
        ->type_name("DEG");
    command.add_flag("--from-inside", options.fromInside, "Fresnel plot with the light inside the material (critical angle)");
}

std::string plotOverlayConflict(const PlotOverlayOptions& options, std::optional<PlotOverlayKind> plot, bool reference,
                                const std::string& outputPath) {
    if (!plot) {
        if (options.incidenceGiven) return "--incidence needs --overlay polar, lobe or albedo";
        if (options.fromInside) return "--from-inside needs --overlay fresnel";
        return "";
    }
    if (reference) return "--overlay plots are drawn with OpenGL, not with --reference";
    if (lowerExtension(outputPath) != "png") return "--overlay plots are drawn on the PNG (-o OUT.png), not into radiance";
    if (options.fromInside && *plot != PlotOverlayKind::Fresnel) return "--from-inside needs --overlay fresnel";
    if (options.incidenceGiven && *plot == PlotOverlayKind::Fresnel) return "--incidence is not used by --overlay fresnel";
    return "";
}

float plotOverlayFontPixels(int width, int height) {
    return std::clamp(static_cast<float>(std::min(width, height)) / 20.0f, 13.0f, 28.0f);
}

Status drawPlotOverlay(const Scene& scene, PlotOverlayKind kind, const PlotOverlayOptions& options, int width, int height) {
    BrdfSampler sampler(defaultShaderSources());
    const std::vector<PlotMaterial> materials = plotOverlayMaterials(scene, sampler);
    if (materials.empty()) return makeError("the scene has no object with a material to plot");
    std::optional<FresnelCurves> fresnel;
    std::string fresnelName;
    if (kind == PlotOverlayKind::Fresnel) {
        std::string whyNone;  // a measured or .brdf material: why it gives no curve
        for (const PlotMaterial& material : materials) {
            if (auto index = materialComplexIndex(material)) {
                fresnel = fresnelCurves(*index, options.fromInside);
                fresnelName = material.name;
                break;
            }
            if (const std::string kind = kindWithoutIndex(material); whyNone.empty() && !kind.empty())
                whyNone = " (\"" + material.name + "\" is " + kind + ": it has no index to plot)";
        }
        if (!fresnel) return makeError("no material in the scene has an index of refraction (n, κ) for --overlay fresnel" + whyNone);
    }
    std::vector<PlottedMaterial> plotted;
    for (size_t i = 0; i < materials.size(); ++i)
        plotted.push_back(computePlottedMaterial(materials[i], plotSeriesColour(static_cast<int>(i)), options.incidenceDegrees));

    ImDrawList* drawList = ImGui::GetBackgroundDrawList();
    const ImVec2 topLeft(2, 2), bottomRight(static_cast<float>(width) - 2, static_cast<float>(height) - 2);
    switch (kind) {
        case PlotOverlayKind::Polar: drawPolarPlot(drawList, topLeft, bottomRight, plotted); break;
        case PlotOverlayKind::Lobe: drawLobePlot(drawList, topLeft, bottomRight, plotted, -0.6f, 0.45f); break;
        case PlotOverlayKind::Albedo: drawAlbedoPlot(drawList, topLeft, bottomRight, plotted); break;
        case PlotOverlayKind::Fresnel: drawFresnelPlot(drawList, topLeft, bottomRight, *fresnel, fresnelName); break;
    }
    return success();
}

}  // namespace glint
