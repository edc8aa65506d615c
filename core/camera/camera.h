// Camera: a look-at camera with a perspective or orthographic projection, its matrices in
// OpenGL conventions, and the primary ray through a pixel. The CPU reference and the GPU shader
// build rays the same way (unprojecting the pixel centre), so both see the same coverage.
#pragma once

#include <glm/glm.hpp>

namespace glint {

enum class Projection { Perspective, Orthographic };

struct Camera {
    Projection projection = Projection::Perspective;
    glm::vec3 position{0, 0, 4};
    glm::vec3 target{0, 0, 0};
    glm::vec3 up{0, 1, 0};
    float verticalFovDegrees = 40.0f;  // perspective
    float orthoHeight = 2.5f;          // orthographic: height of the view [m]
    float nearPlane = 0.05f;
    float farPlane = 100.0f;

    glm::mat4 view() const;
    glm::mat4 projectionMatrix(float aspect) const;
    glm::mat4 viewProjection(float aspect) const { return projectionMatrix(aspect) * view(); }
};

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length
};

// The ray through the point (x, y) in pixels (y down, pixel centres at +0.5) of a
// width×height image, from the inverse view-projection matrix.
Ray primaryRay(const glm::mat4& inverseViewProjection, float x, float y, int width, int height);

// Unit direction from a world point towards the viewer: the eye of a perspective camera, the
// view axis of an orthographic one. GLSL twin: towardsViewerFrom() in shaders/common/frame.glsl.
glm::vec3 towardsViewerFrom(const Camera& camera, glm::vec3 position);

// Distance from a world point back to the origin of the primary ray that reaches it (on the
// near plane), as a hit's distance. GLSL: length(position − rayTowards(position).origin).
float viewerDistance(const Camera& camera, glm::vec3 position);

}  // namespace glint
