// `glint thumbnails` (see thumbnails_command.h).
#include "cli/thumbnails_command.h"

#include <cstdio>
#include <filesystem>
#include <optional>

#include "cli/command_options.h"
#include "cli/render_pool.h"
#include "image/contact_sheet.h"
#include "image/image_io.h"
#include "snapshot/case_source.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr const char* kUsage =
    "usage: glint thumbnails DIR -o OUTDIR [--size N] [--jobs N] [--columns N]\n"
    "  DIR          material files (\"format\": \"glint-material\", shown on the preview stage) and scene files\n"
    "  -o OUTDIR    receives NAME.png for each file and contact_sheet.png with every thumbnail labelled\n"
    "  --size N     thumbnail size, N×N pixels (default 256)\n"
    "  --jobs N     render on N threads, each with its own OSMesa context (default 1)\n"
    "  --columns N  thumbnails per row of the contact sheet (default: about square)\n";

constexpr const char* kContactSheetName = "contact_sheet.png";
// zlib level 1 for thumbnails and the sheet: about 40% larger files than the default 6, written
// about 4x faster (compression was most of the time of a 256×256 thumbnail).
constexpr int kThumbnailPngCompression = 1;

int usageError(const std::string& message) {
    std::fprintf(stderr, "glint thumbnails: %s\n%s", message.c_str(), kUsage);
    return 2;
}

struct Thumbnail {
    std::string name;
    std::optional<DisplayImage> image;  // empty when the file could not be rendered
    std::string error;
};

}  // namespace

int runThumbnailsCommand(const std::vector<std::string>& arguments) {
    std::string inputDirectory, outputDirectory;
    int size = 256, jobs = 1, columns = 0;
    const std::vector<CommandOption> known = {
        {{"-o", "--output"}, "a directory", [&](const std::string& value) { outputDirectory = value; return std::string(); }},
        {{"--size"}, "a number of pixels", wholeNumberOption(size, 8, 4096, "--size needs a number of pixels from 8 to 4096")},
        {{"-j", "--jobs"}, "a number", wholeNumberOption(jobs, 1, 999, "--jobs needs a number from 1 to 999")},
        {{"--columns"}, "a number", wholeNumberOption(columns, 1, 1000, "--columns needs a number from 1 to 1000")},
    };
    auto parsed = parseCommandOptions(arguments, known, "directory");
    if (!parsed) return usageError(parsed.error().message);
    if (parsed->help) {
        std::printf("%s", kUsage);
        return 0;
    }
    if (!parsed->positionals.empty()) inputDirectory = parsed->positionals[0];
    if (inputDirectory.empty()) return usageError("no directory of materials given");
    if (outputDirectory.empty()) return usageError("no output directory given (-o OUTDIR)");

    auto files = listJsonFiles(inputDirectory);
    if (!files) {
        std::fprintf(stderr, "glint thumbnails: %s\n", files.error().format().c_str());
        return 2;
    }
    if (files->empty()) {
        std::fprintf(stderr, "glint thumbnails: %s: no *.json material or scene files\n", inputDirectory.c_str());
        return 2;
    }
    auto font = LabelFont::load();
    if (!font) {
        std::fprintf(stderr, "glint thumbnails: %s\n", font.error().format().c_str());
        return 2;
    }
    std::error_code error;
    fs::create_directories(outputDirectory, error);
    if (error) {
        std::fprintf(stderr, "glint thumbnails: cannot create %s: %s\n", outputDirectory.c_str(), error.message().c_str());
        return 2;
    }

    std::vector<Thumbnail> thumbnails(files->size());
    const Status rendered = renderInParallel(jobs, files->size(), [&](HeadlessRenderer& headless, size_t index) {
        const std::string& file = (*files)[index];
        Thumbnail& thumbnail = thumbnails[index];
        thumbnail.name = fs::path(file).stem().string();
        auto scene = loadRenderable(file, size, size);
        if (!scene) {
            thumbnail.error = scene.error().format();
            return;
        }
        auto images = headless.render(*scene, size, size);
        if (!images) {
            thumbnail.error = file + ": render failed: " + images.error().format();
            return;
        }
        if (Status written = writeDisplayImage(images->display, (fs::path(outputDirectory) / (thumbnail.name + ".png")).string(),
                                             kThumbnailPngCompression); !written) {
            thumbnail.error = written.error().format();
            return;
        }
        thumbnail.image = std::move(images->display);
    });
    if (!rendered) {
        std::fprintf(stderr, "glint thumbnails: %s\n", rendered.error().format().c_str());
        return 2;
    }

    std::vector<LabelledImage> sheetEntries;
    int failed = 0;
    for (const Thumbnail& thumbnail : thumbnails) {
        if (thumbnail.image) {
            sheetEntries.push_back({thumbnail.name, &*thumbnail.image});
        } else {
            std::fprintf(stderr, "glint thumbnails: %s\n", thumbnail.error.c_str());
            ++failed;
        }
    }
    const std::string sheetPath = (fs::path(outputDirectory) / kContactSheetName).string();
    if (!sheetEntries.empty()) {
        if (Status written = writeDisplayImage(contactSheet(sheetEntries, columns, *font), sheetPath, kThumbnailPngCompression); !written) {
            std::fprintf(stderr, "glint thumbnails: %s\n", written.error().format().c_str());
            return 2;
        }
    }
    std::printf("%zu thumbnails (%dx%d) and %s written to %s; %d files could not be rendered\n", sheetEntries.size(), size, size,
                sheetEntries.empty() ? "no contact sheet" : kContactSheetName, outputDirectory.c_str(), failed);
    return failed == 0 ? 0 : 1;
}

}  // namespace glint
