// Mesh import through assimp (see mesh_import.h): read (triangulated, nothing else asked of
// assimp), check and merge the node tree's meshes with their transforms into a MeshBuilder (which
// welds, drops zero-area faces, makes normals and tangents), or one MeshBuilder per part, normalise
// into the unit sphere.
// Sections: progress and cancel · messages · checks · merge · normalise · entry points.
#include "geometry/mesh_import.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string_view>
#include <optional>
#include <regex>
#include <stdexcept>

#ifdef __GLIBC__
#include <malloc.h>
#endif

#include <assimp/Importer.hpp>
#include <assimp/ProgressHandler.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include "geometry/mesh_builder.h"
#include "geometry/mesh_file_checks.h"
#include "geometry/mesh_io_system.h"
#include "geometry/ply_strips.h"
#include "util/file_io.h"
#include "util/text.h"

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
    // Passes the fraction on; false once cancelled (and for every later offer).
    bool offer(float fraction) {
        if (!cancelled_ && progress_ && !progress_(fraction)) cancelled_ = true;
        return !cancelled_;
    }
    void report(float fraction) {
        if (!offer(fraction)) throw CancelImport();  // again on every later report: assimp may go on after the first
    }
    bool cancelled() const { return cancelled_; }

private:
    const MeshImportProgress& progress_;
    bool cancelled_ = false;
};

// --- messages -------------------------------------------------------------------------------

// Assimp's messages carry the line where its text parsers know one ("line 12", "Line: 12"). Where
// the import opened a file the mesh names, the message may quote that file: it is replaced by one
// that names the file.
Diagnostic importError(const std::string& name, const std::string& assimpMessage, const MeshIoSystem& files) {
    if (files.refusal()) return *files.refusal();
    if (!files.referencedFilesOpened().empty())
        return makeError("cannot load mesh: it, or a file it names ('" + files.referencedFilesOpened().back() +
                             "'), is not valid mesh data (assimp's message is left out: it may quote that file)",
                         {name});
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

std::string meshLabel(const aiMesh& mesh, unsigned meshIndex) {
    return "mesh " + std::to_string(meshIndex) +
           (mesh.mName.length ? " ('" + std::string(mesh.mName.C_Str()) + "')" : std::string());
}

// Refuses, in one pass over the mesh as assimp read it (no processing step has run: assimp's
// own validation is not asked for, and its steps may crash on what this refuses), missing
// arrays, non-finite coordinates, faces of more corners than the mesh has vertices and indices
// outside the mesh. Notes faces of more than three corners in `hasPolygons`.
std::optional<Diagnostic> checkMesh(const aiMesh& mesh, unsigned meshIndex, const std::string& name, bool& hasPolygons) {
    if ((mesh.mNumVertices > 0 && !mesh.mVertices) || (mesh.mNumFaces > 0 && !mesh.mFaces))
        return makeError("cannot load mesh: " + meshLabel(mesh, meshIndex) + " lacks its vertices or faces", {name});
    for (unsigned i = 0; i < mesh.mNumVertices; ++i)
        if (!finite(mesh.mVertices[i]))
            return makeError("cannot load mesh: vertex " + std::to_string(i) + " of " + meshLabel(mesh, meshIndex) +
                                 " has a coordinate that is not a finite number (NaN or infinity)",
                             {name});
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices > 0 && !face.mIndices)
            return makeError("cannot load mesh: face " + std::to_string(f) + " of " + meshLabel(mesh, meshIndex) +
                                 " lacks its indices",
                             {name});
        // More corners than vertices is a lie about the count (a PLY list's, say), and assimp's
        // Triangulate would take ages over it.
        if (face.mNumIndices > mesh.mNumVertices)
            return makeError("cannot load mesh: face " + std::to_string(f) + " of " + meshLabel(mesh, meshIndex) + " has " +
                                 std::to_string(face.mNumIndices) + " corners, but the mesh has only " +
                                 std::to_string(mesh.mNumVertices) + " vertices",
                             {name});
        hasPolygons = hasPolygons || face.mNumIndices > 3;
        for (unsigned k = 0; k < face.mNumIndices; ++k)
            if (face.mIndices[k] >= mesh.mNumVertices)
                return makeError("cannot load mesh: face " + std::to_string(f) + " of " + meshLabel(mesh, meshIndex) +
                                     " uses vertex " + std::to_string(face.mIndices[k]) + ", but the mesh has only " +
                                     std::to_string(mesh.mNumVertices) + " vertices",
                                 {name});
    }
    return std::nullopt;
}

