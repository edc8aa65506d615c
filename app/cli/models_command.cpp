// `glint models` (see models_command.h).
#include "cli/models_command.h"

#include <cstdio>

#include "brdf/model_docs.h"
#include "brdf/model_registry.h"

namespace glint {

int runModelsCommand(const std::vector<std::string>& arguments) {
    if (arguments.empty()) {
        for (const ModelInfo& model : allModels()) std::printf("%-16s %s\n", model.id, model.label);
        return 0;
    }
    if (arguments.size() == 1 && arguments[0] == "--markdown") {
        std::printf("%s", modelsMarkdown(allModels()).c_str());
        return 0;
    }
    std::fprintf(stderr, "usage: glint models [--markdown]\n");
    return arguments[0] == "-h" || arguments[0] == "--help" ? 0 : 2;
}

}  // namespace glint
