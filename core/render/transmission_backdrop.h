// Screen-space transmission (as three.js's MeshPhysicalMaterial and Filament do): the backdrop is
// what the frame's opaque pass drew (the opaque objects, linear radiance [W/(sr·m²)], with their
// coverage) with a mip chain of 2×2 means; a transmissive surface looks it up where its
// transmitted ray leaves the object, projected to the screen, at a level that grows with the
// roughness, and sees the environment or background along the ray where no object covers it
// (unlike three.js, whose backdrop holds the background as seen from the camera). CPU twin of
// shaders/common/transmission_backdrop.glsl (the GPU makes the chain in core/gl/transmission_pass.*).
// It holds only what the frame shows: other transmissive objects, anything hidden or off screen
// are not in it (the caller falls back to the environment).
#pragma once

#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "image/image.h"
#include "scene/material.h"
#include "scene/scene.h"

namespace glint {

// Whether a material lets light through from behind: its model transmits (brdf/model_traits.h:
// glass; openpbr with a transmission weight above 0, or a texture on it). Frames without one draw
// no backdrop.
bool transmitsLight(const Material& material);
// Whether a frame of the scene draws the backdrop: it has a transmissive object and an opaque one
// (with no opaque object the backdrop would hold nothing; transmissive surfaces then see the
// environment or background directly).
bool drawsTransmissionBackdrop(const Scene& scene);

// The opaque pass as the backdrop holds it, top row first: rgb the radiance premultiplied by the
// coverage a (1 where an opaque object was drawn, 0 where none, between on an MSAA silhouette).
struct OpaquePassImage {
    int width = 0, height = 0;
    std::vector<glm::vec4> pixels;
    glm::vec4 at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

class TransmissionBackdrop {
public:
    // `opaque`: the opaque pass at the frame's size (Renderer::readTransmissionBackdrop);
    // `viewProjection`: the frame's camera (Camera::viewProjection at the frame's aspect).
    TransmissionBackdrop(const OpaquePassImage& opaque, const glm::mat4& viewProjection);

    int levelCount() const { return static_cast<int>(levels_.size()); }
    // The mip level for a rough transmission of perceptual roughness r through index η: three.js's
    // log2(width)·r·clamp(2η − 2, 0, 1) (η = 1 does not blur, η ≥ 1.5 blurs fully at r = 1).
    float levelFor(float perceptualRoughness, float ior) const;
    // Trilinear lookup at uv ∈ [0, 1]² (GL's convention: v up) and a fractional level, clamped to
    // the chain; texels are read one by one and interpolated here, as in the GLSL twin.
    glm::vec4 sample(glm::vec2 uv, float level) const;
    // The backdrop (premultiplied radiance, coverage) where a ray leaving its object at
    // `exitPoint` along `direction` meets it: the exit point projected to the screen, when it lies
    // in front of the camera, inside the frame, and the ray goes away from the viewer
    // (dot(direction, viewDirection) > 0, viewDirection the primary ray's). Else nothing.
    std::optional<glm::vec4> behind(glm::vec3 exitPoint, glm::vec3 direction, glm::vec3 viewDirection, float level) const;

private:
    struct Level {
        int width, height;
        std::vector<glm::vec4> texels;  // bottom row first, as the GL texture
        glm::vec4 at(int x, int y) const { return texels[static_cast<size_t>(y) * width + x]; }
    };
    std::vector<Level> levels_;
    glm::mat4 viewProjection_;
};

}  // namespace glint
