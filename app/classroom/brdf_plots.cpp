// The classroom plots drawn with ImGui draw lists (see brdf_plots.h).
// Section index: shared helpers · series and data · polar plot · 3D lobe · albedo · Fresnel.
#include "classroom/brdf_plots.h"

#include <algorithm>
#include <cmath>

#include "math/constants.h"
#include "util/text.h"

namespace glint {
namespace {

// ---- shared helpers ------------------------------------------------------------------------

constexpr ImU32 kPlotBackground = IM_COL32(18, 20, 26, 235);
constexpr ImU32 kPlotGrid = IM_COL32(90, 96, 110, 255);
constexpr ImU32 kPlotAxis = IM_COL32(190, 195, 205, 255);
constexpr ImU32 kPlotText = IM_COL32(225, 228, 235, 255);
constexpr ImU32 kPlotLight = IM_COL32(255, 215, 60, 255);
constexpr ImU32 kPlotWarning = IM_COL32(255, 70, 60, 255);
constexpr float kPlotRadians = kPi / 180.0f;

void plotFrame(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, const std::string& title) {
    drawList->AddRectFilled(topLeft, bottomRight, kPlotBackground, 4.0f);
    drawList->AddText(ImVec2(topLeft.x + 6, topLeft.y + 4), kPlotText, title.c_str());
}

// An arrow from `from` to `to` with a filled head.
void plotArrow(ImDrawList* drawList, ImVec2 from, ImVec2 to, ImU32 colour, float thickness = 2.0f) {
    drawList->AddLine(from, to, colour, thickness);
    const float dx = to.x - from.x, dy = to.y - from.y;
    const float length = std::sqrt(dx * dx + dy * dy);
    if (length < 1.0f) return;
    const float ux = dx / length, uy = dy / length, head = std::min(10.0f, 0.4f * length);
    drawList->AddTriangleFilled(to, ImVec2(to.x - ux * head - uy * head * 0.45f, to.y - uy * head + ux * head * 0.45f),
                                ImVec2(to.x - ux * head + uy * head * 0.45f, to.y - uy * head - ux * head * 0.45f), colour);
}

// Dashed polyline: `dash` pixels drawn, `dash` pixels skipped.
void plotDashedPolyline(ImDrawList* drawList, const std::vector<ImVec2>& points, ImU32 colour, float thickness, float dash) {
    float travelled = 0.0f;
    for (size_t i = 1; i < points.size(); ++i) {
        const ImVec2 a = points[i - 1], b = points[i];
        const float length = std::hypot(b.x - a.x, b.y - a.y);
        if (std::fmod(travelled, 2.0f * dash) < dash) drawList->AddLine(a, b, colour, thickness);
        travelled += std::max(length, 0.5f);
    }
}

// Text at `at`, moved left so that it ends inside the frame.
void plotLabel(ImDrawList* drawList, ImVec2 at, ImVec2 bottomRight, ImU32 colour, const std::string& text) {
    at.x = std::min(at.x, bottomRight.x - ImGui::CalcTextSize(text.c_str()).x - 4.0f);
    drawList->AddText(at, colour, text.c_str());
}

// Names of the overlaid materials in their colours, from `at` downwards.
void plotLegend(ImDrawList* drawList, ImVec2 at, std::span<const PlottedMaterial> materials) {
    const float lineHeight = ImGui::GetTextLineHeight();
    for (const PlottedMaterial& plotted : materials) {
        drawList->AddRectFilled(ImVec2(at.x, at.y + lineHeight * 0.3f), ImVec2(at.x + 14, at.y + lineHeight * 0.7f), plotted.colour);
        drawList->AddText(ImVec2(at.x + 18, at.y), kPlotText, plotted.material.name.c_str());
        at.y += lineHeight;
    }
}

// A graph area inside the frame: x from 0° to 90°, y from 0 to yMax, with ticks and labels.
struct PlotGraph {
    ImVec2 origin, size;  // origin: bottom-left of the graph area
    float yMax = 1.0f;
    ImVec2 at(float degrees, float value) const {
        return ImVec2(origin.x + size.x * degrees / 90.0f, origin.y - size.y * std::min(value, yMax * 1.02f) / yMax);
    }
};

// headerLines: text lines above the graph (the title and, for Fresnel, a legend and the angles).
PlotGraph plotAngleGraph(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, float yMax, const char* xLabel,
                         float headerLines = 1.8f) {
    const float line = ImGui::GetTextLineHeight();
    PlotGraph graph;
    graph.origin = ImVec2(topLeft.x + 3.2f * line, bottomRight.y - 2.2f * line);
    graph.size = ImVec2(bottomRight.x - graph.origin.x - line, graph.origin.y - topLeft.y - headerLines * line);
    graph.yMax = yMax;
    for (int degrees = 0; degrees <= 90; degrees += 15) {
        const ImVec2 base = graph.at(static_cast<float>(degrees), 0.0f);
        drawList->AddLine(base, ImVec2(base.x, base.y - graph.size.y), kPlotGrid);
        if (degrees % 30 == 0) {
            const std::string label = formatNumber(degrees, "%.0f°");
            drawList->AddText(ImVec2(base.x - line * 0.5f, base.y + 2), kPlotText, label.c_str());
        }
    }
    const float step = yMax > 1.5f ? 0.5f : 0.25f;
    for (float value = 0.0f; value <= yMax + 1e-4f; value += step) {
        const ImVec2 left = graph.at(0.0f, value);
        drawList->AddLine(left, ImVec2(left.x + graph.size.x, left.y), kPlotGrid);
        const std::string label = formatNumber(value, "%.2f");
        drawList->AddText(ImVec2(topLeft.x + 4, left.y - line * 0.5f), kPlotText, label.c_str());
    }
    drawList->AddRect(ImVec2(graph.origin.x, graph.origin.y - graph.size.y), ImVec2(graph.origin.x + graph.size.x, graph.origin.y), kPlotAxis);
    drawList->AddText(ImVec2(graph.origin.x + graph.size.x * 0.5f - 2.0f * line, bottomRight.y - 1.1f * line), kPlotText, xLabel);
    return graph;
}

}  // namespace

// ---- series and data -----------------------------------------------------------------------

ImU32 plotSeriesColour(int index) {
    static constexpr ImU32 kPalette[] = {IM_COL32(90, 200, 255, 255), IM_COL32(255, 140, 60, 255),
                                         IM_COL32(120, 230, 110, 255), IM_COL32(235, 110, 235, 255),
                                         IM_COL32(250, 240, 120, 255), IM_COL32(200, 200, 200, 255)};
    return kPalette[static_cast<size_t>(index) % std::size(kPalette)];
}

PlottedMaterial computePlottedMaterial(const PlotMaterial& material, ImU32 colour, float incidenceDegrees) {
    PlottedMaterial plotted;
    plotted.material = material;
    plotted.colour = colour;
    plotted.polar = polarPlotData(material, incidenceDegrees);
    plotted.lobe = lobeMesh(material, incidenceDegrees);
    plotted.delta = deltaLobes(material, incidenceDegrees);
    plotted.albedo = albedoCurve(material);
    return plotted;
}

// ---- polar plot ----------------------------------------------------------------------------

void drawPolarPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, std::span<const PlottedMaterial> materials) {
    const float incidenceDegrees = materials.empty() ? 0.0f : materials.front().polar.incidenceDegrees;
    float largest = 0.0f;
    bool anyTransmission = false;
    for (const PlottedMaterial& plotted : materials) {
        for (const glm::vec3& value : plotted.polar.cosineWeighted) largest = std::max(largest, plotLuminance(value));
        anyTransmission |= plotted.delta.hasTransmission;
    }
    plotFrame(drawList, topLeft, bottomRight,
              "f_r·cos θ_o [1/sr] in plane, θ_i = " + formatNumber(incidenceDegrees, "%.0f°"));
    const float line = ImGui::GetTextLineHeight();
    const float width = bottomRight.x - topLeft.x, height = bottomRight.y - topLeft.y;
    const float surfaceFraction = anyTransmission ? 0.62f : 0.86f;
    const ImVec2 centre(topLeft.x + 0.5f * width, topLeft.y + surfaceFraction * height);
    const float radius = std::max(10.0f, std::min(0.5f * width - 1.5f * line, centre.y - topLeft.y - 2.6f * line));
    const float scale = largest > 0.0f ? radius / largest : radius;  // pixels per 1/sr
    auto toScreen = [&](glm::vec3 local, float pixelsPerUnit) {
        return ImVec2(centre.x + local.x * pixelsPerUnit, centre.y - local.z * pixelsPerUnit);
    };
    // Rings at quarters of the largest value, spokes every 30° with θ_o labels.
    for (int ring = 1; ring <= 4; ++ring) {
        const float r = radius * static_cast<float>(ring) / 4.0f;
        drawList->PathArcTo(centre, r, kPi, 2.0f * kPi, 48);
        drawList->PathStroke(kPlotGrid, 0, 1.0f);
    }
    if (largest > 0.0f) {
        const std::string top = formatNumber(largest, "%.3g");
        drawList->AddText(ImVec2(centre.x + 3, centre.y - radius - line), kPlotText, top.c_str());
    }
    for (int degrees = -90; degrees <= 90; degrees += 30) {
        const glm::vec3 direction = plotOutgoingDirection(static_cast<float>(degrees) * kPlotRadians);
        drawList->AddLine(centre, toScreen(direction, radius), kPlotGrid);
        const std::string label = formatNumber(degrees, "%.0f°");
        const ImVec2 at = toScreen(direction, radius + 0.9f * line);
        drawList->AddText(ImVec2(at.x - line * 0.8f, at.y - line * 0.5f), kPlotText, label.c_str());
    }
    drawList->AddLine(ImVec2(topLeft.x + 4, centre.y), ImVec2(bottomRight.x - 4, centre.y), kPlotAxis, 2.0f);
    // The light arrives along −ω_i.
    const glm::vec3 incident = plotIncidentDirection(incidenceDegrees * kPlotRadians);
    plotArrow(drawList, toScreen(incident, radius * 1.05f), centre, kPlotLight, 2.0f);
    drawList->AddText(toScreen(incident, radius * 0.55f), kPlotLight, "ω_i");
    for (const PlottedMaterial& plotted : materials) {
        std::vector<ImVec2> points;
        for (size_t i = 0; i < plotted.polar.outgoingDegrees.size(); ++i) {
            const glm::vec3 direction = plotOutgoingDirection(plotted.polar.outgoingDegrees[i] * kPlotRadians);
            points.push_back(toScreen(direction * plotLuminance(plotted.polar.cosineWeighted[i]), scale));
        }
        drawList->AddPolyline(points.data(), static_cast<int>(points.size()), plotted.colour, 0, 2.0f);
        // Delta lobes: arrows whose length is the weight (1 = the outer ring, or the space below).
        const DeltaLobes& delta = plotted.delta;
        if (delta.hasReflection) {
            const float weight = plotLuminance(delta.reflectedWeight);
            const ImVec2 tip = toScreen(delta.reflectedDirection, radius * std::max(weight, 0.05f));
            plotArrow(drawList, centre, tip, plotted.colour, 2.5f);
            plotLabel(drawList, ImVec2(tip.x + 4, tip.y - line), bottomRight, plotted.colour, formatNumber(weight, "R %.3f"));
        }
        if (delta.hasTransmission) {
            const float weight = plotLuminance(delta.transmittedWeight);
            const float room = bottomRight.y - centre.y - 1.2f * line;
            const ImVec2 tip = toScreen(delta.transmittedDirection, room * std::max(weight, 0.05f));
            plotArrow(drawList, centre, tip, plotted.colour, 2.5f);
            const std::string label = formatNumber(weight, "T %.3f") + formatNumber(delta.transmittedDegrees, ", θ_t %.1f°");
            plotLabel(drawList, ImVec2(tip.x + 4, tip.y - 0.5f * line), bottomRight, plotted.colour, label);
        }
    }
    if (anyTransmission)
        drawList->AddText(ImVec2(topLeft.x + 6, centre.y + 4), kPlotText, "transmitted");
    plotLegend(drawList, ImVec2(topLeft.x + 6, topLeft.y + 4 + line), materials);
}

