// Mesh loading on a worker thread (see mesh_loading.h).
#include "editor/mesh_loading.h"

#include <filesystem>

#include "editor/asset_open.h"
#include "editor/object_actions.h"

namespace glint {

MeshLoadJob::MeshLoadJob(std::string path, MeshLoadKind kind)
    : WorkerJob([path, kind](const Progress& progress) {
          if (kind == MeshLoadKind::Asset) return MeshLoadOutcome{loadAsset(path, MeshImportOptions{}, progress), {}};
          Result<ImportedMesh> mesh = importMesh(path, MeshImportOptions{}, progress);
          ObjMaterial material = mesh ? readObjMaterial(path) : ObjMaterial{};  // an .obj's mtllib and usemtl
          return MeshLoadOutcome{std::move(mesh), std::move(material)};
      }),
      path_(std::move(path)) {}

void startMeshLoad(EditorState& state, const std::string& path, MeshLoadKind kind) {
    if (state.meshLoad) {
        state.statusMessage = "Still loading " + state.meshLoad->path() + "; wait or cancel first";
        return;
    }
    state.meshLoad = std::make_shared<MeshLoadJob>(path, kind);
}

bool pollMeshLoad(EditorState& state) {
    if (!state.meshLoad) return false;
    if (!state.meshLoad->finished()) return true;
    const std::string path = state.meshLoad->path();
    auto outcome = state.meshLoad->takeResult();
    state.meshLoad.reset();
    if (!outcome) return false;
    if (auto* asset = std::get_if<Result<Asset>>(&outcome->loaded)) {
        if (asset->ok()) openLoadedAsset(state, path, std::move(**asset));
        else if (isImportCancellation(asset->error())) state.statusMessage = "Cancelled loading " + path;
        else state.errorMessage = "Could not open the asset; your work is unchanged.\n\n" + asset->error().format();
        return false;
    }
    Result<ImportedMesh>& result = std::get<Result<ImportedMesh>>(outcome->loaded);
    if (result.ok()) addMeshObject(state, path, std::move(*result), std::move(outcome->material));
    else if (isImportCancellation(result.error())) state.statusMessage = "Cancelled loading " + path;
    else state.errorMessage = "Could not load the mesh; the scene is unchanged.\n\n" + result.error().format();
    return false;
}

void addMeshObject(EditorState& state, const std::string& path, ImportedMesh imported, ObjMaterial material) {
    MeshShape shape;
    // Absolute, as a scene file's meshes are (util/referenced_path.h): the recovery file, written
    // in another folder, names the same file.
    shape.path = std::filesystem::absolute(path).lexically_normal().string();
    shape.resolvedPath = shape.path;
    shape.mesh = std::move(imported.mesh);
    shape.statistics = imported.statistics;
    std::optional<Material> named;
    if (material.material) named = std::move(material.material->material);
    const std::string loaded = "Loaded " + path + (named ? " with its material '" + named->name + "'" : "");
    addObjectWithShape(state, std::filesystem::path(path).stem().string(), std::move(shape), std::move(named));
    state.statusMessage = loaded;
    for (const Diagnostic& warning : material.warnings) state.statusMessage += "; " + warning.format();
}

}  // namespace glint
