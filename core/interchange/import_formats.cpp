// The table of interchange formats (see import_formats.h).
#include "interchange/import_formats.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "interchange/glb.h"
#include "interchange/gltf.h"
#include "interchange/materialx.h"
#include "interchange/measured_brdf.h"
#include "interchange/mtl.h"

namespace glint {
namespace {

constexpr ImportFormat kFormats[] = {
    {".mtl", "Wavefront material library", loadMtl},
    {".gltf", "glTF 2.0 (materials and KHR_lights_punctual lights)", loadGltf},
    {".glb", "binary glTF 2.0 (materials and KHR_lights_punctual lights)", loadGlb},
    {".binary", "MERL measured BRDF", importMerl},
    {".mtlx", "MaterialX document (open_pbr_surface, standard_surface, gltf_pbr)", loadMaterialX},
};

}  // namespace

std::span<const ImportFormat> importFormats() { return kFormats; }

const ImportFormat* findImportFormat(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (const ImportFormat& format : kFormats)
        if (extension == format.extension) return &format;
    return nullptr;
}

}  // namespace glint
