// OpenPBR Surface: GLSL twin of core/brdf/openpbr.h (layering, eval, ambient), of the OpenPBR
// case of core/environment/environment_lighting.cpp (environment hook) and of
// core/render/openpbr_transport.h (emission and transmission). Fields: the names of
// core/brdf/openpbr_params.h. Needs the generated albedo arrays first (material_glsl.cpp).
#include "brdf/openpbr_lobes.glsl"
#include "brdf/openpbr_albedo.glsl"

struct OpenPbrView {
    float cosOut;
    vec2 specularAlphas, coatAlphas;
    float specularRoughness, coatRoughness;
    float dielectricF0, dielectricF90, coatF0;
    vec3 metalF0, metalF82;
    vec3 filmDielectric, filmMetal;
    float filmWeight;
    vec3 dielectricCompensation, metalCompensation;
    float coatCompensation;
    vec3 dielectricAlbedo, metalAlbedo;
    float coatAlbedo, sheenAlbedo;
    float sheenScale;
    float underFuzz;
    vec3 underCoat;
};

float openPbrOutsideIor(MaterialParams p) { return 1.0 + (p.coat_ior - 1.0) * p.coat_weight; }

float refractedCosine(float cosine, float eta) {
    return sqrt(max(0.0, 1.0 - (1.0 - cosine * cosine) / (eta * eta)));
}

vec3 coatAbsorption(MaterialParams p, float cosIn, float cosOut) {
    if (p.coat_weight <= 0.0) return vec3(1.0);
    float path = 0.5 / max(refractedCosine(cosIn, p.coat_ior), 1e-4) + 0.5 / max(refractedCosine(cosOut, p.coat_ior), 1e-4);
    vec3 transmittance = pow(max(p.coat_color, vec3(0.0)), vec3(path));
    return mix(vec3(1.0), transmittance, p.coat_weight);
}

OpenPbrView openPbrView(MaterialParams p, float cosOut) {
    OpenPbrView v;
    v.cosOut = clamp(cosOut, 0.0, 1.0);
    float coated = pow(min(1.0, 2.0 * pow(p.coat_roughness, 4.0) + pow(p.specular_roughness, 4.0)), 0.25);
    float specularRoughness = p.specular_roughness + (coated - p.specular_roughness) * p.coat_weight;
    v.specularAlphas = openPbrAlphas(specularRoughness, p.specular_roughness_anisotropy);
    v.coatAlphas = openPbrAlphas(p.coat_roughness, p.coat_roughness_anisotropy);
    v.specularRoughness = openPbrEquivalentRoughness(v.specularAlphas);
    v.coatRoughness = openPbrEquivalentRoughness(v.coatAlphas);
    float outsideIor = openPbrOutsideIor(p);
    v.dielectricF0 = min(1.0, p.specular_weight * dielectricF0(p.specular_ior / outsideIor));
    v.dielectricF90 = min(1.0, p.specular_weight);
    v.coatF0 = dielectricF0(p.coat_ior);
    float metalScale = min(1.0, p.specular_weight);
    v.metalF0 = metalScale * p.base_weight * p.base_color;
    v.metalF82 = f82Coefficient(v.metalF0, p.specular_color);
    v.filmWeight = p.thin_film_weight;
    v.filmDielectric = vec3(0.0);
    v.filmMetal = vec3(0.0);
    if (v.filmWeight > 0.0) {
        float thicknessNm = 1000.0 * p.thin_film_thickness;
        v.filmDielectric = thinFilmFresnel(outsideIor, p.thin_film_ior, thicknessNm, v.cosOut, vec3(v.dielectricF0));
        v.filmMetal = thinFilmFresnel(outsideIor, p.thin_film_ior, thicknessNm, v.cosOut, v.metalF0);
    }
    vec3 terms = ggxAlbedoTerms(v.cosOut, v.specularRoughness);
    float energy = max(terms.x + terms.y, 1e-4);
    vec3 dielectricReference = mix(vec3(v.dielectricF0), v.filmDielectric, v.filmWeight);
    vec3 metalReference = mix(v.metalF0, v.filmMetal, v.filmWeight);
    v.dielectricCompensation = 1.0 + dielectricReference * (1.0 - energy) / energy;
    v.metalCompensation = 1.0 + metalReference * (1.0 - energy) / energy;
    v.dielectricAlbedo = v.dielectricCompensation *
                         mix(vec3(v.dielectricF0 * terms.x + v.dielectricF90 * terms.y), v.filmDielectric * energy,
                             v.filmWeight);
    v.metalAlbedo = v.metalCompensation *
                    mix(v.metalF0 * terms.x + terms.y - v.metalF82 * terms.z, v.filmMetal * energy, v.filmWeight);
    vec3 coatTerms = ggxAlbedoTerms(v.cosOut, v.coatRoughness);
    float coatEnergy = max(coatTerms.x + coatTerms.y, 1e-4);
    v.coatCompensation = 1.0 + v.coatF0 * (1.0 - coatEnergy) / coatEnergy;
    v.coatAlbedo = v.coatCompensation * (v.coatF0 * coatTerms.x + coatTerms.y);
    float coatAverageFresnel = v.coatF0 + (1.0 - v.coatF0) / 21.0;
    float internal = 1.0 - (1.0 - coatAverageFresnel) / (p.coat_ior * p.coat_ior);
    vec3 baseAlbedo = p.base_weight * p.base_color;
    vec3 darkening = (1.0 - internal) / (1.0 - baseAlbedo * internal);
    v.underCoat = (1.0 - p.coat_weight * v.coatAlbedo) * mix(vec3(1.0), darkening, p.coat_weight * p.coat_darkening);
    float sheen = sheenAlbedo(v.cosOut, max(p.fuzz_roughness, OPENPBR_MIN_FUZZ_ROUGHNESS));
    v.sheenScale = 1.0 / max(1.0, sheen);
    v.sheenAlbedo = sheen * v.sheenScale;
    v.underFuzz = 1.0 - p.fuzz_weight * v.sheenAlbedo;
    return v;
}

