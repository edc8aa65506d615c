// The editor's frame loop, as Dear ImGui's own example loop plus calls: wait for input, take
// what background work finished, build the UI, let the renderer do other jobs, then the viewport
// (editor/viewport_presenter.h renders what changed and puts it on screen), autosave and the title.
// Panels live in panels/, shortcuts in shortcuts.cpp, camera input in camera_actions.cpp, file
// actions in document.cpp, the window's callbacks in window_events.cpp.
// Sections: set-up · screenshot · one iteration · the loop.
#include "editor/editor.h"

#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <utility>

#include "classroom/classroom_editor.h"
#include "classroom/lesson_document.h"
#include "classroom/presentation.h"
#include "classroom/compare_view.h"
#include "runtime/headless.h"
#include "editor/recovery.h"
#include "editor/camera_actions.h"
#include "editor/custom_brdf_editor.h"
#include "editor/document.h"
#include "editor/key_events.h"
#include "editor/light_handles.h"
#include "editor/environment_loading.h"
#include "editor/mesh_loading.h"
#include "editor/object_actions.h"
#include "editor/panels/panels.h"
#include "editor/probe_panel.h"
#include "editor/shortcuts.h"
#include "editor/viewport_presenter.h"
#include "editor/window_events.h"
#include "editor/window_placement.h"
#include "gl/brdf_sampler.h"
#include "gl/program_compiler.h"
#include "gl/renderer.h"
#include "image/image_io.h"
#include "platform/x11_errors.h"

