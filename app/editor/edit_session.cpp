// EditSession's steps, undo and redo (see edit_session.h). Whether a step changed anything is
// decided on the scenes' JSON form, so a new scene field needs no change here.
#include "editor/edit_session.h"

#include "scene/scene_json.h"

namespace glint {

EditSession::EditSession(Scene scene, std::string path) : scene_(std::move(scene)), path_(std::move(path)) {}

Scene& EditSession::change(std::string_view label) {
    if (!open_) {
        open_ = true;
        openLabel_ = std::string(label);
        openBefore_ = scene_;
    }
    ++revision_;
    return scene_;
}

bool EditSession::settle(bool gestureInProgress) {
    if (!open_ || gestureInProgress) return false;
    open_ = false;
    if (sceneToJson(openBefore_) == sceneToJson(scene_)) return false;  // e.g. dragged and put back
    undo_.push_back(Step{std::move(openLabel_), std::move(openBefore_), scene_, nextStepId_++});
    if (undo_.size() > kMaxUndoSteps) {
        baseStep_ = undo_.front().id;
        undo_.pop_front();
    }
    redo_.clear();
    ++settledRevision_;
    return true;
}

std::string EditSession::undoLabel() const {
    if (open_) return openLabel_;
    return undo_.empty() ? std::string() : undo_.back().label;
}

std::string EditSession::redoLabel() const { return canRedo() ? redo_.back().label : std::string(); }

bool EditSession::undo() {
    settle(false);
    return !undo_.empty() && moveLastStep(undo_, redo_, &Step::before);
}

bool EditSession::redo() { return canRedo() && moveLastStep(redo_, undo_, &Step::after); }

bool EditSession::moveLastStep(std::deque<Step>& from, std::deque<Step>& to, Scene Step::*shown) {
    to.push_back(std::move(from.back()));
    from.pop_back();
    scene_ = to.back().*shown;
    ++revision_;
    ++settledRevision_;
    return true;
}

void EditSession::markSaved(std::string path) {
    settle(false);
    path_ = std::move(path);
    savedStep_ = currentStep();
    ++documentGeneration_;
    ++settledRevision_;  // dirty changed: autosave drops the recovery file, the crash copy empties
}

void EditSession::replace(Scene scene, std::string path, bool dirty) {
    scene_ = std::move(scene);
    path_ = std::move(path);
    open_ = false;
    undo_.clear();
    redo_.clear();
    baseStep_ = nextStepId_++;
    // Recovered work counts as unsaved: its saved state is one no step can reach.
    savedStep_ = dirty ? nextStepId_++ : baseStep_;
    ++documentGeneration_;
    ++replacements_;
    ++revision_;
    ++settledRevision_;
}

void EditSession::completeEnvironment(EnvironmentKind kind, const std::string& file,
                                      const std::shared_ptr<const EnvironmentMap>& map) {
    auto complete = [&](Scene& scene) {
        Environment& environment = scene.environment;
        if (environment.kind == kind && environment.file == file && !environment.map) environment.map = map;
    };
    complete(scene_);
    complete(openBefore_);
    for (std::deque<Step>* steps : {&undo_, &redo_}) {
        for (Step& step : *steps) {
            complete(step.before);
            complete(step.after);
        }
    }
    ++revision_;  // drawn again, with the map
}

}  // namespace glint
