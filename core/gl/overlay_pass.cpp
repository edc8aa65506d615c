// Wireframe and normals overlays (see overlay_pass.h). Shaders: shaders/overlay/.
#include "gl/overlay_pass.h"

#include "gl/uniform_blocks.h"

namespace glint {
namespace {

// Display-encoded colours, chosen to stand out on grey materials and dark backgrounds.
constexpr float kWireframeColor[4] = {1.0f, 0.62f, 0.1f, 1.0f};
constexpr float kNormalColor[4] = {0.25f, 0.85f, 1.0f, 1.0f};

Result<ShaderProgram> buildOverlayProgram(const ShaderSources& sources, const char* geometryPath) {
    auto program = ShaderProgram::buildWithGeometry(sources, "overlay/overlay.vert", geometryPath, "overlay/overlay.frag");
    if (program) program->bindBlock("FrameBlock", kFrameBinding);
    return program;
}

}  // namespace

Result<OverlayPass> OverlayPass::create(const ShaderSources& sources) {
    OverlayPass pass;
    auto wireframe = buildOverlayProgram(sources, "overlay/wireframe.geom");
    if (!wireframe) return wireframe.error();
    auto normals = buildOverlayProgram(sources, "overlay/normals.geom");
    if (!normals) return normals.error();
    pass.wireframeProgram_ = std::move(*wireframe);
    pass.normalsProgram_ = std::move(*normals);
    return pass;
}

void OverlayPass::draw(const OverlaySettings& settings, const std::vector<OverlayMesh>& meshes,
                            GLuint sceneDepth, glm::ivec2 viewportOrigin, int pixelScale) const {
    if (!settings.any()) return;
    glDisable(GL_DEPTH_TEST);  // hidden lines are found against sceneDepth in overlay.frag
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, sceneDepth);
    auto drawWith = [&](const ShaderProgram& program, const float* color, bool cull) {
        glUseProgram(program.id());
        glUniform1i(program.uniform("sceneDepth"), 0);
        glUniform2i(program.uniform("viewportOrigin"), viewportOrigin.x, viewportOrigin.y);
        glUniform1i(program.uniform("pixelScale"), pixelScale);
        glUniform4fv(program.uniform("overlayColor"), 1, color);
        glUniform1f(program.uniform("normalLength"), settings.normalLength);
        for (const OverlayMesh& mesh : meshes) {
            glUniform1i(program.uniform("cullBackFaces"), cull && mesh.closed ? 1 : 0);
            glUniform4f(program.uniform("placement"), mesh.placement.x, mesh.placement.y, mesh.placement.z,
                        mesh.placement.w);
            glBindVertexArray(mesh.vertexArray);
            glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
        }
    };
    if (settings.wireframe) drawWith(wireframeProgram_, kWireframeColor, true);
    if (settings.normals) drawWith(normalsProgram_, kNormalColor, false);
    glBindVertexArray(0);
    glBindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace glint
