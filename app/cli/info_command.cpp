// `glint info` (see commands.h).
#include "cli/commands.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "brdf/model_registry.h"
#include "cli/command_line.h"
#include "cli/render_input.h"
#include "geometry/mesh_import.h"
#include "interchange/asset.h"
#include "interchange/bparam_file.h"
#include "interchange/custom_brdf.h"
#include "interchange/import_formats.h"
#include "interchange/measured_brdf.h"
#include "light/light_type_name.h"
#include "scene/scene_json.h"
#include "util/file_io.h"
#include "util/text.h"

namespace glint {
namespace {

void printMaterials(const std::vector<const Material*>& materials) {
    std::printf("materials (%zu):\n", materials.size());
    for (size_t i = 0; i < materials.size(); ++i)
        std::printf("  %zu '%s' (%s)\n", i, materials[i]->name.c_str(),
                    std::visit(Overloaded{[](const AnalyticMaterial& analytic) { return std::string(modelInfo(analytic.model).id); },
                                          [](const CustomMaterial& custom) { return custom.brdf->displayName; },
                                          [](const MeasuredMaterial& measured) { return measured.brdf->displayName; }},
                               materials[i]->kind)
                        .c_str());
}

// Where a rendered texture's values come from: its image file (or the image inside a glTF), or its kind.
std::string textureSourceText(const MaterialTexture& texture) {
    constexpr const char* kProcedural[] = {"", "checker", "marble", "wood"};  // order of TextureKind
    if (texture.kind != TextureKind::Image) return std::string(kProcedural[static_cast<int>(texture.kind)]) + " (procedural)";
    if (texture.gltfImage < 0) return texture.file;
    return "image " + std::to_string(texture.gltfImage) + " inside " + texture.file;
}

void printLights(const std::vector<Light>& lights) {
    if (lights.empty()) return;
    std::printf("lights (%zu):\n", lights.size());
    for (size_t i = 0; i < lights.size(); ++i) std::printf("  %zu '%s' (%s)\n", i, lights[i].name.c_str(), lightTypeName(lights[i].type));
}

void printParams(const std::vector<BrdfFileParam>& params) {
    std::printf("parameters (%zu):\n", params.size());
    for (const BrdfFileParam& param : params) {
        const float* value = param.defaultValue.data();
        std::printf("  %s\n", formatBrdfParamLine(param, value).c_str());
    }
}

void printWarnings(const std::vector<Diagnostic>& warnings) {
    if (warnings.empty()) return;
    std::printf("warnings (%zu):\n", warnings.size());
    for (const Diagnostic& warning : warnings) std::printf("  %s\n", warning.format().c_str());
}

// The parts an asset opens as (interchange/asset.h): each a scene object with its material.
void printParts(const Asset& asset) {
    std::printf("parts (%zu):\n", asset.objects.size());
    for (size_t i = 0; i < asset.objects.size(); ++i) {
        const SceneObject& part = asset.objects[i];
        const auto* mesh = std::get_if<MeshShape>(&part.shape);
        std::printf("  %zu '%s': material '%s', %zu triangles\n", i, part.name.c_str(), asset.materials.at(part.materialIndex).name.c_str(),
                    mesh ? mesh->statistics.triangleCount : size_t{0});
    }
}

// An OBJ as the editor opens it: its parts, each with its own material of the .mtl.
int describeObjAsset(const std::string& path) {
    auto asset = loadAsset(path);
    if (!asset) return commandFailed("info", asset.error().format());
    std::printf("%s: Wavefront OBJ asset: %s; %s\n", path.c_str(), meshStatisticsText(asset->statistics).c_str(),
                assetSummary(*asset).c_str());
    printParts(*asset);
    std::vector<const Material*> materials;
    for (const Material& material : asset->materials) materials.push_back(&material);
    printMaterials(materials);
    printWarnings(asset->warnings);
    return 0;
}

// Lists what `path` holds; the exit code.
int describeFile(const std::string& path) {
    if (isBrdfFilePath(path)) {
        auto file = loadBrdfFile(path);
        if (!file) return commandFailed("info", file.error().format());
        std::printf("%s: BRDF Explorer analytic BRDF (GLSL shader at line %d)\n", path.c_str(), file->shaderLine);
        printParams(file->params);
        printWarnings(file->warnings);
        return 0;
    }
    if (isBparamFilePath(path)) {
        auto text = readTextFile(path);
        auto file = text ? parseBparamFile(*text, path) : Result<BparamFile>(text.error());
        if (!file) return commandFailed("info", file.error().format());
        auto brdf = findBparamBrdf(*file, path);
        std::printf("%s: BRDF Explorer parameter values for %s (%s)\n", path.c_str(),
                    file->brdfPath.empty() ? "(no .brdf named)" : file->brdfPath.c_str(),
                    (brdf ? "found: " + *brdf : "not read: " + brdf.error().message).c_str());
        printParams(file->params);
        printWarnings(file->warnings);
        return 0;
    }
    std::optional<Diagnostic> materialsError;  // a glTF whose materials are not read is listed as a mesh below
    if (const ImportFormat* format = findImportFormat(path)) {
        auto file = format->load(path);
        if (!file && isMeshFile(path)) materialsError = file.error();
        if (file || !isMeshFile(path)) {
            if (!file) return commandFailed("info", file.error().format());
            std::printf("%s: %s\n", path.c_str(), format->description);
            std::vector<const Material*> materials;
            for (const ImportedMaterial& material : file->materials) materials.push_back(&material.material);
            printMaterials(materials);
            for (size_t i = 0; i < file->materials.size(); ++i) {
                if (const AnalyticMaterial* analytic = file->materials[i].material.analytic())
                    for (const MaterialTexture& texture : analytic->textures)
                        std::printf("  %zu renders texture %s: %s\n", i, texture.parameter.c_str(), textureSourceText(texture).c_str());
                for (const TextureReference& texture : file->materials[i].textures)
                    std::printf("  %zu names texture %s: %s (not rendered)\n", i, texture.slot.c_str(), texture.path.c_str());
            }
            printLights(file->lights);
            if (!file->meshNames.empty()) {  // an asset: its parts, or the mesh names and why they do not open
                if (auto asset = loadAsset(path)) {
                    printParts(*asset);
                } else {
                    std::printf("meshes (%zu), not opened: %s\n", file->meshNames.size(), asset.error().format().c_str());
                    for (size_t i = 0; i < file->meshNames.size(); ++i) std::printf("  %zu '%s'\n", i, file->meshNames[i].c_str());
                }
            }
            printWarnings(allWarnings(*file));
            return 0;
        }
    }
    if (lowerExtension(path) == "obj") return describeObjAsset(path);
    if (isMeshFile(path)) {
        auto mesh = importMesh(path);
        if (!mesh) return commandFailed("info", (materialsError ? *materialsError : mesh.error()).format());
        std::printf("%s: mesh: %s\n", path.c_str(), meshStatisticsText(mesh->statistics).c_str());
        if (materialsError) std::printf("materials not read: %s\n", materialsError->format().c_str());
        return 0;
    }
    auto text = readTextFile(path);
    if (!text) return commandFailed("info", text.error().format());
    if (text->find("\"glint-material\"") != std::string::npos) {
        auto material = parseMaterial(*text, path);
        if (!material) return commandFailed("info", material.error().format());
        std::printf("%s: Glint material\n", path.c_str());
        printMaterials({&*material});
        return 0;
    }
    auto scene = parseScene(*text, path);
    if (!scene) return commandFailed("info", scene.error().format());
    std::printf("%s: Glint scene\n", path.c_str());
    std::vector<const Material*> materials;
    for (const Material& material : scene->materials) materials.push_back(&material);
    printMaterials(materials);
    std::printf("objects (%zu):\n", scene->objects.size());
    for (size_t i = 0; i < scene->objects.size(); ++i)
        std::printf("  %zu '%s' (material %d)\n", i, scene->objects[i].name.c_str(), scene->objects[i].materialIndex);
    printLights(scene->lights);
    return 0;
}

}  // namespace

void addInfoCommand(CLI::App& glint) {
    auto path = std::make_shared<std::string>();
    addCommand(glint, "info", "list what a file holds (materials, meshes, lights, parameters) and its warnings",
               [path] { return describeFile(*path); })
        ->add_option("FILE", *path,
                     "a .mtl, .gltf or .glb (materials, lights, meshes, by index and name: `glint render --material "
                     "NAME|INDEX` chooses one), a MERL .binary, a mesh .obj|.ply|.stl|.fbx (vertices, triangles, what was "
                     "dropped), a BRDF Explorer .brdf or .bparam (parameters), or a scene or material .json; then the "
                     "warnings opening it gives. Exit 0 when it loads, 2 when not.")
        ->required();
}

}  // namespace glint
