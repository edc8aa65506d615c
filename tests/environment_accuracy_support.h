// Environment light against its Monte-Carlo ground truth (issue 21): a unit sphere lit by an
// environment alone, seen orthographically; three maps (a smooth sky, one small bright light on a
// dim fill, a real studio HDRI shipped in tests/environments), the materials of every model with
// an environment hook, and the two measures: PSNR over the sphere's interior pixels (peak: the
// reference's brightest channel there) and the ratio of the means. Shared by the GPU test and
// tests/bench/environment_accuracy.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <string>
#include <tuple>
#include <vector>

#include "brdf/cook_torrance.h"
#include "brdf/model_registry.h"
#include "brdf/param_table.h"
#include "environment/environment_map.h"
#include "environment/environment_source.h"
#include "image/image.h"
#include "math/constants.h"
#include "scene/scene.h"

namespace glint::test {

struct AccuracyMap {
    std::string name;
    Environment environment;
};

// One small bright light (a disc of 4° radius, radiance 300, towards (0.3, 0.8, 0.5)) on a dim
// grey fill (0.05 below the horizon, 0.1 above): the map SH9 irradiance rings on.
inline EquirectImage smallLightImage() {
    EquirectImage image(256, 128);
    const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
    const float cosRadius = std::cos(4.0f * kPi / 180.0f);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::vec3 d = equirectDirection({(x + 0.5f) / image.width, (y + 0.5f) / image.height});
            image.at(x, y) = glm::vec3(d.y > 0.0f ? 0.1f : 0.05f) + (glm::dot(d, light) >= cosRadius ? 300.0f : 0.0f);
        }
    return image;
}

inline std::vector<AccuracyMap> accuracyMaps(const std::string& studioFile) {
    std::vector<AccuracyMap> maps(3);
    maps[0].name = "smooth sky";
    maps[0].environment.kind = EnvironmentKind::Sky;
    maps[1].name = "small light";
    maps[1].environment.kind = EnvironmentKind::File;
    maps[1].environment.file = "small light (synthetic)";
    maps[1].environment.map = makeEnvironmentMap(smallLightImage());
    maps[2].name = "studio HDRI";
    maps[2].environment.kind = EnvironmentKind::File;
    maps[2].environment.file = studioFile;
    for (AccuracyMap& map : maps)
        if (!map.environment.map) (void)loadEnvironment(map.environment);
    return maps;
}

struct AccuracyMaterial {
    std::string name;
    Material material;
    float alpha = 0.0f;  // the glossy lobe's GGX roughness (0: a diffuse model)
    bool options = false;  // a model's options other than its defaults
};

inline void setParam(Material& material, const char* name, std::initializer_list<float> values) {
    const auto table = modelInfo(material.analytic()->model).params;
    const int index = findParam(table, name);
    std::copy(values.begin(), values.end(), material.analytic()->values.begin() + packedOffset(table, index));
}

// A model's material with its glossy lobe at GGX roughness α (the environment roughness the
// preview prefilters with: environment_lighting.h): microfacet α itself, Ward α, Blinn-Phong
// n = 2/α² − 2, Phong n = (2/α² − 2)/4.
inline Material glossyMaterial(BrdfModel model, float alpha) {
    Material material = Material::withDefaults("m", model);
    const float blinnExponent = 2.0f / (alpha * alpha) - 2.0f;
    switch (model) {
        case BrdfModel::CookTorrance:  // F = 1 (Schlick with F0 = 1): the lobe alone
            setParam(material, "ior", {1, 1, 1});
            setParam(material, "extinction", {1e4f, 1e4f, 1e4f});
            setParam(material, "roughness", {alpha});
            break;
        case BrdfModel::GgxAnisotropic:
            setParam(material, "roughness_x", {alpha});
            setParam(material, "roughness_y", {alpha});
            break;
        case BrdfModel::Ward:
            setParam(material, "roughness_x", {alpha});
            setParam(material, "roughness_y", {alpha});
            break;
        case BrdfModel::BlinnPhong: setParam(material, "exponent", {blinnExponent}); break;
        case BrdfModel::Phong: setParam(material, "exponent", {blinnExponent / 4.0f}); break;
        default: break;
    }
    return material;
}

