// GPU mesh buffers, their closure and their simplified stand-ins (see gpu_mesh_cache.h).
#include "gl/gpu_mesh_cache.h"

#include <chrono>
#include <cstddef>

#include "geometry/mesh_simplify.h"
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
        return cube->center == other.center && cube->size == other.size && cube->rotationDegrees == other.rotationDegrees;
    }
    const auto& torus = std::get<TorusShape>(a);
    const auto& other = std::get<TorusShape>(b);
    return torus.center == other.center && torus.majorRadius == other.majorRadius &&
           torus.minorRadius == other.minorRadius && torus.segments == other.segments && torus.rings == other.rings &&
           torus.rotationDegrees == other.rotationDegrees;
}

}  // namespace

GpuMeshCache::~GpuMeshCache() {
    for (ProceduralEntry& entry : procedural_) forgetSimplified(entry.levels), destroy(entry.levels.full);
    for (auto& [key, entry] : imported_) forgetSimplified(entry.levels), destroy(entry.levels.full);
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
    glEnableVertexAttribArray(3);  // texture coordinates (material textures)
    glVertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, uv)));
    glBindVertexArray(0);
    gpu.indexCount = static_cast<GLsizei>(mesh.indices.size());
}

void GpuMeshCache::destroy(GpuMesh& gpu) {
    glDeleteVertexArrays(1, &gpu.vertexArray);
    glDeleteBuffers(1, &gpu.vertexBuffer);
    glDeleteBuffers(1, &gpu.indexBuffer);
    gpu = {};
}

GpuMeshCache::Levels* GpuMeshCache::levelsFor(size_t objectIndex, const SceneObject& object) {
    if (const auto* meshShape = std::get_if<MeshShape>(&object.shape)) {
        if (!meshShape->mesh) return nullptr;
        ImportedEntry& entry = imported_[meshShape->mesh.get()];
        // A freed mesh's address can come back for a new one: the weak pointer tells them apart.
        if (!entry.levels.full.vertexArray || entry.source.lock() != meshShape->mesh) {
            upload(entry.levels.full, *meshShape->mesh);
            entry.levels.full.closure = meshClosure(*meshShape->mesh);
            forgetSimplified(entry.levels);
            entry.source = meshShape->mesh;
        }
        return &entry.levels;
    }
    if (procedural_.size() <= objectIndex) procedural_.resize(objectIndex + 1);
    ProceduralEntry& entry = procedural_[objectIndex];
    const bool proxy = !drawnAsTriangles(object.shape, object.interpolation);
    if (entry.levels.full.vertexArray && entry.proxy == proxy && sameTriangles(entry.shape, object.shape)) return &entry.levels;
    Mesh mesh;
    if (proxy) {
        const auto& sphere = std::get<SphereShape>(object.shape);
        mesh = makeUvSphere(sphere.center, sphere.radius * proxyScale_, proxySegments_, proxyRings_);
    } else {
        mesh = proceduralMesh(object.shape);
    }
    upload(entry.levels.full, mesh);
    entry.levels.full.closure = meshClosure(mesh);
    forgetSimplified(entry.levels);
    entry.shape = object.shape;
    entry.proxy = proxy;
    return &entry.levels;
}

void GpuMeshCache::forgetSimplified(Levels& levels) {
    for (GpuMesh& level : levels.simplified) destroy(level);
    levels.simplified.clear();
    levels.simplifiedDone = false;
    if (levels.making.valid()) abandoned_.push_back(std::move(levels.making));
}

namespace {

// A mesh's stand-ins, finest first (the budgets of at most half its triangles): each level
// simplifies the one before.
std::vector<Mesh> simplifiedLevels(const Mesh& mesh) {
    std::vector<Mesh> levels;
    for (const size_t budget : kSimplifiedTriangles) {
        if (2 * budget > mesh.triangleCount()) continue;
        const Mesh& finer = levels.empty() ? mesh : levels.back();
        Mesh level = simplifyMesh(finer, budget).mesh;
        if (level.indices.empty()) break;  // nothing came out at this budget: nor at coarser ones
        levels.push_back(std::move(level));
    }
    return levels;
}

}  // namespace

