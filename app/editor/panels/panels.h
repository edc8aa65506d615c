// The editor's panels and dialogs: free functions over EditorState, one file each. Panels read
// the scene from state.session and change it only through state.session.change() (core's edit
// API), so every change is undoable and autosaved.
#pragma once

#include "editor/editor_state.h"

namespace glint {

// Menu bar (File, Edit, View, Help); returns its height in pixels.
float drawMenuBar(EditorState& state);
// Status bar along the bottom; returns its height in pixels.
float drawStatusBar(EditorState& state, float top, float width);

// The side columns' widths on screen: their widths at UI scale 1 times the UI scale (presentation
// mode doubles it), each at most 40 % of the window so the viewport keeps a fifth of it.
float leftColumnScreenWidth(const EditorState& state);
float rightColumnScreenWidth(const EditorState& state);
// The left column (scene: lights, display) and the right column (object and material).
void drawScenePanel(EditorState& state, float top, float height);
void drawMaterialColumn(EditorState& state, float top, float height, float windowWidth);
void drawObjectSection(EditorState& state);
void drawPresetBrowser(EditorState& state, int materialIndex);
void drawLightsSection(EditorState& state);
void drawDisplaySection(EditorState& state);
void drawCameraSection(EditorState& state);
// The display panel's Environment section (environment_section.cpp).
void drawEnvironmentSection(EditorState& state);

// The help window (F1), then the modals: the recovery offer (alone while it waits), a mesh's
// progress, unsaved changes, the file browser, a material choice, errors, the files refused
// outside a file's folder. Called after every other window of the frame: Dear ImGui 1.86 aborts
// (imgui.cpp "blocking_modal != NULL") when a window appears after a modal in the frame that
// modal opens.
void drawDialogs(EditorState& state);
// The progress modal of a mesh loading in the background (editor/mesh_loading.h), with Cancel.
void drawMeshLoadDialog(EditorState& state);
// The modal that asks about files refused outside a file's folder (reference_prompt.cpp).
void drawReferencePrompt(EditorState& state);

}  // namespace glint
