// The OpenGL renderer (see renderer.h).
// Sections: creation · programs · meshes · per-frame uniforms · drawing (the frame plan, then one
// function per pass) · display · readback.
#include "gl/renderer.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "display/display_chain.h"
#include "geometry/mesh.h"
#include "geometry/shape_mesh.h"
#include "gl/frame_plan.h"
#include "gl/frame_uniforms.h"
#include "gl/gl_loader.h"
#include "gl/material_glsl.h"
#include "gl/material_textures.h"
#include "gl/shader_specialisation.h"
#include "render/sphere_occlusion.h"
#include "scene/plane_edge_fade.h"
#include "gl/uniform_blocks.h"
#include "math/constants.h"
#include "render/visibility.h"

namespace glint {
namespace {

// The proxy mesh drawn for an analytic sphere: a fixed tessellation, enlarged so that it
// circumscribes the sphere (each face's circumcircle spans at most π/S + π/R radians).
constexpr int kProxySegments = 48, kProxyRings = 24;
const float kProxyScale = 1.001f / std::cos(kPi / kProxySegments + kPi / kProxyRings);

// The display chain's uniforms (shaders/common/display_encode.glsl) of a program that has them.
void setDisplayUniforms(const ShaderProgram& program, const DisplaySettings& display) {
    glUniform1f(program.uniform("exposureScale"), std::exp2(display.exposureStops));
    glUniform1i(program.uniform("transfer"), static_cast<int>(display.transfer));  // order of enum Transfer
    glUniform1f(program.uniform("gamma"), display.gamma);
    glUniform1i(program.uniform("toneMap"), static_cast<int>(display.toneMap));
    glUniform1i(program.uniform("levels"), display.levels);  // display_quantise.glsl
    glUniform1i(program.uniform("dither"), static_cast<int>(display.dither));
}

// Same encoding (the overlays are drawn over the encoded image afterwards, fused or not).
bool sameDisplay(const DisplaySettings& a, const DisplaySettings& b) {
    static_assert(sizeof(DisplaySettings) == 7 * sizeof(float) + sizeof(OverlaySettings),
                  "a new display setting: compare it here");
    return a.exposureStops == b.exposureStops && a.transfer == b.transfer && a.gamma == b.gamma && a.toneMap == b.toneMap &&
           a.levels == b.levels && a.dither == b.dither && a.levelsRamp == b.levelsRamp;
}

// The radiance passes' half of the fused display (display_output.glsl).
void setFusedDisplayUniforms(const ShaderProgram& program, const std::optional<DisplaySettings>& fused) {
    glUniform1i(program.uniform("fusedDisplay"), fused ? 1 : 0);
    if (fused) setDisplayUniforms(program, *fused);
}

}  // namespace

// --- creation -------------------------------------------------------------------------------

Renderer::Renderer(GlPlatform& platform, ShaderSources sources)
    : platform_(platform), sources_(std::move(sources)),
      meshes_(std::make_unique<GpuMeshCache>(kProxySegments, kProxyRings, kProxyScale)) {}

Result<std::unique_ptr<Renderer>> Renderer::create(GlPlatform& platform, ShaderSources sources) {
    platform.makeCurrent();
    if (Status loaded = loadGlFunctions(platform); !loaded) return loaded.error();
    std::unique_ptr<Renderer> renderer(new Renderer(platform, std::move(sources)));
    renderer->description_ = glDescription();
    glGetIntegerv(GL_MAX_SAMPLES, &renderer->maxSamples_);
    renderer->maxSamples_ = std::max(1, renderer->maxSamples_);
    renderer->environment_ = std::make_unique<EnvironmentTextures>();
    auto program = ShaderProgram::build(renderer->sources_, "fullscreen.vert", "display.frag");
    if (!program) return program.error();
    renderer->displayPrograms_.emplace("", std::move(*program));  // the generic one
    renderer->displayFiles_ = {"fullscreen.vert", "display.frag"};
    renderer->displayBuiltAt_ = renderer->newestModification(renderer->displayFiles_);
    auto background = renderer->backgroundProgram("");  // the generic one: the shaders compile
    if (!background) return background.error();
    renderer->backgroundFiles_ = {"fullscreen.vert"};
    if (auto assembled = assembleShader(renderer->sources_, "background.frag"))
        renderer->backgroundFiles_.insert(renderer->backgroundFiles_.end(), assembled->files.begin(), assembled->files.end());
    renderer->backgroundBuiltAt_ = renderer->newestModification(renderer->backgroundFiles_);
    auto overlays = OverlayPass::create(renderer->sources_);
    if (!overlays) return overlays.error();
    renderer->overlayPass_ = std::move(*overlays);
    glGenBuffers(3, renderer->uniformBuffers_);
    const GLsizeiptr sizes[3] = {sizeof(FrameBlockStd140), sizeof(LightBlockStd140), sizeof(MaterialBlockStd140)};
    for (int i = 0; i < 3; ++i) {
        glBindBuffer(GL_UNIFORM_BUFFER, renderer->uniformBuffers_[i]);
        glBufferData(GL_UNIFORM_BUFFER, sizes[i], nullptr, GL_DYNAMIC_DRAW);
        glBindBufferBase(GL_UNIFORM_BUFFER, i, renderer->uniformBuffers_[i]);
    }
    glGenVertexArrays(1, &renderer->emptyVertexArray_);
    auto shadowMaps = ShadowMaps::create(renderer->sources_);
    if (!shadowMaps) return shadowMaps.error();
    renderer->shadowMaps_ = std::move(*shadowMaps);
    auto transmission = TransmissionPass::create(renderer->sources_);
    if (!transmission) return transmission.error();
    renderer->transmission_ = std::move(*transmission);
    if (Status errors = takeGlErrors("renderer creation"); !errors) return errors.error();
    return renderer;
}

Renderer::~Renderer() {
    compiler_.reset();  // its worker may be building a program
    platform_.makeCurrent();
    meshes_.reset();
    glDeleteBuffers(3, uniformBuffers_);
    glDeleteVertexArrays(1, &emptyVertexArray_);
}

// --- programs -------------------------------------------------------------------------------

long long Renderer::newestModification(const std::vector<std::string>& files) const {
    long long newest = 0;
    for (const std::string& file : files) newest = std::max(newest, sources_.modificationTime(file));
    return newest;
}

Result<ShaderProgram> Renderer::buildBackgroundProgram(const std::string& prelude) const {
    auto program = ShaderProgram::build(sources_, "fullscreen.vert", "background.frag", prelude);
    if (program) program->bindBlock("FrameBlock", kFrameBinding);
    if (program) EnvironmentTextures::connect(*program);
    return program;
}

Result<const ShaderProgram*> Renderer::backgroundProgram(const std::string& prelude) {
    if (ShaderProgram* found = backgroundPrograms_.use(prelude, framesRendered_)) return found;
    auto built = buildBackgroundProgram(prelude);
    if (!built) return built.error();
    return &backgroundPrograms_.insert(prelude, std::move(*built), framesRendered_);
}

Result<Renderer::SurfaceProgram> Renderer::buildSurfaceProgram(BrdfModel model, SurfaceVariant variant,
                                                              TexturedParams textured) const {
    const ModelInfo& info = modelInfo(model);
    const std::string prelude = variant.prelude();
    const GeneratedShaderFiles generated = {{"generated/material.glsl", generateMaterialGlsl(info, textured)}};
    auto program = ShaderProgram::build(sources_, "surface.vert", "surface.frag", prelude, generated);
    if (!program) return program.error();
    program->bindBlock("FrameBlock", kFrameBinding);
    program->bindBlock("LightBlock", kLightBinding);
    program->bindBlock("MaterialBlock", kMaterialBinding);
    EnvironmentTextures::connect(*program);
    SurfaceProgram entry{std::move(*program), {}, 0};
    if (auto assembled = assembleShader(sources_, "surface.vert", prelude, generated)) entry.files = assembled->files;
    if (auto assembled = assembleShader(sources_, "surface.frag", prelude, generated))
        entry.files.insert(entry.files.end(), assembled->files.begin(), assembled->files.end());
    entry.builtAt = newestModification(entry.files);
    return entry;
}

Result<const ShaderProgram*> Renderer::surfaceProgram(BrdfModel model, SurfaceVariant variant, TexturedParams textured) {
    const SurfaceKey key{model, variant, textured.mask};
    if (SurfaceProgram* found = surfacePrograms_.use(key, framesRendered_)) {
        found->drawn = true;
        return &found->program;
    }
    if (compiler_ && !failedInBackground_.count(key)) {
        if (SurfaceProgram* standIn = standInFor(key)) {
            requestPrograms({key}, nullptr);
            ++standInProgramsDrawn_;
            return &standIn->program;
        }
    }
    auto built = buildSurfaceProgram(model, variant, textured);
    if (!built) return built.error();
    built->drawn = true;
    return &surfacePrograms_.insert(key, std::move(*built), framesRendered_).program;
}

SurfaceVariant Renderer::surfaceVariant(const SceneObject& object, const Material& material, int samples,
                                        const std::string& frameDefines, bool seesBackdrop) const {
    const bool triangles = drawnAsTriangles(object.shape, object.interpolation);
    const bool sphere = !triangles && std::holds_alternative<SphereShape>(object.shape);
    const AnalyticMaterial* analytic = material.analytic();
    const auto* plane = std::get_if<PlaneShape>(&object.shape);
    return {samples, object.interpolation == SurfaceInterpolation::Gouraud, sphere, plane && planeEdgeFadeRadii(*plane).y > 0.0f,
            (options_.specialisePrograms && analytic ? frameDefines + materialSpecialisation(*analytic) : frameDefines) +
                (seesBackdrop ? TransmissionPass::kProgramDefine : "")};
}

// --- programs built in the background -------------------------------------------------------

Renderer::SurfaceProgram* Renderer::standInFor(const SurfaceKey& key) {
    auto generic = key;
    std::get<SurfaceVariant>(generic).specialisation.clear();
    if (generic == key) return nullptr;
    SurfaceProgram* found = surfacePrograms_.use(generic, framesRendered_);  // used as the stand-in
    return found && found->drawn ? found : nullptr;
}

void Renderer::compileInBackground(std::unique_ptr<ProgramCompiler> compiler) {
    compiler_ = std::move(compiler);
    if (compiler_) compiler_->atStop([this] { warmUp_.reset(); });
}

void Renderer::requestPrograms(const std::vector<SurfaceKey>& keys, std::shared_ptr<const Scene> warmUpScene) {
    std::vector<std::pair<SurfaceKey, std::shared_ptr<PendingSurfaceProgram>>> batch;
    for (const SurfaceKey& key : keys) {
        if (surfacePrograms_.contains(key) || pendingPrograms_.count(key)) continue;
        batch.emplace_back(key, std::make_shared<PendingSurfaceProgram>());
        pendingPrograms_.insert(batch.back());
    }
    if (batch.empty()) return;
    // The same programs and targets as here; each warm-up scene is drawn once, with nothing to redraw.
    RendererOptions warmUpOptions = options_;
    warmUpOptions.redrawOnlyChanges = false;
    compiler_->submit(
        [this, batch, warmUpScene, warmUpOptions](GlPlatform& worker) {
            for (const auto& [key, pending] : batch) {
                const auto& [model, variant, textured] = key;
                pending->result = buildSurfaceProgram(model, variant, {textured});
            }
            // llvmpipe makes a program's machine code per context, at its first draw, and keeps it in
            // Mesa's shader cache: drawn here first, with the same targets, textures and state,
            // the renderer's first draw finds it there instead of compiling it.
            if (warmUpScene && !warmUp_)
                if (auto created = Renderer::create(worker, sources_)) warmUp_ = std::move(*created);
            if (warmUpScene && warmUp_) {
                warmUp_->options() = warmUpOptions;
                (void)warmUp_->renderRadiance(*warmUpScene, kWarmUpSize, kWarmUpSize);
                glFinish();
            }
            for (const auto& entry : batch) entry.second->done.store(true, std::memory_order_release);
        },
        ProgramCompiler::Priority::Urgent);
}

bool Renderer::adoptCompiledPrograms() {
    bool arrived = false;
    for (auto entry = pendingPrograms_.begin(); entry != pendingPrograms_.end();) {
        PendingSurfaceProgram& pending = *entry->second;
        if (!pending.done.load(std::memory_order_acquire)) {
            ++entry;
            continue;
        }
        if (!*pending.result) {
            failedInBackground_.insert(entry->first);
        } else if (!surfacePrograms_.contains(entry->first)) {
            platform_.makeCurrent();
            surfacePrograms_.insert(entry->first, std::move(**pending.result), framesRendered_);
            arrived = true;
        }
        entry = pendingPrograms_.erase(entry);
    }
    return arrived;
}

const ShaderProgram& Renderer::displayProgram(const DisplaySettings& display) {
    const std::string prelude = options_.specialisePrograms ? displaySpecialisation(display) : "";
    if (auto found = displayPrograms_.find(prelude); found != displayPrograms_.end()) return found->second;
    auto built = ShaderProgram::build(sources_, "fullscreen.vert", "display.frag", prelude);
    if (!built) {
        frameShaderError_ = built.error().format();
        return displayPrograms_.at("");
    }
    return displayPrograms_.insert_or_assign(prelude, std::move(*built)).first->second;
}

std::string Renderer::shaderError() const {
    std::string reloadError = !displayReloadError_.empty() ? displayReloadError_ : backgroundReloadError_;
    surfacePrograms_.forEach([&](const SurfaceKey&, const SurfaceProgram& entry) {
        if (reloadError.empty()) reloadError = entry.reloadError;
    });
    return !reloadError.empty() ? reloadError : frameShaderError_;
}

bool Renderer::reloadChangedShaders() {
    if (!sources_.readsFromDisk()) return false;
    bool changed = false;
    // Whether `files` changed since `builtAt`, which then becomes their newest modification.
    const auto outdated = [&](const std::vector<std::string>& files, long long& builtAt) {
        const long long newest = newestModification(files);
        if (newest <= builtAt) return false;
        builtAt = newest;
        return changed = true;
    };
    // A program whose files changed is rebuilt; when that fails, the last good one stays.
    surfacePrograms_.forEach([&](const SurfaceKey& key, SurfaceProgram& entry) {
        if (!outdated(entry.files, entry.builtAt)) return;
        const auto& [model, variant, textured] = key;
        if (auto rebuilt = buildSurfaceProgram(model, variant, {textured})) entry = std::move(*rebuilt);
        else entry.reloadError = rebuilt.error().format();
    });
    if (outdated(displayFiles_, displayBuiltAt_)) {
        displayReloadError_.clear();
        for (auto& [prelude, program] : displayPrograms_) {
            if (auto rebuilt = ShaderProgram::build(sources_, "fullscreen.vert", "display.frag", prelude))
                program = std::move(*rebuilt);
            else displayReloadError_ = rebuilt.error().format();
        }
    }
    if (outdated(backgroundFiles_, backgroundBuiltAt_)) {
        backgroundReloadError_.clear();
        backgroundPrograms_.forEach([&](const std::string& prelude, ShaderProgram& program) {
            if (auto rebuilt = buildBackgroundProgram(prelude)) program = std::move(*rebuilt);
            else backgroundReloadError_ = rebuilt.error().format();
        });
    }
    if (changed) {
        for (SingleSampleTargets& kept : singleSample_) kept.held.reset();
        multisampleHeld_.reset();
    }
    return changed;
}

// --- meshes ---------------------------------------------------------------------------------

void Renderer::prepareSimplifiedMeshes(const Scene& scene) {
    platform_.makeCurrent();
    for (size_t i = 0; i < scene.objects.size(); ++i) meshes_->prepareSimplified(i, scene.objects[i]);
}

void Renderer::finishSimplifiedMeshes() { meshes_->finishSimplified(); }

std::string Renderer::samplesNote(int requested) const {
    if (requested <= maxSamples_) return {};
    return "MSAA " + std::to_string(requested) + " asked; this OpenGL offers at most " + std::to_string(maxSamples_) +
           " samples, so " + std::to_string(maxSamples_) + " are used";
}

// --- per-frame uniforms ---------------------------------------------------------------------

FrameUniforms Renderer::uploadFrame(const Scene& scene, int width, int height) {
    const FrameUniforms packed = packFrameUniforms(scene, width, height);
    glBindBuffer(GL_UNIFORM_BUFFER, uniformBuffers_[kFrameBinding]);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof packed.frame, &packed.frame);
    glBindBuffer(GL_UNIFORM_BUFFER, uniformBuffers_[kLightBinding]);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof packed.lights, &packed.lights);
    return packed;
}

