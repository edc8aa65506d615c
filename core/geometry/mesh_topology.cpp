// Mesh closure (see mesh_topology.h).
// Sections: welding · edges · orientation.
#include "geometry/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "geometry/weld_table.h"
#include "util/diagnostic.h"

namespace glint {

// --- welding ----------------------------------------------------------------------------------

std::vector<uint32_t> weldPositions(const Mesh& mesh) {
    std::vector<uint32_t> welded(mesh.vertices.size());
    WeldTable firstAt(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const glm::vec3 position = mesh.vertices[i].position;
        const uint32_t key[3] = {floatKey(position.x), floatKey(position.y), floatKey(position.z)};
        welded[i] = firstAt.findOrAdd(hashWords(key, 3), static_cast<uint32_t>(i),
                                      [&](uint32_t stored) { return mesh.vertices[stored].position == position; });
    }
    return welded;
}

// --- edges ------------------------------------------------------------------------------------

namespace {

// Closed: every directed edge u→v of the non-degenerate welded triangles appears once, and so
// does its reverse v→u (so each edge has exactly two triangles, running along it opposite ways).
// The directed edges are listed per start vertex (compressed rows), each row sorted: no sort of
// all the edges at once.
bool everyEdgeHasTwoOppositeTriangles(const std::vector<uint32_t>& indices, const std::vector<uint32_t>& welded) {
    const auto corners = [&](size_t t, uint32_t corner[3]) {
        for (int k = 0; k < 3; ++k) corner[k] = welded[indices[t + k]];
        return corner[0] != corner[1] && corner[1] != corner[2] && corner[2] != corner[0];
    };
    std::vector<uint32_t> rowStart(welded.size() + 1, 0);
    uint32_t corner[3];
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        if (corners(t, corner))
            for (int k = 0; k < 3; ++k) ++rowStart[corner[k] + 1];
    for (size_t v = 0; v < welded.size(); ++v) rowStart[v + 1] += rowStart[v];
    if (rowStart.back() == 0) return false;
    std::vector<uint32_t> edgeEnd(rowStart.back());
    std::vector<uint32_t> fill(rowStart.begin(), rowStart.end() - 1);
    for (size_t t = 0; t + 2 < indices.size(); t += 3)
        if (corners(t, corner))
            for (int k = 0; k < 3; ++k) edgeEnd[fill[corner[k]]++] = corner[(k + 1) % 3];
    for (size_t v = 0; v < welded.size(); ++v) {
        const auto begin = edgeEnd.begin() + rowStart[v], end = edgeEnd.begin() + rowStart[v + 1];
        std::sort(begin, end);
        if (std::adjacent_find(begin, end) != end) return false;  // two triangles run the same way
    }
    for (size_t v = 0; v < welded.size(); ++v)
        for (uint32_t e = rowStart[v]; e < rowStart[v + 1]; ++e) {
            const uint32_t to = edgeEnd[e];
            if (!std::binary_search(edgeEnd.begin() + rowStart[to], edgeEnd.begin() + rowStart[to + 1], static_cast<uint32_t>(v)))
                return false;  // an edge with one triangle
        }
    return true;
}

// --- orientation ------------------------------------------------------------------------------

uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t id) {
    while (parent[id] != id) id = parent[id] = parent[parent[id]];  // path halving
    return id;
}

// The signed volume of each connected part, by the divergence theorem: V = Σ a·(b × c) / 6 over
// its triangles (positive when they turn counter-clockwise seen from outside). A part whose
// volume is tiny against the sum of the terms' magnitudes encloses nothing: undecided.
MeshClosure orientationOfParts(const Mesh& mesh, const std::vector<uint32_t>& welded, glm::vec3 origin) {
    std::vector<uint32_t> parent(mesh.vertices.size());
    std::iota(parent.begin(), parent.end(), 0u);
    const auto& indices = mesh.indices;
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const uint32_t a = findRoot(parent, welded[indices[t]]), b = findRoot(parent, welded[indices[t + 1]]),
                       c = findRoot(parent, welded[indices[t + 2]]);
        parent[b] = a;
        parent[findRoot(parent, c)] = a;
    }
    std::vector<double> volume(mesh.vertices.size(), 0.0), magnitude(mesh.vertices.size(), 0.0);
    for (size_t t = 0; t + 2 < indices.size(); t += 3) {
        const glm::dvec3 a = glm::dvec3(mesh.vertices[indices[t]].position - origin);
        const glm::dvec3 b = glm::dvec3(mesh.vertices[indices[t + 1]].position - origin);
        const glm::dvec3 c = glm::dvec3(mesh.vertices[indices[t + 2]].position - origin);
        const double term = glm::dot(a, glm::cross(b, c));
        const uint32_t part = findRoot(parent, welded[indices[t]]);
        volume[part] += term;
        magnitude[part] += std::abs(term);
    }
    bool outward = false, inward = false;
    for (size_t part = 0; part < volume.size(); ++part) {
        if (magnitude[part] == 0.0) continue;  // not a root, or no triangles
        if (std::abs(volume[part]) < 1e-4 * magnitude[part]) return MeshClosure::Open;
        (volume[part] > 0.0 ? outward : inward) = true;
    }
    if (outward == inward) return MeshClosure::Open;
    return outward ? MeshClosure::ClosedOutward : MeshClosure::ClosedInward;
}

}  // namespace

MeshClosure meshClosure(const Mesh& mesh) {
    GLINT_CHECK(mesh.vertices.size() < (1u << 31));
    if (mesh.indices.empty()) return MeshClosure::Open;
    const MeshBounds bounds = meshBounds(mesh);
    const std::vector<uint32_t> welded = weldPositions(mesh);
    if (!everyEdgeHasTwoOppositeTriangles(mesh.indices, welded)) return MeshClosure::Open;
    return orientationOfParts(mesh, welded, 0.5f * (bounds.low + bounds.high));
}

}  // namespace glint