// --- merge ----------------------------------------------------------------------------------

glm::vec3 toGlm(const aiVector3D& v) { return {v.x, v.y, v.z}; }

// The scene's meshes (checked: checkMesh), each instance placed by its node's accumulated
// transform, into one MeshBuilder, or (splitParts) one MeshBuilder per instance: the parts.
struct Merger {
    struct Part {
        MeshBuilder builder;
        MeshStatistics statistics;
        std::string name;
        unsigned materialIndex = 0;
        std::string materialName;
    };

    const aiScene& scene;
    ProgressRelay& relay;
    const std::string& name;
    bool fileNormalsAreFaceNormals;  // STL: its facet normals carry no smoothing; Glint makes its own
    float creaseAngleDegrees;
    bool splitParts;
    std::vector<Part> parts;
    size_t itemsSeen = 0, itemsTotal = 0;  // vertices and faces, for progress
    std::optional<Diagnostic> error;

    static constexpr int kDeepestNode = 1000;  // deeper is a malformed (or cyclic) node tree

    // Depth-first over the node tree: `visit(node, mesh, meshIndex, transform)` for each mesh instance.
    template <class Visit>
    void walk(const aiNode& node, const aiMatrix4x4& parent, int depth, const Visit& visit) {
        if (error) return;
        if (depth > kDeepestNode || (node.mNumMeshes > 0 && !node.mMeshes) || (node.mNumChildren > 0 && !node.mChildren)) {
            error = makeError("cannot load mesh: malformed node tree (lists missing, or more than " +
                                  std::to_string(kDeepestNode) + " deep)",
                              {name});
            return;
        }
        const aiMatrix4x4 transform = parent * node.mTransformation;
        for (unsigned i = 0; i < node.mNumMeshes && !error; ++i) {
            const unsigned index = node.mMeshes[i];
            if (index >= scene.mNumMeshes) {
                error = makeError("cannot load mesh: a node names mesh " + std::to_string(index) + ", but the file has " +
                                      std::to_string(scene.mNumMeshes),
                                  {name});
                return;
            }
            visit(node, *scene.mMeshes[index], index, transform);
        }
        for (unsigned i = 0; i < node.mNumChildren && !error; ++i)
            if (node.mChildren[i]) walk(*node.mChildren[i], transform, depth + 1, visit);
    }

    void run() {
        size_t vertices = 0, faces = 0;
        walk(*scene.mRootNode, aiMatrix4x4(), 0, [&](const aiNode&, const aiMesh& mesh, unsigned, const aiMatrix4x4&) {
            vertices += mesh.mNumVertices, faces += mesh.mNumFaces;
            if (splitParts) parts.push_back(Part{MeshBuilder(creaseAngleDegrees), {}, {}, 0, {}});
            if (splitParts) parts.back().builder.reserve(mesh.mNumVertices, mesh.mNumFaces);
        });
        itemsTotal = vertices + faces;
        if (!splitParts) {
            parts.push_back(Part{MeshBuilder(creaseAngleDegrees), {}, {}, 0, {}});
            parts.back().builder.reserve(vertices, faces);
        }
        size_t instance = 0;
        walk(*scene.mRootNode, aiMatrix4x4(), 0,
             [&](const aiNode& node, const aiMesh& mesh, unsigned index, const aiMatrix4x4& transform) {
                 Part& part = parts[splitParts ? instance++ : 0];
                 if (splitParts) describe(part, node, mesh, index);
                 append(part, mesh, index, transform);
             });
    }

    // A part's name (its mesh's, else its node's, else its number) and the material the file gives it.
    void describe(Part& part, const aiNode& node, const aiMesh& mesh, unsigned meshIndex) const {
        part.name = mesh.mName.length ? mesh.mName.C_Str()
                    : node.mName.length ? node.mName.C_Str()
                                        : "mesh " + std::to_string(meshIndex);
        part.materialIndex = mesh.mMaterialIndex;
        aiString materialName;
        if (mesh.mMaterialIndex < scene.mNumMaterials && scene.mMaterials && scene.mMaterials[mesh.mMaterialIndex] &&
            scene.mMaterials[mesh.mMaterialIndex]->Get(AI_MATKEY_NAME, materialName) == AI_SUCCESS)
            part.materialName = materialName.C_Str();
    }

    void progressed() {
        if ((++itemsSeen & 0xFFFF) == 0) relay.report(0.8f + 0.1f * itemsSeen / std::max<size_t>(1, itemsTotal));
    }

