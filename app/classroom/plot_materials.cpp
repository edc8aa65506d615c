// Plot materials from scene materials (see plot_materials.h).
#include "classroom/plot_materials.h"

#include <cstdio>

#include "interchange/custom_brdf.h"
#include "interchange/measured_brdf.h"

namespace glint {

Result<PlotMaterial> plotMaterialFor(const Material& material, BrdfSampler& sampler) {
    if (auto plotted = plotMaterialFrom(material)) return *plotted;
    if (Status prepared = sampler.prepare(*material.custom); !prepared) return prepared.error();
    PlotMaterial plotted{material.name, material.model, material.values, nullptr, {}, material.custom};
    plotted.sampler = [&sampler, custom = material.custom, values = material.values](std::span<const glm::vec3> incident,
                                                                                     std::span<const glm::vec3> outgoing) {
        auto sampled = sampler.sample(*custom, values, incident, outgoing);
        if (sampled) return std::move(*sampled);
        // Only a GL failure gets here (the program compiled in prepare): said, and plotted as 0.
        std::fprintf(stderr, "glint: %s\n", sampled.error().format().c_str());
        return std::vector<glm::vec3>(incident.size(), glm::vec3(0.0f));
    };
    return plotted;
}

std::string plotSourceNote(const PlotMaterial& material) {
    if (material.custom)
        return material.name + ": f_r sampled on the GPU from " + material.custom->displayName + " (its own GLSL)";
    if (material.measured)
        return material.name + ": f_r from the measured table " + material.measured->displayName +
               " (MERL, trilinear); no Fresnel index";
    return "";
}

}  // namespace glint