std::string Renderer::frameDefines(const FrameUniforms& packed, const Scene& scene, const std::optional<DisplaySettings>& fused) const {
    return options_.specialisePrograms ? frameSpecialisation(packed, shadowMaps_->block(), scene.environment, fused) : "";
}

Renderer::ProgramsReady Renderer::programsReady(const Scene& scene, int width, int height) {
    if (!compiler_) return ProgramsReady::All;
    // As renderRadiance plans a whole frame (with the shadow maps of the frame before).
    const FramePlan plan = planFrame(scene, {width, height, samplesFor(scene.msaaSamples)}, options_, {});
    const std::string defines = frameDefines(packFrameUniforms(scene, width, height), scene, plan.fusedDisplay);
    ProgramsReady ready = ProgramsReady::All;
    std::vector<SurfaceKey> missing;
    auto warmUpScene = std::make_shared<Scene>(scene);  // with the objects that need them
    warmUpScene->objects.clear();
    for (size_t position = 0; position < plan.drawOrder.size(); ++position) {
        const SceneObject& object = scene.objects[plan.drawOrder[position]];
        const Material& material = scene.materials.at(object.materialIndex);
        const AnalyticMaterial* analytic = material.analytic();
        if (!analytic) continue;
        const SurfaceVariant variant = surfaceVariant(object, material, plan.targets.samples, defines, plan.seesBackdrop(position));
        const SurfaceKey key{analytic->model, variant, TexturedParams::of(*analytic).mask};
        if (surfacePrograms_.contains(key) || failedInBackground_.count(key)) continue;
        missing.push_back(key);
        warmUpScene->objects.push_back(object);
        ready = standInFor(key) && ready != ProgramsReady::No ? ProgramsReady::WithStandIns : ProgramsReady::No;
    }
    if (!missing.empty()) requestPrograms(missing, std::move(warmUpScene));
    return ready;
}

