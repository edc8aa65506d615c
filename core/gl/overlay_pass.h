// OverlayPass: draws the wireframe and vertex-normal overlays (scene/overlays.h) over an image the
// display pass has just written, hiding lines behind the shaded surface by the radiance pass's
// depth. It draws meshes the renderer already uploaded; it owns only its two programs.
#pragma once

#include <vector>

#include <glad/gl.h>
#include <glm/glm.hpp>

#include "gl/shader_program.h"
#include "scene/overlays.h"

namespace glint {

// One object's triangles as the radiance pass drew them.
struct OverlayMesh {
    GLuint vertexArray = 0;  // attribute 0: position, 1: normal
    GLsizei indexCount = 0;  // GL_UNSIGNED_INT triangles
    bool closed = false;     // a closed surface: back-facing triangles get no wireframe
    glm::vec4 placement{0.0f, 0.0f, 0.0f, 1.0f};  // xyz offset [m], w scale (geometry/shape_mesh.h)
};

class OverlayPass {
public:
    static Result<OverlayPass> create(const ShaderSources& sources);

    // Draws into the bound framebuffer and viewport. The FrameBlock of the radiance pass must still
    // be bound; `sceneDepth` is its depth texture, `viewportOrigin`/`pixelScale` place the radiance
    // pixels in the window as the display pass did.
    void draw(const OverlaySettings& settings, const std::vector<OverlayMesh>& meshes, GLuint sceneDepth,
                   glm::ivec2 viewportOrigin, int pixelScale) const;

private:
    ShaderProgram wireframeProgram_;
    ShaderProgram normalsProgram_;
};

}  // namespace glint
