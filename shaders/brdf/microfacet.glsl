// Microfacet terms: D (Beckmann, GGX, anisotropic GGX) and G (V-cavity, height-correlated Smith).
// GLSL twin of core/brdf/microfacet.h (its Fresnel choice: microfacet_fresnel.glsl); no BRDF here.

float sinSquared(vec3 normal, vec3 halfway) {
    vec3 crossed = cross(normal, halfway);
    return dot(crossed, crossed);
}

float distributionBeckmann(float cosHalf, float sin2Half, float alpha) {
    float cos2 = cosHalf * cosHalf;
    return exp(-sin2Half / (cos2 * alpha * alpha)) / (PI * alpha * alpha * cos2 * cos2);
}

float distributionGgx(float cosHalf, float sin2Half, float alpha) {
    float scaled = alpha * cosHalf;
    float k = alpha / (sin2Half + scaled * scaled);
    return k * k * INV_PI;
}

float distributionGgxAnisotropic(vec3 halfLocal, float alphaX, float alphaY) {
    float x = halfLocal.x / alphaX, y = halfLocal.y / alphaY;
    float denominator = x * x + y * y + halfLocal.z * halfLocal.z;
    return 1.0 / (PI * alphaX * alphaY * denominator * denominator);
}

float lambdaGgx(float cosTheta, float alpha) {
    float cos2 = cosTheta * cosTheta;
    float tan2 = max(1.0 - cos2, 0.0) / cos2;
    return 0.5 * (-1.0 + sqrt(1.0 + alpha * alpha * tan2));
}

float lambdaGgxAnisotropic(vec3 local, float alphaX, float alphaY) {
    float projected = (alphaX * alphaX * local.x * local.x + alphaY * alphaY * local.y * local.y) /
                      (local.z * local.z);
    return 0.5 * (-1.0 + sqrt(1.0 + projected));
}

float lambdaBeckmann(float cosTheta, float alpha) {
    float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
    if (sinTheta == 0.0) return 0.0;
    float a = cosTheta / (alpha * sinTheta);
    if (a >= 1.6) return 0.0;
    return (1.0 - 1.259 * a + 0.396 * a * a) / (3.535 * a + 2.181 * a * a);
}

float smithHeightCorrelated(float lambdaIn, float lambdaOut) { return 1.0 / (1.0 + lambdaIn + lambdaOut); }

float maskingVCavity(float cosHalf, float cosIn, float cosOut, float cosDifference) {
    return min(1.0, 2.0 * cosHalf * min(cosIn, cosOut) / cosDifference);
}
