// `glint models [--markdown]`: lists the BRDF models (id, label), or writes the
// models-and-parameters reference (docs/models.md) as Markdown.
#pragma once

#include <string>
#include <vector>

namespace glint {

// Returns the process exit code: 0 listed, 2 bad arguments.
int runModelsCommand(const std::vector<std::string>& arguments);

}  // namespace glint
