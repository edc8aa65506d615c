// Generates "generated/material.glsl" for one BRDF model from its parameter table: the
// MaterialParams struct (one field per parameter, named as in the table), loadMaterialParams()
// that unpacks MaterialBlock in table order, the model's GLSL twin and GLINT_EVAL_BRDF.
// This is the table's "uniform packing" use; the C++ side packs with the same offsets.
// Textured parameters (texture/material_texture.h) read their texture slot instead; the slots
// are numbered in table order, the normal map last (material_textures.h binds them alike).
#pragma once

#include <bit>
#include <cstdint>
#include <string>

#include "brdf/model_registry.h"
#include "scene/scene.h"

namespace glint {

// Which parameters of a material are textured: bit i for the table's parameter i, bit 60 for the
// coat normal map, bit 62 for the occlusion map, bit 63 for the normal map, and bit 61 (no slot) when any texture is procedural, so that a program of image
// textures alone carries no Perlin noise (llvmpipe compiles such a program about five times
// faster). Programs are built per model, MSAA samples and this mask.
struct TexturedParams {
    static constexpr int kCoatNormalMapBit = 60;
    static constexpr int kProceduralBit = 61;
    static constexpr int kOcclusionMapBit = 62;
    static constexpr int kNormalMapBit = 63;
    std::uint64_t mask = 0;

    static TexturedParams of(const AnalyticMaterial& material);
    // The bit of `texture` on a material of `model`: its parameter's index, or a map's bit.
    static int bitOf(BrdfModel model, const MaterialTexture& texture);
    bool has(int paramIndex) const { return (mask >> paramIndex) & 1u; }
    bool hasNormalMap() const { return has(kNormalMapBit); }
    bool hasOcclusionMap() const { return has(kOcclusionMapBit); }
    bool hasProcedural() const { return has(kProceduralBit); }
    // Slot = number of textured parameters before it in table order, whatever the order of the
    // material's textures (the program reads slots, material_textures.cpp binds them by this).
    int slotOf(int paramIndex) const {
        return std::popcount(mask & ((std::uint64_t{1} << paramIndex) - 1u) & ~(std::uint64_t{1} << kProceduralBit));
    }
    int normalMapSlot() const { return slotOf(kNormalMapBit); }
};

std::string generateMaterialGlsl(const ModelInfo& model, TexturedParams textured = {});

}  // namespace glint