vec3 openPbrLocal(MaterialParams p, ShadingFrame frame, vec3 world) {
    vec3 local = toLocal(frame, world);
    float angle = p.geometry_tangent_rotation * (PI / 180.0);
    float c = cos(angle), s = sin(angle);
    return vec3(c * local.x + s * local.y, -s * local.x + c * local.y, local.z);
}

// Twins of openPbrBaseSpecular and openPbrCoat.
vec3 openPbrBaseSpecular(MaterialParams p, OpenPbrView v, float cosDifference, float lobe) {
    vec3 metalFresnel = mix(fresnelF82(v.metalF0, v.metalF82, cosDifference), v.filmMetal, v.filmWeight);
    vec3 dielectricFresnel = mix(schlickF90(vec3(v.dielectricF0), vec3(v.dielectricF90), cosDifference),
                                 v.filmDielectric, v.filmWeight);
    return mix(p.specular_color * v.dielectricCompensation * dielectricFresnel, v.metalCompensation * metalFresnel,
               p.base_metalness) *
           lobe;
}

float openPbrCoat(MaterialParams p, OpenPbrView v, vec3 coatIn, vec3 coatOut, vec2 alphas) {
    if (coatIn.z <= 0.0 || coatOut.z <= 0.0) return 0.0;
    float cosDifference = dot(coatIn, normalize(coatIn + coatOut));
    float coatFresnel = schlickF90(vec3(v.coatF0), vec3(1.0), cosDifference).x;
    return p.coat_weight * v.coatCompensation * coatFresnel * ggxLobe(coatIn, coatOut, alphas);
}

