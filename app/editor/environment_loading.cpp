// Environment maps made on a worker thread (see environment_loading.h).
#include "editor/environment_loading.h"

namespace glint {

EnvironmentLoadJob::EnvironmentLoadJob(EnvironmentKind kind, std::string file, bool choice, std::uint64_t replacements)
    : WorkerJob([kind, file](const Progress& progress) { return loadEnvironmentMap(kind, file, progress); }),
      kind(kind),
      file(std::move(file)),
      choice(choice),
      replacements(replacements) {}

void startEnvironmentLoad(EditorState& state, EnvironmentKind kind, const std::string& file) {
    Environment chosen;
    chosen.kind = kind;
    chosen.file = file;
    state.environmentLoad.reset();  // a superseded map: cancelled, its thread joined within a row
    state.environmentLoad = std::make_shared<EnvironmentLoadJob>(kind, absoluteEnvironmentFile(chosen), true,
                                                                 state.session.replacements());
}

namespace {

// An environment map within the scene opened last: one that failed or was cancelled is not made
// again until another scene is opened (EditorState::environmentDeclined).
std::string environmentKey(const EditorState& state, EnvironmentKind kind, const std::string& file) {
    return std::to_string(state.session.replacements()) + ' ' + kEnvironmentKindIds[static_cast<int>(kind)] + ' ' + file;
}

// Keeps the one job on what the scene needs: a choice for a replaced scene is cancelled, and so is
// the map of an environment the scene no longer names; the one it names without a map is started.
void followScene(EditorState& state) {
    const Environment& named = state.session.scene().environment;
    const std::string key = environmentKey(state, named.kind, named.file);
    const bool needed = named.kind != EnvironmentKind::None && !named.map && key != state.environmentDeclined;
    if (const EnvironmentLoadJob* job = state.environmentLoad.get()) {
        const bool wanted = job->choice ? job->replacements == state.session.replacements()
                                          : needed && job->kind == named.kind && job->file == named.file;
        if (!wanted) state.environmentLoad.reset();
    }
    if (!state.environmentLoad && needed)
        state.environmentLoad = std::make_shared<EnvironmentLoadJob>(named.kind, named.file, false, state.session.replacements());
}

}  // namespace

bool pollEnvironmentLoad(EditorState& state) {
    followScene(state);
    if (!state.environmentLoad) return false;
    if (!state.environmentLoad->finished()) return true;
    const std::shared_ptr<EnvironmentLoadJob> job = std::move(state.environmentLoad);
    auto map = job->takeResult();
    if (!map) return false;
    if (!map->ok()) {
        if (!job->choice) state.environmentDeclined = environmentKey(state, job->kind, job->file);
        if (!isEnvironmentCancellation(map->error()))
            state.errorMessage = (job->choice ? "Could not use the environment image; your scene is unchanged.\n\n"
                                                : "Could not use the environment image the scene names; it stays named "
                                                  "(Save keeps it) but lights nothing.\n\n") +
                                 map->error().format();
        return false;
    }
    if (!job->choice) {
        state.session.completeEnvironment(job->kind, job->file, **map);
        return false;
    }
    state.session.settle(false);  // the choice is a step of its own, not part of a drag
    Environment environment = state.session.scene().environment;
    environment.kind = job->kind;
    environment.file = job->file;
    environment.map = std::move(**map);
    state.session.change(job->kind == EnvironmentKind::File ? "Environment file" : "Environment").environment =
        std::move(environment);
    state.session.settle(false);
    state.statusMessage = "Environment from " + environmentName(job->kind, job->file);
    return false;
}

}  // namespace glint
