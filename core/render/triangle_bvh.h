// A bounding-volume hierarchy over triangles for the CPU reference: built top-down with the
// binned surface area heuristic (Wald, "On fast Construction of SAH-based Bounding Volume
// Hierarchies", 2007), traversed nearest child first; ray-triangle by Möller and Trumbore
// ("Fast, Minimum Storage Ray/Triangle Intersection", JGT 1997). It knows nothing of shading.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera.h"

namespace glint {

class TriangleBvh {
public:
    using Triangle = std::array<glm::vec3, 3>;

    struct Hit {
        float distance;      // along the ray [m]
        uint32_t triangle;   // index into the triangles given to the constructor
        float barycentric1;  // weight of corner 1 (corner 2 below; corner 0 is 1 − both)
        float barycentric2;
    };

    TriangleBvh() = default;
    explicit TriangleBvh(std::vector<Triangle> triangles);

    // The nearest hit with 0 < distance < maxDistance, either side of the triangle.
    std::optional<Hit> intersect(const Ray& ray, float maxDistance) const;

    size_t triangleCount() const { return triangles_.size(); }
    size_t nodeCount() const { return nodes_.size(); }
    int depth() const { return depth_; }

private:
    struct Node {
        glm::vec3 boundsMin, boundsMax;
        uint32_t firstOrRight;  // leaf: first entry of order_; inner: index of the right child
        uint32_t count;         // leaf: number of triangles; inner: 0 (left child is the next node)
    };
    uint32_t build(uint32_t first, uint32_t count, int level);

    std::vector<Triangle> triangles_;
    std::vector<uint32_t> order_;  // triangle indices, grouped by leaf
    std::vector<Node> nodes_;
    std::vector<glm::vec3> centroids_;  // during the build only
    int depth_ = 0;
};

}  // namespace glint
