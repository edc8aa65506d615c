// Renderer: draws a Scene with OpenGL 4.1 core into its own floating-point framebuffer
// (radiance, W/(sr·m²)), then runs the display pass into an 8-bit target or onto the screen.
// It never creates a context: it is handed a GlPlatform that is already current.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "gl/bounded_program_cache.h"
#include "gl/material_glsl.h"
#include "gl/custom_brdf_program.h"
#include "gl/measured_brdf_gpu.h"
#include "gl/environment_textures.h"
#include "gl/frame_plan.h"
#include "gl/frame_uniforms.h"
#include "gl/gpu_mesh_cache.h"
#include "gl/overlay_pass.h"
#include "gl/platform.h"
#include "gl/program_compiler.h"
#include "gl/renderer_options.h"
#include "gl/render_target.h"
#include "gl/shader_program.h"
#include "gl/surface_variant.h"
#include "gl/texture_cache.h"
#include "gl/shadow_maps.h"
#include "gl/transmission_pass.h"
#include "image/image.h"
#include "render/visibility.h"
#include "scene/scene.h"

namespace glint {

class Renderer {
public:
    // The radiance targets' format (the bare shading pass of `glint bench` writes the same).
    static constexpr GLenum kRadianceFormat = GL_RGBA32F;

    // Loads GL through the platform and builds the display program.
    static Result<std::unique_ptr<Renderer>> create(GlPlatform& platform, ShaderSources sources = ShaderSources());
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Draws the scene's radiance at width×height (MSAA per scene.msaaSamples, clamped to
    // maxSamples()). A shader that
    // fails to compile is reported and the model's last good program, if any, is used.
    // MeshDetail::Simplified draws large meshes by simplified stand-ins where they are ready, each
    // with about as many triangles as pixels it may cover (the editor, while the user drags;
    // gl/gpu_mesh_cache.h); headless renders draw every triangle.
    // `rows`: only those rows of the width×height frame are drawn (the editor refines a slow full
    // frame band by band); the others keep what the targets held.
    // A frame with transmissive materials (render/transmission_backdrop.h) draws the opaque objects
    // first, copies them into the transmission backdrop (gl/transmission_pass.h), then draws the
    // background and the transmissive objects, which look it up. A band that holds the top row draws the
    // opaque pass over the whole frame for the backdrop; the bands below it reuse that backdrop (the
    // editor draws a frame's bands top first).
    Status renderRadiance(const Scene& scene, int width, int height, MeshDetail detail = MeshDetail::Full,
                          RowBand rows = {});
    // Starts making the simplified stand-ins of the scene's large meshes on worker threads (the
    // editor, once a full frame proved slow), so that the next drag finds them ready; without it
    // Simplified frames draw the full meshes.
    void prepareSimplifiedMeshes(const Scene& scene);
    // Waits for the stand-ins being made (benchmarks).
    void finishSimplifiedMeshes();
    // Display pass into the offscreen 8-bit target (same size as the last radiance render), then
    // the overlays display.overlays asks for, over the meshes of the last radiance render. The
    // display pass itself is skipped when the last radiance render fused the same display settings.
    void displayOffscreen(const DisplaySettings& display);
    // How frames are drawn (gl/renderer_options.h: fused display, float image kept, specialised
    // programs, transmission backdrop, redrawing only changes); each frame reads them as it begins.
    RendererOptions& options() { return options_; }
    const RendererOptions& options() const { return options_; }
    // Whether the last renderRadiance drew only a material change's pixels (the editor does not
    // take its time for a whole frame's), and the pixels it drew: its band, the changed objects'
    // rectangle within it; none: all (the editor puts only those on screen again).
    bool drewOnlyChanges() const { return drewOnlyChanges_; }
    const std::optional<PixelRegion>& drawnPixels() const { return drawnPixels_; }
    // Specialised programs built in the background (the editor; gl/program_compiler.h): a
    // built-in model's program that programsReady() finds missing is built on the compiler's
    // worker, which then draws the objects that need it with a renderer of its own, so that
    // llvmpipe's machine code for it (made per context at the first draw) is in Mesa's shader
    // cache when this renderer first draws it. Meanwhile an object is drawn with its model's generic
    // program if this renderer has drawn that before (the same picture, slower: a stand-in), or
    // else its program is built here, as without a compiler. Headless renders have no compiler,
    // so every program is built before it draws.
    void compileInBackground(std::unique_ptr<ProgramCompiler> compiler);
    // Takes the programs the compiler has finished; true when any arrived (the editor redraws).
    bool adoptCompiledPrograms();
    // What drawing the scene at width×height would find (the editor asks before each frame, and
    // keeps the frame on screen rather than draw one that is not All or WithStandIns): every program
    // built; stand-ins for those still compiling; or programs that have no stand-in and would be
    // built on this thread. Has the compiler build the missing ones.
    enum class ProgramsReady { All, WithStandIns, No };
    ProgramsReady programsReady(const Scene& scene, int width, int height);
    // Objects the last renderRadiance drew with a stand-in program.
    int standInProgramsDrawn() const { return standInProgramsDrawn_; }
    // Display pass into the default framebuffer, at the given lower-left corner; a scaled copy of
    // the fused image when the last radiance render fused these settings (the editor fuses).
    // `pixelScale` > 1 enlarges each radiance pixel to pixelScale² screen pixels (the editor's
    // reduced-resolution preview while dragging).
    // `framebuffer`: another target than the screen (the editor keeps the reduced frame while it
    // refines the full one).
    void displayToScreen(const DisplaySettings& display, glm::ivec2 lowerLeft, int pixelScale = 1, GLuint framebuffer = 0);

