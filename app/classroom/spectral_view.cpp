// Spectral render window (spectral_view.h): the controls, the synchronous CPU render (a few
// seconds at 256 px and 16 wavelengths) and one GL texture holding the last image.
#include "classroom/spectral_view.h"

#include <glad/gl.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>

#include "colour/cie_cmf.h"
#include "display/display_chain.h"
#include "interchange/custom_brdf.h"
#include "editor/window_placement.h"
#include "gl/display_texture.h"

namespace glint {
namespace {

// The window's one texture: created on first upload, reused after (never more than one).
struct SpectralTexture {
    GLuint name = 0;
    std::uint64_t revision = 0;
    int width = 0, height = 0;
};

SpectralTexture& spectralTexture() {
    static SpectralTexture texture;
    return texture;
}

void uploadSpectralImage(const DisplayImage& image, std::uint64_t revision) {
    SpectralTexture& texture = spectralTexture();
    if (texture.revision == revision || image.pixels.empty()) return;
    texture.name = uploadDisplayTexture(image, GL_NEAREST, texture.name);
    texture.revision = revision;
    texture.width = image.width;
    texture.height = image.height;
}

}  // namespace

void renderSpectralImage(EditorState& state) {
    ClassroomState& classroom = state.classroom;
    const Scene& scene = state.session.scene();
    if (Status cpu = referenceCanRender(scene); !cpu) {
        classroom.spectralMessage = cpu.error().format();
        return;
    }
    const int width = classroom.spectralWidth;
    const int height = std::max(1, width * scene.height / std::max(scene.width, 1));
    const auto start = std::chrono::steady_clock::now();
    auto xyz = renderSpectralXyz(scene, classroom.spectral, width, height);
    if (!xyz) {
        classroom.spectralMessage = xyz.error().format();
        return;
    }
    classroom.spectralImage = applyDisplayChain(spectralImageToRgb(*xyz), scene.display);
    ++classroom.spectralImageRevision;
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    char message[96];
    std::snprintf(message, sizeof message, "%d wavelengths, %dx%d, %.1f s", classroom.spectral.wavelengthSamples, width, height, seconds);
    classroom.spectralMessage = message;
}

void drawSpectralWindow(EditorState& state) {
    ClassroomState& classroom = state.classroom;
    if (!classroom.showSpectralWindow) return;
    const float fontSize = ImGui::GetFontSize();
    if (beginPlacedWindow("Spectral render", &classroom.showSpectralWindow, {ImVec2(24.0f, 30.0f), ImVec2(18.0f, 20.0f)})) {
        SpectralSettings& settings = classroom.spectral;
        ImGui::PushItemWidth(fontSize * 10.0f);
        int spectrum = settings.spectrum == EmitterSpectrum::Flat ? 0 : 1;
        if (ImGui::Combo("Emitter spectrum", &spectrum, "flat (equal energy)\0narrow band\0"))
            settings.spectrum = spectrum == 0 ? EmitterSpectrum::Flat : EmitterSpectrum::NarrowBand;
        if (settings.spectrum == EmitterSpectrum::NarrowBand) {
            ImGui::SliderFloat("Centre λ [nm]", &settings.bandCentreNanometres, kVisibleMinNanometres, kVisibleMaxNanometres, "%.0f");
            ImGui::SliderFloat("Width (FWHM) [nm]", &settings.bandWidthNanometres, 1.0f, 100.0f, "%.0f");
        }
        ImGui::SliderFloat("Cauchy B [µm²]", &settings.cauchyB, 0.0f, 0.05f, "%.4f");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("n(λ) = A + B/λ² for every glass material, A chosen so that n(589.3 nm) is its own index.\n"
                              "BK7 crown glass about 0.0042, dense flint about 0.016.");
        ImGui::SliderInt("Wavelengths", &settings.wavelengthSamples, 1, 64);
        ImGui::SliderInt("Width [px]", &classroom.spectralWidth, 32, 512);
        ImGui::PopItemWidth();
        if (ImGui::Button("Render")) renderSpectralImage(state);
        ImGui::SameLine();
        ImGui::TextDisabled("CPU, per wavelength: takes a few seconds");
        if (!classroom.spectralMessage.empty()) ImGui::TextWrapped("%s", classroom.spectralMessage.c_str());
        uploadSpectralImage(classroom.spectralImage, classroom.spectralImageRevision);
        const SpectralTexture& texture = spectralTexture();
        if (texture.name != 0) {
            const float shownWidth = std::min(ImGui::GetContentRegionAvail().x, static_cast<float>(texture.width) * 2.0f);
            ImGui::Image(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(texture.name)),
                         ImVec2(shownWidth, shownWidth * texture.height / std::max(texture.width, 1)));
        }
        ImGui::TextWrapped("Lights, background and material colours act as their grey mean; colour comes from the "
                           "emitter spectrum and the dispersion of glass. Headless: glint spectral SCENE -o OUT.png");
    }
    ImGui::End();
}

}  // namespace glint
