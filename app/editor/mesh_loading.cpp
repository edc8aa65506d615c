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
        ObjMaterial material;
        if (imported) material = readObjMaterial(path_);  // an .obj's mtllib and usemtl
        {
            std::lock_guard lock(resultMutex_);
            result_.emplace(std::move(imported));
            material_ = std::move(material);
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

ObjMaterial MeshLoadJob::takeMaterial() {
    std::lock_guard lock(resultMutex_);
    return std::move(material_);
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
    ObjMaterial material = state.meshLoad->takeMaterial();
    state.meshLoad.reset();
    if (!result) return false;
    if (result->ok()) addMeshObject(state, path, std::move(**result), std::move(material));
    else if (isImportCancellation(result->error())) state.statusMessage = "Cancelled loading " + path;
    else state.errorMessage = "Could not load the mesh; the scene is unchanged.\n\n" + result->error().format();
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