// ---- 3D lobe -------------------------------------------------------------------------------

void drawLobePlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, std::span<const PlottedMaterial> materials,
                  float yawRadians, float pitchRadians) {
    const float incidenceDegrees = materials.empty() ? 0.0f : materials.front().lobe.incidenceDegrees;
    float largest = 0.0f;
    for (const PlottedMaterial& plotted : materials) largest = std::max(largest, plotted.lobe.largestRadius);
    plotFrame(drawList, topLeft, bottomRight, "lobe: f_r·cos θ_o [1/sr], θ_i = " + formatNumber(incidenceDegrees, "%.0f°"));
    const float line = ImGui::GetTextLineHeight();
    const float width = bottomRight.x - topLeft.x, height = bottomRight.y - topLeft.y;
    const ImVec2 centre(topLeft.x + 0.5f * width, topLeft.y + 0.62f * height);
    const float radius = std::max(10.0f, std::min(0.42f * width, 0.45f * height));
    const float scale = largest > 0.0f ? radius / largest : radius;
    const float cosYaw = std::cos(yawRadians), sinYaw = std::sin(yawRadians);
    const float cosPitch = std::cos(pitchRadians), sinPitch = std::sin(pitchRadians);
    // Orthographic view: turn about the normal (z), tilt about the screen's x axis; z is up.
    auto project = [&](glm::vec3 local, float pixelsPerUnit) {
        const float x = local.x * cosYaw - local.y * sinYaw;
        const float y = local.x * sinYaw + local.y * cosYaw;
        const float up = y * sinPitch + local.z * cosPitch;
        return ImVec2(centre.x + x * pixelsPerUnit, centre.y - up * pixelsPerUnit);
    };
    // The surface: a disc outline of the lobe's size with the plane of incidence and the normal.
    drawList->PathClear();
    for (int i = 0; i < 64; ++i) {
        const float phi = 2.0f * kPi * static_cast<float>(i) / 64.0f;
        drawList->PathLineTo(project(glm::vec3(std::cos(phi), std::sin(phi), 0.0f), radius));
    }
    drawList->PathStroke(kPlotAxis, ImDrawFlags_Closed, 1.5f);
    drawList->AddLine(project(glm::vec3(-1, 0, 0), radius), project(glm::vec3(1, 0, 0), radius), kPlotGrid);
    plotArrow(drawList, centre, project(glm::vec3(0, 0, 1), radius), kPlotAxis, 1.5f);
    drawList->AddText(project(glm::vec3(0, 0, 1.05f), radius), kPlotText, "N");
    const glm::vec3 incident = plotIncidentDirection(incidenceDegrees * kPlotRadians);
    plotArrow(drawList, project(incident, radius * 1.1f), centre, kPlotLight, 2.0f);
    drawList->AddText(project(incident, radius * 1.15f), kPlotLight, "ω_i");
    for (const PlottedMaterial& plotted : materials) {
        const LobeMesh& lobe = plotted.lobe;
        const ImU32 faint = (plotted.colour & 0x00FFFFFFu) | (150u << IM_COL32_A_SHIFT);
        for (int t = 1; t <= lobe.thetaSteps; t += 2) {  // rings of constant θ_o
            drawList->PathClear();
            for (int p = 0; p < lobe.phiSteps; ++p) drawList->PathLineTo(project(lobe.point(t, p), scale));
            drawList->PathStroke(faint, ImDrawFlags_Closed, 1.0f);
        }
        for (int p = 0; p < lobe.phiSteps; p += 2) {  // meridians of constant φ_o
            drawList->PathClear();
            for (int t = 0; t <= lobe.thetaSteps; ++t) drawList->PathLineTo(project(lobe.point(t, p), scale));
            drawList->PathStroke(plotted.colour, 0, 1.0f);
        }
        // Delta lobes as arrows of length weight × the disc radius; transmission goes below.
        if (plotted.delta.hasReflection)
            plotArrow(drawList, centre, project(plotted.delta.reflectedDirection * plotLuminance(plotted.delta.reflectedWeight), radius),
                      plotted.colour, 2.5f);
        if (plotted.delta.hasTransmission) {
            const float weight = plotLuminance(plotted.delta.transmittedWeight);
            const ImVec2 tip = project(plotted.delta.transmittedDirection * weight * 0.6f, radius);
            plotArrow(drawList, centre, tip, plotted.colour, 2.5f);
            drawList->AddText(ImVec2(tip.x + 4, tip.y - 0.5f * line), plotted.colour, formatNumber(weight, "T %.3f").c_str());
        }
    }
    if (largest > 0.0f)
        drawList->AddText(ImVec2(topLeft.x + 6, bottomRight.y - 1.2f * line), kPlotText,
                          ("largest " + formatNumber(largest, "%.3g /sr")).c_str());
    plotLegend(drawList, ImVec2(topLeft.x + 6, topLeft.y + 4 + line), materials);
}

