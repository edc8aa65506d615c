// Uniform blocks shared by the surface shaders. Their C++ mirrors (std140, size-checked) are in
// core/gl/uniform_blocks.h; change both together.

const int MAX_LIGHTS = 16;

layout(std140) uniform FrameBlock {
    mat4 viewProjection;
    mat4 inverseViewProjection;
    vec4 viewportSize;   // x, y: pixels of the render target
    vec4 background;     // rgb: radiance [W/(sr·m²)]
    ivec4 lightCount;    // x: number of lights in LightBlock
};

// A light in homogeneous form (DESIGN.md): position.w = 1 for a point light at position.xyz,
// 0 for a directional light whose position.xyz points towards the light.
struct GpuLight {
    vec4 position;
    vec4 emission;  // rgb: E⊥ [W/m²] for directional; radiant intensity Φ/4π [W/sr] for point
};

layout(std140) uniform LightBlock {
    GpuLight lights[MAX_LIGHTS];
};

layout(std140) uniform MaterialBlock {
    vec4 materialValues[8];  // the model's parameter table, packed in table order
};

float materialValue(int index) { return materialValues[index / 4][index % 4]; }
