// Mesh loading on a worker thread (see mesh_loading.h).
#include "editor/mesh_loading.h"

#include <filesystem>

#include "editor/object_actions.h"

namespace glint {

MeshLoadJob::MeshLoadJob(std::string path) : path_(std::move(path)) {
    thread_ = std::thread([this] {
        auto imported = importMesh(path_, MeshImportOptions{}, [this](float fraction) {
            progress_.store(fraction);
            return !cancelRequested_.load();
        });
        {
            std::lock_guard lock(resultMutex_);
            result_.emplace(std::move(imported));
        }
        finished_.store(true);
    });
}

MeshLoadJob::~MeshLoadJob() {
    cancel();
    if (thread_.joinable()) thread_.join();
}

std::optional<Result<ImportedMesh>> MeshLoadJob::takeResult() {
    std::lock_guard lock(resultMutex_);
    std::optional<Result<ImportedMesh>> taken = std::move(result_);
    result_.reset();
    return taken;
}

void startMeshLoad(EditorState& state, const std::string& path) {
    if (state.meshLoad) {
        state.statusMessage = "Still loading " + state.meshLoad->path() + "; wait or cancel first";
        return;
    }
    state.meshLoad = std::make_shared<MeshLoadJob>(path);
}

bool pollMeshLoad(EditorState& state) {
    if (!state.meshLoad) return false;
    if (!state.meshLoad->finished()) return true;
    const std::string path = state.meshLoad->path();
    auto result = state.meshLoad->takeResult();
    state.meshLoad.reset();
    if (!result) return false;
    if (result->ok()) addMeshObject(state, path, std::move(**result));
    else if (isImportCancellation(result->error())) state.statusMessage = "Cancelled loading " + path;
    else state.errorMessage = "Could not load the mesh; the scene is unchanged.\n\n" + result->error().format();
    return false;
}

void addMeshObject(EditorState& state, const std::string& path, ImportedMesh imported) {
    MeshShape shape;
    shape.path = path;
    shape.resolvedPath = path;
    shape.mesh = std::move(imported.mesh);
    shape.statistics = imported.statistics;
    addObjectWithShape(state, std::filesystem::path(path).stem().string(), std::move(shape));
    state.statusMessage = "Loaded " + path;
}

}  // namespace glint
