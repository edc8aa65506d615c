// The editor's frame loop, input and layout (see editor.h).
// Sections: event tracking · fonts · input · panels · loop.
#include "editor/editor.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <glad/gl.h>

#include <chrono>
#include <cstdio>

#include "camera/orbit.h"
#include "editor/material_panel.h"
#include "gl/renderer.h"

namespace glint {
namespace {

// --- event tracking: any input or window event asks for a few more frames -------------------

bool gEventSeen = false;
void noteCursor(GLFWwindow*, double, double) { gEventSeen = true; }
void noteButton(GLFWwindow*, int, int, int) { gEventSeen = true; }
void noteScroll(GLFWwindow*, double, double) { gEventSeen = true; }
void noteKey(GLFWwindow*, int, int, int, int) { gEventSeen = true; }
void noteChar(GLFWwindow*, unsigned int) { gEventSeen = true; }
void noteSize(GLFWwindow*, int, int) { gEventSeen = true; }
void noteRefresh(GLFWwindow*) { gEventSeen = true; }

void installEventTracking(GLFWwindow* window) {
    // Installed before ImGui's backend, which chains to them.
    glfwSetCursorPosCallback(window, noteCursor);
    glfwSetMouseButtonCallback(window, noteButton);
    glfwSetScrollCallback(window, noteScroll);
    glfwSetKeyCallback(window, noteKey);
    glfwSetCharCallback(window, noteChar);
    glfwSetFramebufferSizeCallback(window, noteSize);
    glfwSetWindowRefreshCallback(window, noteRefresh);
}

// --- fonts: DejaVu Sans for ρ, θ, π, ², · in labels; ImGui's own font when it is missing ----

void loadFont(float pixelSize) {
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x209F, 0x2190, 0x22FF, 0};
    const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    ImGuiIO& io = ImGui::GetIO();
    if (std::FILE* file = std::fopen(path, "rb")) {
        std::fclose(file);
        io.Fonts->AddFontFromFileTTF(path, pixelSize, nullptr, ranges);
    } else {
        io.Fonts->AddFontDefault();
    }
}

// --- the editor's state ---------------------------------------------------------------------

struct EditorState {
    Scene scene;
    std::string scenePath;
    OrbitController orbit;
    int selectedObject = 0;
    bool sceneChanged = true;  // the radiance must be re-rendered
    float panelWidth = 360.0f;
    double lastRenderMilliseconds = 0.0;
};

// --- input: orbit (left drag), pan (right or middle drag), zoom (wheel) ---------------------

void handleViewportInput(EditorState& state, GLFWwindow* window) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantCaptureMouse) return;
    const ImVec2 delta = io.MouseDelta;
    int windowHeight = 0;
    glfwGetWindowSize(window, nullptr, &windowHeight);
    const float scale = 1.0f / std::max(windowHeight, 1);
    bool moved = false;
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left) && (delta.x != 0 || delta.y != 0)) {
        state.orbit.orbit(-delta.x * scale * 3.0f, delta.y * scale * 3.0f);
        moved = true;
    }
    if ((ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)) &&
        (delta.x != 0 || delta.y != 0)) {
        state.orbit.pan(-delta.x * scale, delta.y * scale);
        moved = true;
    }
    if (io.MouseWheel != 0.0f) {
        state.orbit.zoom(std::pow(0.9f, io.MouseWheel));
        moved = true;
    }
    if (!io.WantCaptureKeyboard && ImGui::IsKeyPressed(GLFW_KEY_R, false)) {
        state.orbit = OrbitController::fromCamera(defaultScene().camera);
        moved = true;
    }
    if (moved) {
        state.orbit.applyTo(state.scene.camera);
        state.sceneChanged = true;
    }
}

// --- panels ---------------------------------------------------------------------------------

