// Uniform blocks shared by the surface shaders. Their C++ mirrors (std140, size-checked) are in
// core/gl/uniform_blocks.h; change both together.

const int MAX_LIGHTS = 256;  // 256 lights of 64 bytes: the 16 KiB uniform block OpenGL 4.1 guarantees

layout(std140) uniform FrameBlock {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 viewportSize;     // x, y: pixels of the render target
    vec4 background;       // rgb: constant background radiance [W/(sr·m²)]
    vec4 skyZenith;        // rgb: sky radiance straight up (+y)
    vec4 skyHorizon;       // rgb: ... at the horizon
    vec4 skyGround;        // rgb: ... straight down
    vec4 ambientRadiance;  // rgb: Σ L_a of the ambient lights [W/(sr·m²)]
    ivec4 lightCount;      // x: number of lights in LightBlock
    ivec4 backgroundKind;  // x: 0 constant, 1 sky gradient
};

// A light in homogeneous form (docs/architecture.md): position.w = 1 for a point or spot light at
// position.xyz, 0 for a directional light whose position.xyz points towards the light.
// Four vec4s, no spare component: see GpuLightStd140.
struct GpuLight {
    vec4 position;
    vec4 emission;     // rgb: E⊥ [W/m²] for directional; radiant intensity Φ/4π [W/sr] otherwise; w: cos(θ_c − edge width)
    vec4 spotAxis;     // xyz: direction the spot shines; w: cos θ_c (−2 for no cone)
    vec4 attenuation;  // xyz: a0, a1, a2 of E⊥ = I/(a0 + a1·d + a2·d²), (0, 0, 1) for the inverse-square law; w: spot falloff exponent a
};

layout(std140) uniform LightBlock {
    GpuLight lights[MAX_LIGHTS];
};

layout(std140) uniform MaterialBlock {
    vec4 materialValues[12];  // the model's parameter table, packed in table order
};

float materialValue(int index) { return materialValues[index / 4][index % 4]; }
