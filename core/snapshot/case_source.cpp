// Scene or material files for snapshots and thumbnails (see case_source.h).
#include "snapshot/case_source.h"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "interchange/asset.h"
#include "interchange/import_formats.h"
#include "scene/json_document.h"
#include "scene/preview_stage.h"
#include "scene/scene_json.h"
#include "util/file_io.h"

namespace glint {

Result<Scene> loadRenderable(const std::string& path, int width, int height, std::vector<Diagnostic>* warnings) {
    if (isAssetFile(path)) {
        auto asset = loadAsset(path);
        if (!asset) return asset.error();
        if (warnings) warnings->insert(warnings->end(), asset->warnings.begin(), asset->warnings.end());
        return assetStage(*asset, width > 0 ? width : kDefaultMaterialPreviewSize, height > 0 ? height : kDefaultMaterialPreviewSize);
    }
    if (const ImportFormat* format = findImportFormat(path)) {
        auto imported = format->load(path);
        if (!imported) return imported.error();
        if (imported->materials.empty()) return makeError("the file has no material to render", {path});
        if (warnings) {
            const std::vector<Diagnostic> first = warningsFor(*imported, 0);
            warnings->insert(warnings->end(), first.begin(), first.end());
        }
        return previewStage(imported->materials.front().material, width > 0 ? width : kDefaultMaterialPreviewSize,
                            height > 0 ? height : kDefaultMaterialPreviewSize);
    }
    auto text = readTextFile(path);
    if (!text) return text.error();
    auto document = JsonDocument::parse(*text, path);
    if (!document) return document.error();
    const nlohmann::json& root = document->root();
    const bool hasFormat = root.is_object() && root.contains("format") && root["format"].is_string();
    const std::string format = hasFormat ? root["format"].get<std::string>() : "";
    if (format == "glint-material") {
        auto material = parseMaterial(*text, path);
        if (!material) return material.error();
        return previewStage(*material, width > 0 ? width : kDefaultMaterialPreviewSize,
                            height > 0 ? height : kDefaultMaterialPreviewSize);
    }
    if (format == "glint-scene" || !hasFormat) {  // without a format, the scene reader says what is missing
        auto scene = parseScene(*text, path);
        if (!scene) return scene.error();
        if (width > 0) scene->width = width;
        if (height > 0) scene->height = height;
        return std::move(*scene);
    }
    return makeError("'format': expected \"glint-scene\" or \"glint-material\", found \"" + format + "\"",
                     document->locate("/format"));
}

Result<std::vector<std::string>> listJsonFiles(const std::string& directory, const std::vector<std::string>& excluded) {
    std::error_code error;
    std::filesystem::directory_iterator entries(directory, error);
    if (error) return makeError("cannot read the directory: " + error.message(), {directory});
    std::vector<std::string> files;
    for (auto entry = entries; entry != std::filesystem::directory_iterator(); entry.increment(error)) {
        if (error) return makeError("cannot read the directory: " + error.message(), {directory});
        const std::filesystem::path& path = entry->path();
        if (path.extension() != ".json" || !entry->is_regular_file(error)) continue;
        if (std::find(excluded.begin(), excluded.end(), path.filename().string()) != excluded.end()) continue;
        files.push_back(path.string());
    }
    if (error) return makeError("cannot read the directory: " + error.message(), {directory});
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace glint