vec3 evalOpenpbr(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {
    vec3 inLocal = openPbrLocal(p, frame, wi), outLocal = openPbrLocal(p, frame, wo);
    if (inLocal.z <= 0.0 || outLocal.z <= 0.0) return vec3(0.0);
    OpenPbrView v = openPbrView(p, outLocal.z);
    vec3 diffuse = (1.0 - v.dielectricAlbedo) * (1.0 - p.transmission_weight) *
                   eonLobe(p.base_weight * p.base_color, p.base_diffuse_roughness, inLocal, outLocal);
    float cosDifference = dot(inLocal, normalize(inLocal + outLocal));
    vec3 base = openPbrBaseSpecular(p, v, cosDifference, ggxLobe(inLocal, outLocal, v.specularAlphas)) +
                (1.0 - p.base_metalness) * diffuse;
    ShadingFrame coatFrame = coatFrameOf(frame);
    float coat = openPbrCoat(p, v, openPbrLocal(p, coatFrame, wi), openPbrLocal(p, coatFrame, wo), v.coatAlphas);
    vec3 fuzz = p.fuzz_weight * p.fuzz_color * v.sheenScale * sheenLobe(inLocal, outLocal, p.fuzz_roughness);
    return fuzz + v.underFuzz * (coat + v.underCoat * coatAbsorption(p, inLocal.z, outLocal.z) * base);
}

struct OpenPbrResponse {
    vec3 diffuse, coat, specular, transmission;
};

OpenPbrResponse openPbrResponse(MaterialParams p, OpenPbrView v) {
    vec3 underCoat = v.underFuzz * v.underCoat * coatAbsorption(p, v.cosOut, v.cosOut);
    vec3 dielectricBelow = (1.0 - p.base_metalness) * (1.0 - v.dielectricAlbedo);
    OpenPbrResponse r;
    r.diffuse = p.fuzz_weight * p.fuzz_color * v.sheenAlbedo +
                underCoat * dielectricBelow * (1.0 - p.transmission_weight) *
                    eonAlbedo(p.base_weight * p.base_color, p.base_diffuse_roughness, v.cosOut);
    r.coat = vec3(v.underFuzz * p.coat_weight * v.coatAlbedo);
    r.specular = underCoat * mix(p.specular_color * v.dielectricAlbedo, v.metalAlbedo, p.base_metalness);
    r.transmission = underCoat * dielectricBelow * p.transmission_weight;
    return r;
}

vec3 ambientReflectanceOpenpbr(MaterialParams p, vec3 wo, ShadingFrame frame) {
    OpenPbrResponse r = openPbrResponse(p, openPbrView(p, cosTheta(frame, wo)));
    return r.diffuse + r.coat + r.specular;
}

vec3 emissionOpenPbr(MaterialParams p, OpenPbrView v) {
    float throughCoat = 1.0 - p.coat_weight * v.coatAlbedo;
    return p.emission_luminance / 683.0 * p.emission_color * v.underFuzz * throughCoat *
           sqrt(coatAbsorption(p, v.cosOut, v.cosOut));
}

#ifdef GLINT_HAS_ENVIRONMENT
// The base's specular lobe and the coat's lit by a peak light, under the layers above each
// (twins of the peak terms of lightingOf(OpenPbrParams)).
vec3 openPbrSpecularPeakLobe(MaterialParams p, OpenPbrView v, vec3 wi, vec3 outLocal, ShadingFrame frame, float widen) {
    vec3 inLocal = openPbrLocal(p, frame, wi);
    float lobe = ggxLobe(inLocal, outLocal, v.specularAlphas * widen);
    return v.underFuzz * v.underCoat * coatAbsorption(p, inLocal.z, outLocal.z) *
           openPbrBaseSpecular(p, v, dot(inLocal, normalize(inLocal + outLocal)), lobe) * inLocal.z;
}

vec3 openPbrCoatPeakLobe(MaterialParams p, OpenPbrView v, vec3 wi, vec3 coatOut, ShadingFrame coatFrame, float widen) {
    vec3 coatIn = openPbrLocal(p, coatFrame, wi);
    return vec3(v.underFuzz * openPbrCoat(p, v, coatIn, coatOut, v.coatAlphas * widen) * coatIn.z);
}

// Environment hook: twin of lightingOf(OpenPbrParams) in core/environment/environment_lighting.cpp.
vec3 environmentLightingOpenpbr(MaterialParams p, vec3 wo, ShadingFrame frame) {
    OpenPbrView v = openPbrView(p, cosTheta(frame, wo));
    OpenPbrResponse r = openPbrResponse(p, v);
    float coatAlpha = v.coatRoughness * v.coatRoughness, specularAlpha = v.specularRoughness * v.specularRoughness;
    ShadingFrame coatFrame = coatFrameOf(frame);
    vec3 outLocal = openPbrLocal(p, frame, wo), coatOut = openPbrLocal(p, coatFrame, wo);
    vec3 peaks = vec3(0.0);
    ENVIRONMENT_ADD_PEAKS(peaks, specularAlpha, wo, frame,
                          openPbrSpecularPeakLobe(p, v, wi, outLocal, frame, widened / specularAlpha))
    if (p.coat_weight > 0.0) {
        ENVIRONMENT_ADD_PEAKS(peaks, coatAlpha, wo, coatFrame,
                              openPbrCoatPeakLobe(p, v, wi, coatOut, coatFrame, widened / coatAlpha))
    }
    return r.diffuse * environmentDiffuseRadiance(frame.normal) +
           r.coat * environmentObliqueGlossyRadiance(environmentDominantDirection(wo, coatFrame, coatAlpha), coatFrame, wo,
                                                     coatAlpha, v.coatRoughness) +
           r.specular * environmentObliqueGlossyRadiance(environmentDominantDirection(wo, frame, specularAlpha), frame, wo,
                                                         specularAlpha, v.specularRoughness) +
           peaks;
}
#endif

vec3 openPbrVolumeTransmittance(MaterialParams p, float distance) {
    if (p.transmission_depth <= 0.0) return p.transmission_color;
    return pow(max(p.transmission_color, vec3(0.0)), vec3(distance / p.transmission_depth));
}

// Transport hook: emission and transmission (twin of transportOpenpbr in render/openpbr_transport.h).
vec3 transportOpenpbr(MaterialParams p, vec3 position, ShadingFrame frame, vec3 towardsViewer) {
    vec3 normal = frame.normal;
    OpenPbrView v = openPbrView(p, dot(normal, towardsViewer));
    vec3 emission = emissionOpenPbr(p, v);
    if (p.transmission_weight <= 0.0) return emission;
    vec3 weight = openPbrResponse(p, v).transmission;
    vec3 incoming = -towardsViewer;
    bool outsideSphere = shapeKind == SHAPE_SPHERE && dot(normal, position - sphere.xyz) > 0.0;
    if (!p.geometry_thin_walled && shapeKind != SHAPE_SPHERE && p.geometry_thickness > 0.0) {
        vec3 exitPoint = position + p.geometry_thickness * refractDirection(incoming, normal, 1.0 / p.specular_ior);
        return emission + weight * openPbrVolumeTransmittance(p, p.geometry_thickness) *
                              transmittedRadianceRough(exitPoint, incoming, incoming, v.specularRoughness, p.specular_ior);
    }
    if (p.geometry_thin_walled || !outsideSphere)
        return emission + weight * p.transmission_color *
                              transmittedRadianceRough(position, incoming, incoming, v.specularRoughness, p.specular_ior);
    vec3 refracted = refractDirection(incoming, normal, 1.0 / p.specular_ior);
    float chord = sphereExitDistance(sphere, position, refracted);
    vec3 exitPoint = position + chord * refracted;
    vec3 inwardNormal = (sphere.xyz - exitPoint) / sphere.w;
    float exitReflectance = fresnelDielectric(-dot(refracted, inwardNormal), 1.0 / p.specular_ior);
    if (exitReflectance >= 1.0) return emission;
    vec3 leaving = refractDirection(refracted, inwardNormal, p.specular_ior);
    return emission + weight * openPbrVolumeTransmittance(p, chord) * (1.0 - exitReflectance) *
                          transmittedRadianceRough(exitPoint, leaving, incoming, v.specularRoughness, p.specular_ior);
}
