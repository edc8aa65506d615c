// `glint spectral`: parses the spectral settings, renders the scene's XYZ per wavelength through
// core/colour/spectral_render.h and writes it as linear sRGB (EXR) or display-encoded (PNG).
#include "cli/commands.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "cli/command_line.h"
#include "runtime/headless.h"
#include "runtime/progress_line.h"
#include "colour/spectral_render.h"
#include "display/display_chain.h"
#include "interchange/custom_brdf.h"
#include "snapshot/case_source.h"

namespace glint {
namespace {

// A finite number filling the whole of `text`, or NaN.
double wholeNumber(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return (!text.empty() && end == text.c_str() + text.size() && std::isfinite(value)) ? value : std::nan("");
}

struct SpectralOptions {
    SpectralSettings settings;
    std::string scenePath, outputPath;
    int width = 0, height = 0;
};

int renderSpectral(SpectralOptions& options) {
    SpectralSettings& settings = options.settings;
    const std::string& outputPath = options.outputPath;
    if (Status valid = checkSpectralSettings(settings); !valid) return commandFailed("spectral", valid.error().format());
    auto scene = loadRenderable(options.scenePath);
    if (!scene) return commandFailed("spectral", scene.error().format());
    if (Status cpu = referenceCanRender(*scene); !cpu) return commandFailed("spectral", cpu.error().format());
    ProgressLine line("glint spectral: wavelengths");  // runtime/progress_line.h
    auto xyz = renderSpectralXyz(*scene, settings, options.width, options.height, [&](float done) { line.update(done); });
    if (!xyz) return commandFailed("spectral", xyz.error().format());
    RenderedImages images;
    images.radiance = spectralImageToRgb(*xyz);
    images.display = applyDisplayChain(images.radiance, scene->display);
    if (Status written = writeRenderedImage(images, outputPath); !written) return commandFailed("spectral", written.error().format());
    std::printf("glint spectral: %d wavelengths, %dx%d, written to %s\n", settings.wavelengthSamples, images.radiance.width,
                images.radiance.height, outputPath.c_str());
    return 0;
}

}  // namespace

void addSpectralCommand(CLI::App& glint) {
    auto options = std::make_shared<SpectralOptions>();
    CLI::App* command =
        addCommand(glint, "spectral", "render per wavelength (CPU) and convert through the CIE 1931 matching functions",
                   [options] { return renderSpectral(*options); });
    command->footer("The scene is rendered one wavelength at a time (CPU reference renderer) and converted to RGB through the "
                    "CIE 1931 colour matching functions; glass disperses by Cauchy's equation n(λ) = A + B/λ².");
    command->add_option("SCENE", options->scenePath, "the scene or material file")->required();
    command->add_option("-o,--output", options->outputPath, "PNG (display-encoded) or EXR (linear)")->required()->type_name("OUT.png|OUT.exr");
    addPixelSize(*command, options->width, options->height, 1, 16384, "output size in pixels (default: the scene's \"output\")");
    command
        ->add_option_function<std::string>(
            "--band",
            [options](const std::string& value) {
                const size_t comma = value.find(',');
                options->settings.spectrum = EmitterSpectrum::NarrowBand;
                options->settings.bandCentreNanometres = static_cast<float>(wholeNumber(value.substr(0, comma)));
                options->settings.bandWidthNanometres = static_cast<float>(wholeNumber(value.substr(comma + 1)));
            },
            "lights emit a narrow band (Gaussian, centre and full width in nm) instead of a flat spectrum")
        ->check(needs("CENTRE,FWHM in nm, e.g. 555,10", [](const std::string& value) {
            const size_t comma = value.find(',');
            return comma != std::string::npos && !std::isnan(wholeNumber(value.substr(0, comma))) &&
                   !std::isnan(wholeNumber(value.substr(comma + 1)));
        }))
        ->type_name("NM,FWHM");
    command
        ->add_option_function<std::string>(
            "--cauchy-b", [options](const std::string& value) { options->settings.cauchyB = static_cast<float>(wholeNumber(value)); },
            "Cauchy's B in µm² for every glass material (default 0.0042, BK7; dense flint about 0.016); A is chosen so "
            "that n(589.3 nm) is the material's own index")
        ->check(needs("a number in µm², e.g. 0.0042", [](const std::string& value) { return !std::isnan(wholeNumber(value)); }))
        ->type_name("B");
    command->add_option("--wavelengths", options->settings.wavelengthSamples, "wavelengths rendered (default 16)")
        ->check(needsWholeNumber("a count from 1 to 256", 1, 256))
        ->type_name("N");
}

}  // namespace glint
