// Environment maps made on a worker thread (see environment_loading.h).
#include "editor/environment_loading.h"

#include <filesystem>

namespace glint {

EnvironmentLoadJob::EnvironmentLoadJob(EnvironmentKind kind, std::string file)
    : WorkerJob([kind, file](const Progress& progress) { return loadEnvironmentMap(kind, file, progress); }),
      kind_(kind),
      file_(std::move(file)) {}

std::string EnvironmentLoadJob::name() const {
    if (kind_ == EnvironmentKind::File) return std::filesystem::path(file_).filename().string();
    return kEnvironmentKindIds[static_cast<int>(kind_)];
}

void startEnvironmentLoad(EditorState& state, EnvironmentKind kind, const std::string& file) {
    Environment chosen;
    chosen.kind = kind;
    chosen.file = file;
    state.environmentLoad.reset();  // a superseded map: cancelled, its thread joined within a row
    state.environmentLoad = std::make_shared<EnvironmentLoadJob>(kind, absoluteEnvironmentFile(chosen));
}

bool pollEnvironmentLoad(EditorState& state) {
    if (!state.environmentLoad) return false;
    if (!state.environmentLoad->finished()) return true;
    const std::shared_ptr<EnvironmentLoadJob> job = std::move(state.environmentLoad);
    auto map = job->takeResult();
    if (!map) return false;
    if (!map->ok()) {
        if (!isEnvironmentCancellation(map->error()))
            state.errorMessage = "Could not use the environment image; your scene is unchanged.\n\n" + map->error().format();
        return false;
    }
    state.session.settle(false);  // the choice is a step of its own, not part of a drag
    Environment environment = state.session.scene().environment;
    environment.kind = job->kind();
    environment.file = job->file();
    environment.map = std::move(**map);
    state.session.change(job->kind() == EnvironmentKind::File ? "Environment file" : "Environment").environment =
        std::move(environment);
    state.session.settle(false);
    state.statusMessage = "Environment from " + job->name();
    return false;
}

}  // namespace glint
