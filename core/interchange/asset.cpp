// An asset file opened whole (see asset.h). Sections: materials · loading · the stage.
#include "interchange/asset.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>

#include <nlohmann/json.hpp>

#include "interchange/glb.h"
#include "interchange/import_formats.h"
#include "interchange/obj_material.h"
#include "scene/preview_stage.h"
#include "util/file_io.h"
#include "util/text.h"

namespace glint {
namespace {

// --- materials ------------------------------------------------------------------------------

// The materials a file offers its parts, and which one a part names.
struct FileMaterials {
    std::vector<ImportedMaterial> materials;
    std::vector<Diagnostic> warnings;  // about the file
    bool byName = false;               // OBJ: a part names its material; glTF: by index, in the file's order

    std::optional<size_t> of(const ImportedPart& part) const {
        if (!byName) return part.materialIndex < materials.size() ? std::optional(size_t{part.materialIndex}) : std::nullopt;
        for (size_t i = 0; i < materials.size(); ++i)
            if (materials[i].material.name == part.materialName) return i;
        return std::nullopt;
    }
};

Result<FileMaterials> readFileMaterials(const std::string& path, std::vector<Light>& lights) {
    FileMaterials file;
    if (lowerExtension(path) == "obj") {
        ObjMaterialLibraries libraries = readObjMaterialLibraries(path);
        file.materials = std::move(libraries.materials);
        file.warnings = std::move(libraries.warnings);
        file.byName = true;
        return file;
    }
    auto imported = findImportFormat(path)->load(path);
    if (!imported) return imported.error();
    file.materials = std::move(imported->materials);
    file.warnings = std::move(imported->warnings);
    lights = std::move(imported->lights);
    return file;
}

// `name`, or `name 2`, `name 3`, … : the first not in `taken` (a scene names its materials, and the
// editor lists its objects, by name).
std::string uniqueName(const std::string& name, const std::vector<std::string>& taken) {
    std::string candidate = name;
    for (int suffix = 2; std::find(taken.begin(), taken.end(), candidate) != taken.end(); ++suffix)
        candidate = name + " " + std::to_string(suffix);
    return candidate;
}

// A light of the file moved into the asset's frame (turned up as the meshes are, centred, divided
// by the file's radius), its power divided by radius² so that what it gives the asset (Φ/4πd²)
// stays what the file meant.
Light intoAssetFrame(Light light, const ImportedParts& parts, MeshUpAxis upAxis) {
    if (upAxis == MeshUpAxis::Z) {  // as geometry/mesh_import.cpp turns the meshes: (x, y, z) → (x, z, −y)
        light.position = {light.position.x, light.position.z, -light.position.y};
        light.direction = {light.direction.x, light.direction.z, -light.direction.y};
    }
    light.position = (light.position - parts.fileCentre) / parts.fileRadius;
    light.power /= parts.fileRadius * parts.fileRadius;
    return light;
}

}  // namespace

// --- loading --------------------------------------------------------------------------------

bool isAssetFile(const std::string& path) {
    const std::string extension = lowerExtension(path);
    if (extension == "obj") return true;
    if (extension != "gltf" && extension != "glb") return false;
    // Only the JSON is read here: loadAsset reads the rest once. Unreadable: the reader says why.
    std::optional<std::string> text = extension == "glb" ? readGlbJsonChunk(path) : std::nullopt;
    if (extension == "gltf")
        if (auto read = readTextFile(path)) text = std::move(*read);
    if (!text) return false;
    const auto root = nlohmann::json::parse(*text, nullptr, false);
    return root.is_object() && root.contains("meshes") && root["meshes"].is_array() && !root["meshes"].empty();
}

Result<Asset> loadAsset(const std::string& path, const MeshImportOptions& options, const MeshImportProgress& progress) {
    std::vector<Light> fileLights;
    auto file = readFileMaterials(path, fileLights);
    if (!file) return file.error();
    if (fileLights.size() + 1 > static_cast<size_t>(kMaxLights))  // beside the stage's key light
        return makeError("the file's " + std::to_string(fileLights.size()) + " lights and the stage's key light are too many: " +
                             lightLimitExplanation(),
                         {path});
    auto parts = importMeshParts(path, options, progress);
    if (!parts) return parts.error();
    Asset asset;
    asset.warnings = file->warnings;
    asset.statistics = parts->statistics;
    std::map<std::optional<size_t>, int> sceneMaterialOf;  // the file's material (none: the default) → the asset's
    std::vector<std::string> names = {"stage floor"};  // the stage's own material (preview_stage.h)
    const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
    std::vector<std::string> partNames;
    for (size_t i = 0; i < parts->parts.size(); ++i) {
        ImportedPart& part = parts->parts[i];
        const std::optional<size_t> fileMaterial = file->of(part);
        auto [entry, added] = sceneMaterialOf.emplace(fileMaterial, static_cast<int>(asset.materials.size()));
        if (added) {
            Material material = fileMaterial ? file->materials[*fileMaterial].material
                                             : Material::withDefaults("default", BrdfModel::Lambert);
            material.name = uniqueName(material.name, names);
            names.push_back(material.name);
            asset.materials.push_back(std::move(material));
            if (fileMaterial) {
                const std::vector<Diagnostic>& warnings = file->materials[*fileMaterial].warnings;
                asset.warnings.insert(asset.warnings.end(), warnings.begin(), warnings.end());
            }
        }
        MeshShape shape;
        shape.path = shape.resolvedPath = absolute;  // absolute, as the editor's meshes are (util/referenced_path.h)
        shape.part = static_cast<int>(i);
        shape.mesh = std::move(part.mesh.mesh);
        shape.statistics = part.mesh.statistics;
        // A mesh that several nodes place is several parts of one name: "Marker", "Marker 2".
        asset.objects.push_back({uniqueName(part.name, partNames), shape, entry->second, defaultInterpolation(shape)});
        partNames.push_back(asset.objects.back().name);
    }
    for (const Light& light : fileLights) asset.lights.push_back(intoAssetFrame(light, *parts, options.upAxis));
    return asset;
}

// --- the stage ------------------------------------------------------------------------------

Scene assetStage(const Asset& asset, int width, int height) {
    Scene scene = previewStage(asset.materials.empty() ? Material::withDefaults("default", BrdfModel::Lambert) : asset.materials.front(),
                               width, height);
    const SceneObject floor = scene.objects.back();
    const Material floorMaterial = scene.materials[floor.materialIndex];
    const float floorHeight = std::get<PlaneShape>(floor.shape).center.y;
    float lowest = 1.0f;  // of the asset in its unit sphere
    for (const SceneObject& object : asset.objects)
        for (const Vertex& vertex : std::get<MeshShape>(object.shape).mesh->vertices) lowest = std::min(lowest, vertex.position.y);
    const glm::vec3 lift(0.0f, floorHeight - lowest, 0.0f);
    scene.materials = asset.materials;
    scene.objects = asset.objects;
    for (SceneObject& object : scene.objects) std::get<MeshShape>(object.shape).center += lift;
    scene.materials.push_back(floorMaterial);
    scene.objects.push_back(floor);
    scene.objects.back().materialIndex = static_cast<int>(scene.materials.size()) - 1;
    scene.camera.target += lift;
    for (Light light : asset.lights) {
        light.position += lift;
        scene.lights.push_back(light);
    }
    return scene;
}

std::string assetSummary(const Asset& asset) {
    auto count = [](size_t n, const std::string& what) { return std::to_string(n) + " " + what + (n == 1 ? "" : "s"); };
    std::string text = count(asset.objects.size(), "part") + ", " + count(asset.materials.size(), "material");
    if (!asset.lights.empty()) text += ", " + count(asset.lights.size(), "light");
    return text;
}

}  // namespace glint
