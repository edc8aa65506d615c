// Triangle BVH: binned SAH build and traversal (see triangle_bvh.h).
#include "render/triangle_bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace glint {
namespace {

constexpr int kBins = 12;
constexpr uint32_t kLeafSize = 4;
constexpr int kMaxDepth = 60;  // the traversal stack holds 64 nodes
constexpr float kTraversalCost = 1.0f, kIntersectionCost = 1.0f;  // SAH constants (Wald 2007)

struct Box {
    glm::vec3 low{std::numeric_limits<float>::max()}, high{-std::numeric_limits<float>::max()};
    void grow(glm::vec3 point) { low = glm::min(low, point), high = glm::max(high, point); }
    void grow(const Box& other) { low = glm::min(low, other.low), high = glm::max(high, other.high); }
    float area() const {
        const glm::vec3 extent = high - low;
        return extent.x < 0.0f ? 0.0f : 2.0f * (extent.x * extent.y + extent.y * extent.z + extent.z * extent.x);
    }
};

// Slab test (Kay and Kajiya 1986): the entry distance, or +∞ when the ray misses the box.
float enterBox(glm::vec3 low, glm::vec3 high, glm::vec3 origin, glm::vec3 inverseDirection, float maxDistance) {
    const glm::vec3 t0 = (low - origin) * inverseDirection, t1 = (high - origin) * inverseDirection;
    const glm::vec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
    const float enter = std::max({near.x, near.y, near.z, 0.0f});
    const float leave = std::min({far.x, far.y, far.z, maxDistance});
    return enter <= leave ? enter : std::numeric_limits<float>::infinity();
}

}  // namespace

TriangleBvh::TriangleBvh(std::vector<Triangle> triangles) : triangles_(std::move(triangles)) {
    order_.resize(triangles_.size());
    centroids_.resize(triangles_.size());
    for (uint32_t i = 0; i < triangles_.size(); ++i) {
        order_[i] = i;
        centroids_[i] = (triangles_[i][0] + triangles_[i][1] + triangles_[i][2]) / 3.0f;
    }
    nodes_.reserve(2 * triangles_.size() / kLeafSize + 1);
    if (!triangles_.empty()) build(0, static_cast<uint32_t>(triangles_.size()), 1);
    centroids_ = {};
}

uint32_t TriangleBvh::build(uint32_t first, uint32_t count, int level) {
    depth_ = std::max(depth_, level);
    const auto index = static_cast<uint32_t>(nodes_.size());
    nodes_.push_back({});
    Box bounds, centroidBounds;
    for (uint32_t i = first; i < first + count; ++i) {
        for (const glm::vec3& corner : triangles_[order_[i]]) bounds.grow(corner);
        centroidBounds.grow(centroids_[order_[i]]);
    }
    nodes_[index].boundsMin = bounds.low;
    nodes_[index].boundsMax = bounds.high;
    auto makeLeaf = [&] {
        nodes_[index].firstOrRight = first;
        nodes_[index].count = count;
        return index;
    };
    if (count <= kLeafSize || level >= kMaxDepth) return makeLeaf();

    // Binned SAH: the cheapest of kBins − 1 planes on each axis, by centroid.
    float bestCost = std::numeric_limits<float>::infinity();
    int bestAxis = -1, bestSplit = 0;
    const glm::vec3 extent = centroidBounds.high - centroidBounds.low;
    for (int axis = 0; axis < 3; ++axis) {
        if (!(extent[axis] > 0.0f)) continue;
        Box binBounds[kBins];
        uint32_t binCounts[kBins] = {};
        const float scale = kBins / extent[axis];
        for (uint32_t i = first; i < first + count; ++i) {
            const int bin = std::min(kBins - 1, static_cast<int>((centroids_[order_[i]][axis] - centroidBounds.low[axis]) * scale));
            ++binCounts[bin];
            for (const glm::vec3& corner : triangles_[order_[i]]) binBounds[bin].grow(corner);
        }
        float rightAreas[kBins];
        uint32_t rightCounts[kBins];
        Box right;
        uint32_t rightCount = 0;
        for (int bin = kBins - 1; bin > 0; --bin) {
            right.grow(binBounds[bin]);
            rightCount += binCounts[bin];
            rightAreas[bin] = right.area();
            rightCounts[bin] = rightCount;
        }
        Box left;
        uint32_t leftCount = 0;
        for (int split = 1; split < kBins; ++split) {
            left.grow(binBounds[split - 1]);
            leftCount += binCounts[split - 1];
            if (leftCount == 0 || rightCounts[split] == 0) continue;
            const float cost = left.area() * leftCount + rightAreas[split] * rightCounts[split];
            if (cost < bestCost) bestCost = cost, bestAxis = axis, bestSplit = split;
        }
    }
    const float leafCost = kIntersectionCost * count;
    if (bestAxis < 0) return makeLeaf();  // all centroids coincide
    const float splitCost = kTraversalCost + kIntersectionCost * bestCost / std::max(bounds.area(), 1e-30f);
    if (splitCost >= leafCost && count <= 16) return makeLeaf();

    const float scale = kBins / extent[bestAxis];
    const auto middle = std::partition(order_.begin() + first, order_.begin() + first + count, [&](uint32_t triangle) {
        const int bin = std::min(kBins - 1, static_cast<int>((centroids_[triangle][bestAxis] - centroidBounds.low[bestAxis]) * scale));
        return bin < bestSplit;
    });
    const auto leftCount = static_cast<uint32_t>(middle - (order_.begin() + first));
    build(first, leftCount, level + 1);
    const uint32_t rightChild = build(first + leftCount, count - leftCount, level + 1);
    nodes_[index].firstOrRight = rightChild;
    nodes_[index].count = 0;
    return index;
}

