// GPU vertex and index buffers for the scene's objects: one per object for procedural shapes
// (rebuilt when the shape changes), one per imported Mesh shared by every object that shows it
// and uploaded once (so a million-triangle mesh costs no upload per frame). With each, whether
// the mesh is closed (geometry/mesh_topology.h, found once at upload) and, for a large mesh, its
// simplified stand-ins (geometry/mesh_simplify.h) at a few levels of detail, made on a worker
// thread when prepareSimplified asks and uploaded when done. It draws nothing.
#pragma once

#include <glad/gl.h>

#include <future>
#include <map>
#include <memory>
#include <vector>

#include "geometry/mesh.h"
#include "geometry/mesh_topology.h"
#include "gl/shader_program.h"
#include "render/visibility.h"
#include "scene/scene.h"

namespace glint {

struct GpuMesh {
    GLuint vertexArray = 0, vertexBuffer = 0, indexBuffer = 0;
    GLsizei indexCount = 0;
    MeshClosure closure = MeshClosure::Open;
    bool simplified = false;  // a large mesh's stand-in, not its own triangles
};

// Which triangles of a large mesh to draw: its own, or a simplified stand-in (once made) while
// the user drags. Headless renders and tests always draw the full mesh.
enum class MeshDetail { Full, Simplified };

// The stand-ins' triangle budgets, finest first, each a quarter of the one before: a mesh gets
// those of at most half its own triangles (so one of more than 12,500 triangles gets some).
inline constexpr size_t kSimplifiedTriangles[] = {100'000, 25'000, 6'250};
inline constexpr size_t kEveryTriangle = ~size_t{0};

class GpuMeshCache {
public:
    // An exact sphere is drawn as a circumscribing proxy: a `proxySegments` × `proxyRings` UV
    // sphere of `proxyScale` × its radius (the fragment shader ray-casts the sphere inside it).
    GpuMeshCache(int proxySegments, int proxyRings, float proxyScale)
        : proxySegments_(proxySegments), proxyRings_(proxyRings), proxyScale_(proxyScale) {}
    ~GpuMeshCache();  // the GL context must be current; waits for running simplifications
    GpuMeshCache(const GpuMeshCache&) = delete;
    GpuMeshCache& operator=(const GpuMeshCache&) = delete;

    // The buffers drawing object `objectIndex`: an exact sphere's proxy or the shape's triangles
    // (geometry/shape_mesh.h), before the object's placement. A mesh of more triangles than
    // `triangleBudget` is drawn by its finest stand-in within the budget (the coarsest when none
    // is), once prepareSimplified had them made (until then, by the full mesh).
    const GpuMesh& forObject(size_t objectIndex, const SceneObject& object, size_t triangleBudget = kEveryTriangle);
    // Starts making the stand-ins of the object's mesh, if it is large and has none yet (not from
    // forObject: a shape changed by a drag would start one worker per frame).
    void prepareSimplified(size_t objectIndex, const SceneObject& object);
    // Waits until every stand-in being made is done (benchmarks).
    void finishSimplified();
    // Frees the buffers of imported meshes no scene holds any more.
    void releaseUnused();

private:
    // A mesh's buffers and its stand-ins: not asked for, being made, or uploaded (finest first;
    // possibly none: nothing simplified came out).
    struct Levels {
        GpuMesh full;
        std::vector<GpuMesh> simplified;
        std::future<std::vector<Mesh>> making;
        bool simplifiedDone = false;
    };
    struct ProceduralEntry {
        Levels levels;
        Shape shape;  // what was uploaded (never a MeshShape)
        bool proxy = false;
    };
    struct ImportedEntry {
        Levels levels;
        std::weak_ptr<const Mesh> source;
    };
    static void upload(GpuMesh& gpu, const Mesh& mesh);
    static void destroy(GpuMesh& gpu);
    // The entry holding the object's buffers, uploaded and up to date; nullptr for a mesh object
    // with no mesh loaded.
    Levels* levelsFor(size_t objectIndex, const SceneObject& object);
    // Forgets the stand-ins (the mesh changed); those still being made are left to finish.
    void forgetSimplified(Levels& levels);
    // Starts the stand-ins of a large mesh that has none.
    void startSimplifying(Levels& levels, const SceneObject& object);
    // Uploads the stand-ins once the worker made them.
    void collectSimplified(Levels& levels);

    int proxySegments_, proxyRings_;
    float proxyScale_;
    std::vector<ProceduralEntry> procedural_;
    std::map<const Mesh*, ImportedEntry> imported_;
    std::vector<std::future<std::vector<Mesh>>> abandoned_;  // stand-ins of meshes gone while being made
    GpuMesh empty_;
};

// Sets the surface program's per-object triangle uniforms: `placement` (an imported mesh's offset
// and scale) and `flatNormals` (1 for flat interpolation: the face normal per pixel).
void setTriangleUniforms(const ShaderProgram& program, const SceneObject& object);
// Enables GL_CULL_FACE for the faces named (counter-clockwise front faces), or disables it.
void setFaceCulling(CulledFaces faces);

}  // namespace glint
