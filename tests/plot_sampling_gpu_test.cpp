// The classroom plots of a .brdf material, sampled on the GPU (core/gl/brdf_sampler.h through
// app/classroom/plot_materials.h): .brdf files written here (twin_brdf_texts.h), Lambert and the normalised
// Blinn-Phong, give the polar plot, lobe and albedo curve of their built-in twins (CPU) within
// 1e-3; a GLSL error names the .brdf line; the pass leaves the GL state it found.
#include <fstream>

#include <gtest/gtest.h>

#include "classroom/plot_materials.h"
#include "gpu_test_support.h"
#include "interchange/custom_brdf.h"
#include "test_support.h"
#include "twin_brdf_texts.h"

namespace glint {
namespace {

// The .brdf text written to the test's folder and read back, with `values`, as a scene material.
Material writtenCustomMaterial(const std::string& name, const char* text, std::vector<float> values) {
    const std::string path = test::outputDirectory("plot_sampling") + "/" + name;
    std::ofstream(path) << text;
    auto brdf = loadCustomBrdf(path);
    EXPECT_TRUE(brdf) << brdf.error().format();
    Material material = customBrdfMaterial(*brdf);
    material.custom()->values = std::move(values);
    return material;
}

void expectRelativelyNear(glm::vec3 sampled, glm::vec3 twin, const std::string& where) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(sampled[c], twin[c], 1e-3f * std::abs(twin[c]) + 1e-7f) << where << ", channel " << c;
}

// Every plot's numbers of the sampled .brdf against its built-in twin's CPU plot data.
void expectPlotsMatchTwin(const Material& custom, const Material& twin) {
    test::sharedHeadless();  // the OSMesa context, current
    BrdfSampler sampler(defaultShaderSources());
    auto sampled = plotMaterialFor(custom, sampler);
    ASSERT_TRUE(sampled) << sampled.error().format();
    ASSERT_TRUE(sampled->custom());
    const PlotMaterial reference = *plotMaterialFrom(twin);
    for (float incidence : {0.0f, 35.0f, 70.0f}) {
        const PolarPlotData polar = polarPlotData(*sampled, incidence, 37), expected = polarPlotData(reference, incidence, 37);
        for (size_t i = 0; i < polar.reflectance.size(); ++i) {
            expectRelativelyNear(polar.reflectance[i], expected.reflectance[i], "polar f_r at " + std::to_string(polar.outgoingDegrees[i]));
            expectRelativelyNear(polar.cosineWeighted[i], expected.cosineWeighted[i], "polar f_r cos");
        }
        const LobeMesh lobe = lobeMesh(*sampled, incidence, 6, 12), expectedLobe = lobeMesh(reference, incidence, 6, 12);
        for (size_t i = 0; i < lobe.points.size(); ++i) expectRelativelyNear(lobe.points[i], expectedLobe.points[i], "lobe point");
    }
    const AlbedoCurve albedo = albedoCurve(*sampled, 7, 16, 32), expectedAlbedo = albedoCurve(reference, 7, 16, 32);
    for (size_t i = 0; i < albedo.albedo.size(); ++i)
        expectRelativelyNear(albedo.albedo[i], expectedAlbedo.albedo[i], "albedo at " + std::to_string(albedo.incidenceDegrees[i]));
    EXPECT_FALSE(deltaLobes(*sampled, 35.0f).hasReflection);
}

TEST(PlotSamplingGpu, LambertBrdfMatchesBuiltInLambert) {
    Material twin = Material::withDefaults("twin", BrdfModel::Lambert);
    twin.analytic()->values = {0.6f, 0.3f, 0.15f};
    expectPlotsMatchTwin(writtenCustomMaterial("lambert.brdf", test::kLambertTwinBrdf, {0.6f, 0.3f, 0.15f}), twin);
}

TEST(PlotSamplingGpu, BlinnPhongBrdfMatchesNormalisedBlinnPhong) {
    Material twin = Material::withDefaults("twin", BrdfModel::BlinnPhong);
    twin.analytic()->values = {0.4f, 0.2f, 0.1f, 0.3f, 0.3f, 0.3f, 40.0f, 3.0f};  // form 3: normalised
    expectPlotsMatchTwin(writtenCustomMaterial("blinn_phong.brdf", test::kBlinnPhongTwinBrdf, {0.4f, 0.2f, 0.1f, 0.3f, 40.0f}), twin);
}

TEST(PlotSamplingGpu, GlslErrorNamesTheBrdfLineAndStateIsKept) {
    test::sharedHeadless();
    BrdfSampler sampler(defaultShaderSources());
    auto broken = loadCustomBrdf(test::dataPath("brdf_files/glsl_error.brdf"));
    ASSERT_TRUE(broken) << broken.error().format();
    auto plotted = plotMaterialFor(customBrdfMaterial(*broken), sampler);
    ASSERT_FALSE(plotted);
    EXPECT_NE(plotted.error().message.find("glsl_error.brdf:7:"), std::string::npos) << plotted.error().message;

    // A sampling pass between someone else's binds: their framebuffer, viewport and program stay.
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(3, 4, 50, 60);
    const Material lambert = writtenCustomMaterial("state.brdf", test::kLambertTwinBrdf, {0.5f, 0.5f, 0.5f});
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    auto values = sampler.sample(*lambert.custom()->brdf, lambert.custom()->values, std::span(&up, 1), std::span(&up, 1));
    ASSERT_TRUE(values) << values.error().format();
    EXPECT_NEAR((*values)[0].g, 0.5f / 3.14159265f, 1e-6f);
    GLint bound = 0, viewport[4] = {};
    glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
    glGetIntegerv(GL_VIEWPORT, viewport);
    EXPECT_EQ(static_cast<GLuint>(bound), framebuffer);
    EXPECT_EQ(viewport[0], 3);
    EXPECT_EQ(viewport[3], 60);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
}

}  // namespace
}  // namespace glint
