// The OpenPBR model on the CPU: the white furnace with and without the multiple-scattering
// compensation, layering that conserves energy, the hooks against the integrated BRDF, the
// parameters as the specification names them, the tables and what each lobe does.
// (Registry-wide properties, f_r ≥ 0 and albedo ≤ 1 on random parameters: brdf_test.cpp; GPU
// against CPU: brdf_gpu_sweep_test.cpp and environment_gpu_test.cpp.)
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "brdf/model_registry.h"
#include "brdf/openpbr.h"
#include "environment/environment_lighting.h"
#include "environment/environment_source.h"
#include "render/openpbr_transport.h"
#include "scene/scene.h"

namespace glint {
namespace {

std::vector<float> openPbrValues(std::initializer_list<std::pair<const char*, glm::vec3>> settings) {
    std::vector<float> values = defaultValues(kOpenPbrTable);
    for (const auto& [name, value] : settings) {
        const int index = findParam(kOpenPbrTable, name);
        EXPECT_GE(index, 0) << name;
        for (int c = 0; c < componentCount(kOpenPbrTable[index].kind); ++c)
            values[packedOffset(kOpenPbrTable, index) + c] = value[c];
    }
    return values;
}

glm::vec3 viewAt(float theta) { return {std::sin(theta), 0.0f, std::cos(theta)}; }

// ∫ f cos θ_i dω_i parametrised by the half vector around the mirror direction (θ_h = (π/2)t⁴)
// so that lobes down to α = 0.001 are resolved; diffuse lobes are smooth in it too.
template <typename Brdf>
glm::vec3 albedoAroundMirror(const Brdf& brdf, glm::vec3 wo, int thetaSteps = 256, int phiSteps = 96) {
    glm::dvec3 sum(0.0);
    const double halfPi = 0.5 * M_PI;
    for (int i = 0; i < thetaSteps; ++i) {
        const double t = (i + 0.5) / thetaSteps;
        const double thetaHalf = halfPi * t * t * t * t, dTheta = halfPi * 4.0 * t * t * t / thetaSteps;
        for (int j = 0; j < phiSteps; ++j) {
            const double phi = 2.0 * M_PI * (j + 0.5) / phiSteps;
            const glm::dvec3 h(std::sin(thetaHalf) * std::cos(phi), std::sin(thetaHalf) * std::sin(phi), std::cos(thetaHalf));
            const double cosOutHalf = glm::dot(glm::dvec3(wo), h);
            if (cosOutHalf <= 0.0) continue;
            const glm::dvec3 wi = 2.0 * cosOutHalf * h - glm::dvec3(wo);
            if (wi.z <= 0.0) continue;
            sum += glm::dvec3(brdf(glm::vec3(glm::normalize(wi)), wo)) * wi.z * 4.0 * cosOutHalf * std::sin(thetaHalf) *
                   dTheta * (2.0 * M_PI / phiSteps);
        }
    }
    return glm::vec3(sum);
}

glm::vec3 openPbrAlbedo(const std::vector<float>& values, glm::vec3 wo) {
    return albedoAroundMirror([&](glm::vec3 wi, glm::vec3 out) { return evalBrdf(BrdfModel::OpenPbr, values, wi, out, {}); },
                              wo);
}

constexpr float kRoughnesses[] = {0.0f, 0.1f, 0.2f, 0.3f, 0.4f, 0.5f, 0.6f, 0.7f, 0.8f, 0.9f, 1.0f};
constexpr float kViews[] = {0.0f, 0.5f, 1.0f, 1.3f};

// The criterion: a white, rough, non-absorbing material reflects ≥ 0.98 under a uniform
// white environment at every roughness, where single-scattering GGX loses up to ~60% at α = 1.
// A white metal (F0 = 1): its one lobe is all the GGX lobe, compensated. Prints the table.
TEST(OpenPbrFurnace, WhiteMetalReflectsAtLeast098AtEveryRoughness) {
    for (float roughness : kRoughnesses) {
        const auto values = openPbrValues({{"base_color", glm::vec3(1)}, {"base_metalness", glm::vec3(1)},
                                           {"specular_roughness", glm::vec3(roughness)}});
        const glm::vec2 alphas = openPbrAlphas(roughness, 0.0f);
        std::string row = "white metal, r = " + std::to_string(roughness).substr(0, 3) + ": compensated";
        std::string single = "; single scattering";
        for (float theta : kViews) {
            const float albedo = openPbrAlbedo(values, viewAt(theta)).g;
            const float singleScattering =
                albedoAroundMirror([&](glm::vec3 wi, glm::vec3 wo) { return glm::vec3(ggxLobe(wi, wo, alphas)); },
                                   viewAt(theta)).g;
            row += " " + std::to_string(albedo).substr(0, 5);
            single += " " + std::to_string(singleScattering).substr(0, 5);
            EXPECT_GE(albedo, 0.98f) << "r " << roughness << " θ " << theta;
            EXPECT_LE(albedo, 1.0f + 5e-3f) << "r " << roughness << " θ " << theta;
        }
        std::printf("%s%s (θ_o = 0, 0.5, 1, 1.3 rad)\n", row.c_str(), single.c_str());
    }
}

// A white dielectric (diffuse ρ = 1 under the specular layer), a white coat over it, and white
// fuzz over that: each layer passes on what it does not reflect.
TEST(OpenPbrFurnace, WhiteLayersReflectAtLeast098AtEveryRoughness) {
    for (float roughness : kRoughnesses) {
        const glm::vec3 r(roughness);
        const std::pair<const char*, std::vector<float>> stacks[] = {
            {"dielectric", openPbrValues({{"base_color", glm::vec3(1)}, {"specular_roughness", r}})},
            {"rough diffuse", openPbrValues({{"base_color", glm::vec3(1)}, {"specular_roughness", r},
                                             {"base_diffuse_roughness", glm::vec3(1)}})},
            {"coated", openPbrValues({{"base_color", glm::vec3(1)}, {"coat_weight", glm::vec3(1)}, {"coat_roughness", r}})},
            {"fuzz", openPbrValues({{"base_color", glm::vec3(1)}, {"fuzz_weight", glm::vec3(1)}, {"fuzz_roughness", r}})},
        };
        std::string row = "r = " + std::to_string(roughness).substr(0, 3) + ":";
        for (const auto& [name, values] : stacks) {
            row += std::string(" ") + name;
            for (float theta : kViews) {
                const float albedo = openPbrAlbedo(values, viewAt(theta)).g;
                row += " " + std::to_string(albedo).substr(0, 5);
                EXPECT_GE(albedo, 0.98f) << name << " r " << roughness << " θ " << theta;
                EXPECT_LE(albedo, 1.0f + 5e-3f) << name << " r " << roughness << " θ " << theta;
            }
        }
        std::printf("%s\n", row.c_str());
    }
}

// The same under the uniform white map, through the environment hook the preview uses.
TEST(OpenPbrFurnace, WhiteMaterialsUnderTheWhiteMapReflectAtLeast098) {
    Environment white;
    white.kind = EnvironmentKind::White;
    ASSERT_TRUE(loadEnvironment(white));
    for (float roughness : kRoughnesses) {
        for (float metalness : {0.0f, 1.0f}) {
            const auto values = openPbrValues({{"base_color", glm::vec3(1)}, {"base_metalness", glm::vec3(metalness)},
                                               {"specular_roughness", glm::vec3(roughness)}, {"coat_weight", glm::vec3(0.5f)}});
            for (float theta : kViews) {
                const glm::vec3 lit = environmentLighting(BrdfModel::OpenPbr, values, viewAt(theta), {}, white);
                EXPECT_GE(lit.g, 0.98f) << "r " << roughness << " metal " << metalness << " θ " << theta;
                EXPECT_LE(lit.g, 1.0f + 5e-3f) << "r " << roughness << " metal " << metalness << " θ " << theta;
            }
        }
    }
}

// The hooks are the directional albedo they claim to be: ambient k_a against the integral.
TEST(OpenPbrHooks, AmbientIsTheDirectionalAlbedo) {
    const std::vector<float> materials[] = {
        defaultValues(kOpenPbrTable),
        openPbrValues({{"base_color", {0.9f, 0.6f, 0.2f}}, {"base_metalness", glm::vec3(1)}, {"specular_color", {1.0f, 0.8f, 0.6f}},
                       {"specular_roughness", glm::vec3(0.4f)}}),
        openPbrValues({{"base_color", {0.6f, 0.05f, 0.05f}}, {"coat_weight", glm::vec3(1)}, {"coat_color", {0.9f, 0.9f, 0.7f}},
                       {"coat_roughness", glm::vec3(0.1f)}, {"base_diffuse_roughness", glm::vec3(0.5f)}}),
        openPbrValues({{"base_color", {0.2f, 0.02f, 0.1f}}, {"fuzz_weight", glm::vec3(1)}, {"fuzz_color", {0.8f, 0.3f, 0.5f}},
                       {"fuzz_roughness", glm::vec3(0.5f)}, {"specular_roughness", glm::vec3(0.6f)}}),
        openPbrValues({{"thin_film_weight", glm::vec3(1)}, {"thin_film_thickness", glm::vec3(0.4f)}, {"specular_roughness", glm::vec3(0.2f)}}),
    };
    for (const auto& values : materials) {
        for (float theta : {0.0f, 0.8f, 1.3f}) {
            const glm::vec3 ka = ambientReflectance(BrdfModel::OpenPbr, values, viewAt(theta), {});
            const glm::vec3 albedo = openPbrAlbedo(values, viewAt(theta));
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(ka[c], albedo[c], 0.01f + 0.01f * albedo[c]) << "θ " << theta << " c " << c;
        }
    }
}

TEST(OpenPbrParameters, NamesAndDefaultsFollowTheSpecification) {
    // OpenPBR Surface 1.1 (MaterialX open_pbr_surface): the defaults other tools assume.
    const std::pair<const char*, glm::vec3> defaults[] = {
        {"base_weight", glm::vec3(1.0f, 0, 0)},        {"base_color", glm::vec3(0.8f)},
        {"base_metalness", glm::vec3(0)},             {"base_diffuse_roughness", glm::vec3(0)},
        {"specular_weight", glm::vec3(1.0f, 0, 0)},    {"specular_color", glm::vec3(1)},
        {"specular_roughness", glm::vec3(0.3f, 0, 0)}, {"specular_roughness_anisotropy", glm::vec3(0)},
        {"specular_ior", glm::vec3(1.5f, 0, 0)},       {"transmission_weight", glm::vec3(0)},
        {"transmission_color", glm::vec3(1)},         {"transmission_depth", glm::vec3(0)},
        {"fuzz_weight", glm::vec3(0)},                {"fuzz_color", glm::vec3(1)},
        {"fuzz_roughness", glm::vec3(0.5f, 0, 0)},     {"coat_weight", glm::vec3(0)},
        {"coat_color", glm::vec3(1)},                 {"coat_roughness", glm::vec3(0)},
        {"coat_roughness_anisotropy", glm::vec3(0)},  {"coat_ior", glm::vec3(1.6f, 0, 0)},
        {"coat_darkening", glm::vec3(1.0f, 0, 0)},     {"thin_film_weight", glm::vec3(0)},
        {"thin_film_thickness", glm::vec3(0.5f, 0, 0)}, {"thin_film_ior", glm::vec3(1.4f, 0, 0)},
        {"emission_luminance", glm::vec3(0)},         {"emission_color", glm::vec3(1)},
        {"geometry_thin_walled", glm::vec3(0)},       {"geometry_tangent_rotation", glm::vec3(0)},
        {"geometry_thickness", glm::vec3(0)},
    };
    EXPECT_EQ(std::size(kOpenPbrTable), std::size(defaults));
    for (const auto& [name, value] : defaults) {
        const int index = findParam(kOpenPbrTable, name);
        ASSERT_GE(index, 0) << name;
        for (int c = 0; c < componentCount(kOpenPbrTable[index].kind); ++c)
            EXPECT_FLOAT_EQ(kOpenPbrTable[index].defaultValue[c], value[c]) << name;
    }
    // The unpacking reads every field from its table offset.
    const auto values = openPbrValues({{"geometry_tangent_rotation", glm::vec3(33)}, {"emission_color", {0.1f, 0.2f, 0.3f}},
                                       {"geometry_thin_walled", glm::vec3(1)}, {"coat_darkening", glm::vec3(0.25f)}});
    ASSERT_EQ(static_cast<int>(values.size()), packedSize(kOpenPbrTable));
    const OpenPbrParams p = unpack<OpenPbr>(values.data());
    EXPECT_EQ(p.tangentRotation, 33.0f);
    EXPECT_EQ(p.emissionColor, glm::vec3(0.1f, 0.2f, 0.3f));
    EXPECT_TRUE(p.thinWalled);
    EXPECT_EQ(p.coatDarkening, 0.25f);
    EXPECT_EQ(p.specularIor, 1.5f);
}

TEST(OpenPbrLobes, AnisotropyStretchesAlongTheRotatedTangent) {
    const glm::vec2 alphas = openPbrAlphas(0.5f, 0.8f);
    EXPECT_NEAR(alphas.y, 0.2f * alphas.x, 1e-6f);
    EXPECT_EQ(openPbrAlphas(0.5f, 0.0f), glm::vec2(0.25f));
    // Tilting the light along the stretched axis keeps more of the highlight; turning the tangent
    // by 90° swaps the axes.
    const glm::vec3 wo(0, 0, 1);
    const glm::vec3 tiltX = glm::normalize(glm::vec3(0.4f, 0, 1)), tiltY = glm::normalize(glm::vec3(0, 0.4f, 1));
    auto values = openPbrValues({{"base_metalness", glm::vec3(1)}, {"specular_roughness_anisotropy", glm::vec3(0.8f)}});
    EXPECT_GT(evalBrdf(BrdfModel::OpenPbr, values, tiltX, wo, {}).g, 3.0f * evalBrdf(BrdfModel::OpenPbr, values, tiltY, wo, {}).g);
    const float alongX = evalBrdf(BrdfModel::OpenPbr, values, tiltX, wo, {}).g;
    values[packedOffset(kOpenPbrTable, findParam(kOpenPbrTable, "geometry_tangent_rotation"))] = 90.0f;
    EXPECT_NEAR(evalBrdf(BrdfModel::OpenPbr, values, tiltY, wo, {}).g, alongX, 1e-4f * alongX);
}

TEST(OpenPbrLobes, F82TintHitsItsTargetAndSchlickWithoutTint) {
    const glm::vec3 f0(0.9f, 0.6f, 0.3f), tint(1.0f, 0.7f, 0.5f);
    const glm::vec3 a = f82Coefficient(f0, tint);
    const glm::vec3 at82 = fresnelF82(f0, a, 1.0f / 7.0f);
    const glm::vec3 schlick82 = schlickF90(f0, glm::vec3(1), 1.0f / 7.0f);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(at82[c], tint[c] * schlick82[c], 1e-5f);
    EXPECT_EQ(f82Coefficient(f0, glm::vec3(1)), glm::vec3(0));
    EXPECT_EQ(fresnelF82(f0, a, 1.0f), f0);
}

TEST(OpenPbrLobes, ThinFilmColoursTheReflectionAndVanishesWhenThin) {
    // A 0.4 µm soap film (η = 1.33) on nothing denser: coloured, each channel in [0, 1].
    const glm::vec3 film = thinFilmFresnel(1.0f, 1.33f, 400.0f, 1.0f, glm::vec3(0.04f));
    EXPECT_GT(std::max({film.r, film.g, film.b}) - std::min({film.r, film.g, film.b}), 0.02f);
    // No film left: about the base's own reflectance F0 = 0.04 (measured 0.046-0.047: the
    // Gaussian fit of the sensitivities does not integrate to exactly 1 at zero path).
    const glm::vec3 bare = thinFilmFresnel(1.0f, 1.33f, 0.0f, 1.0f, glm::vec3(0.04f));
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(bare[c], 0.04f, 0.01f);
}

TEST(OpenPbrLobes, SheenTableMatchesItsIntegral) {
    for (float roughness : {0.1f, 0.5f, 1.0f}) {
        for (float theta : {0.0f, 1.0f}) {
            const float integral =
                albedoAroundMirror([&](glm::vec3 wi, glm::vec3 wo) { return glm::vec3(sheenLobe(wi, wo, roughness)); },
                                   viewAt(theta), 256, 256).g;
            EXPECT_NEAR(sheenAlbedo(std::cos(theta), roughness), integral, 0.01f) << roughness << " " << theta;
        }
    }
    // Thin fibres at grazing view: the raw lobe reflects more than it receives; the model scales
    // it back to 1.
    EXPECT_GT(sheenAlbedo(0.02f, 0.07f), 2.0f);
    const auto values = openPbrValues({{"fuzz_weight", glm::vec3(1)}, {"fuzz_roughness", glm::vec3(0)}, {"base_color", glm::vec3(1)}});
    EXPECT_LE(openPbrAlbedo(values, viewAt(1.55f)).g, 1.0f + 5e-3f);
}

TEST(OpenPbrTransport, EmissionIsLuminanceOver683AndDimmedByTheCoat) {
    const auto values = openPbrValues({{"emission_luminance", glm::vec3(683)}, {"emission_color", {1.0f, 0.5f, 0.25f}}});
    const MissRadiance background{Background{}};
    const glm::vec3 emitted = traceSpecular(BrdfModel::OpenPbr, values, background, nullptr, {}, {0, 0, 1}, {0, 0, 1}, 1.0f);
    EXPECT_NEAR(emitted.r, 1.0f, 1e-5f);
    EXPECT_NEAR(emitted.g, 0.5f, 1e-5f);
    auto coated = values;
    coated[packedOffset(kOpenPbrTable, findParam(kOpenPbrTable, "coat_weight"))] = 1.0f;
    const glm::vec3 throughCoat = traceSpecular(BrdfModel::OpenPbr, coated, background, nullptr, {}, {0, 0, 1}, {0, 0, 1}, 1.0f);
    EXPECT_NEAR(throughCoat.r, 1.0f - dielectricF0(1.6f), 2e-3f);
}

TEST(OpenPbrTransport, ThinWalledClearTransmissionSeesTheBackground) {
    // A thin, clear, transmissive sheet in front of a uniform background L: what the specular
    // layer does not reflect passes through; reflection (from the same uniform L) plus
    // transmission gives L back.
    const auto values = openPbrValues({{"transmission_weight", glm::vec3(1)}, {"geometry_thin_walled", glm::vec3(1)},
                                       {"specular_roughness", glm::vec3(0.3f)}});
    Environment white;
    white.kind = EnvironmentKind::White;
    ASSERT_TRUE(loadEnvironment(white));
    const MissRadiance miss(Background{}, &white);
    for (float theta : {0.0f, 0.8f}) {
        const glm::vec3 through = traceSpecular(BrdfModel::OpenPbr, values, miss, nullptr, {}, {0, 0, 1}, viewAt(theta), 1.0f);
        const glm::vec3 reflected = environmentLighting(BrdfModel::OpenPbr, values, viewAt(theta), {}, white);
        EXPECT_NEAR(through.g + reflected.g, 1.0f, 0.01f) << theta;
        EXPECT_GT(through.g, 0.85f);
    }
}

}  // namespace
}  // namespace glint