// ---- albedo --------------------------------------------------------------------------------

void drawAlbedoPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, std::span<const PlottedMaterial> materials) {
    float largest = 0.0f;
    std::vector<std::string> warnings;  // red, under the title
    for (const PlottedMaterial& plotted : materials) {
        largest = std::max(largest, plotted.albedo.largestAlbedo);
        if (plotted.albedo.exceedsOne)
            warnings.push_back("ρ > 1: " + plotted.material.name + formatNumber(plotted.albedo.largestAlbedo, " (up to %.2f)"));
    }
    // Up to 2: a curve that climbs further (the lecture Phong at grazing) leaves through the top.
    const float yMax = std::min(2.0f, std::ceil(std::max(1.25f, largest * 1.05f) * 4.0f) / 4.0f);
    plotFrame(drawList, topLeft, bottomRight, "albedo ρ(θ_i) = ∫ f_r cos θ_o dω_o");
    const float line = ImGui::GetTextLineHeight();
    for (size_t i = 0; i < warnings.size(); ++i)
        drawList->AddText(ImVec2(topLeft.x + 6, topLeft.y + 4 + line * static_cast<float>(i + 1)), kPlotWarning, warnings[i].c_str());
    const PlotGraph graph = plotAngleGraph(drawList, topLeft, bottomRight, yMax, "θ_i", 1.8f + static_cast<float>(warnings.size()));
    drawList->PushClipRect(ImVec2(graph.origin.x, graph.origin.y - graph.size.y), ImVec2(graph.origin.x + graph.size.x, graph.origin.y), true);
    const ImVec2 one = graph.at(0.0f, 1.0f);
    drawList->AddLine(one, ImVec2(one.x + graph.size.x, one.y), IM_COL32(240, 240, 240, 255), 1.5f);
    drawList->AddText(ImVec2(one.x + graph.size.x - 3.0f * line, one.y - line), kPlotText, "ρ = 1");
    if (!materials.empty()) {
        const ImVec2 now = graph.at(materials.front().polar.incidenceDegrees, 0.0f);
        drawList->AddLine(now, ImVec2(now.x, now.y - graph.size.y), kPlotLight, 1.0f);
    }
    for (const PlottedMaterial& plotted : materials) {
        const AlbedoCurve& curve = plotted.albedo;
        std::vector<ImVec2> channels[3], luminance;
        for (size_t i = 0; i < curve.albedo.size(); ++i) {
            for (int c = 0; c < 3; ++c) channels[c].push_back(graph.at(curve.incidenceDegrees[i], curve.albedo[i][c]));
            luminance.push_back(graph.at(curve.incidenceDegrees[i], plotLuminance(curve.albedo[i])));
        }
        if (materials.size() == 1) {  // one material: its R, G and B channels too
            static constexpr ImU32 kChannelColours[] = {IM_COL32(255, 80, 80, 200), IM_COL32(80, 230, 80, 200), IM_COL32(90, 140, 255, 200)};
            for (int c = 0; c < 3; ++c) drawList->AddPolyline(channels[c].data(), static_cast<int>(channels[c].size()), kChannelColours[c], 0, 1.0f);
        }
        drawList->AddPolyline(luminance.data(), static_cast<int>(luminance.size()), plotted.colour, 0, 2.5f);
    }
    drawList->PopClipRect();
    plotLegend(drawList, ImVec2(graph.origin.x + 4, graph.origin.y - graph.size.y + 2), materials);
}