void GpuMeshCache::startSimplifying(Levels& levels, const SceneObject& object) {
    constexpr size_t kCoarsest = kSimplifiedTriangles[std::size(kSimplifiedTriangles) - 1];
    if (levels.simplifiedDone || levels.making.valid() || static_cast<size_t>(levels.full.indexCount) / 3 < 2 * kCoarsest)
        return;
    // The worker makes its own copy of a procedural shape's triangles; an imported mesh is shared
    // (immutable) for as long as the worker reads it.
    std::shared_ptr<const Mesh> mesh;
    if (const auto* meshShape = std::get_if<MeshShape>(&object.shape)) mesh = meshShape->mesh;
    levels.making = std::async(std::launch::async, [mesh, shape = object.shape] {
        return simplifiedLevels(mesh ? *mesh : proceduralMesh(shape));
    });
}

void GpuMeshCache::collectSimplified(Levels& levels) {
    if (!levels.making.valid() || levels.making.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return;
    levels.simplifiedDone = true;
    for (const Mesh& made : levels.making.get()) {
        GpuMesh& level = levels.simplified.emplace_back();
        upload(level, made);
        // Culled as the mesh it stands for: clustering leaves a few non-manifold edges in a closed
        // surface (where a cell holds a fold), each smaller than a cell, which would otherwise make
        // it two-sided and twice as costly.
        level.closure = levels.full.closure;
        level.simplified = true;
    }
}

const GpuMesh& GpuMeshCache::forObject(size_t objectIndex, const SceneObject& object, size_t triangleBudget) {
    Levels* levels = levelsFor(objectIndex, object);
    if (!levels) return empty_;
    if (static_cast<size_t>(levels->full.indexCount) / 3 <= triangleBudget) return levels->full;
    collectSimplified(*levels);
    for (const GpuMesh& level : levels->simplified)
        if (static_cast<size_t>(level.indexCount) / 3 <= triangleBudget) return level;
    return levels->simplified.empty() ? levels->full : levels->simplified.back();
}

void GpuMeshCache::prepareSimplified(size_t objectIndex, const SceneObject& object) {
    if (Levels* levels = levelsFor(objectIndex, object)) startSimplifying(*levels, object), collectSimplified(*levels);
}

void GpuMeshCache::finishSimplified() {
    for (ProceduralEntry& entry : procedural_)
        if (entry.levels.making.valid()) entry.levels.making.wait();
    for (auto& [key, entry] : imported_)
        if (entry.levels.making.valid()) entry.levels.making.wait();
}

void GpuMeshCache::releaseUnused() {
    for (auto it = imported_.begin(); it != imported_.end();) {
        if (it->second.source.expired()) {
            forgetSimplified(it->second.levels);
            destroy(it->second.levels.full);
            it = imported_.erase(it);
        } else {
            ++it;
        }
    }
    // Stand-ins nobody wants any more are dropped once their worker is done.
    std::erase_if(abandoned_, [](const auto& job) { return job.wait_for(std::chrono::seconds(0)) == std::future_status::ready; });
}

void setTriangleUniforms(const ShaderProgram& program, const SceneObject& object) {
    const MeshPlacement placement = placementOf(object.shape);
    glUniform4f(program.uniform("placement"), placement.offset.x, placement.offset.y, placement.offset.z, placement.scale);
    glUniform1i(program.uniform("flatNormals"), object.interpolation == SurfaceInterpolation::Flat ? 1 : 0);
}

void setFaceCulling(CulledFaces faces) {
    if (faces == CulledFaces::None) {
        glDisable(GL_CULL_FACE);
        return;
    }
    glEnable(GL_CULL_FACE);
    glCullFace(faces == CulledFaces::Back ? GL_BACK : GL_FRONT);
}

}  // namespace glint