    void append(Part& part, const aiMesh& source, unsigned meshIndex, const aiMatrix4x4& transform) {
        MeshBuilder& builder = part.builder;
        MeshStatistics& statistics = part.statistics;
        const aiVector3D* normals = fileNormalsAreFaceNormals ? nullptr : source.mNormals;
        const aiVector3D* uvs = source.mTextureCoords[0];
        statistics.hadNormals = statistics.hadNormals || normals;
        statistics.hadUvs = statistics.hadUvs || uvs;
        // Normals transform with the inverse transpose (docs/architecture.md), tangents (along the surface) as positions do.
        aiMatrix3x3 normalMatrix(transform);
        normalMatrix.Inverse().Transpose();
        const aiMatrix3x3 tangentMatrix(transform);
        const bool identity = transform == aiMatrix4x4();  // exactly (IsIdentity allows 0.01)
        const auto first = static_cast<uint32_t>(builder.vertexCount());
        for (unsigned i = 0; i < source.mNumVertices; ++i) {
            progressed();
            const glm::vec3 position = toGlm(identity ? source.mVertices[i] : transform * source.mVertices[i]);
            if (!std::isfinite(position.x + position.y + position.z)) {
                error = makeError("cannot load mesh: a node transform takes vertex " + std::to_string(i) + " of " +
                                      meshLabel(source, meshIndex) + " outside the finite numbers",
                                  {name});
                return;
            }
            builder.addVertex(position, normals ? toGlm(normalMatrix * normals[i]) : glm::vec3(0.0f),
                              uvs ? glm::vec2(uvs[i].x, uvs[i].y) : glm::vec2(0.0f),
                              source.mTangents ? toGlm(tangentMatrix * source.mTangents[i]) : glm::vec3(0.0f));
        }
        const size_t trianglesBefore = builder.triangleCount() + builder.degenerateTrianglesDropped();
        for (unsigned f = 0; f < source.mNumFaces; ++f) {
            progressed();
            const aiFace& face = source.mFaces[f];
            // Points and lines are left out (and counted); Triangulate has cut every polygon into triangles.
            if (face.mNumIndices == 3)
                builder.addTriangle(first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]);
            else
                ++statistics.pointsAndLinesDropped;
        }
        if (builder.triangleCount() + builder.degenerateTrianglesDropped() > trianglesBefore) ++statistics.meshesMerged;
    }
};

// --- normalise ------------------------------------------------------------------------------

// A quarter turn about x, (x, y, z) → (x, z, −y): the file's +z becomes Glint's up (+y). A rotation,
// so normals and tangents turn the same way and stay unit length.
void turnZUpToYUp(Mesh& mesh) {
    auto turn = [](glm::vec3 v) { return glm::vec3(v.x, v.z, -v.y); };
    for (Vertex& vertex : mesh.vertices) {
        vertex.position = turn(vertex.position);
        vertex.normal = turn(vertex.normal);
        vertex.tangent = turn(vertex.tangent);
    }
}

// Centre of the bounding box of all the meshes to the origin, their farthest vertex to distance 1;
// each mesh's statistics get its own bounds. Returns the centre and radius taken out, or why not.
Result<std::pair<glm::vec3, float>> normalise(std::vector<Mesh>& meshes, std::vector<MeshStatistics>& statistics) {
    MeshBounds all;
    for (size_t i = 0; i < meshes.size(); ++i) {
        const MeshBounds bounds = meshBounds(meshes[i]);
        statistics[i].boundsMin = bounds.low;
        statistics[i].boundsMax = bounds.high;
        all.low = glm::min(all.low, bounds.low);
        all.high = glm::max(all.high, bounds.high);
    }
    const glm::vec3 centre = 0.5f * (all.low + all.high);
    float radius = 0.0f;
    for (const Mesh& mesh : meshes)
        for (const Vertex& vertex : mesh.vertices) radius = std::max(radius, glm::distance(vertex.position, centre));
    if (!(radius > 0.0f) || !std::isfinite(radius)) return makeError("the mesh has no extent (all vertices coincide)");
    for (Mesh& mesh : meshes)
        for (Vertex& vertex : mesh.vertices) vertex.position = (vertex.position - centre) / radius;
    return std::pair{centre, radius};
}

// --- entry points ---------------------------------------------------------------------------

// OBJ and glTF are read whole by Glint's own checks first (mesh_file_checks.h).
bool needsWholeFileCheck(const std::string& extension) { return extension == "obj" || extension == "gltf" || extension == "glb"; }

