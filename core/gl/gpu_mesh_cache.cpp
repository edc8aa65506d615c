// GPU mesh buffers (see gpu_mesh_cache.h).
#include "gl/gpu_mesh_cache.h"

#include <cstddef>

#include "geometry/shape_mesh.h"

namespace glint {
namespace {

// Whether two procedural shapes produce the same triangles.
bool sameTriangles(const Shape& a, const Shape& b) {
    if (a.index() != b.index()) return false;
    if (const auto* sphere = std::get_if<SphereShape>(&a)) {
        const auto& other = std::get<SphereShape>(b);
        return sphere->center == other.center && sphere->radius == other.radius && sphere->segments == other.segments &&
               sphere->rings == other.rings;
    }
    if (const auto* plane = std::get_if<PlaneShape>(&a)) {
        const auto& other = std::get<PlaneShape>(b);
        return plane->center == other.center && plane->normal == other.normal && plane->size == other.size;
    }
    if (const auto* cube = std::get_if<CubeShape>(&a)) {
        const auto& other = std::get<CubeShape>(b);
        return cube->center == other.center && cube->size == other.size;
    }
    const auto& torus = std::get<TorusShape>(a);
    const auto& other = std::get<TorusShape>(b);
    return torus.center == other.center && torus.majorRadius == other.majorRadius &&
           torus.minorRadius == other.minorRadius && torus.segments == other.segments && torus.rings == other.rings;
}

}  // namespace

GpuMeshCache::~GpuMeshCache() {
    for (ProceduralEntry& entry : procedural_) destroy(entry.gpu);
    for (auto& [key, entry] : imported_) destroy(entry.gpu);
}

void GpuMeshCache::upload(GpuMesh& gpu, const Mesh& mesh) {
    if (!gpu.vertexArray) {
        glGenVertexArrays(1, &gpu.vertexArray);
        glGenBuffers(1, &gpu.vertexBuffer);
        glGenBuffers(1, &gpu.indexBuffer);
    }
    glBindVertexArray(gpu.vertexArray);
    glBindBuffer(GL_ARRAY_BUFFER, gpu.vertexBuffer);
    glBufferData(GL_ARRAY_BUFFER, mesh.vertices.size() * sizeof(Vertex), mesh.vertices.data(), GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, gpu.indexBuffer);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, mesh.indices.size() * sizeof(uint32_t), mesh.indices.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, tangent)));
    glBindVertexArray(0);
    gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
}

void GpuMeshCache::destroy(GpuMesh& gpu) {
    glDeleteVertexArrays(1, &gpu.vertexArray);
    glDeleteBuffers(1, &gpu.vertexBuffer);
    glDeleteBuffers(1, &gpu.indexBuffer);
    gpu = {};
}

const GpuMesh& GpuMeshCache::forObject(size_t objectIndex, const SceneObject& object, int proxySegments, int proxyRings,
                                       float proxyScale) {
    if (const auto* meshShape = std::get_if<MeshShape>(&object.shape)) {
        if (!meshShape->mesh) return empty_;
        ImportedEntry& entry = imported_[meshShape->mesh.get()];
        // A freed mesh's address can come back for a new one: the weak pointer tells them apart.
        if (!entry.gpu.vertexArray || entry.source.lock() != meshShape->mesh) {
            upload(entry.gpu, *meshShape->mesh);
            entry.source = meshShape->mesh;
        }
        return entry.gpu;
    }
    if (procedural_.size() <= objectIndex) procedural_.resize(objectIndex + 1);
    ProceduralEntry& entry = procedural_[objectIndex];
    const bool proxy = !drawnAsTriangles(object.shape, object.interpolation);
    if (entry.gpu.vertexArray && entry.proxy == proxy && sameTriangles(entry.shape, object.shape)) return entry.gpu;
    if (proxy) {
        const auto& sphere = std::get<SphereShape>(object.shape);
        upload(entry.gpu, makeUvSphere(sphere.center, sphere.radius * proxyScale, proxySegments, proxyRings));
    } else {
        upload(entry.gpu, proceduralMesh(object.shape));
    }
    entry.shape = object.shape;
    entry.proxy = proxy;
    return entry.gpu;
}

void GpuMeshCache::releaseUnused() {
    for (auto it = imported_.begin(); it != imported_.end();) {
        if (it->second.source.expired()) {
            destroy(it->second.gpu);
            it = imported_.erase(it);
        } else {
            ++it;
        }
    }
}

void setTriangleUniforms(const ShaderProgram& program, const SceneObject& object) {
    const MeshPlacement placement = placementOf(object.shape);
    glUniform4f(program.uniform("placement"), placement.offset.x, placement.offset.y, placement.offset.z, placement.scale);
    glUniform1i(program.uniform("flatNormals"), object.interpolation == SurfaceInterpolation::Flat ? 1 : 0);
}

}  // namespace glint
