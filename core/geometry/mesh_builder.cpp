// Welded, indexed meshes from triangle soups (see mesh_builder.h).
// Sections: adding vertices and triangles · build.
#include "geometry/mesh_builder.h"

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <cmath>

#include "geometry/crease_normals.h"
#include "geometry/tangent_frames.h"

namespace glint {
namespace {

// Appends to a per-vertex attribute that exists only once some vertex has it: zeros stand for
// the vertices added before.
template <class Value>
void appendAttribute(std::vector<Value>& values, size_t vertexIndex, Value value) {
    if (values.empty() && value == Value(0.0f)) return;
    if (values.size() < vertexIndex) values.resize(vertexIndex, Value(0.0f));
    values.push_back(value);
}

// Frees what a container holds (clear() keeps the capacity).
template <class Value>
void releaseMemory(Value& value) {
    value = Value();
}

// A corner whose vertex has no attributes (corners_ before any vertex had one).
constexpr uint32_t kNoAttributes = UINT32_MAX;

template <class Value>
Value attribute(const std::vector<Value>& values, uint32_t vertex) {
    return vertex < values.size() ? values[vertex] : Value(0.0f);
}

// −0 as +0 (x + 0 is +0 for x = ±0 and x otherwise, IEEE 754), so that equal vertices have equal bits.
Vertex canonical(const Vertex& vertex) {
    const glm::vec3 zero(0.0f);
    return {vertex.position + zero, vertex.normal + zero, vertex.uv + glm::vec2(0.0f), vertex.tangent + zero};
}

// Whether two vertices at one position have the same normal, UV and tangent (bit for bit).
static_assert(sizeof(Vertex) == 11 * sizeof(float) && offsetof(Vertex, normal) == 3 * sizeof(float));
bool sameAttributes(const Vertex& a, const Vertex& b) {
    return std::memcmp(&a.normal, &b.normal, sizeof(Vertex) - offsetof(Vertex, normal)) == 0;
}

}  // namespace

// --- adding vertices and triangles ----------------------------------------------------------

MeshBuilder::MeshBuilder(float creaseAngleDegrees) : creaseAngleDegrees_(creaseAngleDegrees) {}

void MeshBuilder::reserve(size_t vertices, size_t triangles) {
    positionOf_.reserve(vertices);
    cornerPositions_.reserve(3 * triangles);
}

uint32_t MeshBuilder::addVertex(glm::vec3 position, glm::vec3 normal, glm::vec2 uv, glm::vec3 tangent) {
    const uint32_t key[3] = {floatKey(position.x), floatKey(position.y), floatKey(position.z)};
    const auto candidate = static_cast<uint32_t>(positions_.size());
    const uint32_t welded = positionTable_.findOrAdd(hashWords(key, 3), candidate, [&](uint32_t stored) {
        const glm::vec3& other = positions_[stored];
        return floatKey(other.x) == key[0] && floatKey(other.y) == key[1] && floatKey(other.z) == key[2];
    });
    if (welded == candidate) positions_.push_back(position);
    const auto index = static_cast<uint32_t>(positionOf_.size());
    positionOf_.push_back(welded);
    const bool hadAttributes = hasAttributes();
    if (normal != glm::vec3(0.0f)) {
        const float length = glm::length(normal);
        normal = std::isfinite(length) && length > 0.0f ? normal / length : glm::vec3(0.0f);
    }
    appendAttribute(normals_, index, normal);
    appendAttribute(uvs_, index, std::isfinite(uv.x + uv.y) ? uv : glm::vec2(0.0f));
    appendAttribute(tangents_, index, std::isfinite(tangent.x + tangent.y + tangent.z) ? tangent : glm::vec3(0.0f));
    if (!hadAttributes && hasAttributes()) {  // the triangles so far use no vertex with attributes
        corners_.reserve(cornerPositions_.capacity());
        corners_.assign(cornerPositions_.size(), kNoAttributes);
    }
    return index;
}

bool MeshBuilder::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    const uint32_t at0 = positionOf_[a], at1 = positionOf_[b], at2 = positionOf_[c];
    const glm::vec3 p0 = positions_[at0], p1 = positions_[at1], p2 = positions_[at2];
    const glm::vec3 edge1 = p1 - p0, edge2 = p2 - p0;
    const float doubleArea = glm::length(glm::cross(edge1, edge2));
    const float longestSquared =
        std::max({glm::dot(edge1, edge1), glm::dot(edge2, edge2), glm::dot(edge2 - edge1, edge2 - edge1)});
    if (!(doubleArea > 1e-10f * longestSquared)) {
        ++degenerateTriangles_;
        return false;
    }
    if (hasAttributes()) corners_.insert(corners_.end(), {a, b, c});
    cornerPositions_.insert(cornerPositions_.end(), {at0, at1, at2});
    return true;
}

