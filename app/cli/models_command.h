// `glint models [--markdown]`: lists the BRDF models (id, label), or writes the
// models-and-parameters reference (docs/models.md) as Markdown.
#pragma once

namespace CLI {
class App;
}

namespace glint {

// Adds the command to `glint`; its exit code is 0.
void addModelsCommand(CLI::App& glint);

}  // namespace glint
