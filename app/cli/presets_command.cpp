// `glint presets` (see presets_command.h).
#include "cli/presets_command.h"

#include <cstdio>

#include "brdf/presets.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

constexpr const char* kUsage =
    "usage: glint presets                  list the material presets and their sources\n"
    "       glint presets NAME -o FILE.json  write preset NAME as a material file\n";

int usageError(const std::string& message) {
    std::fprintf(stderr, "glint presets: %s\n%s", message.c_str(), kUsage);
    return 2;
}

void listPresets() {
    std::printf("%-18s %-11s %-16s %s\n", "NAME", "CATEGORY", "MODEL", "SOURCE");
    for (const Preset& preset : allPresets())
        std::printf("%-18s %-11s %-16s %s\n", preset.name, preset.category, modelInfo(preset.model).id, preset.source);
}

}  // namespace

int runPresetsCommand(const std::vector<std::string>& arguments) {
    if (arguments.empty()) {
        listPresets();
        return 0;
    }
    if (arguments[0] == "-h" || arguments[0] == "--help") {
        std::printf("%s", kUsage);
        return 0;
    }
    if (arguments.size() != 3 || (arguments[1] != "-o" && arguments[1] != "--output"))
        return usageError("expected NAME -o FILE.json");
    const Preset* preset = findPreset(arguments[0]);
    if (!preset) {
        std::string names;
        for (const Preset& known : allPresets()) names += std::string(names.empty() ? "" : ", ") + known.name;
        return usageError("unknown preset '" + arguments[0] + "' (known presets: " + names + ")");
    }
    if (Status written = saveMaterial(preset->material(), arguments[2]); !written) {
        std::fprintf(stderr, "glint presets: %s\n", written.error().format().c_str());
        return 2;
    }
    std::printf("glint: wrote preset '%s' (%s; %s) to %s\n", preset->name, modelInfo(preset->model).id, preset->source,
                arguments[2].c_str());
    return 0;
}

}  // namespace glint