void drawSidePanel(EditorState& state, const Renderer& renderer, glm::ivec2 windowSize) {
    ImGui::SetNextWindowPos(ImVec2(windowSize.x - state.panelWidth, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(state.panelWidth, static_cast<float>(windowSize.y)), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(240, 0), ImVec2(900, 1e6f));
    ImGui::Begin("Material", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
    state.panelWidth = ImGui::GetWindowWidth();
    ImGui::PushItemWidth(-ImGui::GetFontSize() * 9.5f);  // room for the label and the reset button
    if (state.scene.objects.empty()) {
        ImGui::TextWrapped("The scene has no objects.");
    } else {
        if (ImGui::BeginCombo("Object", state.scene.objects[state.selectedObject].name.c_str())) {
            for (size_t i = 0; i < state.scene.objects.size(); ++i)
                if (ImGui::Selectable(state.scene.objects[i].name.c_str(), state.selectedObject == static_cast<int>(i)))
                    state.selectedObject = static_cast<int>(i);
            ImGui::EndCombo();
        }
        Material& material = state.scene.materials[state.scene.objects[state.selectedObject].materialIndex];
        ImGui::Text("Material: %s", material.name.c_str());
        ImGui::Separator();
        if (drawMaterialPanel(material)) state.sceneChanged = true;
    }
    ImGui::Separator();
    if (!renderer.shaderError().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", renderer.shaderError().c_str());
        ImGui::PopStyleColor();
    }
    ImGui::TextDisabled("Render %.1f ms", state.lastRenderMilliseconds);
    ImGui::PushTextWrapPos();
    ImGui::TextDisabled("%s", renderer.description().c_str());
    ImGui::PopTextWrapPos();
    ImGui::TextWrapped("Left drag: orbit · right drag: pan · wheel: zoom · R: reset view");
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace

// --- loop -----------------------------------------------------------------------------------

int runEditor(std::unique_ptr<GlfwPlatform> platform, Scene scene, const std::string& scenePath) {
    auto created = Renderer::create(*platform, defaultShaderSources());
    if (!created) {
        std::fprintf(stderr, "glint: %s\n", created.error().format().c_str());
        return 2;
    }
    Renderer& renderer = **created;
    GLFWwindow* window = platform->window();

    EditorState state;
    state.scene = std::move(scene);
    state.scenePath = scenePath;
    state.orbit = OrbitController::fromCamera(state.scene.camera);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // the layout is fixed; write no imgui.ini
    ImGui::StyleColorsDark();
    loadFont(17.0f);
    installEventTracking(window);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 410 core");

    glm::ivec2 renderedSize{0, 0};
    int framesToDraw = 3;  // ImGui settles its layout over a couple of frames
    while (!glfwWindowShouldClose(window)) {
        gEventSeen = false;
        if (framesToDraw > 0) glfwPollEvents();
        else glfwWaitEvents();
        if (renderer.reloadChangedShaders()) state.sceneChanged = true;

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const glm::ivec2 framebuffer = platform->framebufferSize();
        drawSidePanel(state, renderer, framebuffer);
        handleViewportInput(state, window);
        ImGui::Render();

        const glm::ivec2 viewport{std::max(1, framebuffer.x - static_cast<int>(state.panelWidth)), std::max(1, framebuffer.y)};
        if (viewport != renderedSize) state.sceneChanged = true;
        if (state.sceneChanged) {
            const auto start = std::chrono::steady_clock::now();
            if (Status status = renderer.renderRadiance(state.scene, viewport.x, viewport.y); !status)
                std::fprintf(stderr, "glint: %s\n", status.error().format().c_str());
            glFinish();
            state.lastRenderMilliseconds =
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            renderedSize = viewport;
            state.sceneChanged = false;
            framesToDraw = std::max(framesToDraw, 2);
        }
        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, framebuffer.x, framebuffer.y);
        glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        renderer.displayToScreen(state.scene.display, {0, 0});
        glViewport(0, 0, framebuffer.x, framebuffer.y);
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        platform->present();
        framesToDraw = gEventSeen ? 3 : framesToDraw - 1;
    }

    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

}  // namespace glint