// --- drawing --------------------------------------------------------------------------------

// One frame being drawn: its plan and what its passes share.
struct Renderer::FrameDraw {
    const Scene& scene;
    const FramePlan& plan;
    MeshDetail detail;
    RenderTarget& target;  // the multisample target, or the single-sample radiance target
    FrameUniforms packed;
    std::string frameDefines;  // the frame's specialisation (none when switched off)
    glm::mat4 viewProjection;
    std::vector<glm::vec4> occluders;  // render/sphere_occlusion.h
    std::vector<float> sampleOffsets;  // the MSAA sample positions the shaders use
    // Depth is cleared before the first draw that tests it, not when nothing is drawn (an empty
    // frame is then one clear of the 8-bit image); only what was drawn reads it (the overlays).
    // An objects-only frame draws over the held depth.
    bool depthCleared = plan.objectsOnly;
    Status result = success();

    void clearDepthOnce() {
        if (!depthCleared) glClear(GL_DEPTH_BUFFER_BIT);
        depthCleared = true;
    }
    void fail(const Diagnostic& error) { result = error; }
};

namespace {

// Clears, draws and the MSAA resolve keep to the band or the changed pixels; none: all.
void scissorTo(const std::optional<PixelRegion>& rect) {
    if (rect) {
        glEnable(GL_SCISSOR_TEST);
        glScissor(rect->x, rect->y, rect->width, rect->height);
    } else {
        glDisable(GL_SCISSOR_TEST);
    }
}

// The analytic sphere an object's program ray-casts inside its proxy; null for triangles.
const SphereShape* rayCastSphere(const SceneObject& object) {
    return drawnAsTriangles(object.shape, object.interpolation) ? nullptr : std::get_if<SphereShape>(&object.shape);
}

// What is drawn: the sphere's proxy (which circumscribes it) or the shape's triangles.
BoundingSphere drawnBounds(const SceneObject& object) {
    const SphereShape* sphere = rayCastSphere(object);
    return sphere ? BoundingSphere{sphere->center, sphere->radius * kProxyScale} : boundingSphere(object.shape);
}

}  // namespace

