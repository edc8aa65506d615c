// `glint spectral`: parses the spectral settings, renders the scene's XYZ per wavelength through
// core/colour/spectral_render.h and writes it as linear sRGB (EXR) or display-encoded (PNG).
#include "cli/spectral_command.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "cli/command_options.h"
#include "cli/headless.h"
#include "colour/spectral_render.h"
#include "display/display_chain.h"
#include "interchange/custom_brdf.h"
#include "snapshot/case_source.h"

namespace glint {
namespace {

constexpr const char* kSpectralUsage =
    "usage: glint spectral SCENE.json -o OUT.png|OUT.exr [--size WxH] [--band NM,FWHM] [--cauchy-b B] [--wavelengths N]\n"
    "  renders the scene one wavelength at a time (CPU reference renderer) and converts to RGB through the\n"
    "  CIE 1931 colour matching functions; glass disperses by Cauchy's equation n(λ) = A + B/λ².\n"
    "  --size WxH        output size in pixels (default: the scene's \"output\")\n"
    "  --band NM,FWHM    lights emit a narrow band (Gaussian, centre and full width in nm) instead of a flat spectrum\n"
    "  --cauchy-b B      Cauchy's B in µm² for every glass material (default 0.0042, BK7; dense flint about 0.016);\n"
    "                    A is chosen so that n(589.3 nm) is the material's own index\n"
    "  --wavelengths N   wavelengths rendered, 1-256 (default 16)\n";

// A finite number filling the whole of `text`, or NaN.
double wholeNumber(const std::string& text) {
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return (!text.empty() && end == text.c_str() + text.size() && std::isfinite(value)) ? value : std::nan("");
}

}  // namespace

int runSpectralCommand(const std::vector<std::string>& arguments) {
    SpectralSettings settings;
    std::string outputPath;
    int width = 0, height = 0;
    const std::vector<CommandOption> options = {
        {{"-o", "--output"}, "a file name", [&](const std::string& value) { outputPath = value; return std::string(); }},
        {{"--size"}, "WIDTHxHEIGHT", pixelSizeOption(width, height, 1, 16384, "--size needs WIDTHxHEIGHT from 1x1 to 16384x16384")},
        {{"--band"}, "NM,FWHM", [&](const std::string& value) {
             const size_t comma = value.find(',');
             const double centre = wholeNumber(value.substr(0, comma));
             const double fullWidth = comma == std::string::npos ? std::nan("") : wholeNumber(value.substr(comma + 1));
             if (std::isnan(centre) || std::isnan(fullWidth)) return std::string("--band needs CENTRE,FWHM in nm, e.g. 555,10");
             settings.spectrum = EmitterSpectrum::NarrowBand;
             settings.bandCentreNanometres = static_cast<float>(centre);
             settings.bandWidthNanometres = static_cast<float>(fullWidth);
             return std::string();
         }},
        {{"--cauchy-b"}, "B in µm²", [&](const std::string& value) {
             const double coefficient = wholeNumber(value);
             if (std::isnan(coefficient)) return std::string("--cauchy-b needs a number in µm², e.g. 0.0042");
             settings.cauchyB = static_cast<float>(coefficient);
             return std::string();
         }},
        {{"--wavelengths"}, "a count", wholeNumberOption(settings.wavelengthSamples, 1, 256, "--wavelengths needs a count from 1 to 256")},
    };
    auto parsed = parseCommandOptions(arguments, options, "scene");
    if (!parsed) {
        std::fprintf(stderr, "glint spectral: %s\n%s", parsed.error().format().c_str(), kSpectralUsage);
        return 2;
    }
    if (parsed->help) {
        std::printf("%s", kSpectralUsage);
        return 0;
    }
    if (parsed->positionals.empty() || outputPath.empty()) {
        std::fprintf(stderr, "glint spectral: needs a scene and -o OUT\n%s", kSpectralUsage);
        return 2;
    }
    if (Status valid = checkSpectralSettings(settings); !valid) {
        std::fprintf(stderr, "glint spectral: %s\n", valid.error().format().c_str());
        return 2;
    }
    auto scene = loadRenderable(parsed->positionals[0]);
    if (!scene) {
        std::fprintf(stderr, "glint spectral: %s\n", scene.error().format().c_str());
        return 2;
    }
    if (Status cpu = referenceCanRender(*scene); !cpu) {
        std::fprintf(stderr, "glint spectral: %s\n", cpu.error().format().c_str());
        return 2;
    }
    auto xyz = renderSpectralXyz(*scene, settings, width, height);
    if (!xyz) {
        std::fprintf(stderr, "glint spectral: %s\n", xyz.error().format().c_str());
        return 2;
    }
    RenderedImages images;
    images.radiance = spectralImageToRgb(*xyz);
    images.display = applyDisplayChain(images.radiance, scene->display);
    if (Status written = writeRenderedImage(images, outputPath); !written) {
        std::fprintf(stderr, "glint spectral: %s\n", written.error().format().c_str());
        return 2;
    }
    std::printf("glint spectral: %d wavelengths, %dx%d, written to %s\n", settings.wavelengthSamples, images.radiance.width,
                images.radiance.height, outputPath.c_str());
    return 0;
}

}  // namespace glint