namespace glint {
namespace {

// --- fonts and scale: DejaVu Sans for ρ, θ, π, ², ·, ć; sizes follow the UI scale setting ----
// (presentation mode's font, style and scale: app/classroom/presentation.cpp)

void loadFont(float pixelSize) {
    static const ImWchar ranges[] = {0x0020, 0x017F, 0x0370, 0x03FF, 0x2000, 0x209F, 0x2190, 0x22FF, 0x25CF, 0x25CF, 0};
    const char* path = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
    ImGuiIO& io = ImGui::GetIO();
    if (std::FILE* file = std::fopen(path, "rb")) {
        std::fclose(file);
        io.Fonts->AddFontFromFileTTF(path, pixelSize, nullptr, ranges);
    } else {
        io.Fonts->AddFontDefault();
    }
}

// --- screenshot: the viewport's display-encoded PNG or its linear radiance EXR ---------------

// Rendered afresh at the viewport's full size and detail; with the float image only for an EXR.
void saveScreenshot(EditorState& state, Renderer& renderer, glm::ivec2 size) {
    const Scene& scene = state.session.scene();
    const bool floatImage = isFloatImagePath(state.screenshotPath);
    renderer.options().keepRadiance = floatImage;
    const Status rendered = renderer.renderRadiance(scene, size.x, size.y);
    renderer.options().keepRadiance = false;
    if (!rendered) {
        state.errorMessage = "Could not render the screenshot.\n\n" + rendered.error().format();
        return;
    }
    renderer.displayOffscreen(scene.display);
    const RenderedImages images{floatImage ? renderer.readRadiance() : RadianceImage(), renderer.readDisplay()};
    if (Status written = writeRenderedImage(images, state.screenshotPath); !written)
        state.errorMessage = "Could not save the screenshot.\n\n" + written.error().format();
    else state.statusMessage = "Screenshot " + state.screenshotPath;
}

// "Glint — name" with a dot while there are unsaved changes.
std::string windowTitle(const EditorState& state) {
    const std::string& path = state.session.path();
    const std::string name = path.empty() ? "untitled" : std::filesystem::path(path).filename().string();
    const std::string lesson = lessonDocumentName(state);
    return "Glint — " + (lesson.empty() ? name : lesson) + (hasUnsavedWork(state) ? " ●" : "");
}

double autosaveIntervalSeconds() {
    if (const char* text = std::getenv("GLINT_AUTOSAVE_SECONDS")) {
        const double seconds = std::atof(text);
        if (seconds > 0.0 && seconds <= 30.0) return seconds;
    }
    return 5.0;
}

// --- set-up ---------------------------------------------------------------------------------

// The renderer as the editor uses it. The radiance pass also writes the displayed image, so that
// putting it on screen is a scaled copy rather than a display pass over every screen pixel
// (renderer.h); the float image is not written (the screenshot renders its own when it saves an
// EXR). A material's slider redraws only the pixels of the objects that wear it. New specialised
// programs are built on a worker thread, the loop woken when one is ready.
Result<std::unique_ptr<Renderer>> createEditorRenderer(GlfwPlatform& platform) {
    auto created = Renderer::create(platform, defaultShaderSources());
    if (!created) return created.error();
    Renderer& renderer = **created;
    RendererOptions& options = renderer.options();
    options.fuseDisplay = true;
    options.keepRadiance = false;
    options.redrawOnlyChanges = true;
    if (auto context = platform.createWorkerContext())
        renderer.compileInBackground(std::make_unique<ProgramCompiler>(std::move(context), platform.procAddressLoader(),
                                                                       [] { glfwPostEmptyEvent(); }));
    return created;
}

// The default scene, then what the command line opens (`glint FILE`: as File ▸ Open; `glint
// present LIST`: lesson 1), then the recovery prompt for crashed editors' work.
void startEditorState(EditorState& state, const Renderer& renderer, const std::string& openPath, const std::string& presentLessonList) {
    state.settings = loadSettings();
    if (state.settings.allowOutsideReferences) setOutsideReferencesAllowed(true);  // else as --allow-outside-references says
    state.rendererDescription = renderer.description();
    state.customBrdfs.wake = [] { glfwPostEmptyEvent(); };
    if (!openPath.empty()) openDroppedFile(state, openPath);
    if (!presentLessonList.empty()) startPresentation(state, presentLessonList);
    startRecovery(state);
    state.lastAutosaveSeconds = glfwGetTime();  // the first autosave comes one interval after start, not at the first edit
}

// The UI's look as last applied: it follows the UI scale setting and presentation mode.
struct EditorLook {
    static constexpr float kFontPixels = 17.0f, kPresentationFontPixels = 40.0f;
    ImGuiStyle baseStyle;
    ImFont* presentationFont = nullptr;
    float appliedScale = 0.0f;
    bool appliedPresentation = false;
};

// Dear ImGui for the window; floating windows' places are remembered beside settings.json
// (editor/window_placement.h). The window's callbacks go in before ImGui's backend, which chains to them.
EditorLook startImGui(GLFWwindow* window, WindowEvents& events) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    static const std::string layoutFile = windowLayoutFilePath();
    ImGui::GetIO().IniFilename = ensureParentDirectory(layoutFile) ? layoutFile.c_str() : nullptr;
    ImGui::StyleColorsDark();
    EditorLook look;
    look.baseStyle = ImGui::GetStyle();
    loadFont(EditorLook::kFontPixels);
    look.presentationFont = loadPresentationFont(EditorLook::kPresentationFontPixels);
    trackWindowEvents(window, events);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 410 core");
    return look;
}

void keepLook(EditorLook& look, const EditorState& state, GLFWwindow* window) {
    const float displayHeight = ImGui::GetIO().DisplaySize.y;
    const float scale = effectiveUiScale(state.settings, displayHeight);
    if (scale == look.appliedScale && state.settings.presentationMode == look.appliedPresentation) return;
    look.appliedScale = scale;
    look.appliedPresentation = state.settings.presentationMode;
    applyEditorLook(state.settings, displayHeight, look.baseStyle, look.presentationFont, EditorLook::kFontPixels,
                    EditorLook::kPresentationFontPixels);
    fitWindowToPresentation(window, look.appliedPresentation);  // the whole screen while presenting
}

// --- one iteration ----------------------------------------------------------------------------

// When the loop must wake up without input, and how many frames it still owes (ImGui settles its
// layout over a couple of frames; any input asks for a few more).
struct LoopSchedule {
    int framesToDraw = 3;
    double secondsToAutosave = 1e9;
    double secondsToBrdfPoll = 1e9;
    void owe(int frames) { framesToDraw = std::max(framesToDraw, frames); }
};

// Sleeps until input, a timer or background work needs a frame. GLINT_LOG_IDLE=1 (`idleLog`):
// "glint idle" each time the editor has drawn all it was asked for and finds no input waiting.
void waitForInput(const EditorState& state, const ViewportPresenter& presenter, const LoopSchedule& schedule, bool hotReload,
                  bool idleLog, GLFWwindow* window, WindowEvents& events) {
    events.seen = false;
    const double secondsToShaderPoll = hotReload ? 0.5 : 1e9;  // a shader edited elsewhere shows
    const double secondsToWake = std::min({schedule.secondsToAutosave, schedule.secondsToBrdfPoll, secondsToShaderPoll,
                                           presenter.secondsToRefine(glfwGetTime(), state.waitingForPrograms)});
    const bool drawnAll = schedule.framesToDraw == 0 && !state.meshLoad && !state.environmentLoad && !state.waitingForPrograms &&
                          presenter.secondsToRefine(glfwGetTime(), false) >= 1e8;
    if (idleLog && drawnAll) logIdleUnlessEventWaits(window, events);
    if (events.seen) return;  // input arrived while idleness was checked: draw it
    if (state.meshLoad) glfwWaitEventsTimeout(0.05);  // a mesh loads: keep the progress bar moving
    else if (state.environmentLoad) glfwWaitEventsTimeout(0.25);  // its progress; the precompute keeps the cores
    else if (schedule.framesToDraw > 0) glfwPollEvents();
    else if (secondsToWake < 1e8) glfwWaitEventsTimeout(std::max(secondsToWake, 0.01));
    else glfwWaitEvents();
}

// What finished meanwhile: edited shaders, programs built in the background, .brdf probes, mesh
// and environment loads, files dropped on the window; and a frame the X server refused.
void takeFinishedWork(EditorState& state, Renderer& renderer, ViewportPresenter& presenter, LoopSchedule& schedule,
                      WindowEvents& events) {
    keepSelectionInScene(state);  // the last frame's undo or redo may have removed the selected object
    if (renderer.reloadChangedShaders()) presenter.forgetScene();
    if (renderer.adoptCompiledPrograms()) state.waitingForPrograms = false;
    schedule.secondsToBrdfPoll = pollCustomBrdfs(state, glfwGetTime());
    if (takeXErrors() > 0) {  // platform/x11_errors.h: all of the frame again
        events.exposed = true;
        schedule.owe(1);
    }
    if (pollMeshLoad(state)) schedule.owe(1);
    if (pollEnvironmentLoad(state)) schedule.owe(1);
    for (const std::string& path : events.droppedPaths) openDroppedFile(state, path);
    events.droppedPaths.clear();
    keepPresentationColumns(state);  // collapsed on entering presentation mode, one open at a time
}

// The UI of one frame: where the viewport is, and whether a gesture is in progress.
struct UiFrame {
    ViewportRect viewport;
    float statusHeight = 0.0f;
    bool gesture = false;
};

// The viewport: between the side columns (or their collapsed strips), below the menu bar.
ViewportRect viewportBetweenColumns(const EditorState& state, float menuHeight, float columnHeight, float windowWidth) {
    ViewportRect viewport;
    viewport.x = state.showLeftPanel ? leftColumnScreenWidth(state) : collapsedColumnStripWidth(state.settings);
    viewport.y = menuHeight;
    const float right = state.showRightPanel ? rightColumnScreenWidth(state) : collapsedColumnStripWidth(state.settings);
    viewport.width = std::max(1.0f, windowWidth - viewport.x - right);
    viewport.height = std::max(1.0f, columnHeight);
    return viewport;
}

// Builds the frame's UI: bars, columns, floating windows, the viewport's input, dialogs, shortcuts.
UiFrame buildUi(EditorState& state, BrdfSampler& plotSampler, float appliedScale, WindowEvents& events) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const ImVec2 windowSize = ImGui::GetIO().DisplaySize;
    UiFrame ui;
    const float menuHeight = drawMenuBar(state);
    ui.statusHeight = drawStatusBar(state, windowSize.y, windowSize.x);
    const float columnHeight = windowSize.y - menuHeight - ui.statusHeight;
    drawScenePanel(state, menuHeight, columnHeight);
    drawMaterialColumn(state, menuHeight, columnHeight, windowSize.x);
    drawCollapsedColumnStrips(state, menuHeight, columnHeight, windowSize.x);  // presentation mode
    const ViewportRect viewport = ui.viewport = viewportBetweenColumns(state, menuHeight, columnHeight, windowSize.x);
    // Floating windows open where they cover nothing reserved (the lesson note, the probe, the plot);
    // while presenting, over the viewport only, so an open side column never hides one.
    const ScreenRect viewportRect{viewport.x, viewport.y, viewport.width, viewport.height};
    beginWindowLayoutFrame(state.settings.presentationMode ? viewportRect : ScreenRect{0.0f, menuHeight, windowSize.x, columnHeight},
                           viewportRect,
                           windowLayoutKey(appliedScale, state.settings.presentationMode, state.showLeftPanel, state.showRightPanel,
                                           windowSize.x, windowSize.y));
    drawPlotsWindow(state, plotSampler);  // .brdf materials sampled on the GPU
    drawCompareWindow(state);  // classroom/compare_view.h
    drawClassroom(state, viewport.x, viewport.y, viewport.width, viewport.height);  // lessons, presentation key, colour windows
    const bool handleDrag = handleLightHandles(state, viewport);
    // Classroom surface probe: Shift+click sets its point (so no camera drag starts), then its arrows and window.
    const bool probeClick = !handleDrag && handleProbeClick(viewport);
    const bool cameraDrag = !handleDrag && !probeClick && handleViewportInput(state, viewport);
    drawProbe(state, viewport);
    drawDialogs(state);  // the last windows of the frame (panels.h), and first to take their keys
    handleShortcuts(state);
    // A slider, colour picker, light handle or camera drag is one undo step, closed when it ends.
    ui.gesture = ImGui::IsAnyItemActive() || cameraDrag || handleDrag;
    state.session.settle(ui.gesture);
    // The window's close button after this frame's keys: a redo typed just before closing must
    // count as unsaved work, or the close would lose it without asking.
    if (std::exchange(events.closeRequested, false)) requestQuit(state);
    endWindowLayoutFrame();  // GLINT_LOG_LAYOUT: the rectangles on screen, for the GUI tests
    ImGui::Render();
    return ui;
}