void Renderer::useTargetsOfSize(int width, int height) {
    const auto ofSize = [&](const SingleSampleTargets& kept) { return kept.radiance.width() == width && kept.radiance.height() == height; };
    const auto found = std::find_if(std::begin(singleSample_), std::end(singleSample_), ofSize);
    // Else the least recently used targets are remade at this size.
    const auto chosen = found != std::end(singleSample_)
                            ? found
                            : std::min_element(std::begin(singleSample_), std::end(singleSample_),
                                               [](const SingleSampleTargets& a, const SingleSampleTargets& b) { return a.lastUsed < b.lastUsed; });
    current_ = static_cast<int>(chosen - std::begin(singleSample_));
    targets().lastUsed = framesRendered_;
    if (found != std::end(singleSample_)) return;
    targets().radiance.ensure(width, height, 1);
    targets().held.reset();
    targets().resolveHeld = false;
}

Status Renderer::renderRadiance(const Scene& scene, int width, int height, MeshDetail detail, RowBand rows) {
    platform_.makeCurrent();
    ++framesRendered_;  // programs looked up from here on belong to this frame (the program caches spare them)
    GLINT_CHECK(width > 0 && height > 0);
    updateShadowMaps(scene, width, height, detail);
    useTargetsOfSize(width, height);
    const int samples = allocateSamples(scene, width, height);
    std::optional<HeldFrame>& held = heldFrame(samples);
    const HeldState holds{held ? &*held : nullptr, targets().resolveHeld, transmission_->holds(width, height)};
    const FramePlan plan = planFrame(scene, {width, height, samples, rows}, options_, holds);
    adoptPlan(plan);
    RenderTarget& drawTarget = samples > 1 ? multisampleTarget_ : targets().radiance;
    bindTargets(plan, drawTarget);
    FrameDraw draw{scene, plan, detail, drawTarget, uploadFrame(scene, width, height)};
    beginFrame(draw);
    for (size_t position = 0; position < plan.drawOrder.size(); ++position) {
        if (position == plan.firstTransmissive && plan.capturesBackdrop) captureBackdrop(draw);
        drawObject(draw, position);
    }
    glDisable(GL_CULL_FACE);
    if (plan.drawsBackgroundPass && !plan.capturesBackdrop) drawBackground(draw);
    if (samples > 1) resolveMultisample(plan);
    glDisable(GL_SCISSOR_TEST);
    targets().resolveHeld = samples > 1 && (!plan.region || plan.changesOnly());
    if (samples > 1) targets().held.reset();  // the resolve overwrote the single-sample frame's float image
    holdFrame(scene, plan, rows, draw.result, held);
    if (draw.result) frameShaderError_.clear();
    // An object was left out: the display pass runs again, from the float image where there is one.
    else if (radianceWritten_) fusedDisplay_.reset();
    if (Status errors = takeGlErrors("renderRadiance"); !errors) return errors;
    return draw.result;
}

