// GPU vertex and index buffers for the scene's objects: one per object for procedural shapes
// (rebuilt when the shape changes), one per imported Mesh shared by every object that shows it
// and uploaded once (so a million-triangle mesh costs no upload per frame). It draws nothing.
#pragma once

#include <glad/gl.h>

#include <map>
#include <memory>
#include <vector>

#include "geometry/mesh.h"
#include "gl/shader_program.h"
#include "scene/scene.h"

namespace glint {

struct GpuMesh {
    GLuint vertexArray = 0, vertexBuffer = 0, indexBuffer = 0;
    GLsizei indexCount = 0;
};

class GpuMeshCache {
public:
    GpuMeshCache() = default;
    ~GpuMeshCache();  // the GL context must be current
    GpuMeshCache(const GpuMeshCache&) = delete;
    GpuMeshCache& operator=(const GpuMeshCache&) = delete;

    // The buffers drawing object `objectIndex`: an exact sphere's circumscribing proxy
    // (`proxyScale` × radius, the fragment shader ray-casts the sphere inside it) or the shape's
    // triangles (geometry/shape_mesh.h), before the object's placement.
    const GpuMesh& forObject(size_t objectIndex, const SceneObject& object, int proxySegments, int proxyRings,
                             float proxyScale);
    // Frees the buffers of imported meshes no scene holds any more.
    void releaseUnused();

private:
    struct ProceduralEntry {
        GpuMesh gpu;
        Shape shape;  // what was uploaded (never a MeshShape)
        bool proxy = false;
    };
    struct ImportedEntry {
        GpuMesh gpu;
        std::weak_ptr<const Mesh> source;
    };
    static void upload(GpuMesh& gpu, const Mesh& mesh);
    static void destroy(GpuMesh& gpu);

    std::vector<ProceduralEntry> procedural_;
    std::map<const Mesh*, ImportedEntry> imported_;
    GpuMesh empty_;
};

// Sets the surface program's per-object triangle uniforms: `placement` (an imported mesh's offset
// and scale) and `flatNormals` (1 for flat interpolation: the face normal per pixel).
void setTriangleUniforms(const ShaderProgram& program, const SceneObject& object);

}  // namespace glint
