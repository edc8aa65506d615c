// Shading overhead benchmark: the frame time of a 1280×720 sphere that fills the frame, lit by
// 4 lights (radiance pass + display pass, OSMesa), against a bare full-screen pass that evaluates
// the same generated BRDF code for 4 lights with no scene, no depth, no display. Prints medians
// and their ratio per model (and the radiance pass's alone, without the display pass the bare
// pass lacks by definition); timings interleaved frame by frame. Not run by ctest.
// usage: shading_ratio [FRAMES]   (DISPLAY unset; LP_NUM_THREADS as you like)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "cli/headless.h"
#include "gl/frame_uniforms.h"
#include "gl/material_glsl.h"
#include "gl/render_target.h"
#include "gl/shadow_maps.h"
#include "gl/uniform_blocks.h"

namespace glint {
namespace {

constexpr int kWidth = 1280, kHeight = 720;
constexpr GLuint kBareBinding = 8;  // the renderer uses 0-2

// The bare pass: a normal and a view direction per pixel (a dome facing the viewer; neither a
// constant, so the compiler cannot fold the BRDF away), the same shadeSurface() and generated
// material as the surface shader, written to a float target.
constexpr const char* kBareFragment = R"(#version 410 core
#include "common/uniforms.glsl"
#include "common/frame.glsl"
#include "common/lights.glsl"
#include "generated/material.glsl"
#include "common/shading.glsl"
out vec4 outRadiance;
void main() {
    vec2 ndc = 2.0 * gl_FragCoord.xy / viewportSize.xy - 1.0;
    vec3 normal = normalize(vec3(0.8 * ndc, 1.0));
    ShadingFrame frame = frameFromNormalAndTangent(normal, vec3(1.0, 0.0, 0.0));
    vec3 towardsViewer = normalize(vec3(-0.5 * ndc, 1.0));  // per pixel, as a camera's would be
    outRadiance = vec4(shadeSurface(normal, frame, towardsViewer), 1.0);
}
)";

Scene benchScene(BrdfModel model) {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 1.5f};  // the unit sphere covers every pixel at 40° fov
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.materials = {Material::withDefaults("bench", model)};
    scene.objects.push_back({"sphere", SphereShape{}, 0});
    const glm::vec3 positions[4] = {{2, 2, 2}, {-2, 1, 2}, {0, -2, 3}, {1, 0, 4}};
    for (int i = 0; i < 4; ++i) {
        Light light;
        light.type = i % 2 ? LightType::Directional : LightType::Point;
        light.position = positions[i];
        light.direction = -positions[i];
        light.irradiance = 1.0f;
        scene.lights.push_back(light);
    }
    return scene;
}

double medianMs(std::vector<double> times) {
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
}

