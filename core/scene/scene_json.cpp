// Scene and material JSON, version 1 (see scene_json.h and docs/scene-format.md).
// Sections: format header · materials · lights · background · objects · camera/display · writers.
#include "scene/scene_json.h"

#include <array>

#include "display/quantisation.h"
#include "interchange/file_material_json.h"
#include "scene/environment_json.h"
#include "scene/json_object_reader.h"
#include "scene/json_vectors.h"
#include "scene/param_values_json.h"
#include "texture/texture_json.h"
#include "scene/shadow_json.h"
#include "scene/shape_json.h"
#include "util/file_io.h"

namespace glint {
namespace {

using nlohmann::json;

constexpr const char* kSceneFormat = "glint-scene";
constexpr const char* kMaterialFormat = "glint-material";

// --- format header -------------------------------------------------------------------------

void readHeader(ObjectReader& root, const char* expectedFormat) {
    const std::string format = root.requiredString("format");
    if (format != expectedFormat)
        root.fail("format", "expected \"" + std::string(expectedFormat) + "\", found \"" + format + "\"");
    const int version = root.integer("version", -1, 1, 1'000'000);
    if (version < 0) root.failHere("the file needs a \"version\" (this Glint writes version " +
                                   std::to_string(kSceneFormatVersion) + ")");
    if (version > kSceneFormatVersion)
        root.fail("version", "the file is version " + std::to_string(version) +
                                 ", written by a newer Glint; this one reads up to version " +
                                 std::to_string(kSceneFormatVersion));
}

// --- materials ------------------------------------------------------------------------------

constexpr const char* kMaterialReservedKeys[] = {"name", "model", "format", "version"};

Material readMaterial(ObjectReader& reader) {
    Material material;
    material.name = reader.string("name", "material");
    if (reader.has("brdf_file")) return readCustomBrdfMaterial(reader, std::move(material.name));  // a .brdf file
    if (reader.has("merl_file")) return readMeasuredMaterial(reader, std::move(material.name));  // a MERL table
    const std::string modelId = reader.requiredString("model");
    const auto model = findModel(modelId);
    if (!model) {
        std::string list;
        for (const ModelInfo& info : allModels()) list += std::string(list.empty() ? "" : ", ") + info.id;
        reader.fail("model", "unknown model '" + modelId + "' (known models: " + list + ")");
    }
    AnalyticMaterial& analytic = material.kind.emplace<AnalyticMaterial>(
        AnalyticMaterial{*model, readParamValues(reader, modelInfo(*model).params)});
    readMaterialTextures(reader, analytic);
    reader.rejectUnknownKeys(kMaterialReservedKeys);
    return material;
}

// `file`: where the JSON goes, so that texture and .brdf paths are written relative to it ("" for absolute).
json materialBody(const Material& material, const std::string& file) {
    return std::visit(Overloaded{[&](const AnalyticMaterial& analytic) {
                                     json out = {{"name", material.name}, {"model", modelInfo(analytic.model).id}};
                                     writeParamValues(out, modelInfo(analytic.model).params, analytic.values);
                                     if (json textures = materialTexturesToJson(analytic, file); !textures.is_null())
                                         out["textures"] = textures;
                                     return out;
                                 },
                                 [&](const CustomMaterial& custom) { return customBrdfMaterialBody(material.name, custom, file); },
                                 [&](const MeasuredMaterial& measured) {
                                     return measuredMaterialBody(material.name, measured, file);
                                 }},
                      material.kind);
}

// --- lights ---------------------------------------------------------------------------------

constexpr const char* kLightTypes[] = {"directional", "point", "spot", "ambient"};

// The classic radial attenuation [a0, a1, a2] (non-physical; present = enabled).
void readAttenuation(ObjectReader& reader, Light& light) {
    if (!reader.has("attenuation")) return;
    light.attenuation.enabled = true;
    light.attenuation.coefficients = reader.vec3("attenuation", light.attenuation.coefficients, Bounds::nonNegative());
    const glm::vec3& a = light.attenuation.coefficients;
    if (a.x == 0.0f && a.y == 0.0f && a.z == 0.0f)
        reader.fail("attenuation", "[a0, a1, a2] must not all be zero (1/(a0 + a1·d + a2·d²) would be infinite)");
}

void readSpot(ObjectReader& reader, Light& light) {
    light.direction = reader.vec3("direction", light.direction);
    if (glm::length(light.direction) < 1e-6f) reader.fail("direction", "must not be the zero vector");
    light.direction = glm::normalize(light.direction);
    const Bounds halfAngle{0.0, 90.0, true};  // (0°, 90°]
    light.coneHalfAngleDegrees = static_cast<float>(reader.number("cone_half_angle_degrees", light.coneHalfAngleDegrees, halfAngle));
    light.falloffExponent = static_cast<float>(reader.number("falloff_exponent", light.falloffExponent, Bounds::between(0, 10000)));
    light.edgeWidthDegrees = std::min(light.edgeWidthDegrees, light.coneHalfAngleDegrees);
    light.edgeWidthDegrees = static_cast<float>(
        reader.number("edge_width_degrees", light.edgeWidthDegrees, Bounds::between(0, light.coneHalfAngleDegrees)));
}

Light readLight(ObjectReader& reader) {
    Light light;
    if (!reader.has("type")) reader.failHere("a light needs the key 'type' (directional, point, spot or ambient)");
    light.type = static_cast<LightType>(reader.choice("type", kLightTypes, 0));
    light.name = reader.string("name", kLightTypes[static_cast<int>(light.type)]);
    light.enabled = reader.boolean("enabled", true);
    light.color = reader.vec3("color", light.color, Bounds::nonNegative());
    switch (light.type) {
        case LightType::Directional:
            light.irradiance = static_cast<float>(reader.number("irradiance", light.irradiance, Bounds::nonNegative()));
            light.direction = reader.vec3("direction", light.direction);
            if (glm::length(light.direction) < 1e-6f) reader.fail("direction", "must not be the zero vector");
            light.direction = glm::normalize(light.direction);
            break;
        case LightType::Point:
        case LightType::Spot:
            light.power = static_cast<float>(reader.number("power", light.power, Bounds::nonNegative()));
            light.position = reader.vec3("position", light.position);
            if (light.type == LightType::Spot) readSpot(reader, light);
            readAttenuation(reader, light);
            break;
        case LightType::Ambient:
            light.ambientRadiance = static_cast<float>(reader.number("radiance", light.ambientRadiance, Bounds::nonNegative()));
            break;
    }
    readLightShadows(reader, light);
    reader.rejectUnknownKeys();
    return light;
}

json lightToJson(const Light& light) {
    json out = {{"name", light.name},
                {"type", kLightTypes[static_cast<int>(light.type)]},
                {"enabled", light.enabled},
                {"color", {light.color.r, light.color.g, light.color.b}}};
    switch (light.type) {
        case LightType::Directional:
            out["irradiance"] = light.irradiance;
            out["direction"] = vec3Json(light.direction);
            break;
        case LightType::Point:
        case LightType::Spot:
            out["power"] = light.power;
            out["position"] = vec3Json(light.position);
            if (light.type == LightType::Spot) {
                out["direction"] = vec3Json(light.direction);
                out["cone_half_angle_degrees"] = light.coneHalfAngleDegrees;
                out["falloff_exponent"] = light.falloffExponent;
                out["edge_width_degrees"] = light.edgeWidthDegrees;
            }
            if (light.attenuation.enabled) {
                const glm::vec3& a = light.attenuation.coefficients;
                out["attenuation"] = {a.x, a.y, a.z};
            }
            break;
        case LightType::Ambient: out["radiance"] = light.ambientRadiance; break;
    }
    writeLightShadows(light, out);
    return out;
}

// --- background -----------------------------------------------------------------------------

constexpr const char* kBackgroundTypes[] = {"constant", "sky"};

// "background": [r, g, b] (constant radiance) or an object {"type": "constant"|"sky", ...}.
Background readBackground(ObjectReader& root) {
    Background background;
    if (!root.has("background")) return background;
    if (!root.take("background").is_object()) {
        background.color = root.vec3("background", background.color, Bounds::nonNegative());
        return background;
    }
    ObjectReader reader = root.object("background");
    background.kind = static_cast<BackgroundKind>(reader.choice("type", kBackgroundTypes, 0));
    if (background.kind == BackgroundKind::Constant) {
        background.color = reader.vec3("color", background.color, Bounds::nonNegative());
    } else {
        background.zenith = reader.vec3("zenith", background.zenith, Bounds::nonNegative());
        background.horizon = reader.vec3("horizon", background.horizon, Bounds::nonNegative());
        background.ground = reader.vec3("ground", background.ground, Bounds::nonNegative());
    }
    reader.rejectUnknownKeys();
    return background;
}

json backgroundToJson(const Background& background) {
    if (background.kind == BackgroundKind::Constant) return vec3Json(background.color);
    return {{"type", "sky"}, {"zenith", vec3Json(background.zenith)}, {"horizon", vec3Json(background.horizon)},
            {"ground", vec3Json(background.ground)}};
}

// --- objects --------------------------------------------------------------------------------

constexpr const char* kShapes[] = {"sphere", "plane", "cube", "torus", "mesh"};  // order of Shape
constexpr const char* kInterpolations[] = {"exact", "flat", "gouraud", "phong"};  // order of SurfaceInterpolation

SceneObject readObject(ObjectReader& reader, const std::vector<Material>& materials) {
    SceneObject object;
    if (!reader.has("shape")) reader.failHere("an object needs the key 'shape' (sphere, plane, cube, torus or mesh)");
    const int shape = reader.choice("shape", kShapes, 0);
    object.name = reader.string("name", kShapes[shape]);
    switch (shape) {
        case 0: object.shape = readSphereShape(reader); break;
        case 1: object.shape = readPlaneShape(reader); break;
        default: object.shape = readMeshLikeShape(reader, shape); break;
    }
    object.interpolation = static_cast<SurfaceInterpolation>(
        reader.choice("interpolation", kInterpolations, static_cast<int>(defaultInterpolation(object.shape))));
    if (object.interpolation == SurfaceInterpolation::Exact &&
        (std::holds_alternative<TorusShape>(object.shape) || std::holds_alternative<MeshShape>(object.shape)))
        reader.fail("interpolation", "'exact' needs an analytic surface (sphere, plane or cube); a " +
                                         std::string(kShapes[shape]) + " is drawn from triangles: use flat, gouraud or phong");
    const std::string materialName = reader.requiredString("material");
    object.materialIndex = -1;
    for (size_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == materialName) object.materialIndex = static_cast<int>(i);
    if (object.materialIndex < 0) reader.fail("material", "no material named '" + materialName + "' in \"materials\"");
    reader.rejectUnknownKeys();
    return object;
}

// `file`: where the JSON goes, so that a mesh path is written relative to it ("" for absolute).
json objectToJson(const SceneObject& object, const std::vector<Material>& materials, const std::string& file) {
    json out = {{"name", object.name}, {"shape", kShapes[object.shape.index()]}};
    out.update(shapeToJson(object.shape, file));
    if (object.interpolation != defaultInterpolation(object.shape))
        out["interpolation"] = kInterpolations[static_cast<int>(object.interpolation)];
    out["material"] = materials.at(object.materialIndex).name;
    return out;
}

// --- camera, display, output ----------------------------------------------------------------

constexpr const char* kProjections[] = {"perspective", "orthographic"};
constexpr const char* kTransfers[] = {"srgb", "gamma", "linear"};  // order of enum Transfer
constexpr const char* kToneMaps[] = {"none", "reinhard", "aces", "pbr_neutral"};  // order of enum ToneMap

Camera readCamera(ObjectReader& reader) {
    Camera camera;
    camera.projection = static_cast<Projection>(reader.choice("projection", kProjections, 0));
    camera.position = reader.vec3("position", camera.position);
    camera.target = reader.vec3("target", camera.target);
    camera.up = reader.vec3("up", camera.up);
    camera.verticalFovDegrees = static_cast<float>(reader.number("fov_degrees", camera.verticalFovDegrees, {0.0, 179.0, true}));
    camera.orthoHeight = static_cast<float>(reader.number("ortho_height", camera.orthoHeight, Bounds::positive()));
    camera.nearPlane = static_cast<float>(reader.number("near", camera.nearPlane, Bounds::positive()));
    camera.farPlane = static_cast<float>(reader.number("far", camera.farPlane, Bounds::positive()));
    if (camera.farPlane <= camera.nearPlane) reader.fail("far", "must be greater than near");
    const glm::vec3 forward = camera.target - camera.position;
    if (glm::length(forward) < 1e-6f) reader.fail("target", "must differ from the camera position");
    if (glm::length(glm::cross(forward, camera.up)) < 1e-6f * glm::length(forward))
        reader.fail("up", "must not be parallel to the viewing direction");
    reader.rejectUnknownKeys();
    return camera;
}

Scene readScene(const JsonDocument& document, EnvironmentMapLoading environment) {
    ObjectReader root = readRoot(document, "scene");
    readHeader(root, kSceneFormat);
    Scene scene;
    // Without "msaa" a scene file renders anti-aliased, as the preview stage the editor opens on.
    scene.msaaSamples = kDefaultMsaaSamples;
    if (root.has("output")) {
        ObjectReader output = root.object("output");
        scene.width = output.integer("width", scene.width, 1, 16384);
        scene.height = output.integer("height", scene.height, 1, 16384);
        scene.msaaSamples = output.integer("msaa", scene.msaaSamples, 1, 16);
        output.rejectUnknownKeys();
    }
    if (root.has("camera")) {
        ObjectReader camera = root.object("camera");
        scene.camera = readCamera(camera);
    }
    scene.background = readBackground(root);
    scene.environment = readEnvironment(root, environment);
    if (root.has("display")) {
        ObjectReader display = root.object("display");
        scene.display.exposureStops = static_cast<float>(display.number("exposure", 0.0, Bounds::between(-30, 30)));
        scene.display.transfer = static_cast<Transfer>(display.choice("transfer", kTransfers, 0));
        scene.display.gamma = static_cast<float>(display.number("gamma", scene.display.gamma, Bounds::between(0.1, 10)));
        scene.display.toneMap = static_cast<ToneMap>(display.choice("tone_map", kToneMaps, 0));
        // Classroom display lessons (display/quantisation.h).
        scene.display.levels = display.integer("levels", scene.display.levels, 2, 256);
        scene.display.dither = static_cast<Dither>(display.choice("dither", kDitherIds, 0));
        scene.display.levelsRamp = display.boolean("levels_ramp", false);
        if (display.has("overlays")) {
            ObjectReader overlays = display.object("overlays");
            scene.display.overlays.wireframe = overlays.boolean("wireframe", false);
            scene.display.overlays.normals = overlays.boolean("normals", false);
            scene.display.overlays.normalLength =
                static_cast<float>(overlays.number("normal_length", scene.display.overlays.normalLength, Bounds::positive()));
            overlays.rejectUnknownKeys();
        }
        display.rejectUnknownKeys();
    }
    for (ObjectReader& reader : root.objectArray("materials")) scene.materials.push_back(readMaterial(reader));
    for (ObjectReader& reader : root.objectArray("lights")) scene.lights.push_back(readLight(reader));
    if (scene.lights.size() > static_cast<size_t>(kMaxLights))
        root.fail("lights", std::to_string(scene.lights.size()) + " lights: " + lightLimitExplanation());
    checkShadowedLightCount(root, scene.lights);
    for (ObjectReader& reader : root.objectArray("objects")) scene.objects.push_back(readObject(reader, scene.materials));
    root.rejectUnknownKeys();
    return scene;
}

}  // namespace

// --- writers and entry points ---------------------------------------------------------------

Result<Scene> parseScene(const std::string& text, const std::string& file, EnvironmentMapLoading environment) {
    auto document = JsonDocument::parse(text, file);
    if (!document) return document.error();
    try {
        return readScene(*document, environment);
    } catch (const JsonReadError& error) {
        return error.diagnostic;
    }
}

Result<Scene> loadScene(const std::string& path, EnvironmentMapLoading environment) {
    return parseTextFile(path, [environment](const std::string& text, const std::string& file) {
        return parseScene(text, file, environment);
    });
}

json sceneToJson(const Scene& scene, const std::string& file) {
    json out = {{"format", kSceneFormat}, {"version", kSceneFormatVersion}};
    out["output"] = {{"width", scene.width}, {"height", scene.height}, {"msaa", scene.msaaSamples}};
    const Camera& camera = scene.camera;
    out["camera"] = {{"projection", kProjections[static_cast<int>(camera.projection)]},
                     {"position", vec3Json(camera.position)},
                     {"target", vec3Json(camera.target)},
                     {"up", vec3Json(camera.up)},
                     {"fov_degrees", camera.verticalFovDegrees},
                     {"ortho_height", camera.orthoHeight},
                     {"near", camera.nearPlane},
                     {"far", camera.farPlane}};
    out["background"] = backgroundToJson(scene.background);
    if (scene.environment.kind != EnvironmentKind::None) out["environment"] = environmentToJson(scene.environment, file);
    out["display"] = {{"exposure", scene.display.exposureStops},
                      {"transfer", kTransfers[static_cast<int>(scene.display.transfer)]},
                      {"gamma", scene.display.gamma},
                      {"tone_map", kToneMaps[static_cast<int>(scene.display.toneMap)]}};
    if (scene.display.levels != 256) out["display"]["levels"] = scene.display.levels;
    if (scene.display.dither != Dither::None) out["display"]["dither"] = kDitherIds[static_cast<int>(scene.display.dither)];
    if (scene.display.levelsRamp) out["display"]["levels_ramp"] = true;
    if (const OverlaySettings& overlays = scene.display.overlays; overlays.any() || overlays.normalLength != OverlaySettings{}.normalLength)
        out["display"]["overlays"] = {{"wireframe", overlays.wireframe},
                                      {"normals", overlays.normals},
                                      {"normal_length", overlays.normalLength}};
    out["materials"] = json::array();
    for (const Material& material : scene.materials) out["materials"].push_back(materialBody(material, file));
    out["lights"] = json::array();
    for (const Light& light : scene.lights) out["lights"].push_back(lightToJson(light));
    out["objects"] = json::array();
    for (const SceneObject& object : scene.objects) out["objects"].push_back(objectToJson(object, scene.materials, file));
    return out;
}

Status saveScene(const Scene& scene, const std::string& path) {
    // Meshes, textures, the environment, .brdf and MERL files named relative to `path`.
    return writeFileAtomically(path, sceneToJson(scene, path).dump(2) + "\n");
}

Result<Material> parseMaterial(const std::string& text, const std::string& file) {
    auto document = JsonDocument::parse(text, file);
    if (!document) return document.error();
    try {
        ObjectReader root = readRoot(*document, "material");
        readHeader(root, kMaterialFormat);
        return readMaterial(root);
    } catch (const JsonReadError& error) {
        return error.diagnostic;
    }
}

Result<Material> loadMaterial(const std::string& path) { return parseTextFile(path, parseMaterial); }

json materialToJson(const Material& material, const std::string& file) {
    json out = {{"format", kMaterialFormat}, {"version", kSceneFormatVersion}};
    out.update(materialBody(material, file));
    return out;
}

Status saveMaterial(const Material& material, const std::string& path) {
    return writeFileAtomically(path, materialToJson(material, path).dump(2) + "\n");
}

}  // namespace glint
