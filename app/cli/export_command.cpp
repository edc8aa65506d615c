// `glint export` (see export_command.h).
#include "cli/export_command.h"

#include <cstdio>

#include "interchange/export_formats.h"
#include "interchange/import_formats.h"
#include "scene/scene_json.h"
#include "util/file_io.h"

namespace glint {
namespace {

constexpr const char* kUsage =
    "usage: glint export IN -o OUT.mtl|OUT.gltf|OUT.mtlx [--material NAME|INDEX]\n"
    "  IN     a material file, a scene (its materials; for glTF the first object's material and\n"
    "         the scene's lights), or a .mtl / .gltf file\n"
    "  OUT    .mtl: every material as a Wavefront library; .gltf: a UV sphere carrying the\n"
    "         material, the lights as KHR_lights_punctual, the buffer embedded (base64);\n"
    "         .mtlx: every material as a MaterialX 1.39 open_pbr_surface\n"
    "  --material NAME|INDEX  only that material of IN (`glint info IN` lists them), with its warnings\n";

int fail(const std::string& message) {
    std::fprintf(stderr, "glint export: %s\n", message.c_str());
    return 2;
}

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

}  // namespace

int runExportCommand(const std::vector<std::string>& arguments) {
    if (arguments.size() == 1 && (arguments[0] == "-h" || arguments[0] == "--help")) {
        std::printf("%s", kUsage);
        return 0;
    }
    const bool chooses = arguments.size() == 5 && arguments[3] == "--material";
    if ((arguments.size() != 3 && !chooses) || (arguments[1] != "-o" && arguments[1] != "--output")) {
        std::fprintf(stderr, "glint export: expected IN -o OUT.mtl|OUT.gltf|OUT.mtlx [--material NAME|INDEX]\n%s", kUsage);
        return 2;
    }
    const std::string& input = arguments[0];
    const std::string& output = arguments[2];
    if (!isExportPath(output)) return fail("the output must end in .mtl, .gltf or .mtlx (got '" + output + "')");
    auto file = readInput(input);
    if (!file) return fail(file.error().format());
    if (chooses) {
        auto chosen = chooseMaterial(*file, arguments[4], input);
        if (!chosen) return fail(chosen.error().format());
        for (const Diagnostic& warning : warningsFor(*file, *chosen)) std::fprintf(stderr, "glint export: %s\n", warning.format().c_str());
        file->materials = {file->materials[*chosen]};
    } else {
        for (const Diagnostic& warning : allWarnings(*file)) std::fprintf(stderr, "glint export: %s\n", warning.format().c_str());
    }
    if (file->materials.empty()) return fail(input + ": no material to export");
    auto written = exportMaterials(file->materials, file->lights, output);
    if (!written) return fail(written.error().message);
    for (const Diagnostic& warning : written->warnings) std::fprintf(stderr, "glint export: %s\n", warning.format().c_str());
    if (Status saved = writeFileAtomically(output, written->text); !saved) return fail(saved.error().format());
    std::printf("glint: wrote %s\n", output.c_str());
    return 0;
}

}  // namespace glint
