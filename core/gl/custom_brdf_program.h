// Custom BRDFs (.brdf files) in Glint's surface shader: the generated wrapper that maps
// ShadingFrame to BRDF Explorer's L, V, N, X, Y and declares the parameters as uniforms, the
// compiled programs (cached per source and MSAA count, failures too; also the sampling program of
// gl/brdf_sampler.h, the same wrapper in a full-screen pass) and the per-draw uniforms.
// Proving a shader finishes (no endless loop) is not done here: app/runtime/brdf_probe.h does it.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <variant>

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
    // The surface program for `brdf`; a compile error is kept and returned again (not rebuilt
    // every frame) until the source changes.
    // In the variant `variant` (MSAA, Gouraud, ray-cast sphere), as the built-in models' programs.
    Result<const ShaderProgram*> program(const ShaderSources& sources, const CustomBrdf& brdf, SurfaceVariant variant);
    // fullscreen.vert + brdf_sampler.frag with the same wrapper: f_r at direction pairs
    // (gl/brdf_sampler.h). Cached and reported like program().
    Result<const ShaderProgram*> samplingProgram(const ShaderSources& sources, const CustomBrdf& brdf);

private:
    Result<const ShaderProgram*> cached(const ShaderSources& sources, const CustomBrdf& brdf, const std::string& vertexPath,
                                        const std::string& fragmentPath, const std::string& prelude);
    // (generated sources, stages + prelude) → the program or its error.
    std::map<std::pair<std::string, std::string>, std::variant<ShaderProgram, Diagnostic>> programs_;
};

// Sets the parameter uniforms of a bound custom-BRDF program from packed values.
void setCustomBrdfUniforms(const ShaderProgram& program, const CustomBrdf& brdf, const std::vector<float>& values);

}  // namespace glint
