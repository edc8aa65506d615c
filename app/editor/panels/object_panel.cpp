// The object and material section: pick the object; its material through the table-driven
// material widgets (editor/material_panel.h) on a copy written back through the edit API, so a
// slider drag is one undo step; then add, duplicate and remove objects, the overlays (wireframe,
// normals), the shading mode and the shape's own parameters (placement, sizes, tessellation;
// a loaded mesh's statistics).
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "editor/material_panel.h"
#include "editor/model_limits.h"
#include "editor/object_actions.h"
#include "editor/panels/panels.h"
#include "editor/panels/typed_numbers.h"
#include "editor/panels/widgets.h"

namespace glint {
namespace {

// A drag field for a length that must stay positive; `refusal` says why a typed value was refused.
bool positiveLength(const char* label, float& value, std::string& refusal) {
    float edited = value;
    if (!editNumbers(label, &edited, 1, [&](float* typed) { return ImGui::DragFloat(label, typed, 0.005f, 0.0f, 0.0f, "%.3f"); }))
        return false;
    if (edited > 0.0f && std::isfinite(edited)) {
        value = edited;
        refusal.clear();
        return true;
    }
    refusal = std::string(label) + " must be greater than 0";
    return false;
}

// A shape's centre [m], any finite point.
bool centreField(glm::vec3& centre) {
    glm::vec3 edited = centre;
    const std::string shown = placeLabel("Centre m", threeNumbersWidth(false));
    if (!editNumbers("Centre m", &edited.x, 3, [&](float* typed) { return ImGui::DragFloat3(shown.c_str(), typed, 0.01f, 0.0f, 0.0f, "%.2f"); }))
        return false;
    if (!std::isfinite(edited.x + edited.y + edited.z)) return false;
    centre = edited;
    return true;
}

// Segments × rings of a tessellated shape; the slider keeps them in range.
bool tessellationSliders(int& segments, int& rings, int minimumRings) {
    bool changed = ImGui::SliderInt("Segments", &segments, 3, 256, "%d", ImGuiSliderFlags_AlwaysClamp);
    changed |= ImGui::SliderInt("Rings", &rings, minimumRings, 128, "%d", ImGuiSliderFlags_AlwaysClamp);
    return changed;
}

// Widgets on a copy of the shape; returns true when the copy changed and is valid. Sizes must be
// positive and a normal non-zero, else `refusal` says why.
bool drawShapeEditor(Shape& shape, std::string& refusal) {
    bool changed = false;
    if (auto* sphere = std::get_if<SphereShape>(&shape)) {
        changed |= centreField(sphere->center);
        changed |= positiveLength("Radius m", sphere->radius, refusal);
        changed |= tessellationSliders(sphere->segments, sphere->rings, 2);
    } else if (auto* cube = std::get_if<CubeShape>(&shape)) {
        changed |= centreField(cube->center);
        changed |= positiveLength("Edge m", cube->size, refusal);
        changed |= ImGui::DragFloat3("Rotation °", &cube->rotationDegrees.x, 0.5f, -360.0f, 360.0f, "%.1f");
    } else if (auto* torus = std::get_if<TorusShape>(&shape)) {
        changed |= centreField(torus->center);
        changed |= positiveLength("Major radius m", torus->majorRadius, refusal);
        changed |= positiveLength("Tube radius m", torus->minorRadius, refusal);
        changed |= tessellationSliders(torus->segments, torus->rings, 3);
        changed |= ImGui::DragFloat3("Rotation °", &torus->rotationDegrees.x, 0.5f, -360.0f, 360.0f, "%.1f");
    } else if (auto* mesh = std::get_if<MeshShape>(&shape)) {
        changed |= centreField(mesh->center);
        changed |= positiveLength("Size (radius) m", mesh->scale, refusal);
    } else if (auto* plane = std::get_if<PlaneShape>(&shape)) {
        changed |= centreField(plane->center);
        glm::vec3 normal = plane->normal;
        const std::string shown = placeLabel("Normal", threeNumbersWidth(false));
        if (editNumbers("Normal", &normal.x, 3, [&](float* typed) { return ImGui::DragFloat3(shown.c_str(), typed, 0.01f, -1.0f, 1.0f, "%.2f"); })) {
            if (glm::length(normal) > 1e-4f) plane->normal = glm::normalize(normal), changed = true, refusal.clear();
            else refusal = "Normal must not be zero";
        }
        glm::vec2 size = plane->size;
        if (editNumbers("Size m", &size.x, 2, [&](float* typed) { return ImGui::DragFloat2("Size m", typed, 0.02f, 0.0f, 0.0f, "%.2f"); })) {
            if (size.x > 0.0f && size.y > 0.0f) plane->size = size, changed = true, refusal.clear();
            else refusal = "Both sides must be longer than 0";
        }
    }
    return changed;
}

void drawAddMenu(EditorState& state) {
    if (ImGui::Button("Add…")) ImGui::OpenPopup("Add object");
    if (ImGui::BeginPopup("Add object")) {
        for (ObjectKind kind : {ObjectKind::Sphere, ObjectKind::Plane, ObjectKind::Cube, ObjectKind::Torus})
            if (ImGui::Selectable(objectKindLabel(kind))) addObject(state, kind);
        if (ImGui::Selectable("Mesh file…")) requestFileBrowser(state.fileBrowser, FilePurpose::OpenMesh, "");
        ImGui::EndPopup();
    }
}

// Exact (the analytic surface) where the shape has one; flat, Gouraud or Phong interpolation over
// the drawn triangles otherwise (scene.h, SurfaceInterpolation).
void drawInterpolationCombo(EditorState& state) {
    constexpr const char* kLabels[] = {"exact (analytic)", "flat", "Gouraud", "Phong"};  // order of SurfaceInterpolation
    const SceneObject& object = state.session.scene().objects[state.selectedObject];
    const bool exactAllowed = !std::holds_alternative<TorusShape>(object.shape) && !std::holds_alternative<MeshShape>(object.shape);
    int selected = static_cast<int>(object.interpolation);
    float widest = 0.0f;
    for (const char* label : kLabels) widest = std::max(widest, ImGui::CalcTextSize(label).x);
    const std::string shadingLabel = placeLabel("Shading", comboWidth(widest));
    if (ImGui::BeginCombo(shadingLabel.c_str(), kLabels[selected])) {
        for (int i = exactAllowed ? 0 : 1; i < 4; ++i)
            if (ImGui::Selectable(kLabels[i], i == selected) && i != selected)
                state.session.change("Shading mode").objects[state.selectedObject].interpolation =
                    static_cast<SurfaceInterpolation>(i);
        ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("flat: one normal per triangle; Gouraud: shade the vertices, interpolate the colour;\n"
                          "Phong: interpolate the normal, shade every pixel; exact: the analytic surface");
}

void drawMeshStatistics(const MeshShape& mesh) {
    const MeshStatistics& statistics = mesh.statistics;
    ImGui::PushTextWrapPos();
    ImGui::TextDisabled("%s", mesh.path.c_str());
    ImGui::PopTextWrapPos();
    ImGui::Text("%zu vertices, %zu triangles", statistics.vertexCount, statistics.triangleCount);
    ImGui::Text("normals: %s", statistics.hadNormals ? "from the file" : "generated (smooth)");
    ImGui::Text("degenerate faces dropped: %zu", statistics.degenerateTrianglesDropped);
    if (statistics.pointsAndLinesDropped > 0) ImGui::Text("points and lines dropped: %zu", statistics.pointsAndLinesDropped);
    ImGui::Text("loaded in %.0f ms", statistics.loadSeconds * 1000.0);
}

void drawOverlayToggles(EditorState& state) {
    OverlaySettings overlays = state.session.scene().display.overlays;
    if (ImGui::Checkbox("Wireframe (W)", &overlays.wireframe)) toggleWireframe(state);
    sameLineIfFits(checkboxWidth("Normals (N)"));
    if (ImGui::Checkbox("Normals (N)", &overlays.normals)) toggleNormals(state);
    if (overlays.normals) {
        if (positiveLength("Normal length m", overlays.normalLength, state.materialPanelMessage.text()))
            state.session.change("Normal length").display.overlays.normalLength = overlays.normalLength;
    }
}

}  // namespace

void drawObjectSection(EditorState& state) {
    const Scene& scene = state.session.scene();
    if (scene.objects.empty()) {
        ImGui::TextWrapped("The scene has no objects.");
        drawAddMenu(state);
        return;
    }
    keepSelectionInScene(state);
    float widestName = 0.0f;
    for (const SceneObject& object : scene.objects) widestName = std::max(widestName, ImGui::CalcTextSize(object.name.c_str()).x);
    const std::string objectLabel = placeLabel("Object", comboWidth(widestName));
    if (ImGui::BeginCombo(objectLabel.c_str(), scene.objects[state.selectedObject].name.c_str())) {
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
    ImGui::PushID(materialIndex);  // numbers typed for one material never land on another
    if (drawMaterialPanel(edited, state.materialPanelMessage.text(), textureFileRequest))
        state.session.change("Edit " + edited.name).materials[materialIndex] = std::move(edited);
    ImGui::PopID();
    if (!textureFileRequest.empty()) {
        state.textureMaterialIndex = materialIndex;
        state.textureParameter = textureFileRequest;
        requestFileBrowser(state.fileBrowser, FilePurpose::OpenTexture, state.session.path());
    }
    if (!state.renderProblem.empty()) drawProblemText("The preview may not show this material as it is:\n" + state.renderProblem);
    if (!state.materialPanelMessage.empty()) {
        ImGui::PushTextWrapPos();
        ImGui::TextColored(ImVec4(1.0f, 0.6f, 0.3f, 1.0f), "%s", state.materialPanelMessage.c_str());
        ImGui::PopTextWrapPos();
    }
    // What the model leaves out here (a mirror under point lights, glass before other objects).
    for (const std::string& note : modelLimitNotes(scene, state.selectedObject)) {
        ImGui::PushTextWrapPos();
        ImGui::TextColored(ImVec4(0.6f, 0.75f, 0.95f, 1.0f), "Note: %s", note.c_str());
        ImGui::PopTextWrapPos();
    }
    drawPresetBrowser(state, materialIndex);
    if (!ImGui::CollapsingHeader("Objects and shape", ImGuiTreeNodeFlags_DefaultOpen)) return;
    drawAddMenu(state);
    sameLineIfFits(buttonWidth("Duplicate"));
    if (ImGui::Button("Duplicate")) duplicateObject(state, state.selectedObject);
    sameLineIfFits(buttonWidth("Remove"));
    if (ImGui::Button("Remove")) {
        removeObject(state, state.selectedObject);
        return;
    }
    drawOverlayToggles(state);
    Shape shape = state.session.scene().objects[state.selectedObject].shape;
    ImGui::TextDisabled("%s", shapeLabel(shape));
    drawInterpolationCombo(state);
    if (drawShapeEditor(shape, state.materialPanelMessage.text()))
        state.session.change("Edit shape").objects[state.selectedObject].shape = shape;
    if (const auto* mesh = std::get_if<MeshShape>(&shape)) drawMeshStatistics(*mesh);
}

}  // namespace glint