std::optional<TriangleBvh::Hit> TriangleBvh::intersect(const Ray& ray, float maxDistance) const {
    if (nodes_.empty()) return std::nullopt;
    const glm::vec3 inverseDirection = 1.0f / ray.direction;  // ±∞ on axis-parallel rays: the slab test copes
    std::optional<Hit> nearest;
    float limit = maxDistance;
    uint32_t stack[64];
    int top = 0;
    if (enterBox(nodes_[0].boundsMin, nodes_[0].boundsMax, ray.origin, inverseDirection, limit) == std::numeric_limits<float>::infinity())
        return std::nullopt;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = nodes_[stack[--top]];
        if (node.count > 0) {
            for (uint32_t i = node.firstOrRight; i < node.firstOrRight + node.count; ++i) {
                // Möller-Trumbore: solve o + t·d = v0 + b1·e1 + b2·e2 by Cramer's rule.
                const Triangle& triangle = triangles_[order_[i]];
                const glm::vec3 edge1 = triangle[1] - triangle[0], edge2 = triangle[2] - triangle[0];
                const glm::vec3 p = glm::cross(ray.direction, edge2);
                const float determinant = glm::dot(edge1, p);
                if (determinant == 0.0f) continue;  // parallel to the triangle's plane
                const float inverseDeterminant = 1.0f / determinant;
                const glm::vec3 offset = ray.origin - triangle[0];
                const float b1 = glm::dot(offset, p) * inverseDeterminant;
                if (b1 < 0.0f || b1 > 1.0f) continue;
                const glm::vec3 q = glm::cross(offset, edge1);
                const float b2 = glm::dot(ray.direction, q) * inverseDeterminant;
                if (b2 < 0.0f || b1 + b2 > 1.0f) continue;
                const float t = glm::dot(edge2, q) * inverseDeterminant;
                if (t <= 0.0f || t >= limit) continue;
                limit = t;
                nearest = Hit{t, order_[i], b1, b2};
            }
            continue;
        }
        // Inner node: visit the nearer child first (pushed last).
        const uint32_t leftIndex = static_cast<uint32_t>(&node - nodes_.data()) + 1, rightIndex = node.firstOrRight;
        const float leftEnter = enterBox(nodes_[leftIndex].boundsMin, nodes_[leftIndex].boundsMax, ray.origin, inverseDirection, limit);
        const float rightEnter = enterBox(nodes_[rightIndex].boundsMin, nodes_[rightIndex].boundsMax, ray.origin, inverseDirection, limit);
        const float infinity = std::numeric_limits<float>::infinity();
        if (leftEnter < rightEnter) {
            if (rightEnter != infinity) stack[top++] = rightIndex;
            stack[top++] = leftIndex;
        } else {
            if (leftEnter != infinity) stack[top++] = leftIndex;
            if (rightEnter != infinity) stack[top++] = rightIndex;
        }
    }
    return nearest;
}

}  // namespace glint
