// Vertex clustering with quadric placement (see mesh_simplify.h).
// Sections: the grid · clustering · cell positions · vertices per side · choosing the grid.
#include "geometry/mesh_simplify.h"

#include <algorithm>
#include <cmath>

#include "geometry/weld_table.h"
#include "math/frame.h"
#include "util/diagnostic.h"

namespace glint {
namespace {

// --- the grid ---------------------------------------------------------------------------------

struct Grid {
    glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // the mesh's box
    int cellsPerAxis = 1;                        // along the box's longest side
    float cellSize = 1.0f;

    glm::ivec3 cellOf(glm::vec3 position) const {
        const glm::ivec3 cell(glm::floor((position - boundsMin) / cellSize));
        return glm::clamp(cell, glm::ivec3(0), glm::ivec3(cellsPerAxis - 1));
    }
};

Grid gridOver(const Mesh& mesh, int cellsPerAxis) {
    Grid grid;
    const MeshBounds bounds = meshBounds(mesh);
    grid.boundsMin = bounds.low, grid.boundsMax = bounds.high;
    const glm::vec3 extent = grid.boundsMax - grid.boundsMin;
    const float longest = std::max({extent.x, extent.y, extent.z});
    grid.cellsPerAxis = cellsPerAxis;
    grid.cellSize = longest > 0.0f ? longest / static_cast<float>(cellsPerAxis) : 1.0f;
    return grid;
}

// --- clustering -------------------------------------------------------------------------------

// Cell coordinates and dense cell indices are packed three to a 64-bit key, 21 bits each.
constexpr uint32_t kMaxCells = (1u << 21) - 1;
constexpr uint32_t kAbsent = ~0u;

uint64_t hashKey(uint64_t key) {
    const uint32_t words[2] = {static_cast<uint32_t>(key), static_cast<uint32_t>(key >> 32)};
    return hashWords(words, 2);
}

struct Clustering {
    Grid grid;
    std::vector<uint32_t> cellOfVertex;  // dense cell index per source vertex
    uint32_t cellCount = 0;
    std::vector<uint32_t> keptTriangles;  // the first source triangle of each distinct cell triple
    size_t estimatedTriangles = 0;  // the kept count, extrapolated when the budget stopped the count early
    bool withinBudget() const { return estimatedTriangles == keptTriangles.size(); }
};

// Rossignac & Borrel: every vertex moves to its cell; a triangle survives when its corners lie in
// three different cells, once per cell triple (either orientation kept: the two sides of a
// collapsed thin wall). Counting stops as soon as `budget` is exceeded.
Clustering cluster(const Mesh& mesh, int cellsPerAxis, size_t budget) {
    Clustering result;
    result.grid = gridOver(mesh, cellsPerAxis);
    result.cellOfVertex.resize(mesh.vertices.size());
    std::vector<uint64_t> keyOfCell;  // per dense cell index: its packed coordinates
    WeldTable cells(mesh.vertices.size() / 4);
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const glm::ivec3 cell = result.grid.cellOf(mesh.vertices[v].position);
        const uint64_t key = static_cast<uint64_t>(cell.x) | static_cast<uint64_t>(cell.y) << 21 | static_cast<uint64_t>(cell.z) << 42;
        const auto candidate = static_cast<uint32_t>(keyOfCell.size());
        const uint32_t index = cells.findOrAdd(hashKey(key), candidate, [&](uint32_t stored) { return keyOfCell[stored] == key; });
        if (index == candidate) {
            if (candidate == kMaxCells) {
                result.estimatedTriangles = ~size_t{0};  // far too fine a grid for any budget
                return result;
            }
            keyOfCell.push_back(key);
        }
        result.cellOfVertex[v] = index;
    }
    result.cellCount = static_cast<uint32_t>(keyOfCell.size());
    const size_t triangleCount = mesh.triangleCount();
    std::vector<uint64_t> keyOfKept;  // per kept triangle: its cell triple, smallest first
    WeldTable seen(std::min(triangleCount, budget + 1));
    for (size_t t = 0; t < triangleCount; ++t) {
        uint64_t corner[3];
        for (int k = 0; k < 3; ++k) corner[k] = result.cellOfVertex[mesh.indices[3 * t + k]];
        if (corner[0] == corner[1] || corner[1] == corner[2] || corner[2] == corner[0]) continue;
        const int first = corner[0] < corner[1] ? (corner[0] < corner[2] ? 0 : 2) : (corner[1] < corner[2] ? 1 : 2);
        const uint64_t key = corner[first] | corner[(first + 1) % 3] << 21 | corner[(first + 2) % 3] << 42;
        const auto candidate = static_cast<uint32_t>(keyOfKept.size());
        if (seen.findOrAdd(hashKey(key), candidate, [&](uint32_t stored) { return keyOfKept[stored] == key; }) != candidate)
            continue;
        keyOfKept.push_back(key);
        result.keptTriangles.push_back(static_cast<uint32_t>(t));
        if (result.keptTriangles.size() > budget) {
            result.estimatedTriangles = result.keptTriangles.size() * triangleCount / (t + 1);
            return result;
        }
    }
    result.estimatedTriangles = result.keptTriangles.size();
    return result;
}

// --- cell positions ---------------------------------------------------------------------------

// Per cell: Σ area·n nᵀ, Σ area·d·n over the planes n·x + d = 0 of the triangles through it
// (Garland & Heckbert's quadric, in Lindstrom's per-cell form), and the mean of its vertices.
struct CellQuadric {
    double a[6] = {0, 0, 0, 0, 0, 0};  // xx, xy, xz, yy, yz, zz
    glm::dvec3 b{0.0};
    glm::dvec3 positionSum{0.0};
    uint32_t vertexCount = 0;
};

// The point minimising Σ area·(n·x + d)², pulled gently towards the cell's mean m: solves
// (A + λI) x = λm − b with λ = 10⁻³·trace(A), so that directions the planes leave free (along a
// flat cell, along a crease) take the mean's coordinate (a truncated pseudo-inverse, in effect).
glm::vec3 quadricPoint(const CellQuadric& quadric) {
    const glm::dvec3 mean = quadric.positionSum / static_cast<double>(quadric.vertexCount);
    const double* a = quadric.a;
    const double trace = a[0] + a[3] + a[5];
    if (!(trace > 0.0)) return glm::vec3(mean);
    const double lambda = 1e-3 * trace;
    const glm::dmat3 matrix(a[0] + lambda, a[1], a[2], a[1], a[3] + lambda, a[4], a[2], a[4], a[5] + lambda);
    const double determinant = glm::determinant(matrix);
    if (!(std::abs(determinant) > 0.0)) return glm::vec3(mean);
    return glm::vec3(glm::inverse(matrix) * (lambda * mean - quadric.b));
}

std::vector<glm::vec3> cellPositions(const Mesh& mesh, const Clustering& clustering) {
    std::vector<CellQuadric> quadrics(clustering.cellCount);
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        CellQuadric& quadric = quadrics[clustering.cellOfVertex[v]];
        quadric.positionSum += glm::dvec3(mesh.vertices[v].position);
        ++quadric.vertexCount;
    }
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const uint32_t* corner = &mesh.indices[3 * t];
        const glm::dvec3 p0(mesh.vertices[corner[0]].position), p1(mesh.vertices[corner[1]].position),
            p2(mesh.vertices[corner[2]].position);
        const glm::dvec3 doubleAreaNormal = glm::cross(p1 - p0, p2 - p0);
        const double doubleArea = glm::length(doubleAreaNormal);
        if (!(doubleArea > 0.0)) continue;
        const glm::dvec3 n = doubleAreaNormal / doubleArea;
        const double area = 0.5 * doubleArea, d = -glm::dot(n, p0);
        const uint32_t cells[3] = {clustering.cellOfVertex[corner[0]], clustering.cellOfVertex[corner[1]],
                                   clustering.cellOfVertex[corner[2]]};
        for (int k = 0; k < 3; ++k) {
            if ((k > 0 && cells[k] == cells[0]) || (k > 1 && cells[k] == cells[1])) continue;  // once per cell
            CellQuadric& quadric = quadrics[cells[k]];
            const double products[6] = {n.x * n.x, n.x * n.y, n.x * n.z, n.y * n.y, n.y * n.z, n.z * n.z};
            for (int i = 0; i < 6; ++i) quadric.a[i] += area * products[i];
            quadric.b += area * d * n;
        }
    }
    std::vector<glm::vec3> positions(clustering.cellCount);
    const Grid& grid = clustering.grid;
    std::vector<bool> placed(clustering.cellCount, false);
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const uint32_t cell = clustering.cellOfVertex[v];
        if (placed[cell]) continue;
        placed[cell] = true;
        // Kept inside the cell (and the mesh's box), so the proxy never strays more than a cell.
        const glm::vec3 cellMin = grid.boundsMin + glm::vec3(grid.cellOf(mesh.vertices[v].position)) * grid.cellSize;
        const glm::vec3 low = glm::max(cellMin, grid.boundsMin), high = glm::min(cellMin + grid.cellSize, grid.boundsMax);
        positions[cell] = glm::clamp(quadricPoint(quadrics[cell]), low, high);
    }
    return positions;
}

