// The editor's frame loop: window callbacks (close, drop), the layout of menu bar, side columns,
// status bar and viewport, redraw-on-change, undo steps closed when a gesture ends, autosave,
// screenshots. Panels live in panels/, shortcuts in shortcuts.cpp, camera input in
// camera_actions.cpp, file actions in document.cpp.
// Sections: window events · fonts and scale · screenshot · loop.
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
#include "editor/ui_damage.h"
#include "editor/viewport_refresh.h"
#include "editor/window_placement.h"
#include "gl/brdf_sampler.h"
#include "gl/program_compiler.h"
#include "gl/render_target.h"
#include "gl/renderer.h"
#include "image/image_io.h"
#include "platform/x11_errors.h"

namespace glint {
namespace {

// --- window events: any input asks for a few more frames; close and drop are queued --------

bool gEventSeen = false;  // since the loop last looked
std::uint64_t gEventCount = 0;  // since start, for GLINT_LOG_IDLE
bool gExposed = true;  // the window's pixels must all be drawn again (mapped, exposed, resized)
bool gCloseRequested = false;
std::vector<std::string> gDroppedPaths;

void noteEvent() {
    gEventSeen = true;
    ++gEventCount;
}
void noteKey(GLFWwindow*, int key, int, int action, int mods) {
    if (action == GLFW_PRESS || action == GLFW_REPEAT) recordKeyPress(key, mods);
    noteEvent();
}
void noteClose(GLFWwindow* window) {
    // The editor decides (unsaved-changes prompt); the window stays open until it does.
    glfwSetWindowShouldClose(window, GLFW_FALSE);
    gCloseRequested = true;
    noteEvent();
}
void noteDrop(GLFWwindow*, int count, const char** paths) {
    for (int i = 0; i < count; ++i) gDroppedPaths.emplace_back(paths[i]);
    noteEvent();
}

// The renderer's error, shown in the editor and printed once each time it changes (not each frame).
void noteRenderProblem(EditorState& state, const std::string& problem) {
    if (!problem.empty() && problem != state.renderProblem) std::fprintf(stderr, "glint: %s\n", problem.c_str());
    state.renderProblem = problem;
}

// "glint idle N X Y": the window events handled since start and where the pointer is, printed when
// the editor sleeps with everything drawn; the GUI tests' sign that what they sent is handled and
// on screen (tests/gui_test_support.py: wait_idle).
// The pointer is asked for before the last poll: the query is a round trip to the X server, so
// every event sent before its answer is queued by then, and the poll finds it.
void logIdleUnlessEventWaits(GLFWwindow* window) {
    double x = 0.0, y = 0.0;
    glfwGetCursorPos(window, &x, &y);
    glfwPollEvents();
    if (gEventSeen) return;
    std::printf("glint idle %llu %.0f %.0f\n", static_cast<unsigned long long>(gEventCount), x, y);
    std::fflush(stdout);
}

void installEventTracking(GLFWwindow* window) {
    // Installed before ImGui's backend, which chains to them.
    glfwSetCursorPosCallback(window, [](GLFWwindow*, double, double) { noteEvent(); });
    glfwSetMouseButtonCallback(window, [](GLFWwindow*, int, int, int) { noteEvent(); });
    glfwSetScrollCallback(window, [](GLFWwindow*, double, double) { noteEvent(); });
    glfwSetKeyCallback(window, noteKey);
    glfwSetCharCallback(window, [](GLFWwindow*, unsigned int) { noteEvent(); });
    glfwSetFramebufferSizeCallback(window, [](GLFWwindow*, int, int) { noteEvent(), gExposed = true; });
    glfwSetWindowRefreshCallback(window, [](GLFWwindow*) { noteEvent(), gExposed = true; });
    glfwSetWindowCloseCallback(window, noteClose);
    glfwSetDropCallback(window, noteDrop);
}

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

}  // namespace

// --- loop -----------------------------------------------------------------------------------

int runEditor(std::unique_ptr<GlfwPlatform> platform, const std::string& openPath, const std::string& presentLessonList) {
    setEnvironmentProgressReport(nullptr);  // not on stderr: maps show their progress in the window
    auto created = Renderer::create(*platform, defaultShaderSources());
    if (!created) {
        std::fprintf(stderr, "glint: %s\n", created.error().format().c_str());
        return 2;
    }
    Renderer& renderer = **created;
    // The radiance pass also writes the displayed image, so that putting it on screen is a scaled
    // copy rather than a display pass over every screen pixel (renderer.h); the float image is not
    // written (the screenshot renders its own when it saves an EXR).
    RendererOptions& options = renderer.options();
    options.fuseDisplay = true;
    options.keepRadiance = false;
    // A material's slider redraws only the pixels of the objects that wear it.
    options.redrawOnlyChanges = true;
    // New specialised programs are built on a worker thread, the loop woken when one is ready.
    if (auto context = platform->createWorkerContext())
        renderer.compileInBackground(std::make_unique<ProgramCompiler>(std::move(context), platform->procAddressLoader(),
                                                                       [] { glfwPostEmptyEvent(); }));
    GLFWwindow* window = platform->window();

    BrdfSampler plotSampler(renderer.sources());  // the Plots window's .brdf materials, on the GPU

    EditorState state;  // the default scene
    state.settings = loadSettings();
    if (state.settings.allowOutsideReferences) setOutsideReferencesAllowed(true);  // else as --allow-outside-references says
    state.rendererDescription = renderer.description();
    state.customBrdfs.wake = [] { glfwPostEmptyEvent(); };
    if (!openPath.empty()) openDroppedFile(state, openPath);  // `glint FILE`: as File ▸ Open
    if (!presentLessonList.empty()) startPresentation(state, presentLessonList);  // `glint present LIST`: lesson 1
    startRecovery(state);
    // The first autosave comes one interval after start, not at the first edit.
    state.lastAutosaveSeconds = glfwGetTime();
    const double autosaveInterval = autosaveIntervalSeconds();
    // GLINT_LOG_FRAMES=1 prints each rendered frame's size, render time, input-to-frame time and
    // when it was presented (glfwGetTime).
    const bool logFrames = std::getenv("GLINT_LOG_FRAMES") != nullptr;

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    // Floating windows' places are remembered beside settings.json (editor/window_placement.h).
    static const std::string layoutFile = windowLayoutFilePath();
    ImGui::GetIO().IniFilename = ensureParentDirectory(layoutFile) ? layoutFile.c_str() : nullptr;
    ImGui::StyleColorsDark();
    const ImGuiStyle baseStyle = ImGui::GetStyle();
    float appliedScale = 0.0f;
    bool appliedPresentation = false;
    constexpr float kFontPixels = 17.0f, kPresentationFontPixels = 40.0f;
    loadFont(kFontPixels);
    ImFont* presentationFont = loadPresentationFont(kPresentationFontPixels);
    installEventTracking(window);
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 410 core");

    glm::ivec2 renderedSize{0, 0};
    std::uint64_t renderedRevision = ~0ull;
    int renderedScale = 1;
    DisplaySettings shownDisplay;  // of the frame last drawn (a change may wait for its programs)
    std::string shownTitle;
    ViewportRefresh refresh;  // reduced frames while dragging, the full one after (viewport_refresh.h)
    // Where the window keeps its pixels between frames (the platform presents regions, and nothing
    // swaps the buffers), only what changed is drawn and put on screen: the pixels the render drew
    // and where the ui changed (ui_damage.h); elsewhere every frame whole.
    const bool presentRegions = platform->presentsRegions();
    UiDamage uiDamage;
    glm::ivec4 placed{0, 0, 0, 0};  // where the viewport was put on screen: lower left, size
    PixelRegion viewportCopied;  // the screen pixels its last (scaled) copy covered
    // Frames drawn whole and swapped after the window was exposed or resized: llvmpipe gives a
    // resized window a new back buffer only at a swap, with no pixels of the frame before.
    int wholeFrames = 0;
    // On screen while the full frame is refined in bands: the frame before, at its own resolution
    // (copied as it is, and scaled as it is put on screen, as it was shown).
    RenderTarget reducedFrame{GL_RGBA8, false};
    int reducedScale = 1;
    int refinedRows = 0;  // the full frame's rows drawn so far, from the top
    // The full-resolution rows of the changed objects' rectangle of the last frame not drawn in
    // bands that redrew only them (a drag's): the bands of the full frame after it split these rows evenly.
    std::optional<RowBand> changedRows;
    double refinedMilliseconds = 0.0;  // the full frame's bands so far
    const float kWindowClearColor[4] = {0.1f, 0.1f, 0.11f, 1.0f};  // under the panels
    int framesToDraw = 3;  // ImGui settles its layout over a couple of frames
    double secondsToAutosave = 1e9;
    double secondsToBrdfPoll = 1e9;
    // GLINT_LOG_IDLE=1: "glint idle" each time the editor has drawn all it was asked for (no frame,
    // band, program or load pending) and finds no input waiting, before it sleeps.
    const bool idleLog = std::getenv("GLINT_LOG_IDLE") != nullptr;
    while (!state.quitNow) {
        gEventSeen = false;
        const double secondsToShaderPoll = renderer.hotReloadsShaders() ? 0.5 : 1e9;  // a shader edited elsewhere shows
        const double secondsToWake = std::min({secondsToAutosave, secondsToBrdfPoll, secondsToShaderPoll,
                                               refresh.secondsToRefine(glfwGetTime(), state.waitingForPrograms)});
        const bool drawnAll = framesToDraw == 0 && !state.meshLoad && !state.environmentLoad &&
                              !state.waitingForPrograms && refresh.secondsToRefine(glfwGetTime(), false) >= 1e8;
        if (idleLog && drawnAll) logIdleUnlessEventWaits(window);
        if (gEventSeen) {}  // input arrived while idleness was checked: draw it
        else if (state.meshLoad) glfwWaitEventsTimeout(0.05);  // a mesh loads: keep the progress bar moving
        else if (state.environmentLoad) glfwWaitEventsTimeout(0.25);  // its progress; the precompute keeps the cores
        else if (framesToDraw > 0) glfwPollEvents();
        else if (secondsToWake < 1e8) glfwWaitEventsTimeout(std::max(secondsToWake, 0.01));
        else glfwWaitEvents();
        const auto frameStart = std::chrono::steady_clock::now();  // input for this frame has arrived
        keepSelectionInScene(state);  // the last frame's undo or redo may have removed the selected object
        if (renderer.reloadChangedShaders()) renderedRevision = ~0ull;
        if (renderer.adoptCompiledPrograms()) state.waitingForPrograms = false;  // programs built in the background
        secondsToBrdfPoll = pollCustomBrdfs(state, glfwGetTime());  // .brdf probes and hot reload
        if (takeXErrors() > 0) {  // a frame the X server refused (platform/x11_errors.h): all of it again
            gExposed = true;
            framesToDraw = std::max(framesToDraw, 1);
        }
        if (pollMeshLoad(state)) framesToDraw = std::max(framesToDraw, 1);
        if (pollEnvironmentLoad(state)) framesToDraw = std::max(framesToDraw, 1);
        for (const std::string& path : gDroppedPaths) openDroppedFile(state, path);
        gDroppedPaths.clear();
        keepPresentationColumns(state);  // collapsed on entering presentation mode, one open at a time
        const float displayHeight = ImGui::GetIO().DisplaySize.y;
        if (effectiveUiScale(state.settings, displayHeight) != appliedScale || state.settings.presentationMode != appliedPresentation) {
            appliedScale = effectiveUiScale(state.settings, displayHeight);
            appliedPresentation = state.settings.presentationMode;
            applyEditorLook(state.settings, displayHeight, baseStyle, presentationFont, kFontPixels, kPresentationFontPixels);
            fitWindowToPresentation(window, appliedPresentation);  // the whole screen while presenting
        }

        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        const glm::ivec2 framebuffer = platform->framebufferSize();
        const ImVec2 windowSize = ImGui::GetIO().DisplaySize;
        const float menuHeight = drawMenuBar(state);
        const float statusHeight = drawStatusBar(state, windowSize.y, windowSize.x);
        const float columnHeight = windowSize.y - menuHeight - statusHeight;
        drawScenePanel(state, menuHeight, columnHeight);
        drawMaterialColumn(state, menuHeight, columnHeight, windowSize.x);
        drawCollapsedColumnStrips(state, menuHeight, columnHeight, windowSize.x);  // presentation mode
        ViewportRect viewport;
        viewport.x = state.showLeftPanel ? leftColumnScreenWidth(state) : collapsedColumnStripWidth(state.settings);
        viewport.y = menuHeight;
        viewport.width = std::max(1.0f, windowSize.x - viewport.x -
                                            (state.showRightPanel ? rightColumnScreenWidth(state)
                                                                  : collapsedColumnStripWidth(state.settings)));
        viewport.height = std::max(1.0f, columnHeight);
        // Floating windows open where they cover nothing reserved (the lesson note, the probe, the plot);
        // while presenting, over the viewport only, so an open side column never hides one.
        const ScreenRect viewportRect{viewport.x, viewport.y, viewport.width, viewport.height};
        beginWindowLayoutFrame(state.settings.presentationMode ? viewportRect : ScreenRect{0.0f, menuHeight, windowSize.x, columnHeight},
                               viewportRect,
                               windowLayoutKey(appliedScale, state.settings.presentationMode, state.showLeftPanel,
                                               state.showRightPanel, windowSize.x, windowSize.y));
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
        const bool gesture = ImGui::IsAnyItemActive() || cameraDrag || handleDrag;
        state.session.settle(gesture);
        // The window's close button after this frame's keys: a redo typed just before closing
        // must count as unsaved work, or the close would lose it without asking.
        if (gCloseRequested) {
            gCloseRequested = false;
            requestQuit(state);
        }
        endWindowLayoutFrame();  // GLINT_LOG_LAYOUT: the rectangles on screen, for the GUI tests
        ImGui::Render();
        const auto uiBuilt = std::chrono::steady_clock::now();

        // Window (ImGui) pixels to framebuffer pixels (HiDPI).
        const float pixelScale = windowSize.x > 0 ? framebuffer.x / windowSize.x : 1.0f;
        const glm::ivec2 viewportPixels{std::max(1, static_cast<int>(viewport.width * pixelScale)),
                                        std::max(1, static_cast<int>(viewport.height * pixelScale))};
        const glm::ivec2 viewportLowerLeft{static_cast<int>(viewport.x * pixelScale),
                                           static_cast<int>(statusHeight * pixelScale)};
        if (updateCompareView(state, renderer)) renderedSize = {0, 0};  // the compare panes used the renderer
        if (updatePresetSwatches(state.presetSwatches, renderer)) {  // so did a swatch; the next one on the next frame
            renderedSize = {0, 0};
            framesToDraw = std::max(framesToDraw, 2);
        }
        if (state.screenshotRequested) {  // uses the renderer: the viewport is drawn afresh below
            state.screenshotRequested = false;
            saveScreenshot(state, renderer, viewportPixels);
            renderedSize = {0, 0};
        }
        const bool changed = state.session.revision() != renderedRevision;
        RefreshPlan plan = refresh.plan({glfwGetTime(), changed, viewportPixels != renderedSize, gesture,
                                         state.settings.simplifyMeshesWhileDragging, state.waitingForPrograms});
        // A reduced-resolution preview (while dragging) skips MSAA, about 1.8x the frame on
        // llvmpipe; the full frame after the drag smooths the edges again.
        const Scene* drawn = &state.session.scene();
        Scene preview;
        const auto drawnAt = [&](int scale) {
            drawn = &state.session.scene();
            if (scale > 1 && drawn->msaaSamples > 1) {
                preview = *drawn;
                preview.msaaSamples = 1;
                drawn = &preview;
            }
            return (viewportPixels + scale - 1) / scale;
        };
        glm::ivec2 renderPixels = drawnAt(plan.pixelScale);
        bool waitedForPrograms = false;
        double renderMilliseconds = 0.0;  // this iteration's render (one band of a banded frame)
        if (plan.render) {
            // Programs still compiling in the background: a frame with their generic stand-ins is
            // drawn at reduced resolution (they are slower), or, where there is none or the frame
            // would refine a reduced one, the frame on screen stays until they arrive.
            using Ready = Renderer::ProgramsReady;
            Ready ready = renderer.programsReady(*drawn, renderPixels.x, renderPixels.y);
            if (ready == Ready::WithStandIns && plan.bands == 1 && plan.pixelScale < ViewportRefresh::kStandInPixelScale) {
                plan.pixelScale = ViewportRefresh::kStandInPixelScale;
                renderPixels = drawnAt(plan.pixelScale);
                ready = renderer.programsReady(*drawn, renderPixels.x, renderPixels.y);  // without MSAA, say
            }
            // Only where the targets still hold the frame on screen (nothing else drew with the renderer).
            const bool frameKept = renderedSize == viewportPixels;
            if (frameKept && (ready == Ready::No || (ready == Ready::WithStandIns && plan.bands > 1))) {
                plan.render = false;
                state.waitingForPrograms = waitedForPrograms = true;
            }
        }
        // What the viewport on screen shows: the targets' frame at this scale, but for a full frame's
        // missing bands (a new frame in place of one being refined is put on screen whole).
        const int scaleOnScreen = renderedScale;
        const bool bandsMissing = refresh.refining();
        RowBand rows;  // of a full frame drawn in bands
        if (plan.render) {
            const long long shadowMapRenders = renderer.shadowMapRenders();
            const auto start = std::chrono::steady_clock::now();
            // A full frame drawn in bands, top first: the reduced frame on screen is kept to show under it.
            if (plan.bands > 1) {
                if (plan.band == 0) {
                    reducedScale = renderedScale;
                    const glm::ivec2 reducedPixels = (viewportPixels + reducedScale - 1) / reducedScale;
                    reducedFrame.ensure(reducedPixels.x, reducedPixels.y, 1);
                    renderer.displayToScreen(drawn->display, {0, 0}, 1, reducedFrame.framebuffer());
                }
                rows = refineBandRows(plan.band, plan.bands, renderPixels.y, changedRows);
                refinedRows = renderPixels.y - rows.first;
            }
            const Status status = renderer.renderRadiance(*drawn, renderPixels.x, renderPixels.y, plan.detail, rows);
            noteRenderProblem(state, !status ? status.error().format() : renderer.shaderError());
            glFinish();
            renderMilliseconds = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            // A frame drawn in bands shows its bands' time so far, the whole frame's at the last.
            refinedMilliseconds = plan.band == 0 ? renderMilliseconds : refinedMilliseconds + renderMilliseconds;
            state.lastRenderMilliseconds = refinedMilliseconds;
            state.standInProgramsShown = renderer.standInProgramsDrawn();
            state.waitingForPrograms = state.standInProgramsShown > 0;
            // Only a material's objects redrawn: its time says nothing of a whole frame's.
            refresh.rendered(plan, renderMilliseconds, renderer.simplifiedMeshesDrawn() > 0 || state.standInProgramsShown > 0,
                             renderer.drewOnlyChanges());
            if (plan.bands == 1) {  // (a band's drawn pixels are only its own part of the rectangle)
                const std::optional<PixelRegion>& drawnPixels = renderer.drawnPixels();
                changedRows.reset();
                if (renderer.drewOnlyChanges() && drawnPixels)
                    changedRows = RowBand{drawnPixels->y * plan.pixelScale, drawnPixels->height * plan.pixelScale};
            }
            // Slow full frames: have the large meshes' stand-ins made now, ready for the first drag.
            if (refresh.fullFramesAreSlow() && state.settings.simplifyMeshesWhileDragging)
                renderer.prepareSimplifiedMeshes(state.session.scene());
            state.previewScale = plan.pixelScale;
            state.simplifiedMeshesShown = renderer.simplifiedMeshesDrawn();
            state.shadowMapsRedrawn = renderer.shadowMapRenders() != shadowMapRenders;
            state.triangleCount = renderer.trianglesDrawn();
            state.samplesNote = renderer.samplesNote(state.session.scene().msaaSamples);
            renderedSize = viewportPixels;
            renderedRevision = state.session.revision();
            renderedScale = plan.pixelScale;
            shownDisplay = drawn->display;
            framesToDraw = std::max(framesToDraw, 2);
        }
        // What changed on screen: the viewport's pixels the render drew (all of them at a new
        // scale), where the ui changed; all of it where the window does not keep its pixels, or
        // after it was exposed or resized or the viewport moved.
        const int shownScale = renderedScale;
        const glm::ivec2 shownSize = (renderedSize + shownScale - 1) / shownScale * shownScale;  // the copy's, whole radiance pixels
        const PixelRegion shownViewport{viewportLowerLeft.x, viewportLowerLeft.y, shownSize.x, shownSize.y};
        std::vector<PixelRegion> damage;
        uiDamage.collect(*ImGui::GetDrawData(), damage);
        if (plan.render) {
            // A band: its rows, which showed the reduced frame (all of it for a new frame in place of
            // one being refined, as the reduced frame kept under it is the targets' mix of both).
            const std::optional<PixelRegion>& drawnPixels = renderer.drawnPixels();
            if (plan.bands > 1 && (plan.band > 0 || !bandsMissing))
                damage.push_back({viewportLowerLeft.x, viewportLowerLeft.y + rows.first * shownScale, shownSize.x, rows.count * shownScale});
            else if (plan.bands == 1 && drawnPixels && shownScale == scaleOnScreen && !bandsMissing)
                damage.push_back({viewportLowerLeft.x + drawnPixels->x * shownScale, viewportLowerLeft.y + drawnPixels->y * shownScale,
                                  drawnPixels->width * shownScale, drawnPixels->height * shownScale});
            else
                damage.push_back(shownViewport);
            if (viewportCopied.width != shownViewport.width || viewportCopied.height != shownViewport.height)
                damage.push_back(viewportCopied);  // a copy at a coarser scale reached further
        }
        viewportCopied = shownViewport;
        const glm::ivec4 placing{viewportLowerLeft, viewportPixels};
        if (gExposed || placing != placed) wholeFrames = 2;
        const bool whole = !presentRegions || wholeFrames > 0;
        if (whole) damage = {PixelRegion{0, 0, framebuffer.x, framebuffer.y}};
        wholeFrames = std::max(0, wholeFrames - 1);
        gExposed = false;
        placed = placing;
        mergeOverlapping(damage);
        // Each changed rectangle drawn as the whole frame would be there: the window's colour under
        // the panels, the viewport (over the reduced frame while the full one is refined in bands:
        // the bands so far), the ui.
        const auto composeStart = std::chrono::steady_clock::now();
        for (const PixelRegion& rect : damage) {
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, framebuffer.x, framebuffer.y);
            glEnable(GL_SCISSOR_TEST);
            glScissor(rect.x, rect.y, rect.width, rect.height);
            glClearColor(kWindowClearColor[0], kWindowClearColor[1], kWindowClearColor[2], kWindowClearColor[3]);
            glClear(GL_COLOR_BUFFER_BIT);
            PixelRegion viewportPart = intersectionOf(rect, shownViewport);
            if (!viewportPart.empty() && refresh.refining()) {
                // The reduced frame where no band is drawn yet, the bands above it. Scaled, the
                // reduced frame's last column and row may reach past the viewport (up to scale − 1
                // pixels): the scissor keeps it inside.
                const int unrefinedRows = renderedSize.y - refinedRows;
                const PixelRegion unrefined =
                    intersectionOf(viewportPart, {viewportLowerLeft.x, viewportLowerLeft.y, renderedSize.x, unrefinedRows});
                if (!unrefined.empty()) {
                    glScissor(unrefined.x, unrefined.y, unrefined.width, unrefined.height);
                    glBindFramebuffer(GL_READ_FRAMEBUFFER, reducedFrame.framebuffer());
                    glBlitFramebuffer(0, 0, reducedFrame.width(), reducedFrame.height(), viewportLowerLeft.x, viewportLowerLeft.y,
                                      viewportLowerLeft.x + reducedFrame.width() * reducedScale,
                                      viewportLowerLeft.y + reducedFrame.height() * reducedScale, GL_COLOR_BUFFER_BIT, GL_NEAREST);
                    glBindFramebuffer(GL_FRAMEBUFFER, 0);
                }
                viewportPart = intersectionOf(viewportPart, {viewportLowerLeft.x, viewportLowerLeft.y + unrefinedRows,
                                                             renderedSize.x, refinedRows});
                glScissor(viewportPart.x, viewportPart.y, viewportPart.width, viewportPart.height);
            }
            if (viewportPart.width > 0 && viewportPart.height > 0) renderer.displayToScreen(shownDisplay, viewportLowerLeft, shownScale);
            glDisable(GL_SCISSOR_TEST);
        }
        if (logFrames) glFinish();  // so that the log can tell the phases apart
        const auto displayed = std::chrono::steady_clock::now();
        glViewport(0, 0, framebuffer.x, framebuffer.y);
        for (const PixelRegion& rect : damage) UiDamage::drawWithin(*ImGui::GetDrawData(), rect);
        if (logFrames) glFinish();
        const auto composed = std::chrono::steady_clock::now();
        long long pixelsPresented = 0;
        for (const PixelRegion& rect : damage) pixelsPresented += static_cast<long long>(rect.width) * rect.height;
        if (whole) platform->present();
        else for (const PixelRegion& rect : damage) platform->presentRegion(rect.x, rect.y, rect.width, rect.height);
        if (logFrames && plan.render) {
            glFinish();
            const auto now = std::chrono::steady_clock::now();
            const auto ms = [](auto from, auto to) { return std::chrono::duration<double, std::milli>(to - from).count(); };
            std::fprintf(stderr,
                         "glint frame: viewport %dx%d scale 1/%d render %.1f ms, input to presented frame %.1f ms, "
                         "%d simplified meshes, shadow maps %s, ui built %.1f ms, displayed %.1f ms, ui drawn %.1f ms, "
                         "presented %.1f ms at %.3f s, %lld pixels presented, band %d/%d, %d stand-in programs, %lld triangles\n",
                         viewportPixels.x, viewportPixels.y, renderedScale, renderMilliseconds, ms(frameStart, now),
                         state.simplifiedMeshesShown, state.shadowMapsRedrawn ? "redrawn" : "kept", ms(frameStart, uiBuilt),
                         ms(composeStart, displayed), ms(displayed, composed), ms(composed, now), glfwGetTime(), pixelsPresented,
                         plan.band + 1, plan.bands, state.standInProgramsShown, state.triangleCount);
        }
        if (logFrames && !plan.render && !waitedForPrograms)  // the UI alone (a progress bar, a menu)
            std::fprintf(stderr, "glint ui frame: input to presented %.1f ms\n",
                         std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
        if (logFrames && waitedForPrograms)
            std::fprintf(stderr, "glint programs: the frame waits for programs compiling in the background; input to presented %.1f ms\n",
                         std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count());
        secondsToAutosave = autosave(state, glfwGetTime(), autosaveInterval);
        // Refusals and status lines written before the scene's last change no longer hold.
        for (SceneMessage* message : {&state.statusMessage, &state.materialPanelMessage, &state.lightPanelMessage,
                                      &state.displayPanelMessage})
            message->expire(state.session.revision());
        if (const std::string title = windowTitle(state); title != shownTitle) {
            glfwSetWindowTitle(window, title.c_str());
            shownTitle = title;
        }
        clearKeyPresses();
        framesToDraw = gEventSeen ? 3 : framesToDraw - 1;
    }

    finishRecovery(state);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

}  // namespace glint
