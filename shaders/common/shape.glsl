// The shape being drawn: a planar mesh or an analytic sphere (set per object by the renderer),
// and the ray-sphere intersection. Shared by surface.frag and the traced models (glass).

const int SHAPE_MESH = 0;
const int SHAPE_SPHERE = 1;

uniform int shapeKind;
uniform vec4 sphere;  // xyz: centre, w: radius

// Nearest t > 0 with |o + t·d − c| = r, or -1.
float intersectSphere(Ray ray) {
    vec3 offset = ray.origin - sphere.xyz;
    float b = dot(offset, ray.direction);
    float c = dot(offset, offset) - sphere.w * sphere.w;
    float discriminant = b * b - c;
    if (discriminant < 0.0) return -1.0;
    float root = sqrt(discriminant);
    if (-b - root > 0.0) return -b - root;
    if (-b + root > 0.0) return -b + root;
    return -1.0;
}