template <typename Draw>
double timeFrame(Draw draw) {
    const auto start = std::chrono::steady_clock::now();
    draw();
    glFinish();
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int run(int frames) {
    auto headless = HeadlessRenderer::create();
    if (!headless) {
        std::fprintf(stderr, "shading_ratio: %s\n", headless.error().format().c_str());
        return 2;
    }
    Renderer& renderer = (*headless)->renderer();
    GLuint buffers[3];
    glGenBuffers(3, buffers);
    GLuint emptyVertexArray;
    glGenVertexArrays(1, &emptyVertexArray);
    RenderTarget bareTarget(GL_RGBA32F, false);
    bareTarget.ensure(kWidth, kHeight, 1);
    std::printf("%dx%d, 4 lights, median of %d frames (%s)\n", kWidth, kHeight, frames, renderer.description().c_str());
    for (BrdfModel model : {BrdfModel::Lambert, BrdfModel::BlinnPhong, BrdfModel::CookTorrance}) {
        const Scene scene = benchScene(model);
        const ModelInfo& info = modelInfo(model);
        const GeneratedShaderFiles generated = {{"generated/material.glsl", generateMaterialGlsl(info)},
                                                {"bench/bare.frag", kBareFragment}};
        auto bare = ShaderProgram::build(renderer.sources(), "fullscreen.vert", "bench/bare.frag", "", generated);
        if (!bare) {
            std::fprintf(stderr, "shading_ratio: %s\n", bare.error().format().c_str());
            return 2;
        }
        // Binding points of its own, so that the renderer's stay bound to the renderer's buffers.
        bare->bindBlock("FrameBlock", kBareBinding + 0);
        bare->bindBlock("LightBlock", kBareBinding + 1);
        bare->bindBlock("MaterialBlock", kBareBinding + 2);
        glUseProgram(bare->id());
        assignShadowSamplerUnits(*bare);  // shading.glsl reads the (empty) shadow block
        // The bare pass's uniforms: the scene's own, packed by the renderer's code (same lights,
        // same light count for the dynamic loop, same material block).
        const FrameUniforms uniforms = packFrameUniforms(scene, kWidth, kHeight);
        const FrameBlockStd140& frame = uniforms.frame;
        const LightBlockStd140& lights = uniforms.lights;
        MaterialBlockStd140 material{};
        std::copy(scene.materials[0].values.begin(), scene.materials[0].values.end(), material.values);
        const auto drawBare = [&] {
            glBindBufferBase(GL_UNIFORM_BUFFER, kBareBinding + 0, buffers[0]);
            glBufferData(GL_UNIFORM_BUFFER, sizeof frame, &frame, GL_STREAM_DRAW);
            glBindBufferBase(GL_UNIFORM_BUFFER, kBareBinding + 1, buffers[1]);
            glBufferData(GL_UNIFORM_BUFFER, sizeof lights, &lights, GL_STREAM_DRAW);
            glBindBufferBase(GL_UNIFORM_BUFFER, kBareBinding + 2, buffers[2]);
            glBufferData(GL_UNIFORM_BUFFER, sizeof material, &material, GL_STREAM_DRAW);
            glBindFramebuffer(GL_FRAMEBUFFER, bareTarget.framebuffer());
            glViewport(0, 0, kWidth, kHeight);
            glDisable(GL_DEPTH_TEST);
            glUseProgram(bare->id());
            glBindVertexArray(emptyVertexArray);
            glDrawArrays(GL_TRIANGLES, 0, 3);
            glBindVertexArray(0);
        };
        const auto drawScene = [&] {
            if (Status status = renderer.renderRadiance(scene, kWidth, kHeight); !status)
                std::fprintf(stderr, "shading_ratio: %s\n", status.error().format().c_str());
            renderer.displayOffscreen(scene.display);
        };
        timeFrame(drawScene);  // compile and warm up both
        timeFrame(drawBare);
        const auto drawRadiance = [&] { (void)renderer.renderRadiance(scene, kWidth, kHeight); };
        const auto drawDisplay = [&] { renderer.displayOffscreen(scene.display); };
        std::vector<double> sceneTimes, bareTimes, radianceTimes, displayTimes;
        for (int i = 0; i < frames; ++i) {
            sceneTimes.push_back(timeFrame(drawScene));
            bareTimes.push_back(timeFrame(drawBare));
            radianceTimes.push_back(timeFrame(drawRadiance));
            displayTimes.push_back(timeFrame(drawDisplay));
        }
        const double sceneMs = medianMs(sceneTimes), bareMs = medianMs(bareTimes);
        const double radianceMs = medianMs(radianceTimes);
        std::printf("%-14s frame %7.2f ms (radiance %7.2f, display %6.2f)   bare pass %7.2f ms   ratio %.3f"
                    "   (radiance pass alone %.3f)\n",
                    info.id, sceneMs, radianceMs, medianMs(displayTimes), bareMs, sceneMs / bareMs, radianceMs / bareMs);
    }
    glDeleteBuffers(3, buffers);
    glDeleteVertexArrays(1, &emptyVertexArray);
    return 0;
}

}  // namespace
}  // namespace glint

int main(int argc, char** argv) {
    const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 15;
    return glint::run(frames);
}