// --- vertices per side ------------------------------------------------------------------------

// Source vertices of one cell that face the same way (normals within 60°, the importer's default
// crease angle) and sit on the same side of any UV seam become one output vertex.
constexpr float kSameSideCosine = 0.5f;
constexpr float kSameSideUvDistance = 0.25f;

struct Side {
    uint32_t cell;
    uint32_t nextInCell;
    glm::vec3 seedNormal;  // the first vertex's, normalised
    glm::vec2 seedUv;
    glm::vec3 normalSum{0.0f}, tangentSum{0.0f};
    glm::vec2 uvSum{0.0f};
    uint32_t vertexCount = 0;
};

glm::vec3 normalisedOr(glm::vec3 v, glm::vec3 fallback) {
    const float length = glm::length(v);
    return length > 1e-12f ? v / length : fallback;
}

std::vector<uint32_t> sidesOfVertices(const Mesh& mesh, const Clustering& clustering, std::vector<Side>& sides) {
    std::vector<uint32_t> firstSide(clustering.cellCount, kAbsent);
    std::vector<uint32_t> sideOfVertex(mesh.vertices.size());
    for (size_t v = 0; v < mesh.vertices.size(); ++v) {
        const Vertex& vertex = mesh.vertices[v];
        const uint32_t cell = clustering.cellOfVertex[v];
        const glm::vec3 normal = normalisedOr(vertex.normal, glm::vec3(0.0f));
        uint32_t side = firstSide[cell];
        while (side != kAbsent && (glm::dot(sides[side].seedNormal, normal) < kSameSideCosine ||
                                               glm::length(sides[side].seedUv - vertex.uv) > kSameSideUvDistance))
            side = sides[side].nextInCell;
        if (side == kAbsent) {
            side = static_cast<uint32_t>(sides.size());
            sides.push_back({cell, firstSide[cell], normal, vertex.uv});
            firstSide[cell] = side;
        }
        Side& entry = sides[side];
        entry.normalSum += normal;
        entry.tangentSum += vertex.tangent;
        entry.uvSum += vertex.uv;
        ++entry.vertexCount;
        sideOfVertex[v] = side;
    }
    return sideOfVertex;
}

