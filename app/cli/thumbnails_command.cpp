// `glint thumbnails` (see commands.h).
#include "cli/commands.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <optional>

#include "cli/command_line.h"
#include "cli/render_pool.h"
#include "image/contact_sheet.h"
#include "image/image_io.h"
#include "snapshot/case_source.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr const char* kContactSheetName = "contact_sheet.png";
// zlib level 1 for thumbnails and the sheet: about 40% larger files than the default 6, written
// about 4x faster (compression was most of the time of a 256×256 thumbnail).
constexpr int kThumbnailPngCompression = 1;

struct Thumbnail {
    std::string name;
    std::optional<DisplayImage> image;  // empty when the file could not be rendered
    std::string error;
};

struct ThumbnailsOptions {
    std::string inputDirectory, outputDirectory;
    int size = 256, jobs = 1, columns = 0;
};

int renderThumbnails(const ThumbnailsOptions& options) {
    const std::string& inputDirectory = options.inputDirectory;
    const std::string& outputDirectory = options.outputDirectory;
    const int size = options.size, jobs = options.jobs, columns = options.columns;
    auto files = listJsonFiles(inputDirectory);
    if (!files) return commandFailed("thumbnails", files.error().format());
    if (files->empty()) return commandFailed("thumbnails", inputDirectory + ": no *.json material or scene files");
    auto font = LabelFont::load();
    if (!font) return commandFailed("thumbnails", font.error().format());
    std::error_code error;
    fs::create_directories(outputDirectory, error);
    if (error) return commandFailed("thumbnails", "cannot create " + outputDirectory + ": " + error.message());

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
    if (!rendered) return commandFailed("thumbnails", rendered.error().format());

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
        if (Status written = writeDisplayImage(contactSheet(sheetEntries, columns, *font), sheetPath, kThumbnailPngCompression); !written)
            return commandFailed("thumbnails", written.error().format());
    }
    std::printf("%zu thumbnails (%dx%d) and %s written to %s; %d files could not be rendered\n", sheetEntries.size(), size, size,
                sheetEntries.empty() ? "no contact sheet" : kContactSheetName, outputDirectory.c_str(), failed);
    return failed == 0 ? 0 : 1;
}

}  // namespace

void addThumbnailsCommand(CLI::App& glint) {
    auto options = std::make_shared<ThumbnailsOptions>();
    CLI::App* command = addCommand(glint, "thumbnails", "one thumbnail per material and a labelled contact sheet",
                                   [options] { return renderThumbnails(*options); });
    command->add_option("DIR", options->inputDirectory,
                        "material files (\"format\": \"glint-material\", shown on the preview stage) and scene files")
        ->required();
    command->add_option("-o,--output", options->outputDirectory,
                        "receives NAME.png for each file and contact_sheet.png with every thumbnail labelled")
        ->required()
        ->type_name("OUTDIR");
    command->add_option("--size", options->size, "thumbnail size, N×N pixels (default 256)")
        ->check(needsWholeNumber("a number of pixels from 8 to 4096", 8, 4096))
        ->type_name("N");
    command->add_option("-j,--jobs", options->jobs, "render on N threads, each with its own OSMesa context (default 1)")
        ->check(needsWholeNumber("a number from 1 to 999", 1, 999))
        ->type_name("N");
    command->add_option("--columns", options->columns, "thumbnails per row of the contact sheet (default: about square)")
        ->check(needsWholeNumber("a number from 1 to 1000", 1, 1000))
        ->type_name("N");
}

}  // namespace glint
