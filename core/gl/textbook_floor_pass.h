// TextbookFloorPass: the floor of `glint bench` — the picture of a scene drawn by a hand-written
// minimal program (shaders/textbook_floor.frag) as a textbook or three.js would write it: one
// full-screen pass, the sphere ray-cast, the same BRDF and lights, an sRGB 8-bit output and
// nothing else. None of Glint's shading code runs in it, so the ratio of a frame to it is what
// Glint costs over the cheapest correct program. It covers scenes of one analytic sphere (or none)
// with a material that has a textbook form (brdf/trait_forms.h: Lambert, or Cook-Torrance with GGX,
// height-correlated Smith and Schlick), a perspective
// camera outside the sphere, a constant background and point (inverse-square, no cone) and directional lights;
// covers() says whether a scene is one. It does not time itself; the caller times draw() + glFinish.
#pragma once

#include <memory>

#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "scene/scene.h"

namespace glint {

class TextbookFloorPass {
public:
    static bool covers(const Scene& scene);
    // Builds the program for the scene's material and light counts; the GL context must be current.
    static Result<std::unique_ptr<TextbookFloorPass>> create(const ShaderSources& sources, const Scene& scene);
    ~TextbookFloorPass();
    TextbookFloorPass(const TextbookFloorPass&) = delete;
    TextbookFloorPass& operator=(const TextbookFloorPass&) = delete;

    // One frame at width×height into its own 8-bit target, uniforms uploaded each time.
    void draw(const Scene& scene, int width, int height);

private:
    explicit TextbookFloorPass(ShaderProgram program) : program_(std::move(program)) {}
    ShaderProgram program_;
    GLuint emptyVertexArray_ = 0;
    RenderTarget target_{GL_RGBA8, false};
};

}  // namespace glint
