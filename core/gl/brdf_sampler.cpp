// The GPU BRDF sampler (see brdf_sampler.h): the direction pairs go up as two RGB32F textures,
// one fragment per pair evaluates the .brdf's BRDF(L, V, N, X, Y), and the RGBA32F result comes back.
// Sections: saved GL state · sampling.
#include "gl/brdf_sampler.h"

#include <algorithm>
#include <initializer_list>
#include <utility>
#include <vector>

#include "gl/gl_loader.h"

namespace glint {
namespace {

// --- saved GL state -------------------------------------------------------------------------

// What the pass changes, restored when it ends: the sampler runs in the middle of the editor's
// frame and of a headless render, whose own passes expect their state to stay put.
class SavedGlState {
public:
    explicit SavedGlState(std::initializer_list<GLint> units) {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
        glGetIntegerv(GL_VIEWPORT, viewport_);
        glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
        glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
        glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
        for (GLint unit : units) {
            glActiveTexture(GL_TEXTURE0 + unit);
            GLint texture = 0;
            glGetIntegerv(GL_TEXTURE_BINDING_2D, &texture);
            textures_.push_back({unit, texture});
        }
        blend_ = glIsEnabled(GL_BLEND);
        depthTest_ = glIsEnabled(GL_DEPTH_TEST);
        scissorTest_ = glIsEnabled(GL_SCISSOR_TEST);
        cullFace_ = glIsEnabled(GL_CULL_FACE);
    }
    ~SavedGlState() {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(drawFramebuffer_));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(readFramebuffer_));
        glViewport(viewport_[0], viewport_[1], viewport_[2], viewport_[3]);
        glUseProgram(static_cast<GLuint>(program_));
        glBindVertexArray(static_cast<GLuint>(vertexArray_));
        for (const auto& [unit, texture] : textures_) {
            glActiveTexture(GL_TEXTURE0 + unit);
            glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(texture));
        }
        glActiveTexture(static_cast<GLenum>(activeTexture_));
        setEnabled(GL_BLEND, blend_);
        setEnabled(GL_DEPTH_TEST, depthTest_);
        setEnabled(GL_SCISSOR_TEST, scissorTest_);
        setEnabled(GL_CULL_FACE, cullFace_);
    }
    SavedGlState(const SavedGlState&) = delete;
    SavedGlState& operator=(const SavedGlState&) = delete;

private:
    static void setEnabled(GLenum capability, GLboolean enabled) {
        if (enabled) glEnable(capability);
        else glDisable(capability);
    }
    GLint drawFramebuffer_ = 0, readFramebuffer_ = 0, viewport_[4] = {0, 0, 0, 0}, program_ = 0, vertexArray_ = 0,
          activeTexture_ = GL_TEXTURE0;
    std::vector<std::pair<GLint, GLint>> textures_;  // unit → the 2D texture bound there
    GLboolean blend_ = GL_FALSE, depthTest_ = GL_FALSE, scissorTest_ = GL_FALSE, cullFace_ = GL_FALSE;
};

// A width×height RGB32F texture of `directions`, padded with zeros to fill the last row.
void uploadDirections(GLuint texture, std::span<const glm::vec3> directions, int width, int height, bool allocate) {
    std::vector<glm::vec3> padded(static_cast<size_t>(width) * static_cast<size_t>(height), glm::vec3(0.0f));
    std::copy(directions.begin(), directions.end(), padded.begin());
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    if (allocate) {
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGB32F, width, height, 0, GL_RGB, GL_FLOAT, padded.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    } else {
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, GL_RGB, GL_FLOAT, padded.data());
    }
}

}  // namespace

// --- sampling -------------------------------------------------------------------------------

BrdfSampler::BrdfSampler(ShaderSources sources) : sources_(std::move(sources)) {}

BrdfSampler::~BrdfSampler() {
    if (directionTextures_[0]) glDeleteTextures(2, directionTextures_);
    if (emptyVertexArray_) glDeleteVertexArrays(1, &emptyVertexArray_);
}

Status BrdfSampler::prepare(const CustomBrdf& brdf) {
    auto program = programs_.samplingProgram(sources_, brdf, ++calls_);
    if (!program) return program.error();
    return success();
}

Result<std::vector<glm::vec3>> BrdfSampler::sample(const CustomBrdf& brdf, const std::vector<float>& values,
                                                   std::span<const glm::vec3> incident,
                                                   std::span<const glm::vec3> outgoing) {
    GLINT_CHECK(incident.size() == outgoing.size());
    auto program = programs_.samplingProgram(sources_, brdf, ++calls_);
    if (!program) return program.error();
    if (incident.empty()) return std::vector<glm::vec3>{};
    const int count = static_cast<int>(incident.size());
    const int width = std::min(count, kRowLength), height = (count + width - 1) / width;

    const SavedGlState saved{kIncidentUnit, kOutgoingUnit};
    const bool allocate = width != width_ || height != height_;
    if (!directionTextures_[0]) {
        glGenTextures(2, directionTextures_);
        glGenVertexArrays(1, &emptyVertexArray_);
    }
    glActiveTexture(GL_TEXTURE0 + kIncidentUnit);
    uploadDirections(directionTextures_[0], incident, width, height, allocate);
    glActiveTexture(GL_TEXTURE0 + kOutgoingUnit);
    uploadDirections(directionTextures_[1], outgoing, width, height, allocate);
    result_.ensure(width, height, 1);
    glBindTexture(GL_TEXTURE_2D, directionTextures_[1]);  // a new result texture was bound on this unit
    width_ = width, height_ = height;

    glBindFramebuffer(GL_FRAMEBUFFER, result_.framebuffer());
    glViewport(0, 0, width, height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_CULL_FACE);
    const ShaderProgram& shader = **program;
    glUseProgram(shader.id());
    glUniform1i(shader.uniform("incidentDirections"), kIncidentUnit);
    glUniform1i(shader.uniform("outgoingDirections"), kOutgoingUnit);
    setCustomBrdfUniforms(shader, brdf, values);
    glBindVertexArray(emptyVertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<glm::vec4> texels(static_cast<size_t>(width) * static_cast<size_t>(height));
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_FLOAT, texels.data());
    if (Status errors = takeGlErrors("the BRDF sampling pass"); !errors) return errors.error();
    std::vector<glm::vec3> reflectance(incident.size());
    for (size_t k = 0; k < reflectance.size(); ++k) reflectance[k] = glm::vec3(texels[k]);
    return reflectance;
}

}  // namespace glint
