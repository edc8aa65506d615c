// Plot materials from scene materials (see plot_materials.h).
#include "classroom/plot_materials.h"

#include <cstdio>

#include "interchange/custom_brdf.h"
#include "interchange/measured_brdf.h"

namespace glint {

Result<PlotMaterial> plotMaterialFor(const Material& material, BrdfSampler& sampler) {
    if (auto plotted = plotMaterialFrom(material)) return *plotted;
    const CustomMaterial& custom = *material.custom();
    if (Status prepared = sampler.prepare(*custom.brdf); !prepared) return prepared.error();
    PlotMaterial plotted{material, {}};
    plotted.sampler = [&sampler, custom](std::span<const glm::vec3> incident, std::span<const glm::vec3> outgoing) {
        auto sampled = sampler.sample(*custom.brdf, custom.values, incident, outgoing);
        if (sampled) return std::move(*sampled);
        // Only a GL failure gets here (the program compiled in prepare): said, and plotted as 0.
        std::fprintf(stderr, "glint: %s\n", sampled.error().format().c_str());
        return std::vector<glm::vec3>(incident.size(), glm::vec3(0.0f));
    };
    return plotted;
}

std::string plotSourceNote(const PlotMaterial& material) {
    return std::visit(Overloaded{[](const AnalyticMaterial&) { return std::string(); },
                                 [&](const CustomMaterial& custom) {
                                     return material.name + ": f_r sampled on the GPU from " + custom.brdf->displayName + " (its own GLSL)";
                                 },
                                 [&](const MeasuredMaterial& measured) {
                                     return material.name + ": f_r from the measured table " + measured.brdf->displayName +
                                            " (MERL, trilinear); no Fresnel index";
                                 }},
                      material.kind);
}

}  // namespace glint
