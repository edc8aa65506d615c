// The textbook floor (see textbook_floor_pass.h).
#include "gl/textbook_floor_pass.h"

#include <cmath>
#include <optional>
#include <vector>

#include <glm/gtc/type_ptr.hpp>

#include "brdf/model_traits.h"
#include "display/display_chain.h"
#include "light/light.h"

namespace glint {
namespace {

// What the floor shader draws for the material: its textbook form, if it has one (untextured).
std::optional<TextbookForm> textbookFormOf(const Material& material) {
    const AnalyticMaterial* analytic = material.analytic();
    if (!analytic || !analytic->textures.empty()) return std::nullopt;
    return textbookForm(analytic->model, analytic->values);
}

}  // namespace

bool TextbookFloorPass::covers(const Scene& scene) {
    if (scene.objects.size() > 1 || scene.camera.projection != Projection::Perspective) return false;
    if (scene.background.kind != BackgroundKind::Constant || scene.environment.enabled() || scene.msaaSamples > 1) return false;
    for (const Light& light : scene.lights) {
        if (!light.enabled || light.type == LightType::Ambient) continue;
        const bool plain = light.type == LightType::Directional || (light.type == LightType::Point && !light.attenuation.enabled);
        if (!plain || light.castsShadows) return false;
    }
    if (scene.objects.empty()) return true;
    const SceneObject& object = scene.objects[0];
    const auto* sphere = std::get_if<SphereShape>(&object.shape);
    return sphere && glm::length(scene.camera.position - sphere->center) > sphere->radius &&  // seen from outside
           object.interpolation != SurfaceInterpolation::Gouraud && textbookFormOf(scene.materials.at(object.materialIndex));
}

Result<std::unique_ptr<TextbookFloorPass>> TextbookFloorPass::create(const ShaderSources& sources, const Scene& scene) {
    GLINT_CHECK(covers(scene));
    int directional = 0, point = 0;
    for (const Light& light : scene.lights) {
        if (light.enabled && light.type == LightType::Directional) ++directional;
        if (light.enabled && light.type == LightType::Point) ++point;
    }
    const bool ggx = !scene.objects.empty() && textbookFormOf(scene.materials.at(scene.objects[0].materialIndex))->specular;
    const std::string prelude = "#define NUM_DIRECTIONAL " + std::to_string(directional) + "\n#define NUM_POINT " +
                                std::to_string(point) + "\n" + (ggx ? "#define GGX 1\n" : "#define LAMBERT 1\n");
    auto program = ShaderProgram::build(sources, "textbook_floor.vert", "textbook_floor.frag", prelude);
    if (!program) return program.error();
    std::unique_ptr<TextbookFloorPass> pass(new TextbookFloorPass(std::move(*program)));
    glGenVertexArrays(1, &pass->emptyVertexArray_);
    return pass;
}

TextbookFloorPass::~TextbookFloorPass() { glDeleteVertexArrays(1, &emptyVertexArray_); }

void TextbookFloorPass::draw(const Scene& scene, int width, int height) {
    target_.ensure(width, height, 1);
    glBindFramebuffer(GL_FRAMEBUFFER, target_.framebuffer());
    glViewport(0, 0, width, height);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program_.id());
    const GLuint id = program_.id();
    const auto uniform = [id](const char* name) { return glGetUniformLocation(id, name); };
    const Camera& camera = scene.camera;
    const glm::vec3 backward = glm::normalize(camera.position - camera.target);
    const glm::vec3 right = glm::normalize(glm::cross(camera.up, backward));
    const glm::mat3 basis(right, glm::cross(backward, right), backward);
    const float tanHalf = std::tan(glm::radians(camera.verticalFovDegrees) / 2.0f);
    glUniform3fv(uniform("eye"), 1, glm::value_ptr(camera.position));
    glUniformMatrix3fv(uniform("cameraBasis"), 1, GL_FALSE, glm::value_ptr(basis));
    glUniform2f(uniform("tanHalfFov"), tanHalf * static_cast<float>(width) / height, tanHalf);
    glUniform2f(uniform("viewportSize"), static_cast<float>(width), static_cast<float>(height));
    // The background: a clear to its sRGB-encoded colour.
    glClearColor(encodeSrgb(scene.background.color.r), encodeSrgb(scene.background.color.g),
                 encodeSrgb(scene.background.color.b), 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    if (scene.objects.empty()) return;
    glUniformMatrix4fv(uniform("viewProjection"), 1, GL_FALSE,
                       glm::value_ptr(camera.viewProjection(static_cast<float>(width) / height)));
    std::vector<glm::vec3> towards, irradiance, positions, intensities;
    glm::vec3 ambient(0.0f);
    for (const Light& light : scene.lights) {
        if (!light.enabled) continue;
        if (light.type == LightType::Ambient) ambient += ambientRadiance(light);
        if (light.type == LightType::Directional) {
            towards.push_back(-glm::normalize(light.direction));
            irradiance.push_back(light.color * light.irradiance);
        }
        if (light.type == LightType::Point) {
            positions.push_back(light.position);
            intensities.push_back(pointIntensity(light));
        }
    }
    glUniform3fv(uniform("ambient"), 1, glm::value_ptr(ambient));
    if (!towards.empty()) {
        glUniform3fv(uniform("directionalTowards"), static_cast<GLsizei>(towards.size()), glm::value_ptr(towards[0]));
        glUniform3fv(uniform("directionalIrradiance"), static_cast<GLsizei>(irradiance.size()), glm::value_ptr(irradiance[0]));
    }
    if (!positions.empty()) {
        glUniform3fv(uniform("pointPosition"), static_cast<GLsizei>(positions.size()), glm::value_ptr(positions[0]));
        glUniform3fv(uniform("pointIntensity"), static_cast<GLsizei>(intensities.size()), glm::value_ptr(intensities[0]));
    }
    const auto& sphere = std::get<SphereShape>(scene.objects[0].shape);
    glUniform4f(uniform("sphere"), sphere.center.x, sphere.center.y, sphere.center.z, sphere.radius);
    const TextbookForm form = *textbookFormOf(scene.materials.at(scene.objects[0].materialIndex));  // covers() checked it
    glUniform3fv(uniform("albedo"), 1, glm::value_ptr(form.diffuseAlbedo));
    if (form.specular) {
        glUniform3fv(uniform("f0"), 1, glm::value_ptr(form.specular->f0));
        glUniform1f(uniform("alpha"), form.specular->alpha);
    }
    glBindVertexArray(emptyVertexArray_);
    glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
    glBindVertexArray(0);
}

}  // namespace glint
