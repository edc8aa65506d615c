// The standard scenes of `glint bench` (see bench_scenes.h).
#include "cli/bench_scenes.h"

#include <glm/gtc/matrix_transform.hpp>

#include "brdf/param_table.h"
#include "environment/environment_source.h"
#include "interchange/material_values.h"

namespace glint {
namespace {

// A unit sphere at the origin seen from 1.5 m with the default 40° field of view: it covers every
// pixel of the frame, so each pixel runs the surface shader once (the bare pass's pixel count).
Scene frameFillingSphere(const Material& material, int lightCount) {
    Scene scene;
    scene.camera.position = {0.0f, 0.0f, 1.5f};
    scene.camera.target = {0.0f, 0.0f, 0.0f};
    scene.materials = {material};
    scene.objects.push_back({"sphere", SphereShape{}, 0});
    scene.background.kind = BackgroundKind::Sky;  // what mirror and glass reflect
    const glm::vec3 positions[4] = {{2, 2, 2}, {-2, 1, 2}, {0, -2, 3}, {1, 0, 4}};
    for (int i = 0; i < lightCount; ++i) {
        Light light;
        light.name = "bench " + std::to_string(i);
        light.type = i % 2 ? LightType::Directional : LightType::Point;
        light.position = positions[i];
        light.direction = -positions[i];
        light.irradiance = 1.0f;
        scene.lights.push_back(light);
    }
    return scene;
}

// The model's defaults with one enum parameter set by its option id ("beckmann").
Material withOption(BrdfModel model, const char* param, const char* option) {
    Material material = Material::withDefaults(std::string(modelInfo(model).id), model);
    const auto table = modelInfo(model).params;
    const int index = findParam(table, param);
    for (size_t i = 0; index >= 0 && i < table[index].options.size(); ++i)
        if (std::string_view(table[index].options[i].id) == option)
            setParam(material, param, static_cast<float>(i));
    return material;
}

// The sphere as a 1,000,000-triangle mesh (1000 segments × 500 rings), drawn through the triangle
// path with Phong interpolation.
void tessellateToOneMillionTriangles(Scene& scene) {
    auto& sphere = std::get<SphereShape>(scene.objects[0].shape);
    sphere.segments = 1000, sphere.rings = 500;
    scene.objects[0].interpolation = SurfaceInterpolation::Phong;
}

// The built-in studio environment as the scene's light (its maps are precomputed here, once).
void lightWithStudio(Scene& scene) {
    scene.environment.kind = EnvironmentKind::Studio;
    (void)loadEnvironment(scene.environment);  // a built-in: baked in memory, cannot fail to read
}

// The first two lights cast shadows onto a floor under the sphere, which the camera looks down
// on so that the floor fills the frame around the sphere.
void castShadowsOnAFloor(Scene& scene) {
    scene.camera.position = {0.0f, 1.6f, 2.2f};
    scene.objects.push_back({"floor", PlaneShape{{0, -1, 0}, {0, 1, 0}, {40, 40}}, 0});
    for (size_t i = 0; i < scene.lights.size() && i < 2; ++i) scene.lights[i].castsShadows = true;
}

struct FamilyMember {
    const char* family;
    const char* name;  // the row's name before "/lights"
    Material material;
};

std::vector<BenchScene> makeBenchScenes() {
    auto defaults = [](BrdfModel model) { return Material::withDefaults(modelInfo(model).id, model); };
    const FamilyMember members[] = {
        {"diffuse", "lambert", defaults(BrdfModel::Lambert)},
        {"diffuse", "oren_nayar", defaults(BrdfModel::OrenNayar)},
        {"phong", "phong", defaults(BrdfModel::Phong)},
        {"phong", "blinn_phong", defaults(BrdfModel::BlinnPhong)},
        {"microfacet", "ggx", withOption(BrdfModel::CookTorrance, "distribution", "ggx")},
        {"microfacet", "beckmann", withOption(BrdfModel::CookTorrance, "distribution", "beckmann")},
        {"anisotropic", "ggx_anisotropic", defaults(BrdfModel::GgxAnisotropic)},
        {"anisotropic", "ward", defaults(BrdfModel::Ward)},
        {"retroreflective", "retroreflective", defaults(BrdfModel::Retroreflective)},
        {"specular", "mirror", defaults(BrdfModel::Mirror)},
        {"specular", "glass", defaults(BrdfModel::Glass)},
    };
    std::vector<BenchScene> scenes;
    for (const FamilyMember& member : members)
        for (int lights : {1, 4})
            scenes.push_back({std::string(member.name) + "/" + std::to_string(lights), member.family,
                              [material = member.material, lights] { return frameFillingSphere(material, lights); }});
    const Material ggx = withOption(BrdfModel::CookTorrance, "distribution", "ggx");
    // A large mesh: Blinn-Phong, 4 lights.
    const auto oneMillionTriangles = [material = defaults(BrdfModel::BlinnPhong)] {
        Scene scene = frameFillingSphere(material, 4);
        tessellateToOneMillionTriangles(scene);
        return scene;
    };
    scenes.push_back({"mesh_1m_triangles/4", "mesh", oneMillionTriangles});
    // Image-based light alone (no delta lights), for a diffuse and a glossy model.
    for (const FamilyMember& member : {members[0], members[4]})
        scenes.push_back({std::string(member.name) + "_studio/0", "environment", [material = member.material] {
                              Scene scene = frameFillingSphere(material, 0);
                              lightWithStudio(scene);
                              return scene;
                          }});
    // Shadow maps: two shadowed lights of four, sphere on a floor.
    scenes.push_back({"ggx_shadows/4", "shadows", [ggx] {
                          Scene scene = frameFillingSphere(ggx, 4);
                          castShadowsOnAFloor(scene);
                          return scene;
                      }});
    // Everything at once: the 1M-triangle sphere on a floor, studio light, two shadowed lights.
    const auto studioShadows = [ggx] {
        Scene scene = frameFillingSphere(ggx, 2);
        tessellateToOneMillionTriangles(scene);
        lightWithStudio(scene);
        castShadowsOnAFloor(scene);
        return scene;
    };
    scenes.push_back({"mesh_1m_studio_shadows/2", "combined", studioShadows});
    // A drag in the editor: the 1M-triangle scenes drawn with the sphere's simplified stand-in
    // (the shadow maps kept from the full mesh, as for a camera or material drag); then the
    // shadowed point light moving 1° around the vertical each frame, its cube map redrawn from
    // the stand-in every frame.
    scenes.push_back({"mesh_1m_simplified/4", "drag", oneMillionTriangles, MeshDetail::Simplified});
    scenes.push_back({"mesh_1m_studio_simplified/2", "drag", studioShadows, MeshDetail::Simplified});
    scenes.push_back({"mesh_1m_light_drag/2", "drag", studioShadows, MeshDetail::Simplified, [](Scene& scene) {
                          Light& bulb = scene.lights[0];  // the point light
                          bulb.position = glm::vec3(glm::rotate(glm::mat4(1.0f), glm::radians(1.0f), glm::vec3(0, 1, 0)) *
                                                    glm::vec4(bulb.position, 1.0f));
                      }});
    return scenes;
}

}  // namespace

const std::vector<BenchScene>& benchScenes() {
    static const std::vector<BenchScene> scenes = makeBenchScenes();
    return scenes;
}

}  // namespace glint
