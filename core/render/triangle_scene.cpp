// The reference's triangles (see triangle_scene.h).
#include "render/triangle_scene.h"

#include <cstring>
#include <mutex>
#include <string>

#include "geometry/shape_mesh.h"

namespace glint {
namespace {

// Bytes that change whenever the triangles of the scene's traced objects would.
std::string geometryKey(const Scene& scene) {
    std::string key;
    auto append = [&key](const auto& value) { key.append(reinterpret_cast<const char*>(&value), sizeof value); };
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& object = scene.objects[i];
        if (!tracedAsTriangles(object)) continue;
        append(i);
        append(object.shape.index());
        std::visit(
            [&](const auto& shape) {
                using T = std::decay_t<decltype(shape)>;
                if constexpr (std::is_same_v<T, MeshShape>) {
                    append(shape.mesh.get());
                    append(shape.center);
                    append(shape.scale);
                } else {
                    append(shape);  // plain data: vectors, floats and ints
                }
            },
            object.shape);
    }
    return key;
}

}  // namespace

bool tracedAsTriangles(const SceneObject& object) {
    if (!drawnAsTriangles(object.shape, object.interpolation)) return false;
    return !std::holds_alternative<PlaneShape>(object.shape) || object.interpolation == SurfaceInterpolation::Gouraud;
}

TriangleScene::TriangleScene(const Scene& scene) {
    std::vector<TriangleBvh::Triangle> triangles;
    meshes_.resize(scene.objects.size());
    firstTriangle_.assign(scene.objects.size(), 0);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        if (!tracedAsTriangles(scene.objects[i])) continue;
        meshes_[i] = worldMesh(scene.objects[i].shape);
        firstTriangle_[i] = static_cast<int>(triangles.size());
        const Mesh& mesh = meshes_[i];
        for (size_t t = 0; t < mesh.triangleCount(); ++t) {
            triangles.push_back({mesh.vertices[mesh.indices[3 * t]].position, mesh.vertices[mesh.indices[3 * t + 1]].position,
                                 mesh.vertices[mesh.indices[3 * t + 2]].position});
            objectOfTriangle_.push_back(static_cast<int>(i));
        }
    }
    bvh_ = TriangleBvh(std::move(triangles));
}

std::optional<SurfaceHit> TriangleScene::intersect(const Scene& scene, const Ray& ray, float maxDistance) const {
    const auto found = bvh_.intersect(ray, maxDistance);
    if (!found) return std::nullopt;
    const int objectIndex = objectOfTriangle_[found->triangle];
    const int triangle = static_cast<int>(found->triangle) - firstTriangle_[objectIndex];
    const Mesh& mesh = meshes_[objectIndex];
    TriangleCorners corners{{}, {1.0f - found->barycentric1 - found->barycentric2, found->barycentric1, found->barycentric2}, triangle};
    for (int k = 0; k < 3; ++k) corners.vertices[k] = mesh.vertices[mesh.indices[3 * triangle + k]];
    const auto interpolate = [&](glm::vec3 Vertex::*member) {
        return corners.barycentric[0] * corners.vertices[0].*member + corners.barycentric[1] * corners.vertices[1].*member +
               corners.barycentric[2] * corners.vertices[2].*member;
    };
    glm::vec3 normal;
    if (scene.objects[objectIndex].interpolation == SurfaceInterpolation::Flat)
        normal = glm::cross(corners.vertices[1].position - corners.vertices[0].position,
                            corners.vertices[2].position - corners.vertices[0].position);
    else
        normal = interpolate(&Vertex::normal);
    normal = glm::normalize(normal);
    if (glm::dot(normal, ray.direction) > 0.0f) normal = -normal;  // two-sided, as surface.frag
    const glm::vec3 position = ray.origin + found->distance * ray.direction;
    return SurfaceHit{found->distance, position, normal, interpolate(&Vertex::tangent), objectIndex, corners};
}

std::shared_ptr<const TriangleScene> triangleSceneFor(const Scene& scene) {
    static std::mutex mutex;
    static std::string cachedKey;
    static std::shared_ptr<const TriangleScene> cached;
    std::string key = geometryKey(scene);
    std::lock_guard lock(mutex);
    if (!cached || key != cachedKey) {
        cached = std::make_shared<const TriangleScene>(scene);
        cachedKey = std::move(key);
    }
    return cached;
}

std::array<std::pair<SurfaceHit, glm::vec3>, 3> gouraudCorners(const Scene& scene, const SurfaceHit& hit) {
    std::array<std::pair<SurfaceHit, glm::vec3>, 3> corners;
    for (int k = 0; k < 3; ++k) {
        const Vertex& vertex = hit.triangle->vertices[k];
        const glm::vec3 towardsViewer = towardsViewerFrom(scene.camera, vertex.position);
        glm::vec3 normal = glm::normalize(vertex.normal);
        if (glm::dot(normal, towardsViewer) < 0.0f) normal = -normal;
        corners[k] = {SurfaceHit{viewerDistance(scene.camera, vertex.position), vertex.position, normal, vertex.tangent,
                                 hit.objectIndex},
                      towardsViewer};
    }
    return corners;
}

}  // namespace glint