    RadianceImage readRadiance() const;  // top row first
    DisplayImage readDisplay() const;    // top row first
    // The opaque pass the last frame's transmissive surfaces saw (base level; empty when the frame
    // had none): the CPU reference's input for the same frame (ReferenceOptions::backdrop).
    OpaquePassImage readTransmissionBackdrop() const;

    // Shaders on disk that changed since they were compiled are rebuilt on the next render.
    // Returns true when something changed (so the caller redraws).
    bool reloadChangedShaders();
    // Whether shaders are read from disk (and so may change while Glint runs).
    bool hotReloadsShaders() const { return sources_.readsFromDisk(); }
    // The shader error to show (empty when all compiled): a hot reload that failed, kept until its
    // program compiles again (the last good one draws meanwhile); else the last frame's.
    std::string shaderError() const;
    const std::string& description() const { return description_; }
    // The most MSAA samples this GL implementation offers for the radiance targets (GL_MAX_SAMPLES,
    // queried once). Requests above it render with this many; samplesNote() says so.
    int maxSamples() const { return maxSamples_; }
    // The samples a request renders with: clamped to 1..maxSamples().
    int samplesFor(int requested) const { return std::clamp(requested, 1, maxSamples_); }
    // What a user who asked for `requested` samples is told ("" when they render as asked).
    std::string samplesNote(int requested) const;
    // Triangles submitted by the last renderRadiance (proxy meshes included).
    long long trianglesDrawn() const { return trianglesDrawn_; }
    // Objects the last renderRadiance drew with a simplified stand-in.
    int simplifiedMeshesDrawn() const { return simplifiedMeshesDrawn_; }
    // Programs held for materials with a .brdf file and for measured materials (each bounded:
    // gl/bounded_program_cache.h).
    size_t customBrdfProgramCount() const { return customPrograms_.size(); }
    size_t measuredProgramCount() const { return measured_.programCount(); }
    // Material texture images on the GPU (uploaded once per file version).
    TextureCache& textureCache() { return textureCache_; }
    const ShaderSources& sources() const { return sources_; }
    // How many renders re-rendered shadow maps (only when shadowed lights or geometry change), and
    // how many maps they drew (only the lights that changed, unless the geometry did).
    long long shadowMapRenders() const { return shadowMaps_->renderCount(); }
    long long shadowMapsDrawn() const { return shadowMaps_->mapRenderCount(); }

private:
    struct SurfaceProgram {
        ShaderProgram program;
        std::vector<std::string> files;
        long long builtAt = 0;  // newest modification time of its files when built
        std::string reloadError;  // why the last hot reload of its files failed; empty when it compiled
        // Drawn in this context: llvmpipe compiles a program's machine code per context at its
        // first draw, so only a program drawn before is a quick stand-in.
        bool drawn = false;
    };
    // The program caches' capacities (gl/bounded_program_cache.h says how they are bounded).
    static constexpr size_t kSurfaceProgramCapacity = 64;
    static constexpr size_t kBackgroundProgramCapacity = 16;

