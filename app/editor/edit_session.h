// EditSession: the one way the editor changes a scene. It owns the scene, groups changes into
// undoable steps (a slider drag is one step), undoes and redoes them, and knows whether the
// scene differs from what was last saved. Snapshot-based: each step keeps the whole scene as it
// was before the step (scenes are a few kB). It does not draw, save files or autosave.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <string>
#include <string_view>

#include "scene/environment.h"
#include "scene/scene.h"

namespace glint {

class EditSession {
public:
    static constexpr size_t kMaxUndoSteps = 256;

    explicit EditSession(Scene scene = defaultScene(), std::string path = {});

    const Scene& scene() const { return scene_; }
    // Where the scene was opened from or last saved to; empty for a new scene.
    const std::string& path() const { return path_; }

    // Returns the scene to change. The change joins the open step, which is named `label` and
    // remembers the scene as it was before the step's first change. Call only when something
    // really changes (each call counts as a new revision and is drawn again).
    Scene& change(std::string_view label);

    // Closes the open step unless a gesture (a slider or a camera drag) is still in progress;
    // a step that left the scene as it was is dropped. Returns true when a step was recorded.
    bool settle(bool gestureInProgress);

    bool canUndo() const { return open_ || !undo_.empty(); }
    bool canRedo() const { return !open_ && !redo_.empty(); }
    // Labels of the step Ctrl+Z / Ctrl+Shift+Z would undo / redo ("" when none).
    std::string undoLabel() const;
    std::string redoLabel() const;
    bool undo();  // closes an open step first; false when there is nothing to undo
    bool redo();

    // Unsaved changes: the scene differs (by step) from the state last saved or opened.
    bool dirty() const { return open_ || currentStep() != savedStep_; }
    void markSaved(std::string path);
    // Replaces everything (open a file, recover work): history cleared. `dirty` is true for
    // recovered work that was never saved.
    void replace(Scene scene, std::string path, bool dirty = false);
    // Gives the map to the scene and every state undo and redo reach that name `kind` and `file`
    // without one (opened while the map was still being made): no step, nothing unsaved.
    void completeEnvironment(EnvironmentKind kind, const std::string& file, const std::shared_ptr<const EnvironmentMap>& map);

    // Grows on every change, undo, redo and replace: the renderer redraws when it moves.
    std::uint64_t revision() const { return revision_; }
    // Grows each time a step is recorded, undone or redone, and on save and replace (not during
    // a gesture): autosave and the crash copy follow it.
    std::uint64_t settledRevision() const { return settledRevision_; }
    // Grows on replace and save: which document the scene is (a lesson open read-only stays the
    // lesson until a new scene, another file or Save as takes its place).
    std::uint64_t documentGeneration() const { return documentGeneration_; }
    // Grows on replace only: work started for the scene before (a map being made) no longer applies.
    std::uint64_t replacements() const { return replacements_; }

private:
    struct Step {
        std::string label;
        Scene before;        // the scene before the step (undo restores it)
        Scene after;         // the scene after it (redo restores it)
        std::uint64_t id;    // unique; identifies the state reached by the step
    };
    std::uint64_t currentStep() const { return undo_.empty() ? baseStep_ : undo_.back().id; }
    // Undo and redo: the last step of `from` moves to `to`, and the scene becomes its `shown` side.
    bool moveLastStep(std::deque<Step>& from, std::deque<Step>& to, Scene Step::*shown);

    Scene scene_;
    std::string path_;
    std::deque<Step> undo_;
    std::deque<Step> redo_;
    bool open_ = false;
    std::string openLabel_;
    Scene openBefore_;
    std::uint64_t nextStepId_ = 1;
    std::uint64_t baseStep_ = 0;   // state id when the undo stack is empty
    std::uint64_t savedStep_ = 0;  // state id at the last save or open
    std::uint64_t revision_ = 0;
    std::uint64_t settledRevision_ = 0;
    std::uint64_t documentGeneration_ = 0;
    std::uint64_t replacements_ = 0;
};

}  // namespace glint