// --- build ----------------------------------------------------------------------------------

std::optional<Mesh> MeshBuilder::build(const MeshBuildProgress& progress) {
    // What is no longer needed goes as soon as it can (peak memory).
    releaseMemory(positionTable_), releaseMemory(positionOf_);
    const bool fromFile = hasAttributes();
    // The corners grouped by position, and the crease normals (only where a normal is missing).
    bool normalsMissing = normals_.empty();
    for (size_t corner = 0; corner < corners_.size() && !normalsMissing; ++corner)
        normalsMissing = attribute(normals_, corners_[corner]) == glm::vec3(0.0f);
    const CornersByPosition around(cornerPositions_, positions_.size());
    std::optional<CreaseNormals> creaseNormals;
    if (normalsMissing) creaseNormals.emplace(positions_, cornerPositions_, around, creaseAngleDegrees_);
    const size_t cornerCount = cornerPositions_.size();
    releaseMemory(cornerPositions_);
    if (progress && !progress(0.3f)) return std::nullopt;

    // Position by position, each corner's vertex, shared with an equal one made at the same
    // position before (most positions have one to three).
    Mesh mesh;
    mesh.indices.resize(cornerCount);
    mesh.vertices.reserve(positions_.size());
    std::vector<CornerNormal> atPosition;
    for (uint32_t position = 0; position < positions_.size(); ++position) {
        if ((position & 0xFFFF) == 0xFFFF && progress && !progress(0.3f + 0.6f * position / positions_.size()))
            return std::nullopt;
        if (creaseNormals) {
            creaseNormals->normalsAt(position, atPosition);
        } else {
            atPosition.clear();
            for (uint32_t i = around.first[position]; i < around.first[position + 1]; ++i)
                atPosition.push_back({around.corners[i], glm::vec3(0.0f)});
        }
        const size_t firstHere = mesh.vertices.size();
        for (const CornerNormal& corner : atPosition) {
            Vertex vertex{positions_[position], corner.normal, glm::vec2(0.0f), glm::vec3(0.0f)};
            if (fromFile) {
                const uint32_t source = corners_[corner.corner];
                const glm::vec3 normal = attribute(normals_, source);
                if (normal != glm::vec3(0.0f)) vertex.normal = normal;
                vertex.uv = attribute(uvs_, source);
                vertex.tangent = attribute(tangents_, source);
            }
            vertex = canonical(vertex);
            size_t index = firstHere;
            while (index < mesh.vertices.size() && !sameAttributes(mesh.vertices[index], vertex)) ++index;
            if (index == mesh.vertices.size()) mesh.vertices.push_back(vertex);
            mesh.indices[corner.corner] = static_cast<uint32_t>(index);
        }
    }
    creaseNormals.reset();
    *this = MeshBuilder(creaseAngleDegrees_);  // what was added is no longer needed
    completeTangents(mesh);
    if (progress && !progress(1.0f)) return std::nullopt;
    return mesh;
}

}  // namespace glint