    Renderer(GlPlatform& platform, ShaderSources sources);
    Result<ShaderProgram> buildBackgroundProgram(const std::string& prelude) const;
    Result<const ShaderProgram*> backgroundProgram(const std::string& prelude);
    // The display pass's program for these settings (specialised unless switched off); the
    // generic one when a specialised one fails to build.
    const ShaderProgram& displayProgram(const DisplaySettings& display);
    // Keyed by model, variant (MSAA, Gouraud, ray-cast sphere, specialisation) and which
    // parameters are textured (TexturedParams::mask).
    using SurfaceKey = std::tuple<BrdfModel, SurfaceVariant, std::uint64_t>;
    // A program the background compiler builds: `result` is set before `done`.
    struct PendingSurfaceProgram {
        std::atomic<bool> done{false};
        std::optional<Result<SurfaceProgram>> result;
    };
    Result<SurfaceProgram> buildSurfaceProgram(BrdfModel model, SurfaceVariant variant, TexturedParams textured) const;
    Result<const ShaderProgram*> surfaceProgram(BrdfModel model, SurfaceVariant variant, TexturedParams textured);
    // The surface program variant an object needs in a frame with these samples and frame defines,
    // drawn over the transmission backdrop or not.
    SurfaceVariant surfaceVariant(const SceneObject& object, const Material& material, int samples,
                                  const std::string& frameDefines, bool seesBackdrop) const;
    // Has the compiler build the programs not built or asked for already, then draw
    // `warmUpScene` (when given: the objects that need them) with its own renderer.
    void requestPrograms(const std::vector<SurfaceKey>& keys, std::shared_ptr<const Scene> warmUpScene);
    static constexpr int kWarmUpSize = 16;  // pixels a side of the warm-up draw
    // The generic program of a specialised key's model and variant, when it was drawn before; or null.
    SurfaceProgram* standInFor(const SurfaceKey& key);
    FrameUniforms uploadFrame(const Scene& scene, int width, int height);
    // The frame's specialisation defines (none when specialisation is off).
    std::string frameDefines(const FrameUniforms& packed, const Scene& scene, const std::optional<DisplaySettings>& fused) const;

    // The passes of renderRadiance, in order (gl/frame_plan.h decides which run and where).
    struct FrameDraw;
    void updateShadowMaps(const Scene& scene, int width, int height, MeshDetail detail);
    int allocateSamples(const Scene& scene, int width, int height);
    void adoptPlan(const FramePlan& plan);
    void bindTargets(const FramePlan& plan, const RenderTarget& drawTarget);
    void beginFrame(FrameDraw& draw);
    void clearColour(const FrameDraw& draw);
    void captureBackdrop(FrameDraw& draw);
    void drawBackground(FrameDraw& draw);
    void drawObject(FrameDraw& draw, size_t position);
    Result<const ShaderProgram*> programFor(const Material& material, const SurfaceVariant& variant);
    Status bindObject(const FrameDraw& draw, const ShaderProgram& shader, const SceneObject& object, const Material& material);
    void drawMesh(FrameDraw& draw, size_t objectIndex, const BoundingSphere& bounds);
    void rememberDrawn(const GpuMesh& mesh, const SceneObject& object);
    void resolveMultisample(const FramePlan& plan);
    void holdFrame(const Scene& scene, const FramePlan& plan, RowBand rows, const Status& result, std::optional<HeldFrame>& held);
    long long newestModification(const std::vector<std::string>& files) const;

