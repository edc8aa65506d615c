// `glint export` (see commands.h).
#include "cli/commands.h"

#include <cstdio>
#include <memory>
#include <string>

#include "cli/command_line.h"
#include "interchange/export_formats.h"
#include "interchange/import_formats.h"
#include "scene/scene_json.h"
#include "util/file_io.h"

namespace glint {
namespace {

// The input's materials and lights, whatever its format.
Result<ImportedFile> readInput(const std::string& path) {
    if (const ImportFormat* format = findImportFormat(path)) return format->load(path);
    auto text = readTextFile(path);
    if (!text) return text.error();
    ImportedFile file;
    if (text->find("\"glint-material\"") != std::string::npos) {
        auto material = parseMaterial(*text, path);
        if (!material) return material.error();
        file.materials.push_back({std::move(*material), {}});
        return file;
    }
    auto scene = parseScene(*text, path);
    if (!scene) return scene.error();
    for (const SceneObject& object : scene->objects) {  // objects' materials first, in object order
        bool seen = false;
        for (const ImportedMaterial& kept : file.materials) seen = seen || kept.material.name == scene->materials[object.materialIndex].name;
        if (!seen) file.materials.push_back({scene->materials[object.materialIndex], {}});
    }
    file.lights = scene->lights;
    return file;
}

struct ExportOptions {
    std::string input, output, material;  // IN, -o OUT, --material NAME|INDEX
};

int runExport(const ExportOptions& options) {
    if (!isExportPath(options.output))
        return commandFailed("export", "the output must end in .mtl, .gltf or .mtlx (got '" + options.output + "')");
    auto file = readInput(options.input);
    if (!file) return commandFailed("export", file.error().format());
    if (!options.material.empty()) {
        auto chosen = chooseMaterial(*file, options.material, options.input);
        if (!chosen) return commandFailed("export", chosen.error().format());
        for (const Diagnostic& warning : warningsFor(*file, *chosen)) std::fprintf(stderr, "glint export: %s\n", warning.format().c_str());
        file->materials = {file->materials[*chosen]};
    } else {
        for (const Diagnostic& warning : allWarnings(*file)) std::fprintf(stderr, "glint export: %s\n", warning.format().c_str());
    }
    if (file->materials.empty()) return commandFailed("export", options.input + ": no material to export");
    auto written = exportMaterials(file->materials, file->lights, options.output);
    if (!written) return commandFailed("export", written.error().message);
    for (const Diagnostic& warning : written->warnings) std::fprintf(stderr, "glint export: %s\n", warning.format().c_str());
    if (Status saved = writeFileAtomically(options.output, written->text); !saved)
        return commandFailed("export", saved.error().format());
    std::printf("glint: wrote %s\n", options.output.c_str());
    return 0;
}

}  // namespace

void addExportCommand(CLI::App& glint) {
    auto options = std::make_shared<ExportOptions>();
    CLI::App* command = addCommand(glint, "export", "write a material (file, scene, .mtl, .gltf or .mtlx) as .mtl, glTF or MaterialX",
                                   [options] { return runExport(*options); });
    command->add_option("IN", options->input,
                        "a material file, a scene (its materials; for glTF the first object's material and the scene's "
                        "lights), or a .mtl / .gltf / .mtlx file")
        ->required();
    command->add_option("-o,--output", options->output,
                        ".mtl: every material as a Wavefront library; .gltf: a UV sphere carrying the material, the "
                        "lights as KHR_lights_punctual, the buffer embedded (base64); .mtlx: every material as a MaterialX 1.39 "
                        "open_pbr_surface")
        ->required()
        ->type_name("OUT.mtl|OUT.gltf|OUT.mtlx");
    command->add_option("--material", options->material, "only that material of IN (`glint info IN` lists them), with its warnings")
        ->type_name("NAME|INDEX");
}

}  // namespace glint