// --- drawing: the passes --------------------------------------------------------------------

// Drag frames draw the shadow maps (when they must be drawn at all) from the finest stand-ins,
// with about two texels a side per pixel of the frame's larger side.
void Renderer::updateShadowMaps(const Scene& scene, int width, int height, MeshDetail detail) {
    const size_t shadowBudget = detail == MeshDetail::Full ? kEveryTriangle : kSimplifiedTriangles[0];
    const auto meshOf = [&](size_t i) -> const GpuMesh& { return meshes_->forObject(i, scene.objects[i], shadowBudget); };
    int dragResolution = 256;
    while (dragResolution < 2 * std::max(width, height)) dragResolution *= 2;
    shadowMaps_->update(scene, meshOf, detail, dragResolution);
}

// The implementation may allocate more samples than asked (a count it has): the shaders and
// sample positions follow what it allocated.
int Renderer::allocateSamples(const Scene& scene, int width, int height) {
    const int requested = samplesFor(scene.msaaSamples);
    if (requested == 1) return 1;
    multisampleTarget_.ensure(width, height, requested);
    return multisampleTarget_.allocatedSamples();
}

// What the renderer keeps of the plan for the display pass, the readback and the editor.
void Renderer::adoptPlan(const FramePlan& plan) {
    if (!plan.showsBackdrop) transmission_->forget();
    fusedDisplay_ = plan.fusedDisplay;
    if (fusedDisplay_) targets().display.ensure(plan.targets.width, plan.targets.height, 1);
    radianceWritten_ = plan.targets.radianceWritten;
    drewOnlyChanges_ = plan.changesOnly();
    drawnPixels_ = plan.drawnPixels;
}

void Renderer::bindTargets(const FramePlan& plan, const RenderTarget& drawTarget) {
    // Fused display: the 8-bit target becomes the radiance framebuffer's second attachment,
    // attached or detached on every render, so that an MSAA resolve into it never reaches it.
    glBindFramebuffer(GL_FRAMEBUFFER, targets().radiance.framebuffer());
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, fusedDisplay_ ? targets().display.colorTexture() : 0, 0);
    const GLenum drawBuffers[2] = {radianceWritten_ ? GLenum{GL_COLOR_ATTACHMENT0} : GLenum{GL_NONE}, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(fusedDisplay_ ? 2 : 1, drawBuffers);
    glBindFramebuffer(GL_FRAMEBUFFER, drawTarget.framebuffer());
    glViewport(0, 0, plan.targets.width, plan.targets.height);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    scissorTo(plan.capturesBackdrop ? std::nullopt : plan.region);  // the backdrop's opaque pass covers the frame
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    // GL_LEQUAL: an object drawn again over the held frame (objectsOnly) passes where it was drawn
    // before, its depth being the same. One depth function for every frame, as llvmpipe compiles a
    // program again for another (a stall of about 300 ms on the first such frame).
    glDepthFunc(GL_LEQUAL);
    if (plan.targets.samples > 1) glEnable(GL_MULTISAMPLE);
}

