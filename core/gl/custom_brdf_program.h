// Custom BRDFs (.brdf files) in Glint's surface shader: the generated wrapper that maps
// ShadingFrame to BRDF Explorer's L, V, N, X, Y and declares the parameters as uniforms, the
// compiled programs (cached per source and variant, failures too, bounded as the built-in models'
// programs; also the sampling program of gl/brdf_sampler.h, the same wrapper in a full-screen pass)
// and the per-draw uniforms.
// Proving a shader finishes (no endless loop) is not done here: app/runtime/brdf_probe.h does it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <variant>

#include "gl/bounded_program_cache.h"
#include "gl/shader_program.h"
#include "gl/surface_variant.h"
#include "interchange/custom_brdf.h"

namespace glint {

// The name a parameter or top-level declaration has in the compiled GLSL: prefixed so that it
// cannot collide with Glint's own names (PI, lights, sphere…), except swizzle-like names.
std::string customBrdfGlslName(const std::string& name);

// generated/material.glsl for the custom BRDF, and the .brdf text under its own path (with its
// own line numbers, so compile errors name the .brdf file's lines).
GeneratedShaderFiles customBrdfShaderFiles(const CustomBrdf& brdf);

class CustomBrdfPrograms {
public:
    // Programs kept (sources × variants); `frame` is the caller's frame count, whose programs are
    // never evicted while it draws (gl/bounded_program_cache.h).
    static constexpr size_t kCapacity = 16;

    // The surface program for `brdf`; a compile error is kept and returned again (not rebuilt
    // every frame) until the source changes.
    // In the variant `variant` (MSAA, Gouraud, ray-cast sphere, lights), as the built-in models' programs.
    Result<const ShaderProgram*> program(const ShaderSources& sources, const CustomBrdf& brdf, SurfaceVariant variant,
                                         std::uint64_t frame);
    // fullscreen.vert + brdf_sampler.frag with the same wrapper: f_r at direction pairs
    // (gl/brdf_sampler.h). Cached and reported like program().
    Result<const ShaderProgram*> samplingProgram(const ShaderSources& sources, const CustomBrdf& brdf, std::uint64_t frame);
    // Programs (and kept errors) held now.
    size_t size() const { return programs_.size(); }

private:
    Result<const ShaderProgram*> cached(const ShaderSources& sources, const CustomBrdf& brdf, const std::string& vertexPath,
                                        const std::string& fragmentPath, const std::string& prelude, std::uint64_t frame);
    // (generated sources, stages + prelude) → the program or its error.
    BoundedProgramCache<std::pair<std::string, std::string>, std::variant<ShaderProgram, Diagnostic>> programs_{kCapacity};
};

// Sets the parameter uniforms of a bound custom-BRDF program from packed values.
void setCustomBrdfUniforms(const ShaderProgram& program, const CustomBrdf& brdf, const std::vector<float>& values);

}  // namespace glint