// `meshFile`: the file the bytes are, "" for bytes in memory.
std::optional<Diagnostic> checkWholeFile(std::string_view bytes, const std::string& extension, const std::string& meshFile,
                                         const std::string& name) {
    if (extension == "obj") return checkObjText(bytes, name);
    return checkGltfIndices(bytes, extension == "glb", meshFile, name);
}

using ReadFunction = std::function<const aiScene*(Assimp::Importer&, unsigned flags)>;

// `format`: the extension, lower case, without the dot; `meshFile`: the file read, "" for bytes in
// memory; `splitParts`: one part per mesh instance, else one part holding them all.
// The file as assimp reads it, checked (checkMesh) and triangulated where it has polygons.
// Triangulate is the only step asked of assimp: welding, normals, tangents and the checks are
// Glint's own (checkMesh, MeshBuilder), the same for every format.
Result<const aiScene*> readCheckedScene(const ReadFunction& read, Assimp::Importer& importer, const ProgressRelay& relay,
                                        const MeshIoSystem& files, const std::string& name) {
    const aiScene* scene = read(importer, 0);
    if (relay.cancelled()) return makeError(kCancelledMessage, {name});
    if (!scene) return importError(name, importer.GetErrorString(), files);
    if (!scene->mRootNode || scene->mNumMeshes == 0 || !scene->mMeshes) return makeError("cannot load mesh: the file holds no triangles", {name});
    bool hasPolygons = false;
    for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
        if (!scene->mMeshes[i]) return makeError("cannot load mesh: mesh " + std::to_string(i) + " is missing", {name});
        if (auto error = checkMesh(*scene->mMeshes[i], i, name, hasPolygons)) return *error;
    }
    if (!hasPolygons) return scene;
    scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
    if (relay.cancelled()) return makeError(kCancelledMessage, {name});
    if (!scene) return importError(name, importer.GetErrorString(), files);
    return scene;
}

// The whole file's statistics, counted before parts without triangles are left out (what they
// dropped counts); an error when no triangle is left.
Result<MeshStatistics> wholeFileStatistics(std::vector<Merger::Part>& parts, const std::string& name) {
    MeshStatistics whole;
    size_t trianglesKept = 0;
    for (Merger::Part& part : parts) {
        part.statistics.degenerateTrianglesDropped = part.builder.degenerateTrianglesDropped();
        trianglesKept += part.builder.triangleCount();
        whole.hadNormals = whole.hadNormals || part.statistics.hadNormals;
        whole.hadUvs = whole.hadUvs || part.statistics.hadUvs;
        whole.degenerateTrianglesDropped += part.statistics.degenerateTrianglesDropped;
        whole.pointsAndLinesDropped += part.statistics.pointsAndLinesDropped;
        whole.meshesMerged += part.statistics.meshesMerged;
    }
    if (trianglesKept > 0) return whole;
    return makeError(whole.degenerateTrianglesDropped > 0 ? "cannot load mesh: every triangle has zero area (" +
                                                                std::to_string(whole.degenerateTrianglesDropped) + " dropped)"
                                                          : "cannot load mesh: the file holds no triangles",
                     {name});
}

// Each part's mesh (progress 0.9 to 0.99), turned Y-up; none when the user cancelled.
std::optional<std::vector<Mesh>> buildParts(std::vector<Merger::Part>& parts, ProgressRelay& relay, MeshUpAxis upAxis) {
    std::vector<Mesh> meshes;
    for (size_t i = 0; i < parts.size(); ++i) {
        const float done = static_cast<float>(i), count = static_cast<float>(parts.size());
        std::optional<Mesh> mesh = parts[i].builder.build([&](float fraction) { return relay.offer(0.9f + 0.09f * (done + fraction) / count); });
        if (!mesh) return std::nullopt;
        if (upAxis == MeshUpAxis::Z) turnZUpToYUp(*mesh);
        meshes.push_back(std::move(*mesh));
    }
    return meshes;
}

