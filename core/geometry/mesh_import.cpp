// Mesh import through assimp (see mesh_import.h): read, check, merge the node tree's meshes with
// their transforms, drop zero-area faces, normalise into the unit sphere.
// Sections: progress and cancel · messages · checks · merge · normalise · entry points.
#include "geometry/mesh_import.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <regex>
#include <stdexcept>

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "math/frame.h"

namespace glint {
namespace {

constexpr const char* kCancelledMessage = "mesh import cancelled";

// --- progress and cancel --------------------------------------------------------------------

// Assimp ignores Update's return value, so a cancel is thrown from inside the parse (assimp's
// importers throw their own errors the same way and unwind cleanly) and caught around ReadFile.
struct CancelImport : std::runtime_error {
    CancelImport() : std::runtime_error(kCancelledMessage) {}
};

class ProgressRelay : public Assimp::ProgressHandler {
public:
    explicit ProgressRelay(const MeshImportProgress& progress) : progress_(progress) {}
    // Assimp's own progress (reading then processing) maps onto [0, 0.8]; merging is the rest.
    bool Update(float percentage) override {
        report(0.8f * std::clamp(percentage, 0.0f, 1.0f));
        return !cancelled_;
    }
    void report(float fraction) {
        if (!cancelled_ && progress_ && !progress_(fraction)) cancelled_ = true;
        if (cancelled_) throw CancelImport();  // again on every later report: assimp may go on after the first
    }
    bool cancelled() const { return cancelled_; }

private:
    const MeshImportProgress& progress_;
    bool cancelled_ = false;
};

// --- messages -------------------------------------------------------------------------------

// Assimp's messages carry the line where its text parsers know one ("line 12", "Line: 12").
Diagnostic importError(const std::string& name, const std::string& assimpMessage) {
    static const std::regex linePattern(R"([Ll]ine:?\s*(\d+))");
    std::smatch match;
    SourceLocation where{name, 0, 0};
    if (std::regex_search(assimpMessage, match, linePattern)) where.line = std::stoi(match[1]);
    std::string message = assimpMessage.empty() ? "assimp could not read the mesh" : assimpMessage;
    if (message.find("No suitable reader") != std::string::npos || message.find("no suitable reader") != std::string::npos)
        message = "not a mesh format Glint reads (OBJ, PLY, STL, glTF 2.0, GLB, FBX): " + message;
    while (!message.empty() && (message.back() == '\n' || message.back() == ' ')) message.pop_back();
    return makeError("cannot load mesh: " + message, where);
}

// --- checks ---------------------------------------------------------------------------------

bool finite(const aiVector3D& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Refuses what assimp lets through: non-finite coordinates and indices outside the mesh.
std::optional<Diagnostic> checkMesh(const aiMesh& mesh, unsigned meshIndex, const std::string& name) {
    const std::string which = "mesh " + std::to_string(meshIndex) +
                              (mesh.mName.length ? " ('" + std::string(mesh.mName.C_Str()) + "')" : std::string());
    for (unsigned i = 0; i < mesh.mNumVertices; ++i)
        if (!finite(mesh.mVertices[i]))
            return makeError("cannot load mesh: vertex " + std::to_string(i) + " of " + which +
                                 " has a coordinate that is not a finite number (NaN or infinity)",
                             {name});
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        for (unsigned k = 0; k < face.mNumIndices; ++k)
            if (face.mIndices[k] >= mesh.mNumVertices)
                return makeError("cannot load mesh: face " + std::to_string(f) + " of " + which + " uses vertex " +
                                     std::to_string(face.mIndices[k]) + ", but the mesh has only " +
                                     std::to_string(mesh.mNumVertices) + " vertices",
                                 {name});
    }
    return std::nullopt;
}

// --- merge ----------------------------------------------------------------------------------

glm::vec3 toGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

struct Merger {
    const aiScene& scene;
    ProgressRelay& relay;
    const std::string& name;
    Mesh mesh;
    MeshStatistics statistics;
    size_t trianglesSeen = 0, trianglesTotal = 0;
    std::optional<Diagnostic> error;