// The renderer's other jobs this frame (compare panes, a preset swatch, a screenshot): each
// leaves the viewport to be rendered afresh.
void lendRenderer(EditorState& state, Renderer& renderer, ViewportPresenter& presenter, glm::ivec2 viewportPixels,
                  LoopSchedule& schedule) {
    if (updateCompareView(state, renderer)) presenter.forgetFrame();
    if (updatePresetSwatches(state.presetSwatches, renderer)) {  // the next swatch on the next frame
        presenter.forgetFrame();
        schedule.owe(2);
    }
    if (state.screenshotRequested) {
        state.screenshotRequested = false;
        saveScreenshot(state, renderer, viewportPixels);
        presenter.forgetFrame();
    }
}

using Clock = std::chrono::steady_clock;

// GLINT_LOG_FRAMES=1: each iteration's size, render time, input-to-presented time and phases.
void logFrame(const EditorState& state, const ViewportRender& render, const PresentTimes& times, glm::ivec2 viewportPixels,
              Clock::time_point frameStart, Clock::time_point uiBuilt) {
    if (render.plan.render) glFinish();
    const auto ms = [](auto from, auto to) { return std::chrono::duration<double, std::milli>(to - from).count(); };
    const auto now = Clock::now();
    if (render.waitedForPrograms) {
        std::fprintf(stderr, "glint programs: the frame waits for programs compiling in the background; input to presented %.1f ms\n",
                     ms(frameStart, now));
    } else if (!render.plan.render) {  // the UI alone (a progress bar, a menu)
        std::fprintf(stderr, "glint ui frame: input to presented %.1f ms\n", ms(frameStart, now));
    } else {
        const RefreshPlan& plan = render.plan;
        std::fprintf(stderr,
                     "glint frame: viewport %dx%d scale 1/%d render %.1f ms, input to presented frame %.1f ms, "
                     "%d simplified meshes, shadow maps %s, ui built %.1f ms, displayed %.1f ms, ui drawn %.1f ms, "
                     "presented %.1f ms at %.3f s, %lld pixels presented, band %d/%d, %d stand-in programs, %lld triangles\n",
                     viewportPixels.x, viewportPixels.y, plan.pixelScale, render.renderMilliseconds, ms(frameStart, now),
                     state.simplifiedMeshesShown, state.shadowMapsRedrawn ? "redrawn" : "kept", ms(frameStart, uiBuilt),
                     times.displayedMilliseconds, times.uiMilliseconds, ms(times.composed, now), glfwGetTime(), times.pixelsPresented,
                     plan.band + 1, plan.bands, state.standInProgramsShown, state.triangleCount);
    }
}

