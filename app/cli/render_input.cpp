// Render inputs by file type (see render_input.h).
#include "cli/render_input.h"

#include <filesystem>

#include "geometry/mesh_import.h"
#include "interchange/asset.h"
#include "interchange/bparam_file.h"
#include "interchange/custom_brdf.h"
#include "interchange/import_formats.h"
#include "scene/preview_stage.h"
#include "snapshot/case_source.h"

namespace glint {
namespace {

Scene stageFor(const Material& material) {
    return previewStage(material, kDefaultMaterialPreviewSize, kDefaultMaterialPreviewSize);
}

// A mesh file (.ply, .stl, .fbx) on the preview stage in the sphere's place (both fill the unit
// sphere), with Glint's default material.
Result<Scene> meshStage(const std::string& path, const RenderInputOptions& options, std::vector<std::string>& notes) {
    MeshImportOptions importOptions;
    importOptions.upAxis = options.upAxis;
    auto imported = importMesh(path, importOptions);
    if (!imported) return imported.error();
    Scene scene = stageFor(Material::withDefaults("default", BrdfModel::Lambert));
    MeshShape mesh;
    mesh.path = mesh.resolvedPath = path;
    mesh.upAxis = options.upAxis;
    mesh.mesh = imported->mesh;
    mesh.statistics = imported->statistics;
    scene.objects[0] = {std::filesystem::path(path).filename().string(), mesh, 0, SurfaceInterpolation::Phong};
    notes.push_back(path + ": " + meshStatisticsText(imported->statistics));
    return scene;
}

// An asset (interchange/asset.h) on the preview stage: every part with its own material.
Result<Scene> assetInput(const std::string& path, const RenderInputOptions& options, std::vector<Diagnostic>& warnings,
                         std::vector<std::string>& notes) {
    MeshImportOptions importOptions;
    importOptions.upAxis = options.upAxis;
    auto asset = loadAsset(path, importOptions);
    if (!asset) {
        Diagnostic error = asset.error();
        if (const ImportFormat* format = findImportFormat(path); format && format->load(path))  // the materials still read
            error.message += " (--material NAME|INDEX renders one of the file's materials on the preview sphere)";
        return error;
    }
    warnings.insert(warnings.end(), asset->warnings.begin(), asset->warnings.end());
    notes.push_back(path + ": " + meshStatisticsText(asset->statistics) + "; " + assetSummary(*asset));
    return assetStage(*asset, kDefaultMaterialPreviewSize, kDefaultMaterialPreviewSize);
}

}  // namespace

std::string meshStatisticsText(const MeshStatistics& statistics) {
    std::string text = std::to_string(statistics.vertexCount) + " vertices, " + std::to_string(statistics.triangleCount) +
                       " triangles";
    if (statistics.meshesMerged > 1) text += " from " + std::to_string(statistics.meshesMerged) + " meshes";
    if (statistics.degenerateTrianglesDropped > 0)
        text += "; dropped " + std::to_string(statistics.degenerateTrianglesDropped) + " zero-area triangles";
    if (statistics.pointsAndLinesDropped > 0)
        text += "; dropped " + std::to_string(statistics.pointsAndLinesDropped) +
                " faces of one or two corners (points and lines: Glint draws triangles)";
    if (!statistics.hadNormals) text += "; normals made by Glint (the file has none)";
    return text;
}

Result<Scene> loadRenderInput(const std::string& path, const RenderInputOptions& options, std::vector<Diagnostic>& warnings,
                              std::vector<std::string>& notes) {
    const ImportFormat* format = findImportFormat(path);
    if (!options.material.empty() && !format)
        return makeError("--material chooses among the materials of a .mtl, .gltf or .glb file", {path});
    if (isBrdfFilePath(path)) return loadBrdfPreviewStage(path, &warnings);
    if (isBparamFilePath(path)) return loadBparamPreviewStage(path, warnings);
    if (options.material.empty() && isAssetFile(path)) return assetInput(path, options, warnings, notes);
    if (format) {
        auto imported = format->load(path);
        if (!imported) return imported.error();
        auto chosen = chooseMaterial(*imported, options.material, path);
        if (!chosen && !imported->materials.empty()) return chosen.error();
        const std::vector<Diagnostic> relevant = warningsFor(*imported, chosen ? *chosen : imported->materials.size());
        warnings.insert(warnings.end(), relevant.begin(), relevant.end());
        Scene scene = stageFor(chosen ? imported->materials[*chosen].material : Material::withDefaults("default", BrdfModel::Lambert));
        if (imported->materials.size() > 1)
            notes.push_back(path + ": " + std::to_string(imported->materials.size()) + " materials; '" +
                            imported->materials[*chosen].material.name + "' (" + std::to_string(*chosen) +
                            ") on the stage (--material NAME|INDEX chooses another; `glint info` lists them)");
        if (!imported->lights.empty()) {
            if (scene.lights.size() + imported->lights.size() > static_cast<size_t>(kMaxLights))
                return makeError("the file's " + std::to_string(imported->lights.size()) + " lights and the stage's " +
                                     std::to_string(scene.lights.size()) + " are too many: " + lightLimitExplanation(),
                                 {path});
            scene.lights.insert(scene.lights.end(), imported->lights.begin(), imported->lights.end());
            notes.push_back(path + ": its " + std::to_string(imported->lights.size()) + " light(s) added to the stage's " +
                            std::to_string(scene.lights.size() - imported->lights.size()));
        }
        return scene;
    }
    if (isMeshFile(path)) return meshStage(path, options, notes);
    return loadRenderable(path, 0, 0, &warnings);
}

}  // namespace glint
