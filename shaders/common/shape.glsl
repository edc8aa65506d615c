// The shape being drawn: a planar mesh or an analytic sphere (set per object by the renderer),
// and the ray-sphere intersection. Shared by surface.frag and the traced models (glass).

const int SHAPE_MESH = 0;
const int SHAPE_SPHERE = 1;

uniform int shapeKind;
uniform vec4 sphere;  // xyz: centre, w: radius

// Nearest t > 0 with |o + t·d − c| = r, or -1: the stable forms of Haines et al. (Ray Tracing
// Gems, 2019, ch. 7), as intersectSphere() in core/render/reference_renderer.cpp.
float intersectSphere(Ray ray) {
    vec3 offset = ray.origin - sphere.xyz;
    float b = dot(offset, ray.direction);
    vec3 perpendicular = offset - b * ray.direction;
    float discriminant = sphere.w * sphere.w - dot(perpendicular, perpendicular);
    if (discriminant < 0.0) return -1.0;
    float c = dot(offset, offset) - sphere.w * sphere.w;
    float q = -b - (b < 0.0 ? -1.0 : 1.0) * sqrt(discriminant);
    float nearT = min(c / q, q), farT = max(c / q, q);
    if (nearT > 0.0) return nearT;
    if (farT > 0.0) return farT;
    return -1.0;
}
