// Glass: GLSL twin of core/brdf/glass.h (fields: ior, absorption, transparency, transmission).
// Both lobes are traced by traceGlass() in common/specular_transport.glsl, through the sphere
// being drawn (common/shape.glsl) or as a thin pane on a plane.

vec3 evalGlass(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    return vec3(0.0);
}

// The viewer distance is measured from the origin of the primary ray reaching the point, as the
// CPU's hit distance (rayTowards works in the vertex stage too, for Gouraud shading).
vec3 transportGlass(MaterialParams p, vec3 position, ShadingFrame frame, vec3 towardsViewer) {
    float viewerDistance = length(position - rayTowards(position).origin);
    return traceGlass(p.ior, p.transparency == TRANSPARENCY_CLASSIC, p.transmission, p.absorption, shapeKind == SHAPE_SPHERE, sphere,
                      position, frame.normal, towardsViewer, viewerDistance);
}