    GlPlatform& platform_;
    ShaderSources sources_;
    std::string description_;
    std::string frameShaderError_;  // a program the last frame needed that did not compile
    std::string displayReloadError_, backgroundReloadError_;  // as SurfaceProgram::reloadError
    BoundedProgramCache<SurfaceKey, SurfaceProgram> surfacePrograms_{kSurfaceProgramCapacity};
    std::map<SurfaceKey, std::shared_ptr<PendingSurfaceProgram>> pendingPrograms_;
    std::set<SurfaceKey> failedInBackground_;  // built here instead, which reports the error
    int standInProgramsDrawn_ = 0;
    CustomBrdfPrograms customPrograms_;  // materials with a .brdf file
    MeasuredBrdfGpu measured_;  // materials with a MERL table
    std::map<std::string, ShaderProgram> displayPrograms_;  // by specialisation prelude
    std::vector<std::string> displayFiles_;
    long long displayBuiltAt_ = 0;
    BoundedProgramCache<std::string, ShaderProgram> backgroundPrograms_{kBackgroundProgramCapacity};  // by specialisation prelude
    std::uint64_t framesRendered_ = 0;  // radiance frames begun
    std::vector<std::string> backgroundFiles_;
    long long backgroundBuiltAt_ = 0;
    GLuint uniformBuffers_[3] = {0, 0, 0};
    GLuint emptyVertexArray_ = 0;
    std::unique_ptr<GpuMeshCache> meshes_;
    OverlayPass overlayPass_;
    std::vector<OverlayMesh> drawnMeshes_;  // what the last renderRadiance drew, for the overlays
    TextureCache textureCache_;
    std::unique_ptr<ShadowMaps> shadowMaps_;
    std::unique_ptr<TransmissionPass> transmission_;
    long long trianglesDrawn_ = 0;
    int simplifiedMeshesDrawn_ = 0;
    std::unique_ptr<EnvironmentTextures> environment_;  // environment map textures and block
    int maxSamples_ = 1;
    RendererOptions options_;
    bool drewOnlyChanges_ = false;
    std::optional<PixelRegion> drawnPixels_;
    // A single-sample frame: the float radiance (with depth) and the 8-bit display image, and what
    // they hold (drawn directly, or the multisample target's frame resolved).
    struct SingleSampleTargets {
        RenderTarget radiance{kRadianceFormat, true};
        RenderTarget display{GL_RGBA8, false};
        std::optional<HeldFrame> held;
        bool resolveHeld = false;
        std::uint64_t lastUsed = 0;  // framesRendered_ of the last frame drawn into them
    };
    // Three sizes are kept: the editor's full frames and its reduced frames while dragging (½ and
    // ¼ resolution) each draw into targets that still hold their last frame, with no reallocation.
    SingleSampleTargets& targets() { return singleSample_[current_]; }
    const SingleSampleTargets& targets() const { return singleSample_[current_]; }
    void useTargetsOfSize(int width, int height);
    SingleSampleTargets singleSample_[3];
    int current_ = 0;  // the targets the last renderRadiance drew into
    std::optional<HeldFrame> multisampleHeld_;
    // The frame the targets of a frame with these samples hold.
    std::optional<HeldFrame>& heldFrame(int samples) { return samples > 1 ? multisampleHeld_ : targets().held; }
    bool radianceWritten_ = true;  // by the last renderRadiance
    std::optional<DisplaySettings> fusedDisplay_;  // what the display target holds, when fused
    RenderTarget multisampleTarget_{kRadianceFormat, true};
    std::unique_ptr<Renderer> warmUp_;  // made, used and deleted on the compiler's worker only
    std::unique_ptr<ProgramCompiler> compiler_;  // last: its worker stops before the rest goes
};

}  // namespace glint