    // Depth-first over the node tree, each mesh instance placed by its accumulated transform.
    void visit(const aiNode& node, const aiMatrix4x4& parent) {
        const aiMatrix4x4 transform = parent * node.mTransformation;
        for (unsigned i = 0; i < node.mNumMeshes && !error; ++i) append(*scene.mMeshes[node.mMeshes[i]], transform);
        for (unsigned i = 0; i < node.mNumChildren && !error; ++i) visit(*node.mChildren[i], transform);
    }

    void append(const aiMesh& source, const aiMatrix4x4& transform) {
        if (!(source.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) return;
        ++statistics.meshesMerged;
        // Normals and tangents transform with the inverse transpose (DESIGN.md).
        aiMatrix3x3 normalMatrix(transform);
        normalMatrix.Inverse().Transpose();
        const auto first = static_cast<uint32_t>(mesh.vertices.size());
        for (unsigned i = 0; i < source.mNumVertices; ++i) {
            Vertex vertex{};
            vertex.position = toGlm(transform * source.mVertices[i]);
            if (!std::isfinite(vertex.position.x + vertex.position.y + vertex.position.z)) {
                error = makeError("cannot load mesh: a node transform takes vertex " + std::to_string(i) +
                                      " outside the finite numbers",
                                  {name});
                return;
            }
            glm::vec3 normal = source.mNormals ? toGlm(normalMatrix * source.mNormals[i]) : glm::vec3(0.0f);
            vertex.normal = normal;
            if (source.mTextureCoords[0]) vertex.uv = {source.mTextureCoords[0][i].x, source.mTextureCoords[0][i].y};
            if (source.mTangents) vertex.tangent = toGlm(normalMatrix * source.mTangents[i]);
            mesh.vertices.push_back(vertex);
        }
        for (unsigned f = 0; f < source.mNumFaces; ++f) {
            if ((++trianglesSeen & 0xFFFF) == 0) relay.report(0.8f + 0.15f * trianglesSeen / std::max<size_t>(1, trianglesTotal));
            const aiFace& face = source.mFaces[f];
            if (face.mNumIndices != 3) continue;
            const uint32_t a = first + face.mIndices[0], b = first + face.mIndices[1], c = first + face.mIndices[2];
            const glm::vec3 edge1 = mesh.vertices[b].position - mesh.vertices[a].position;
            const glm::vec3 edge2 = mesh.vertices[c].position - mesh.vertices[a].position;
            const float doubleArea = glm::length(glm::cross(edge1, edge2));
            const float longestSquared = std::max({glm::dot(edge1, edge1), glm::dot(edge2, edge2),
                                                   glm::dot(edge2 - edge1, edge2 - edge1)});
            // Zero area, relative to the triangle's size (collapsed or collinear corners).
            if (!(doubleArea > 1e-10f * longestSquared)) {
                ++statistics.degenerateTrianglesDropped;
                continue;
            }
            mesh.indices.insert(mesh.indices.end(), {a, b, c});
        }
    }
};

// Unit normals and tangents everywhere: a vertex whose normal is missing or zero (assimp skips
// those only of degenerate faces) takes the normal of a face that uses it; a missing tangent
// (no UVs) is any unit vector ⟂ the normal (Duff et al. 2017).
void repairFrames(Mesh& mesh) {
    std::vector<char> valid(mesh.vertices.size());
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const float length = glm::length(mesh.vertices[i].normal);
        valid[i] = std::isfinite(length) && length > 1e-12f;
        if (valid[i]) mesh.vertices[i].normal /= length;
    }
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
        Vertex& a = mesh.vertices[mesh.indices[t]];
        const Vertex& b = mesh.vertices[mesh.indices[t + 1]];
        const Vertex& c = mesh.vertices[mesh.indices[t + 2]];
        const glm::vec3 face = glm::normalize(glm::cross(b.position - a.position, c.position - a.position));
        for (int k = 0; k < 3; ++k) {
            const uint32_t index = mesh.indices[t + k];
            if (!valid[index]) mesh.vertices[index].normal = face, valid[index] = 1;
        }
    }
    for (Vertex& vertex : mesh.vertices) {
        const glm::vec3 along = vertex.tangent - vertex.normal * glm::dot(vertex.normal, vertex.tangent);
        const float length = glm::length(along);
        vertex.tangent = std::isfinite(length) && length > 1e-6f ? along / length
                                                                  : ShadingFrame::fromNormal(vertex.normal).tangent;
    }
}

// --- normalise ------------------------------------------------------------------------------

// Drops vertices no triangle uses (those of dropped faces) and renumbers the indices.
void compact(Mesh& mesh) {
    std::vector<uint32_t> remap(mesh.vertices.size(), UINT32_MAX);
    std::vector<Vertex> kept;
    kept.reserve(mesh.vertices.size());
    for (uint32_t& index : mesh.indices) {
        if (remap[index] == UINT32_MAX) {
            remap[index] = static_cast<uint32_t>(kept.size());
            kept.push_back(mesh.vertices[index]);
        }
        index = remap[index];
    }
    mesh.vertices = std::move(kept);
}

// Centre of the bounding box to the origin, farthest vertex to distance 1.
std::optional<std::string> normalise(Mesh& mesh, MeshStatistics& statistics) {
    glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
    for (const Vertex& vertex : mesh.vertices) low = glm::min(low, vertex.position), high = glm::max(high, vertex.position);
    statistics.boundsMin = low;
    statistics.boundsMax = high;
    const glm::vec3 centre = 0.5f * (low + high);
    float radius = 0.0f;
    for (const Vertex& vertex : mesh.vertices) radius = std::max(radius, glm::distance(vertex.position, centre));
    if (!(radius > 0.0f) || !std::isfinite(radius)) return "the mesh has no extent (all vertices coincide)";
    for (Vertex& vertex : mesh.vertices) vertex.position = (vertex.position - centre) / radius;
    return std::nullopt;
}

// --- entry points ---------------------------------------------------------------------------

using ReadFunction = std::function<const aiScene*(Assimp::Importer&, unsigned flags)>;

Result<ImportedMesh> importWith(const ReadFunction& read, const std::string& name, const MeshImportOptions& options,
                                const MeshImportProgress& progress) {
    const auto start = std::chrono::steady_clock::now();
    if (!(options.smoothingAngleDegrees > 0.0f && options.smoothingAngleDegrees <= 180.0f))
        return makeError("smoothing angle must be in (0°, 180°]", {name});
    Assimp::Importer importer;
    auto* relay = new ProgressRelay(progress);
    importer.SetProgressHandler(relay);  // the importer owns and deletes it
    importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE, aiPrimitiveType_POINT | aiPrimitiveType_LINE);
    importer.SetPropertyFloat(AI_CONFIG_PP_GSN_MAX_SMOOTHING_ANGLE, options.smoothingAngleDegrees);
    MeshStatistics statistics;
    try {
        const aiScene* scene = read(importer, aiProcess_Triangulate | aiProcess_SortByPType | aiProcess_ValidateDataStructure);
        if (relay->cancelled()) return makeError(kCancelledMessage, {name});
        if (!scene) return importError(name, importer.GetErrorString());
        if (!scene->mRootNode || scene->mNumMeshes == 0) return makeError("cannot load mesh: the file holds no triangles", {name});
        for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
            const aiMesh& mesh = *scene->mMeshes[i];
            if (auto error = checkMesh(mesh, i, name)) return *error;
            statistics.hadNormals = statistics.hadNormals || mesh.mNormals;
            statistics.hadUvs = statistics.hadUvs || mesh.mTextureCoords[0];
        }
        // Normals where missing (with the crease angle), tangents from UVs, shared vertices.
        scene = importer.ApplyPostProcessing(aiProcess_GenSmoothNormals | aiProcess_CalcTangentSpace |
                                             aiProcess_JoinIdenticalVertices);
        if (relay->cancelled()) return makeError(kCancelledMessage, {name});
        if (!scene) return importError(name, importer.GetErrorString());
        Merger merger{*scene, *relay, name, {}, statistics};
        for (unsigned i = 0; i < scene->mNumMeshes; ++i) merger.trianglesTotal += scene->mMeshes[i]->mNumFaces;
        merger.visit(*scene->mRootNode, aiMatrix4x4());
        if (merger.error) return *merger.error;
        statistics = merger.statistics;
        Mesh mesh = std::move(merger.mesh);
        if (mesh.indices.empty())
            return makeError(statistics.degenerateTrianglesDropped > 0
                                 ? "cannot load mesh: every triangle has zero area (" +
                                       std::to_string(statistics.degenerateTrianglesDropped) + " dropped)"
                                 : "cannot load mesh: the file holds no triangles",
                             {name});
        compact(mesh);
        if (auto problem = normalise(mesh, statistics)) return makeError("cannot load mesh: " + *problem, {name});
        repairFrames(mesh);
        relay->report(1.0f);
        statistics.vertexCount = mesh.vertices.size();
        statistics.triangleCount = mesh.triangleCount();
        statistics.loadSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return ImportedMesh{std::make_shared<const Mesh>(std::move(mesh)), statistics};
    } catch (const CancelImport&) {
        return makeError(kCancelledMessage, {name});
    } catch (const std::bad_alloc&) {
        return makeError("cannot load mesh: out of memory", {name});
    } catch (const std::exception& error) {
        return importError(name, error.what());
    }
}

