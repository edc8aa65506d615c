// The published mappings from MaterialX's other surface shaders onto OpenPBR Surface:
// standard_surface after MaterialX's own translation graph
// (libraries/bxdf/translation/standard_surface_to_open_pbr.mtlx, MaterialX 1.39), gltf_pbr
// after the glTF 2.0 extensions' definitions (KHR_materials_*), open_pbr_surface as it is.
// Inputs in, OpenPBR inputs out (materialx_graph.h); it does not build a Glint material.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "brdf/param_table.h"
#include "interchange/materialx_graph.h"

namespace glint {

// The shader categories read: "open_pbr_surface", "standard_surface", "gltf_pbr".
bool isReadableMaterialXShader(const std::string& category);

// The key of the surface map (texture/material_texture.h) an image on `input` becomes:
// geometry_normal → the normal map, geometry_coat_normal → the coat normal map, gltf_pbr's
// occlusion (read as the input "occlusion") → the occlusion map; nullptr for any other input.
const char* surfaceMapOf(const std::string& input);

// The OpenPBR inputs (by OpenPBR name) that `inputs` of a `category` shader amount to, kept to
// those in `glintTable` (Glint's openpbr table) plus the surface maps above when an image drives them.
// An image carries over where an input maps to one OpenPBR input unchanged, else a warning says
// it is dropped; so does every input that changes the look but has no place in Glint's table,
// and every name the source shader does not define.
MaterialXInputs toOpenPbrInputs(const std::string& category, const MaterialXInputs& inputs,
                                std::span<const ParamSpec> glintTable, std::vector<Diagnostic>& warnings);

}  // namespace glint
