// Loading a mesh file into the editor's scene on a worker thread: the job reports progress and
// can be cancelled; when it finishes the frame loop adds a mesh object in one undo step (with the
// material an .obj names through its .mtl library, else a Lambert one), or replaces the scene with
// an asset (asset_open.h), or shows the error (file and line) and leaves the scene exactly as it
// was. Drawing the progress modal lives in panels/mesh_load_dialog.cpp; importing itself in
// core/geometry/mesh_import.h and core/interchange/asset.h.
#pragma once

#include <memory>
#include <string>
#include <variant>

#include "editor/editor_state.h"
#include "editor/worker_job.h"
#include "geometry/mesh_import.h"
#include "interchange/asset.h"
#include "interchange/obj_material.h"

namespace glint {

// What a job reads: one mesh to add as an object, or an asset to replace the scene with.
enum class MeshLoadKind { Mesh, Asset };

// The import's outcome (a mesh, or an asset), and the material an .obj names (a mesh's).
struct MeshLoadOutcome {
    std::variant<Result<ImportedMesh>, Result<Asset>> loaded;
    ObjMaterial material;
};

class MeshLoadJob : public WorkerJob<MeshLoadOutcome> {
public:
    // Starts importing `path` on a new thread.
    explicit MeshLoadJob(std::string path, MeshLoadKind kind = MeshLoadKind::Mesh);
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Starts loading a mesh (or an asset) unless one is loading already (then the status line says so).
void startMeshLoad(EditorState& state, const std::string& path, MeshLoadKind kind = MeshLoadKind::Mesh);
// Each frame: when the job has finished, adds the mesh object or opens the asset (success), notes
// the cancel, or shows the error. Returns true while a load is still running (the loop keeps
// drawing frames).
bool pollMeshLoad(EditorState& state);
// Adds an imported mesh as a new object with its own material (the .obj's, when it names one
// Glint could read; its warnings go to the status line), selected; one undo step.
void addMeshObject(EditorState& state, const std::string& path, ImportedMesh imported, ObjMaterial material = {});

}  // namespace glint