// The parts with their statistics, and the whole file's sums and bounds.
void addParts(std::vector<Mesh>& meshes, std::vector<MeshStatistics>& statistics, const std::vector<Merger::Part>& parts,
              double seconds, ImportedParts& imported) {
    imported.statistics.loadSeconds = seconds;
    imported.statistics.boundsMin = glm::vec3(std::numeric_limits<float>::max());
    imported.statistics.boundsMax = glm::vec3(-std::numeric_limits<float>::max());
    for (size_t i = 0; i < meshes.size(); ++i) {
        statistics[i].vertexCount = meshes[i].vertices.size();
        statistics[i].triangleCount = meshes[i].triangleCount();
        statistics[i].loadSeconds = seconds;
        imported.statistics.vertexCount += statistics[i].vertexCount;
        imported.statistics.triangleCount += statistics[i].triangleCount;
        imported.statistics.boundsMin = glm::min(imported.statistics.boundsMin, statistics[i].boundsMin);
        imported.statistics.boundsMax = glm::max(imported.statistics.boundsMax, statistics[i].boundsMax);
        imported.parts.push_back({parts[i].name, parts[i].materialIndex, parts[i].materialName,
                                  ImportedMesh{std::make_shared<const Mesh>(std::move(meshes[i])), statistics[i]}});
    }
}

Result<ImportedParts> importWith(const ReadFunction& read, const std::string& name, const std::string& meshFile,
                                 const std::string& format, const MeshImportOptions& options, const MeshImportProgress& progress,
                                 bool splitParts) {
    const auto start = std::chrono::steady_clock::now();
    if (!(options.smoothingAngleDegrees >= 0.0f && options.smoothingAngleDegrees <= 180.0f))
        return makeError("smoothing angle must be in [0°, 180°]", {name});
    Assimp::Importer importer;
    auto* relay = new ProgressRelay(progress);
    importer.SetProgressHandler(relay);  // the importer owns and deletes it
    auto* files = new MeshIoSystem(meshFile);
    importer.SetIOHandler(files);  // the importer owns and deletes it too
    try {
        auto scene = readCheckedScene(read, importer, *relay, *files, name);
        if (!scene) return scene.error();
        Merger merger{**scene, *relay, name, format == "stl", options.smoothingAngleDegrees, splitParts, {}};
        merger.run();
        if (merger.error) return *merger.error;
        importer.FreeScene();  // everything is in the builders now
#ifdef __GLIBC__
        malloc_trim(0);  // hands the scene's many small blocks back to the system (peak memory)
#endif
        auto whole = wholeFileStatistics(merger.parts, name);
        if (!whole) return whole.error();
        std::erase_if(merger.parts, [](const Merger::Part& part) { return part.builder.triangleCount() == 0; });
        auto meshes = buildParts(merger.parts, *relay, options.upAxis);
        if (!meshes) return makeError(kCancelledMessage, {name});
        std::vector<MeshStatistics> statistics;
        for (const Merger::Part& part : merger.parts) statistics.push_back(part.statistics);
        auto frame = normalise(*meshes, statistics);
        if (!frame) return makeError("cannot load mesh: " + frame.error().message, {name});
        relay->report(1.0f);
        ImportedParts imported{{}, *whole, frame->first, frame->second};
        addParts(*meshes, statistics, merger.parts, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), imported);
        return imported;
    } catch (const CancelImport&) {
        return makeError(kCancelledMessage, {name});
    } catch (const std::bad_alloc&) {
        return makeError("cannot load mesh: out of memory (the mesh needs more memory than is free): close other programs or load a simplified mesh", {name});
    } catch (const std::exception& error) {
        return importError(name, error.what(), *files);
    }
}

// A PLY of triangle strips, rewritten with faces (ply_strips.h), read from memory.
Result<ImportedParts> importStrips(std::string_view bytes, const std::string& name, const MeshImportOptions& options,
                                   const MeshImportProgress& progress, bool splitParts) {
    auto faces = plyStripsToFaces(bytes, name);
    if (!faces) return faces.error();
    return importWith(
        [&](Assimp::Importer& importer, unsigned flags) {
            return importer.ReadFileFromMemory(faces->data(), faces->size(), flags, "ply");
        },
        name, "", "ply", options, progress, splitParts);
}

