// The fused display output of the passes that write radiance (surface.frag, background.frag):
// when the renderer fuses the display chain into the radiance pass (headless, no MSAA), the
// display-encoded value goes to a second target in the same pass, and the separate display pass
// (which re-reads the whole float image) is skipped. Never fused with the levels ramp (display.frag). Declares outRadiance (location 0) and
// outDisplay (location 1); a pass that writes radiance ends with writeRadiance().
#include "common/display_encode.glsl"

layout(location = 0) out vec4 outRadiance;
layout(location = 1) out vec4 outDisplay;
// false: no second target is bound, the display pass follows (a constant when specialised,
// gl/shader_specialisation.h).
#ifdef GLINT_FUSED_DISPLAY
const bool fusedDisplay = GLINT_FUSED_DISPLAY != 0;
#else
uniform bool fusedDisplay;
#endif

void writeRadiance(vec3 radiance) {
    outRadiance = vec4(radiance, 1.0);
    if (fusedDisplay) outDisplay = vec4(displayEncode(radiance, ivec2(gl_FragCoord.xy)), 1.0);
}
