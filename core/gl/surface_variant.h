// SurfaceVariant: which compile-time variant of the surface program (shaders/surface.vert and
// surface.frag) a draw needs, and the #define prelude that selects it. Only an analytic sphere's
// program ray-casts and writes gl_FragDepth; a triangle mesh's leaves depth to the rasterizer, so
// that fragments hidden behind what is already drawn are rejected before they are shaded (a
// fragment shader that writes depth makes the depth test wait until after shading).
#pragma once

#include <compare>
#include <string>

namespace glint {

struct SurfaceVariant {
    int samples = 1;             // MSAA samples (GLINT_MSAA_SAMPLES when > 1)
    bool gouraud = false;        // shaded per vertex (GLINT_GOURAUD)
    bool rayCastSphere = false;  // the exact sphere inside its proxy (GLINT_RAY_CAST_SPHERE)
    bool fadesEdge = false;      // a plane whose edge fades into the background (GLINT_PLANE_EDGE_FADE)
    std::string specialisation;  // what the frame and material fix (gl/shader_specialisation.h)

    std::string prelude() const {
        std::string text = samples > 1 ? "#define GLINT_MSAA_SAMPLES " + std::to_string(samples) + "\n" : "";
        if (gouraud) text += "#define GLINT_GOURAUD 1\n";
        if (rayCastSphere) text += "#define GLINT_RAY_CAST_SPHERE 1\n";
        if (fadesEdge) text += "#define GLINT_PLANE_EDGE_FADE 1\n";
        return text + specialisation;
    }
    auto operator<=>(const SurfaceVariant&) const = default;
};

}  // namespace glint