Result<ImportedParts> importFile(const std::string& path, const MeshImportOptions& options, const MeshImportProgress& progress,
                                 bool splitParts) {
    std::error_code code;
    const auto status = std::filesystem::status(path, code);
    if (code || !std::filesystem::exists(status)) return makeError("cannot load mesh: no such file", {path});
    if (!std::filesystem::is_regular_file(status)) return makeError("cannot load mesh: not a regular file", {path});
    if (std::filesystem::file_size(path, code) == 0) return makeError("cannot load mesh: the file is empty", {path});
    std::ifstream file(path, std::ios::binary);
    std::string start(4096, '\0');
    file.read(start.data(), static_cast<std::streamsize>(start.size()));
    start.resize(static_cast<size_t>(file.gcount()));
    if (auto error = checkPlyHeader(start, file.eof(), path)) return *error;
    if (!isMeshFile(path))
        return makeError("cannot load mesh: unknown extension '." + lowerExtension(path) +
                             "' (Glint reads .obj, .ply, .stl, .gltf, .glb, .fbx)",
                         {path});
    if (plyHasTristrips(start)) {  // assimp would read each strip as one polygon: Glint makes them faces
        auto bytes = readTextFile(path);
        if (!bytes) return bytes.error();
        return importStrips(*bytes, path, options, progress, splitParts);
    }
    if (const std::string extension = lowerExtension(path); needsWholeFileCheck(extension)) {
        auto bytes = readTextFile(path);  // reads bytes as they are
        if (!bytes) return bytes.error();
        if (auto error = checkWholeFile(*bytes, extension, path, path))
            return *error;
    }
    return importWith([&](Assimp::Importer& importer, unsigned flags) { return importer.ReadFile(path, flags); }, path,
                      path, lowerExtension(path), options, progress, splitParts);
}

// The one part of an import made whole.
Result<ImportedMesh> wholeMesh(Result<ImportedParts> imported) {
    if (!imported) return imported.error();
    return std::move(imported->parts.front().mesh);
}

}  // namespace

Result<ImportedMesh> importMesh(const std::string& path, const MeshImportOptions& options, const MeshImportProgress& progress) {
    return wholeMesh(importFile(path, options, progress, false));
}

Result<ImportedParts> importMeshParts(const std::string& path, const MeshImportOptions& options,
                                      const MeshImportProgress& progress) {
    return importFile(path, options, progress, true);
}

Result<ImportedMesh> importMeshPart(const std::string& path, const MeshImportOptions& options, int part) {
    // The parts of the file read last, held weakly: alive while a scene holds them, never kept for it.
    struct Remembered {
        std::string path;
        float smoothingAngleDegrees;
        MeshUpAxis upAxis;
        std::filesystem::file_time_type written;
        std::vector<std::weak_ptr<const Mesh>> meshes;
        std::vector<MeshStatistics> statistics;
    };
    static std::mutex mutex;
    static Remembered remembered;
    std::error_code error;
    const auto written = std::filesystem::last_write_time(path, error);
    std::lock_guard lock(mutex);
    const bool same = !error && remembered.path == path && remembered.written == written &&
                      remembered.smoothingAngleDegrees == options.smoothingAngleDegrees && remembered.upAxis == options.upAxis;
    if (same && part >= 0 && part < static_cast<int>(remembered.meshes.size()))
        if (auto mesh = remembered.meshes[part].lock()) return ImportedMesh{mesh, remembered.statistics[part]};
    auto imported = importMeshParts(path, options);
    if (!imported) return imported.error();
    if (part < 0 || part >= static_cast<int>(imported->parts.size()))
        return makeError("cannot load mesh: the file has " + std::to_string(imported->parts.size()) + " parts, numbered from 0; there is no part " +
                             std::to_string(part),
                         {path});
    remembered = {path, options.smoothingAngleDegrees, options.upAxis, written, {}, {}};
    for (const ImportedPart& each : imported->parts) {
        remembered.meshes.push_back(each.mesh.mesh);
        remembered.statistics.push_back(each.mesh.statistics);
    }
    return imported->parts[part].mesh;
}

Result<ImportedMesh> importMeshFromMemory(const void* data, size_t size, const std::string& formatHint,
                                          const std::string& name, const MeshImportOptions& options,
                                          const MeshImportProgress& progress) {
    if (size == 0) return makeError("cannot load mesh: the data is empty", {name});
    if (auto error = checkPlyHeader({static_cast<const char*>(data), std::min<size_t>(size, 4096)}, size <= 4096, name))
        return *error;
    if (plyHasTristrips({static_cast<const char*>(data), std::min<size_t>(size, 4096)}))
        return wholeMesh(importStrips({static_cast<const char*>(data), size}, name, options, progress, false));
    if (const std::string extension = lowerExtension("data." + formatHint); needsWholeFileCheck(extension))
        if (auto error = checkWholeFile({static_cast<const char*>(data), size}, extension, "", name)) return *error;
    return wholeMesh(importWith(
        [&](Assimp::Importer& importer, unsigned flags) {
            return importer.ReadFileFromMemory(data, size, flags, formatHint.c_str());
        },
        name, "", lowerExtension("data." + formatHint), options, progress, false));
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
