// Custom BRDFs (.brdf files) in Glint's surface shader: the generated wrapper that maps
// ShadingFrame to BRDF Explorer's L, V, N, X, Y and declares the parameters as uniforms, the
// compiled programs (cached per source and MSAA count, failures too) and the per-draw uniforms.
// Proving a shader finishes (no endless loop) is not done here: app/cli/brdf_probe.h does it.
#pragma once

#include <map>
#include <string>
#include <tuple>
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

private:
    std::map<std::tuple<std::string, SurfaceVariant>, std::variant<ShaderProgram, Diagnostic>> programs_;
};

// Sets the parameter uniforms of a bound custom-BRDF program from packed values.
void setCustomBrdfUniforms(const ShaderProgram& program, const CustomBrdf& brdf, const std::vector<float>& values);

}  // namespace glint
