// Overlay settings: helper lines the GL renderer draws over the displayed image (wireframe of the
// drawn triangles, vertex normals). Display aids only: they never enter the radiance (EXR) image
// and the CPU reference ignores them. Plain data; drawing is core/gl/overlay_pass.h.
#pragma once

namespace glint {

struct OverlaySettings {
    bool wireframe = false;     // edges of the triangles the renderer draws (proxy meshes included)
    bool normals = false;       // vertex normals as short lines
    float normalLength = 0.1f;  // [m] length of a normal line, > 0

    bool any() const { return wireframe || normals; }
};

}  // namespace glint
