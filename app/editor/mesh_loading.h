// Loading a mesh file into the editor's scene on a worker thread: the job reports progress and
// can be cancelled; when it finishes the frame loop adds a mesh object in one undo step (with the
// material an .obj names through its .mtl library, else a Lambert one), or shows the error (file
// and line) and leaves the scene exactly as it was. Drawing the progress modal
// lives in panels/mesh_load_dialog.cpp; importing itself in core/geometry/mesh_import.h.
#pragma once

#include <memory>
#include <string>

#include "editor/editor_state.h"
#include "editor/worker_job.h"
#include "geometry/mesh_import.h"
#include "interchange/obj_material.h"

namespace glint {

// The import's outcome, and the material an .obj names.
struct MeshLoadOutcome {
    Result<ImportedMesh> mesh;
    ObjMaterial material;
};

class MeshLoadJob : public WorkerJob<MeshLoadOutcome> {
public:
    // Starts importing `path` on a new thread.
    explicit MeshLoadJob(std::string path);
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// Starts loading a mesh unless one is loading already (then the status line says so).
void startMeshLoad(EditorState& state, const std::string& path);
// Each frame: when the job has finished, adds the mesh object (success), notes the cancel, or
// shows the error. Returns true while a load is still running (the loop keeps drawing frames).
bool pollMeshLoad(EditorState& state);
// Adds an imported mesh as a new object with its own material (the .obj's, when it names one
// Glint could read; its warnings go to the status line), selected; one undo step.
void addMeshObject(EditorState& state, const std::string& path, ImportedMesh imported, ObjMaterial material = {});

}  // namespace glint