std::string lowerExtension(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    if (!extension.empty()) extension.erase(0, 1);
    std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
    return extension;
}

}  // namespace

Result<ImportedMesh> importMesh(const std::string& path, const MeshImportOptions& options,
                                const MeshImportProgress& progress) {
    std::error_code code;
    const auto status = std::filesystem::status(path, code);
    if (code || !std::filesystem::exists(status)) return makeError("cannot load mesh: no such file", {path});
    if (!std::filesystem::is_regular_file(status)) return makeError("cannot load mesh: not a regular file", {path});
    if (std::filesystem::file_size(path, code) == 0) return makeError("cannot load mesh: the file is empty", {path});
    if (!isMeshFile(path))
        return makeError("cannot load mesh: unknown extension '." + lowerExtension(path) +
                             "' (Glint reads .obj, .ply, .stl, .gltf, .glb, .fbx)",
                         {path});
    return importWith([&](Assimp::Importer& importer, unsigned flags) { return importer.ReadFile(path, flags); }, path,
                      options, progress);
}

Result<ImportedMesh> importMeshFromMemory(const void* data, size_t size, const std::string& formatHint,
                                          const std::string& name, const MeshImportOptions& options,
                                          const MeshImportProgress& progress) {
    if (size == 0) return makeError("cannot load mesh: the data is empty", {name});
    return importWith(
        [&](Assimp::Importer& importer, unsigned flags) {
            return importer.ReadFileFromMemory(data, size, flags, formatHint.c_str());
        },
        name, options, progress);
}

bool isImportCancellation(const Diagnostic& diagnostic) { return diagnostic.message == kCancelledMessage; }

const std::vector<std::string>& meshFileExtensions() {
    static const std::vector<std::string> extensions = {"obj", "ply", "stl", "gltf", "glb", "fbx"};
    return extensions;
}

bool isMeshFile(const std::string& path) {
    const std::string extension = lowerExtension(path);
    const auto& known = meshFileExtensions();
    return std::find(known.begin(), known.end(), extension) != known.end();
}

}  // namespace glint
