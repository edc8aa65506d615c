// Shading frame and primary rays: the GLSL twins of core/math/frame.h and core/camera/camera.h.

const float PI = 3.14159265358979323846;
const float INV_PI = 1.0 / PI;

// base^exponent for base ≥ 0 with 0^0 = 1, as C++'s std::pow: GLSL leaves pow(0, 0) undefined
// (GLSL 4.10 §8.2), and exponents of exactly 0 are valid for the Phong-type lobes.
float powZeroIsOne(float base, float exponent) {
    return exponent == 0.0 ? 1.0 : pow(base, exponent);
}

struct ShadingFrame {
    vec3 tangent;
    vec3 bitangent;
    vec3 normal;
    vec3 coatNormal;  // the coat normal map's normal, zero when the coat shares `normal`
};

// Duff et al., "Building an Orthonormal Basis, Revisited", JCGT 6(1), 2017.
ShadingFrame frameFromNormal(vec3 n) {
    float s = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (s + n.z);
    float b = n.x * n.y * a;
    ShadingFrame frame;
    frame.tangent = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
    frame.bitangent = vec3(b, s + n.y * n.y * a, -n.y);
    frame.normal = n;
    frame.coatNormal = vec3(0.0);
    return frame;
}

// Twin of ShadingFrame::fromNormalAndTangent: Gram-Schmidt of the tangent against the normal,
// falling back to frameFromNormal when they are parallel.
ShadingFrame frameFromNormalAndTangent(vec3 n, vec3 tangentHint) {
    vec3 t = tangentHint - n * dot(n, tangentHint);
    float tangentLength = length(t);
    if (tangentLength < 1e-6) return frameFromNormal(n);
    ShadingFrame frame;
    frame.normal = n;
    frame.tangent = t / tangentLength;
    frame.bitangent = cross(n, frame.tangent);
    frame.coatNormal = vec3(0.0);
    return frame;
}

// Twin of ShadingFrame::coatFrame: the coat's frame around coatNormal, or the frame itself.
ShadingFrame coatFrameOf(ShadingFrame frame) {
    return frame.coatNormal == vec3(0.0) ? frame : frameFromNormalAndTangent(frame.coatNormal, frame.tangent);
}

float cosTheta(ShadingFrame frame, vec3 w) { return dot(w, frame.normal); }

vec3 toLocal(ShadingFrame frame, vec3 world) {
    return vec3(dot(world, frame.tangent), dot(world, frame.bitangent), dot(world, frame.normal));
}

struct Ray {
    vec3 origin;
    vec3 direction;
};

// The ray through a point in window coordinates (gl_FragCoord.xy), by unprojection.
Ray primaryRay(vec2 windowPoint) {
    vec2 ndc = 2.0 * windowPoint / viewportSize.xy - 1.0;
    vec4 nearPoint = inverseViewProjection * vec4(ndc, -1.0, 1.0);
    vec4 farPoint = inverseViewProjection * vec4(ndc, 1.0, 1.0);
    Ray ray;
    ray.origin = nearPoint.xyz / nearPoint.w;
    ray.direction = normalize(farPoint.xyz / farPoint.w - ray.origin);
    return ray;
}

// The primary ray that reaches a world point: the ray through the point's own window position
// (twin of rayTowards() in core/camera/camera.cpp). Usable in every shader stage.
Ray rayTowards(vec3 position) {
    vec4 clip = viewProjection * vec4(position, 1.0);
    vec2 windowPoint = (0.5 * clip.xy / clip.w + 0.5) * viewportSize.xy;
    return primaryRay(windowPoint);
}

// Unit direction from a world point towards the viewer: towards the eye of a perspective camera,
// along the view axis of an orthographic one (the eye is NDC (0, 0, −1, 0) unprojected: a point,
// or a direction when w = 0). Twin of towardsViewerFrom() in core/camera/camera.cpp.
vec3 towardsViewerFrom(vec3 position) {
    vec4 eye = inverseViewProjection * vec4(0.0, 0.0, -1.0, 0.0);
    return abs(eye.w) > 1e-12 ? normalize(eye.xyz / eye.w - position) : normalize(eye.xyz);
}