// After the frame is on screen: autosave, stale messages expired, the window's title.
void finishIteration(EditorState& state, GLFWwindow* window, double autosaveInterval, LoopSchedule& schedule, std::string& shownTitle) {
    schedule.secondsToAutosave = autosave(state, glfwGetTime(), autosaveInterval);
    // Refusals and status lines written before the scene's last change no longer hold.
    for (SceneMessage* message : {&state.statusMessage, &state.materialPanelMessage, &state.lightPanelMessage, &state.displayPanelMessage})
        message->expire(state.session.revision());
    if (const std::string title = windowTitle(state); title != shownTitle) {
        glfwSetWindowTitle(window, title.c_str());
        shownTitle = title;
    }
    clearKeyPresses();
}

}  // namespace

// --- the loop ---------------------------------------------------------------------------------

int runEditor(std::unique_ptr<GlfwPlatform> platform, const std::string& openPath, const std::string& presentLessonList) {
    setEnvironmentProgressReport(nullptr);  // not on stderr: maps show their progress in the window
    auto created = createEditorRenderer(*platform);
    if (!created) {
        std::fprintf(stderr, "glint: %s\n", created.error().format().c_str());
        return 2;
    }
    Renderer& renderer = **created;
    GLFWwindow* window = platform->window();
    BrdfSampler plotSampler(renderer.sources());  // the Plots window's .brdf materials, on the GPU
    EditorState state;
    startEditorState(state, renderer, openPath, presentLessonList);
    const double autosaveInterval = autosaveIntervalSeconds();
    const bool logFrames = std::getenv("GLINT_LOG_FRAMES") != nullptr, idleLog = std::getenv("GLINT_LOG_IDLE") != nullptr;
    WindowEvents events;
    EditorLook look = startImGui(window, events);
    ViewportPresenter presenter(renderer, *platform);
    LoopSchedule schedule;
    std::string shownTitle;
    while (!state.quitNow) {
        waitForInput(state, presenter, schedule, renderer.hotReloadsShaders(), idleLog, window, events);
        const auto frameStart = Clock::now();  // input for this frame has arrived
        takeFinishedWork(state, renderer, presenter, schedule, events);
        keepLook(look, state, window);
        const UiFrame ui = buildUi(state, plotSampler, look.appliedScale, events);
        const auto uiBuilt = Clock::now();
        // Window (ImGui) pixels to framebuffer pixels (HiDPI).
        const glm::ivec2 framebuffer = platform->framebufferSize();
        const float windowWidth = ImGui::GetIO().DisplaySize.x;
        const float pixelScale = windowWidth > 0 ? framebuffer.x / windowWidth : 1.0f;
        const glm::ivec2 viewportPixels{std::max(1, static_cast<int>(ui.viewport.width * pixelScale)),
                                        std::max(1, static_cast<int>(ui.viewport.height * pixelScale))};
        const glm::ivec2 lowerLeft{static_cast<int>(ui.viewport.x * pixelScale), static_cast<int>(ui.statusHeight * pixelScale)};
        lendRenderer(state, renderer, presenter, viewportPixels, schedule);
        const ViewportRender render = presenter.render(state, viewportPixels, ui.gesture);
        if (render.plan.render) schedule.owe(2);
        const PresentTimes times = presenter.present(render, framebuffer, lowerLeft, viewportPixels, events.exposed, logFrames);
        events.exposed = false;
        if (logFrames) logFrame(state, render, times, viewportPixels, frameStart, uiBuilt);
        finishIteration(state, window, autosaveInterval, schedule, shownTitle);
        schedule.framesToDraw = events.seen ? 3 : schedule.framesToDraw - 1;
    }
    finishRecovery(state);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

}  // namespace glint