inline bool isGlossyModel(BrdfModel model) {
    return model == BrdfModel::CookTorrance || model == BrdfModel::GgxAnisotropic || model == BrdfModel::Ward ||
           model == BrdfModel::BlinnPhong || model == BrdfModel::Phong;
}

inline constexpr float kAccuracyAlphas[] = {0.05f, 0.2f, 0.5f, 1.0f};

// Every model with an environment hook: the diffuse ones with their defaults (Lambert at ρ 0.8),
// the glossy ones at each α of kAccuracyAlphas, cook_torrance also with its other D × G pairs.
inline std::vector<AccuracyMaterial> accuracyMaterials() {
    std::vector<AccuracyMaterial> materials;
    for (const ModelInfo& info : allModels()) {
        if (!info.glslEnvironment || info.model == BrdfModel::Glass) continue;
        if (isGlossyModel(info.model)) {
            for (float alpha : kAccuracyAlphas) {
                char name[64];
                std::snprintf(name, sizeof name, "%s α %.2g", info.id, alpha);
                materials.push_back({name, glossyMaterial(info.model, alpha), alpha});
            }
            if (info.model != BrdfModel::CookTorrance) continue;
            // Its other microfacet D × G pairs, each with its own split-sum tables.
            const std::tuple<const char*, MicrofacetDistribution, MicrofacetGeometry> pairs[] = {
                {"beckmann smith", MicrofacetDistribution::Beckmann, MicrofacetGeometry::Smith},
                {"beckmann v_cavity", MicrofacetDistribution::Beckmann, MicrofacetGeometry::VCavity},
                {"ggx v_cavity", MicrofacetDistribution::Ggx, MicrofacetGeometry::VCavity}};
            for (const auto& [pairName, distribution, geometry] : pairs)
                for (float alpha : kAccuracyAlphas) {
                    char name[64];
                    std::snprintf(name, sizeof name, "%s %s α %.2g", info.id, pairName, alpha);
                    Material material = glossyMaterial(info.model, alpha);
                    setParam(material, "distribution", {static_cast<float>(distribution)});
                    setParam(material, "geometry", {static_cast<float>(geometry)});
                    materials.push_back({name, material, alpha, true});
                }
        } else {
            Material material = Material::withDefaults("m", info.model);
            if (info.model == BrdfModel::Lambert) setParam(material, "albedo", {0.8f, 0.8f, 0.8f});
            materials.push_back({info.id, material});
        }
    }
    return materials;
}

// A unit sphere of `material` under `environment` alone, seen from +z (orthographic, 2.2 high).
inline Scene accuracyScene(const Material& material, const Environment& environment) {
    Scene scene;
    scene.camera.projection = Projection::Orthographic;
    scene.camera.position = {0.0f, 0.0f, 5.0f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.camera.orthoHeight = 2.2f;
    scene.materials = {material};
    scene.objects.push_back({"sphere", SphereShape{}, 0});
    scene.environment = environment;
    return scene;
}

struct Accuracy {
    double psnr = 0.0;   // [dB], 10·log10(peak² / mean squared error) over the interior pixels' channels
    double ratio = 0.0;  // mean of the image / mean of the reference over the same pixels
};

// The sphere's interior: pixel centres within 0.97 of the disc's radius.
inline Accuracy measureAccuracy(const RadianceImage& image, const RadianceImage& reference) {
    const float pixelSize = 2.2f / reference.height;
    double squaredError = 0.0, sum = 0.0, referenceSum = 0.0, peak = 0.0;
    long count = 0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            const float px = -1.1f + (x + 0.5f) * pixelSize, py = 1.1f - (y + 0.5f) * pixelSize;
            if (px * px + py * py >= 0.97f * 0.97f) continue;
            for (int c = 0; c < 3; ++c) {
                const double a = image.at(x, y)[c], b = reference.at(x, y)[c];
                squaredError += (a - b) * (a - b);
                sum += a;
                referenceSum += b;
                peak = std::max(peak, b);
                ++count;
            }
        }
    const double meanSquaredError = std::max(squaredError / std::max(count, 1L), 1e-30);
    return {10.0 * std::log10(peak * peak / meanSquaredError), referenceSum > 0.0 ? sum / referenceSum : 0.0};
}

}  // namespace glint::test