// The frame's uniforms and clears, and what every object's draw reads.
void Renderer::beginFrame(FrameDraw& draw) {
    const Scene& scene = draw.scene;
    environment_->prepare(scene.environment);  // uploads only when the map changed
    draw.frameDefines = frameDefines(draw.packed, scene, fusedDisplay_);
    clearColour(draw);
    for (int i = 0; i < draw.plan.targets.samples && draw.plan.targets.samples > 1; ++i) {
        float position[2];
        glGetMultisamplefv(GL_SAMPLE_POSITION, i, position);
        draw.sampleOffsets.insert(draw.sampleOffsets.end(), position, position + 2);
    }
    draw.viewProjection = scene.camera.viewProjection(static_cast<float>(draw.plan.targets.width) / draw.plan.targets.height);
    draw.occluders = occludingSpheres(scene);
    trianglesDrawn_ = 0;
    simplifiedMeshesDrawn_ = 0;
    standInProgramsDrawn_ = 0;
    meshes_->releaseUnused();
    drawnMeshes_.clear();
}

// A frame that captures the backdrop draws its opaque objects over a clear of zero coverage; a
// uniform background is a clear (as cheap as a frame can be), not a pass.
void Renderer::clearColour(const FrameDraw& draw) {
    const GLfloat noCoverage[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    if (draw.plan.capturesBackdrop) glClearBufferfv(GL_COLOR, 0, noCoverage);
    if (!draw.plan.clearsBackground) return;
    const glm::vec3 color = draw.scene.background.color;
    const GLfloat radiance[4] = {color.r, color.g, color.b, 1.0f};
    if (radianceWritten_) glClearBufferfv(GL_COLOR, 0, radiance);
    if (fusedDisplay_) {  // the display chain's twin (display/display_chain.h) gives the stored 8-bit value
        const glm::vec3 encoded = encodeForDisplay(color, *fusedDisplay_);
        GLfloat stored[4] = {0.0f, 0.0f, 0.0f, 1.0f};
        for (int c = 0; c < 3; ++c) stored[c] = displayValue8(encoded[c], *fusedDisplay_, 0, 0) / 255.0f;
        glClearBufferfv(GL_COLOR, 1, stored);
    }
}

// Copies the opaque pass into the backdrop, then draws the background before the transmissive
// objects (which look it up), within the frame's region again.
void Renderer::captureBackdrop(FrameDraw& draw) {
    const int width = draw.plan.targets.width, height = draw.plan.targets.height;
    transmission_->capture(draw.target.framebuffer(), width, height, emptyVertexArray_);
    glBindFramebuffer(GL_FRAMEBUFFER, draw.target.framebuffer());
    glViewport(0, 0, width, height);
    scissorTo(draw.plan.region);
    glDisable(GL_CULL_FACE);
    draw.clearDepthOnce();  // with the depth mask on: the background pass turns it off
    drawBackground(draw);
}

// Any background other than a uniform one (sky, environment, dithered), only where no object
// wrote depth: drawn at depth 1 with GL_LEQUAL against the cleared 1, so that pixels (and MSAA
// samples) an object covers are rejected before the background shader runs.
void Renderer::drawBackground(FrameDraw& draw) {
    const std::string prelude =
        options_.specialisePrograms ? backgroundSpecialisation(draw.packed, draw.scene.environment, fusedDisplay_) : "";
    Result<const ShaderProgram*> background = backgroundProgram(prelude);
    if (!background) {
        frameShaderError_ = background.error().format();
        draw.fail(background.error());
        return;
    }
    glDepthMask(GL_FALSE);
    glDepthRange(1.0, 1.0);
    draw.clearDepthOnce();
    glUseProgram((*background)->id());
    setFusedDisplayUniforms(**background, fusedDisplay_);
    glBindVertexArray(emptyVertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDepthRange(0.0, 1.0);
    glDepthMask(GL_TRUE);
    glBindVertexArray(0);
}

// The object at `position` in the plan's drawing order, unless outside the view; an object whose
// pixels the target holds (objectsOnly) is only remembered for the overlays.
void Renderer::drawObject(FrameDraw& draw, size_t position) {
    const size_t i = draw.plan.drawOrder[position];
    const SceneObject& object = draw.scene.objects[i];
    const BoundingSphere bounds = drawnBounds(object);
    if (outsideFrustum(draw.viewProjection, bounds)) return;  // render/visibility.h
    if (draw.plan.objectsOnly && !draw.plan.change->materials[object.materialIndex]) {
        rememberDrawn(meshes_->forObject(i, object, kEveryTriangle), object);
        return;
    }
    const Material& material = draw.scene.materials.at(object.materialIndex);
    const SurfaceVariant variant =
        surfaceVariant(object, material, draw.plan.targets.samples, draw.frameDefines, draw.plan.seesBackdrop(position));
    auto program = programFor(material, variant);
    if (!program) {
        frameShaderError_ = program.error().format();
        return draw.fail(program.error());
    }
    const ShaderProgram& shader = **program;
    glUseProgram(shader.id());
    // A texture larger than the GPU takes: the object is not drawn.
    if (Status bound = bindObject(draw, shader, object, material); !bound) return draw.fail(bound.error());
    if (position >= draw.plan.firstTransmissive) transmission_->bind(shader);
    if (variant.fadesEdge) {
        const auto& plane = std::get<PlaneShape>(object.shape);
        const glm::vec2 fadeRadii = planeEdgeFadeRadii(plane);
        glUniform2f(shader.uniform("fadeRadii"), fadeRadii.x, fadeRadii.y);
        glUniform3f(shader.uniform("fadeCenter"), plane.center.x, plane.center.y, plane.center.z);
    }
    if (draw.plan.targets.samples > 1)
        glUniform2fv(shader.uniform("sampleOffsets"), draw.plan.targets.samples, draw.sampleOffsets.data());
    drawMesh(draw, i, bounds);
}

Result<const ShaderProgram*> Renderer::programFor(const Material& material, const SurfaceVariant& variant) {
    return std::visit(
        Overloaded{[&](const AnalyticMaterial& analytic) { return surfaceProgram(analytic.model, variant, TexturedParams::of(analytic)); },
                   [&](const CustomMaterial& custom) { return customPrograms_.program(sources_, *custom.brdf, variant, framesRendered_); },
                   [&](const MeasuredMaterial&) { return measured_.program(sources_, variant, framesRendered_); }},
        material.kind);
}

// The object's uniforms: fused display, shadow maps, material values and textures, shape.
Status Renderer::bindObject(const FrameDraw& draw, const ShaderProgram& shader, const SceneObject& object, const Material& material) {
    setFusedDisplayUniforms(shader, fusedDisplay_);
    shadowMaps_->bind(shader);
    MaterialBlockStd140 materialBlock{};
    const auto values = paramValues(material);
    std::copy_n(values.begin(), std::min<size_t>(values.size(), kMaterialBlockFloats), materialBlock.values);
    glBindBuffer(GL_UNIFORM_BUFFER, uniformBuffers_[kMaterialBinding]);
    glBufferSubData(GL_UNIFORM_BUFFER, 0, sizeof materialBlock, &materialBlock);
    const SphereShape* sphere = rayCastSphere(object);
    glUniform1i(shader.uniform("shapeKind"), sphere ? 1 : 0);
    setTriangleUniforms(shader, object);  // gl/gpu_mesh_cache.h
    Status textured = success();
    std::visit(Overloaded{[&](const AnalyticMaterial& analytic) {
                              if (!analytic.textures.empty()) textured = bindMaterialTextures(shader, analytic, object.shape, textureCache_);
                          },
                          [&](const CustomMaterial& custom) { setCustomBrdfUniforms(shader, *custom.brdf, custom.values); },
                          [&](const MeasuredMaterial& measured) { measured_.bind(shader, measured.brdf); }},
               material.kind);
    if (!textured) return textured;
    if (sphere) glUniform4f(shader.uniform("sphere"), sphere->center.x, sphere->center.y, sphere->center.z, sphere->radius);
    const std::vector<glm::vec4>& occluders = draw.occluders;
    glUniform1i(shader.uniform("occludingSphereCount"), static_cast<GLint>(occluders.size()));
    if (!occluders.empty()) glUniform4fv(shader.uniform("occludingSpheres"), static_cast<GLsizei>(occluders.size()), &occluders[0].x);
    return success();
}

void Renderer::drawMesh(FrameDraw& draw, size_t objectIndex, const BoundingSphere& bounds) {
    const Scene& scene = draw.scene;
    const SceneObject& object = scene.objects[objectIndex];
    // A drag frame draws a large mesh by the stand-in with about as many triangles as the
    // pixels it may cover: more would be smaller than a pixel.
    const size_t budget =
        draw.detail == MeshDetail::Full
            ? kEveryTriangle
            : static_cast<size_t>(coveredPixels(scene.camera, bounds, draw.plan.targets.width, draw.plan.targets.height));
    const GpuMesh& mesh = meshes_->forObject(objectIndex, object, budget);
    // Back faces of a closed surface seen from outside are hidden behind its front faces
    // (render/visibility.h): culled, halving the triangles rasterised. That includes the
    // proxy sphere, whose back faces would shade the same front hit a second time
    // (gl_FragDepth disables early depth rejection). Not when the camera may be inside or the
    // near plane cuts the surface open; open surfaces (planes) keep both faces.
    setFaceCulling(culledFaces(mesh.closure, beyondNearPlane(scene.camera, bounds)));
    glBindVertexArray(mesh.vertexArray);
    draw.clearDepthOnce();
    glDrawElements(GL_TRIANGLES, mesh.indexCount, GL_UNSIGNED_INT, nullptr);
    trianglesDrawn_ += mesh.indexCount / 3;
    if (mesh.simplified) ++simplifiedMeshesDrawn_;
    rememberDrawn(mesh, object);
}

// Each object in the frame, drawn or held, for the overlays.
void Renderer::rememberDrawn(const GpuMesh& mesh, const SceneObject& object) {
    const MeshPlacement placement = placementOf(object.shape);
    drawnMeshes_.push_back({mesh.vertexArray, mesh.indexCount, !std::holds_alternative<PlaneShape>(object.shape),
                            glm::vec4(placement.offset, placement.scale)});
}

// Into the single-sample target, within the frame's region unless the plan says the whole frame.
void Renderer::resolveMultisample(const FramePlan& plan) {
    if (plan.resolvesWholeFrame) glDisable(GL_SCISSOR_TEST);
    const int width = plan.targets.width, height = plan.targets.height;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampleTarget_.framebuffer());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, targets().radiance.framebuffer());
    // Depth too: the overlay pass hides lines behind the surface with it.
    glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
}

