// The preview stage (see preview_stage.h). The key light shines from the studio's key soft box
// (environment_source.cpp), so its shadow falls where the box's light would be blocked; the
// environment itself is not occluded (render/environment_sampling.h).
#include "scene/preview_stage.h"

#include "environment/environment_source.h"
#include "util/diagnostic.h"

namespace glint {

Scene previewStage(const Material& material, int width, int height) {
    Scene scene;
    scene.width = width;
    scene.height = height;
    scene.msaaSamples = kDefaultMsaaSamples;  // clamped to what the GL implementation offers (gl/renderer.h)
    scene.camera.projection = Projection::Perspective;
    scene.camera.position = {0.0f, 0.8f, 4.3f};
    scene.camera.target = {0.0f, -0.12f, 0.0f};
    scene.camera.verticalFovDegrees = 36.0f;
    // Behind the ball a dark grey backdrop, lighter towards the horizon, instead of the studio's
    // soft boxes themselves (which the ball still reflects): the floor fades into its horizon.
    scene.background.kind = BackgroundKind::Sky;
    scene.background.zenith = glm::vec3(0.015f);
    scene.background.horizon = glm::vec3(0.09f);
    scene.background.ground = glm::vec3(0.09f);
    scene.environment.kind = EnvironmentKind::Studio;
    scene.environment.showAsBackground = false;
    const Status studio = loadEnvironment(scene.environment);  // a built-in: made once per process, reads no file
    GLINT_CHECK(studio.ok());
    scene.display.toneMap = ToneMap::PbrNeutral;
    scene.display.exposureStops = kPreviewStageExposureStops;

    Material floor = Material::withDefaults("stage floor", BrdfModel::Lambert);
    floor.analytic()->values = {0.3f, 0.3f, 0.3f};
    Material shown = material;
    if (shown.name == floor.name) shown.name += " (material)";
    scene.materials = {shown, floor};
    scene.objects.push_back({"sphere", SphereShape{{0.0f, 0.0f, 0.0f}, 1.0f}, 0});
    // 14 m across, fading into the studio from 2.1 m out to 7 m (scene/plane_edge_fade.h): no edge
    // or corner shows from any side.
    PlaneShape ground{{0.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, {14.0f, 14.0f}};
    ground.edgeFade = 0.7f;
    scene.objects.push_back({"floor", ground, 1, SurfaceInterpolation::Phong});

    Light key;  // along the studio's key soft box, M = 1.5 W/m²
    key.name = "key";
    key.type = LightType::Directional;
    key.direction = -glm::normalize(glm::vec3(0.8f, 0.6f, 0.7f));
    key.irradiance = 1.5f;
    key.color = {1.0f, 0.96f, 0.92f};
    key.castsShadows = true;
    // A coarse map softens the edge: a texel is about 4 cm over the 14 m floor, so the default
    // 1.5-texel filter blurs it over about 12 cm. (A wider filter in texels darkens the sphere's own
    // lit side, where its surface curves away within the filter.)
    key.shadow.mapResolution = 512;
    scene.lights = {key};
    return scene;
}

}  // namespace glint
