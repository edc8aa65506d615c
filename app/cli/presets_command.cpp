// `glint presets` (see commands.h).
#include "cli/commands.h"

#include <cstdio>
#include <memory>
#include <string>

#include "brdf/presets.h"
#include "cli/command_line.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

void listPresets() {
    std::printf("%-18s %-11s %-16s %s\n", "NAME", "CATEGORY", "MODEL", "SOURCE");
    for (const Preset& preset : allPresets())
        std::printf("%-18s %-11s %-16s %s\n", preset.name, preset.category, modelInfo(preset.model).id, preset.source);
}

}  // namespace

void addPresetsCommand(CLI::App& glint) {
    auto name = std::make_shared<std::string>(), output = std::make_shared<std::string>();
    CLI::App* command = addCommand(glint, "presets", "list the material presets, or write one as a material file", [name, output] {
        if (name->empty()) {
            listPresets();
            return 0;
        }
        if (output->empty()) return usageError("presets", "expected NAME -o FILE.json");
        const Preset* preset = findPreset(*name);
        if (!preset) {
            std::string names;
            for (const Preset& known : allPresets()) names += std::string(names.empty() ? "" : ", ") + known.name;
            return usageError("presets", "unknown preset '" + *name + "' (known presets: " + names + ")");
        }
        if (Status written = saveMaterial(preset->material(), *output); !written)
            return commandFailed("presets", written.error().format());
        std::printf("glint: wrote preset '%s' (%s; %s) to %s\n", preset->name, modelInfo(preset->model).id, preset->source,
                    output->c_str());
        return 0;
    });
    command->add_option("NAME", *name, "the preset to write (none: list them all)");
    command->add_option("-o,--output", *output, "the material file to write")->type_name("FILE.json");
}

}  // namespace glint