// What the draw target holds after the frame, for the next one to redraw only changes: the
// frame itself; a band's pixels drawn from a newer scene than the held one; or nothing.
void Renderer::holdFrame(const Scene& scene, const FramePlan& plan, RowBand rows, const Status& result,
                         std::optional<HeldFrame>& held) {
    const bool standIns = simplifiedMeshesDrawn_ > 0 || shadowMaps_->provisional();
    if (!options_.redrawOnlyChanges || !result || standIns || (rows.count > 0 && !plan.changesOnly())) held.reset();
    else if (rows.count > 0) held->newer = held->newer ? boundsOf(*held->newer, *plan.region) : *plan.region;
    else held = HeldFrame{scene, plan.targets, standIns};
}

// --- display --------------------------------------------------------------------------------

namespace {

void runDisplayPass(const ShaderProgram& program, GLuint radianceTexture, GLuint vertexArray,
                    const DisplaySettings& display, glm::ivec2 sourceOffset, int pixelScale) {
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glUseProgram(program.id());
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, radianceTexture);
    glUniform1i(program.uniform("radiance"), 0);
    glUniform2i(program.uniform("sourceOffset"), sourceOffset.x, sourceOffset.y);
    glUniform1i(program.uniform("pixelScale"), pixelScale);
    setDisplayUniforms(program, display);
    glUniform1i(program.uniform("levelsRamp"), display.levelsRamp ? 1 : 0);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace

void Renderer::displayOffscreen(const DisplaySettings& display) {
    platform_.makeCurrent();
    targets().display.ensure(targets().radiance.width(), targets().radiance.height(), 1);
    glBindFramebuffer(GL_FRAMEBUFFER, targets().display.framebuffer());
    glViewport(0, 0, targets().radiance.width(), targets().radiance.height());
    // Skipped when the radiance pass already wrote the encoded image with these settings (fused).
    if (!fusedDisplay_ || !sameDisplay(*fusedDisplay_, display)) {
        GLINT_CHECK(radianceWritten_);  // a render that kept no float image: its display settings only
        runDisplayPass(displayProgram(display), targets().radiance.colorTexture(), emptyVertexArray_, display, {0, 0}, 1);
    }
    overlayPass_.draw(display.overlays, drawnMeshes_, targets().radiance.depthTexture(), {0, 0}, 1);
    fusedDisplay_.reset();  // the target now holds the overlays too: not the fused image any more
    targets().held.reset();
}

void Renderer::displayToScreen(const DisplaySettings& display, glm::ivec2 lowerLeft, int pixelScale, GLuint framebuffer) {
    platform_.makeCurrent();
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    const int width = targets().radiance.width(), height = targets().radiance.height();
    glViewport(lowerLeft.x, lowerLeft.y, width * pixelScale, height * pixelScale);
    if (fusedDisplay_ && sameDisplay(*fusedDisplay_, display)) {
        // The radiance pass wrote this very image (fused): each pixel copied to pixelScale² screen pixels.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, targets().display.framebuffer());
        glReadBuffer(GL_COLOR_ATTACHMENT0);
        glBlitFramebuffer(0, 0, width, height, lowerLeft.x, lowerLeft.y, lowerLeft.x + width * pixelScale,
                          lowerLeft.y + height * pixelScale, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    } else {
        GLINT_CHECK(radianceWritten_);
        runDisplayPass(displayProgram(display), targets().radiance.colorTexture(), emptyVertexArray_, display, lowerLeft, pixelScale);
    }
    overlayPass_.draw(display.overlays, drawnMeshes_, targets().radiance.depthTexture(), lowerLeft, pixelScale);
}

// --- readback -------------------------------------------------------------------------------

namespace {

template <class Pixel>
void readFlipped(GLuint framebuffer, int width, int height, GLenum type, std::vector<Pixel>& pixels) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
    glReadBuffer(GL_COLOR_ATTACHMENT0);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<Pixel> bottomUp(static_cast<size_t>(width) * height * 3);
    glReadPixels(0, 0, width, height, GL_RGB, type, bottomUp.data());
    const size_t rowLength = static_cast<size_t>(width) * 3;
    pixels.resize(bottomUp.size());
    for (int y = 0; y < height; ++y)
        std::memcpy(&pixels[y * rowLength], &bottomUp[(height - 1 - y) * rowLength], rowLength * sizeof(Pixel));
}

}  // namespace

RadianceImage Renderer::readRadiance() const {
    platform_.makeCurrent();
    GLINT_CHECK(radianceWritten_);  // a fused render with options().keepRadiance off has none
    RadianceImage image(targets().radiance.width(), targets().radiance.height());
    readFlipped(targets().radiance.framebuffer(), image.width, image.height, GL_FLOAT, image.pixels);
    return image;
}

OpaquePassImage Renderer::readTransmissionBackdrop() const {
    platform_.makeCurrent();
    return transmission_->read();
}

DisplayImage Renderer::readDisplay() const {
    platform_.makeCurrent();
    DisplayImage image(targets().display.width(), targets().display.height());
    readFlipped(targets().display.framebuffer(), image.width, image.height, GL_UNSIGNED_BYTE, image.pixels);
    return image;
}

}  // namespace glint
