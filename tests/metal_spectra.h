// Measured complex refractive indices n + iκ of six metals over the visible range (the tabulated
// points of published measurements, each with its paper and database file) and the metals'
// normal-to-grazing reflectance integrated into linear sRGB. No fitting here: metal_index_fit.h.
#pragma once

#include <span>
#include <string_view>

#include <glm/glm.hpp>

namespace glint {

struct SpectralIndex {
    float wavelengthNanometres;  // the database's µm × 1000
    float n;                     // real part of the index
    float k;                     // extinction κ
};

struct MetalSpectrum {
    const char* name;                     // as the preset: "gold"
    std::span<const SpectralIndex> table;  // ascending wavelengths, from ≤ 380 nm to ≥ 780 nm
    const char* source;                    // the measurement and the refractiveindex.info file it was read from
};

std::span<const MetalSpectrum> metalSpectra();
const MetalSpectrum* findMetalSpectrum(std::string_view name);

// (n, κ) at λ [nm] in the table's range: linear between the tabulated points either side (at a
// tabulated wavelength, that point's values exactly).
glm::vec2 complexIndexAt(const MetalSpectrum& spectrum, float wavelengthNanometres);

// Unpolarised reflectance of the smooth metal seen from air at cos θ: the exact conductor Fresnel
// (brdf/fresnel.h) at each colorimetric wavelength, integrated to linear sRGB under D65
// (reflectance_colour.h) and clipped to [0, 1] as Real-Time Rendering (4th ed.) clips its Table 9.2
// (gold's red is 1.05 at normal incidence before the clip: out of the sRGB gamut).
glm::vec3 metalReflectance(const MetalSpectrum& spectrum, float cosIncident);

}  // namespace glint
