// The object and material section: pick the object, edit its shape (sphere centre and radius;
// plane centre, normal and size), see its material, edit it through the
// table-driven material widgets (editor/material_panel.h) on a copy that is written back
// through the edit API, so a slider drag is one undo step.
#include <imgui.h>

#include <cmath>
#include <variant>

#include "editor/material_panel.h"
#include "editor/panels/panels.h"

namespace glint {
namespace {

// Widgets on a copy of the shape; returns true when the copy changed and is valid. Sizes must be
// positive and a normal non-zero, else `refusal` says why.
bool drawShapeEditor(Shape& shape, std::string& refusal) {
    bool changed = false;
    if (auto* sphere = std::get_if<SphereShape>(&shape)) {
        changed |= ImGui::DragFloat3("Centre m", &sphere->center.x, 0.01f, 0.0f, 0.0f, "%.2f");
        float radius = sphere->radius;
        if (ImGui::DragFloat("Radius m", &radius, 0.005f, 0.0f, 0.0f, "%.3f")) {
            if (radius > 0.0f && std::isfinite(radius)) sphere->radius = radius, changed = true, refusal.clear();
            else refusal = "Radius must be greater than 0";
        }
    } else if (auto* plane = std::get_if<PlaneShape>(&shape)) {
        changed |= ImGui::DragFloat3("Centre m", &plane->center.x, 0.01f, 0.0f, 0.0f, "%.2f");
        glm::vec3 normal = plane->normal;
        if (ImGui::DragFloat3("Normal", &normal.x, 0.01f, -1.0f, 1.0f, "%.2f")) {
            if (glm::length(normal) > 1e-4f) plane->normal = glm::normalize(normal), changed = true, refusal.clear();
            else refusal = "Normal must not be zero";
        }
        glm::vec2 size = plane->size;
        if (ImGui::DragFloat2("Size m", &size.x, 0.02f, 0.0f, 0.0f, "%.2f")) {
            if (size.x > 0.0f && size.y > 0.0f) plane->size = size, changed = true, refusal.clear();
            else refusal = "Both sides must be longer than 0";
        }
    }
    return changed;
}

}  // namespace

void drawObjectSection(EditorState& state) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) {
        ImGui::TextWrapped("The scene has no objects.");
        return;
    }
    state.selectedObject = std::clamp(state.selectedObject, 0, static_cast<int>(scene.objects.size()) - 1);
    if (ImGui::BeginCombo("Object", scene.objects[state.selectedObject].name.c_str())) {
        for (size_t i = 0; i < scene.objects.size(); ++i)
            if (ImGui::Selectable(scene.objects[i].name.c_str(), state.selectedObject == static_cast<int>(i)))
                state.selectedObject = static_cast<int>(i);
        ImGui::EndCombo();
    }
    const int materialIndex = scene.objects[state.selectedObject].materialIndex;
    Material edited = scene.materials[materialIndex];
    ImGui::Text("Material: %s", edited.name.c_str());
    ImGui::Separator();
    std::string textureFileRequest;
    if (drawMaterialPanel(edited, state.materialPanelMessage, textureFileRequest))
        state.session.change("Edit " + edited.name).materials[materialIndex] = std::move(edited);
    if (!textureFileRequest.empty()) {
        state.textureMaterialIndex = materialIndex;
        state.textureParameter = textureFileRequest;
        requestFileBrowser(state.fileBrowser, FilePurpose::OpenTexture, state.session.path());
    }
    if (!state.materialPanelMessage.empty()) {
        ImGui::PushTextWrapPos();
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", state.materialPanelMessage.c_str());
        ImGui::PopTextWrapPos();
    }
    drawPresetBrowser(state, materialIndex);
    ImGui::Separator();
    Shape shape = state.session.scene().objects[state.selectedObject].shape;
    if (ImGui::TreeNodeEx(std::holds_alternative<SphereShape>(shape) ? "Sphere" : "Plane", ImGuiTreeNodeFlags_None)) {
        if (drawShapeEditor(shape, state.materialPanelMessage))
            state.session.change("Edit shape").objects[state.selectedObject].shape = shape;
        ImGui::TreePop();
    }
}

}  // namespace glint
