// `glint models` (see commands.h).
#include "cli/commands.h"

#include <cstdio>
#include <memory>

#include "brdf/model_docs.h"
#include "brdf/model_registry.h"
#include "cli/command_line.h"

namespace glint {

void addModelsCommand(CLI::App& glint) {
    auto markdown = std::make_shared<bool>(false);
    CLI::App* command = addCommand(glint, "models", "list the BRDF models, or write their parameter reference", [markdown] {
        if (*markdown) {
            std::printf("%s", modelsMarkdown(allModels()).c_str());
            return 0;
        }
        for (const ModelInfo& model : allModels()) std::printf("%-16s %s\n", model.id, model.label);
        return 0;
    });
    command->add_flag("--markdown", *markdown, "write the models-and-parameters reference (docs/models.md) as Markdown");
}

}  // namespace glint