// ---- Fresnel -------------------------------------------------------------------------------

void drawFresnelPlot(ImDrawList* drawList, ImVec2 topLeft, ImVec2 bottomRight, const FresnelCurves& curves,
                     const std::string& materialName) {
    const glm::vec3 n = curves.index.n, k = curves.index.k;
    const bool grey = n.r == n.g && n.g == n.b && k.r == k.g && k.g == k.b;  // one curve set for all channels
    const std::string index = grey ? formatNumber(n.r, "n = %.3g") + (k.r != 0.0f ? formatNumber(k.r, " + %.3gi") : std::string())
                                   : formatNumber(n.r, "n (%.2f") + formatNumber(n.g, " %.2f") + formatNumber(n.b, " %.2f)") +
                                         formatNumber(k.r, " κ (%.2f") + formatNumber(k.g, " %.2f") + formatNumber(k.b, " %.2f)");
    plotFrame(drawList, topLeft, bottomRight,
              "Fresnel " + materialName + (grey ? ": " + index : std::string()) + (curves.fromInside ? ", inside" : ""));
    const PlotGraph graph = plotAngleGraph(drawList, topLeft, bottomRight, 1.0f, "θ_i", 3.4f);
    const float line = ImGui::GetTextLineHeight();
    static constexpr ImU32 kChannelColours[] = {IM_COL32(255, 90, 80, 255), IM_COL32(90, 225, 90, 255), IM_COL32(100, 150, 255, 255)};
    const int channelCount = grey ? 1 : 3;
    // Marked angles: a line with a letter on the graph, the value in the row under the legend.
    ImVec2 angleText(topLeft.x + 6, topLeft.y + 4 + 2.0f * line);
    if (!grey) {  // the per-channel index does not fit the title
        drawList->AddText(angleText, kPlotText, index.c_str());
        angleText.x += ImGui::CalcTextSize(index.c_str()).x + line;
    }
    for (int c = 0; c < channelCount; ++c) {
        const FresnelChannelCurves& channel = curves.channels[c];
        const ImU32 colour = grey ? IM_COL32(235, 235, 235, 255) : kChannelColours[c];
        std::vector<ImVec2> s, p, unpolarised, schlick;
        for (size_t i = 0; i < curves.angleDegrees.size(); ++i) {
            const float degrees = curves.angleDegrees[i];
            s.push_back(graph.at(degrees, channel.s[i]));
            p.push_back(graph.at(degrees, channel.p[i]));
            unpolarised.push_back(graph.at(degrees, channel.unpolarised[i]));
            schlick.push_back(graph.at(degrees, channel.schlick[i]));
        }
        drawList->AddPolyline(unpolarised.data(), static_cast<int>(unpolarised.size()), colour, 0, 2.5f);
        plotDashedPolyline(drawList, s, colour, 1.5f, 6.0f);
        plotDashedPolyline(drawList, p, colour, 1.5f, 2.0f);
        drawList->AddPolyline(schlick.data(), static_cast<int>(schlick.size()), (colour & 0x00FFFFFFu) | (120u << IM_COL32_A_SHIFT), 0, 1.0f);
        // Marked angles: vertical lines with their values.
        const auto mark = [&](float degrees, const char* format) {
            if (degrees < 0.0f) return;
            const ImVec2 base = graph.at(degrees, 0.0f);
            drawList->AddLine(base, ImVec2(base.x, base.y - graph.size.y), colour, 1.0f);
            const std::string label = formatNumber(degrees, format);
            drawList->AddText(angleText, colour, label.c_str());
            angleText.x += ImGui::CalcTextSize(label.c_str()).x + line;
        };
        mark(channel.brewsterDegrees, "θ_B %.1f°");
        mark(channel.criticalDegrees, "θ_c %.1f°");
        if (channel.brewsterDegrees >= 0.0f)
            drawList->AddText(ImVec2(graph.at(channel.brewsterDegrees, 0.0f).x + 2, graph.origin.y - graph.size.y + 2), colour, "B");
        if (channel.criticalDegrees >= 0.0f)
            drawList->AddText(ImVec2(graph.at(channel.criticalDegrees, 0.0f).x + 2, graph.origin.y - graph.size.y + 2), colour, "c");
    }
    // Legend: the line style of each quantity, in one row under the title.
    float x = topLeft.x + 6;
    const float y = topLeft.y + 4 + 1.5f * line;
    const char* names[] = {"unpol.", "R_s", "R_p", "Schlick"};
    for (int i = 0; i < 4; ++i) {
        std::vector<ImVec2> sample;
        for (int step = 0; step <= 6; ++step) sample.push_back(ImVec2(x + 3.0f * static_cast<float>(step), y));
        if (i == 0) drawList->AddLine(sample.front(), sample.back(), kPlotText, 2.5f);
        if (i == 1) plotDashedPolyline(drawList, sample, kPlotText, 1.5f, 6.0f);
        if (i == 2) plotDashedPolyline(drawList, sample, kPlotText, 1.5f, 2.0f);
        if (i == 3) drawList->AddLine(sample.front(), sample.back(), IM_COL32(225, 228, 235, 120), 1.0f);
        drawList->AddText(ImVec2(x + 21, y - 0.5f * line), kPlotText, names[i]);
        x += 21 + ImGui::CalcTextSize(names[i]).x + 0.6f * line;
    }
}

}  // namespace glint