Mesh buildProxy(const Mesh& mesh, const Clustering& clustering) {
    const std::vector<glm::vec3> positions = cellPositions(mesh, clustering);
    std::vector<Side> sides;
    const std::vector<uint32_t> sideOfVertex = sidesOfVertices(mesh, clustering, sides);
    std::vector<uint32_t> outputOfSide(sides.size(), kAbsent);
    Mesh proxy;
    proxy.indices.reserve(3 * clustering.keptTriangles.size());
    for (const uint32_t t : clustering.keptTriangles) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t side = sideOfVertex[mesh.indices[3 * t + k]];
            if (outputOfSide[side] == kAbsent) {
                const Side& entry = sides[side];
                const glm::vec3 normal = normalisedOr(entry.normalSum, glm::vec3(0.0f, 0.0f, 1.0f));
                const glm::vec3 tangent = ShadingFrame::fromNormalAndTangent(normal, entry.tangentSum).tangent;
                outputOfSide[side] = static_cast<uint32_t>(proxy.vertices.size());
                proxy.vertices.push_back({positions[entry.cell], normal, entry.uvSum / static_cast<float>(entry.vertexCount), tangent});
            }
            proxy.indices.push_back(outputOfSide[side]);
        }
    }
    return proxy;
}

// --- choosing the grid ------------------------------------------------------------------------

// A surface of area S cut by cells of edge s passes through about 1.5·S/s² of them (cells meet it
// obliquely), and a closed mesh has about twice as many triangles as vertices: s = √(3S/budget)
// is the first guess; then a few tries between the finest grid found within the budget and the
// coarsest found over it, each guess scaled by √(0.9·budget/triangles).

}  // namespace

SimplifiedMesh simplifyMesh(const Mesh& mesh, size_t triangleBudget) {
    GLINT_CHECK(triangleBudget >= 1);
    if (mesh.triangleCount() <= triangleBudget) return {mesh, 0.0f};
    double area = 0.0;
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
        const glm::vec3 p0 = mesh.vertices[mesh.indices[3 * t]].position;
        area += 0.5 * glm::length(glm::cross(mesh.vertices[mesh.indices[3 * t + 1]].position - p0,
                                             mesh.vertices[mesh.indices[3 * t + 2]].position - p0));
    }
    const Grid box = gridOver(mesh, 1);
    constexpr int kMaxCellsPerAxis = 1 << 20;
    const double guessCellSize = std::sqrt(3.0 * area / static_cast<double>(triangleBudget));
    int cells = std::clamp(static_cast<int>(std::ceil(box.cellSize / std::max(guessCellSize, 1e-30))), 1, kMaxCellsPerAxis);
    Clustering best = cluster(mesh, 1, triangleBudget);  // one cell: no triangle, always within
    int bestCells = 1, overCells = kMaxCellsPerAxis + 1;
    for (int attempt = 0; attempt < 6 && cells > bestCells && cells < overCells; ++attempt) {
        Clustering trial = cluster(mesh, cells, triangleBudget);
        const double triangles = static_cast<double>(std::max<size_t>(trial.estimatedTriangles, 1));
        const bool farTooFine = trial.estimatedTriangles == ~size_t{0};  // more cells than keys can hold
        const double scale = farTooFine ? 0.5 : std::sqrt(0.9 * static_cast<double>(triangleBudget) / triangles);
        if (trial.withinBudget()) {
            const bool closeEnough = trial.keptTriangles.size() >= 0.7 * triangleBudget;
            bestCells = cells;
            best = std::move(trial);
            if (closeEnough) break;
            cells = std::max(cells + 1, static_cast<int>(cells * scale));
        } else {
            overCells = cells;
            cells = std::min(cells - 1, static_cast<int>(cells * scale));
        }
        cells = std::clamp(cells, 1, kMaxCellsPerAxis);
    }
    return {buildProxy(mesh, best), best.grid.cellSize};
}

}  // namespace glint
