// Scene: everything a picture depends on: camera, lights, materials, objects, background,
// display chain and output size. Plain data; loading and saving live in scene_json.h,
// drawing in the CPU reference (render/) and the GL renderer (core/gl).
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "camera/camera.h"
#include "geometry/mesh.h"
#include "light/light.h"
#include "scene/background.h"
#include "scene/display_settings.h"
#include "scene/environment.h"
#include "scene/material.h"

namespace glint {

inline constexpr int kSceneFormatVersion = 1;
// Lights per scene. Each costs 64 bytes of the LightBlock (GpuLightStd140): 256 fill the 16 KiB
// that OpenGL 4.1 guarantees per uniform block; the shader loops only over those present.
inline constexpr int kMaxLights = 256;
// What every message that meets the limit says after the count: the limit, where it comes from and
// what to do.
inline std::string lightLimitExplanation() {
    return "Glint supports at most " + std::to_string(kMaxLights) +
           " lights per scene (the GPU's light block: 64 bytes a light, in the 16 KiB that OpenGL 4.1 guarantees); merge lights that are close together, or light the "
           "scene with an environment map";
}

struct SphereShape {
    glm::vec3 center{0.0f};
    float radius = 1.0f;
    int segments = 64;  // tessellation of the proxy mesh around the pole axis
    int rings = 32;     // ...and from pole to pole
};

struct PlaneShape {
    glm::vec3 center{0, -1, 0};
    glm::vec3 normal{0, 1, 0};
    glm::vec2 size{6, 6};  // [m]
    float edgeFade = 0.0f;  // [0, 1]: outer share of the half-size that fades into the background (scene/plane_edge_fade.h)
};

// An axis-aligned cube; `size` is its edge length [m].
struct CubeShape {
    glm::vec3 center{0.0f};
    float size = 1.5f;
    glm::vec3 rotationDegrees{0.0f};  // about `center`: x, then y, then z [degrees]
};

// A torus around the +y axis: a tube of `minorRadius` whose centre line is a circle of
// `majorRadius` [m]; `segments` around the y axis, `rings` around the tube.
struct TorusShape {
    glm::vec3 center{0.0f};
    float majorRadius = 0.75f;
    float minorRadius = 0.3f;
    int segments = 64;
    int rings = 32;
    glm::vec3 rotationDegrees{0.0f};  // about `center`: x, then y, then z [degrees]
};

// A triangle mesh loaded from a file (geometry/mesh_import.h). The importer centres it and
// scales it into the unit sphere; `center` and `scale` place that unit-sized mesh in the scene.
// A part of an asset (one glTF primitive, one OBJ `usemtl` group) is centred and scaled as its
// whole file is, so the parts with the same `center` and `scale` fit together.
struct MeshShape {
    std::string path;          // as written in the scene file (relative to the scene file's folder)
    std::string resolvedPath;  // the file actually read
    int part = -1;             // which of the file's parts (importMeshParts); -1: the whole file merged
    glm::vec3 center{0.0f};
    float scale = 1.0f;  // radius of the mesh's bounding sphere [m]
    float smoothingAngleDegrees = 60.0f;  // crease angle for normals the file lacks (mesh_import.h)
    MeshUpAxis upAxis = MeshUpAxis::Y;    // the file's up axis ("up": "y" | "z")
    glm::vec3 rotationDegrees{0.0f};      // x, then y, then z [degrees], turned into `mesh` when it is read
    std::shared_ptr<const Mesh> mesh;  // shared between copies of the scene (undo history)
    MeshStatistics statistics;
};

using Shape = std::variant<SphereShape, PlaneShape, CubeShape, TorusShape, MeshShape>;

// How a surface is drawn (the lecture's interpolation schemes). Exact ray-casts the analytic
// sphere (spheres only: the GPU-vs-CPU tests use it); the others draw the triangle mesh of the
// shape (a sphere's UV tessellation, segments × rings): Flat uses each face's normal, Gouraud
// shades the vertices and interpolates the radiance, Phong interpolates the normal and shades
// every pixel. On planes and cubes, whose faces are flat, Exact is Phong.
enum class SurfaceInterpolation { Exact, Flat, Gouraud, Phong };

// Exact for spheres, Phong for everything else.
SurfaceInterpolation defaultInterpolation(const Shape& shape);
// Whether a shape with this mode is drawn from triangles (everything but an exact sphere).
bool drawnAsTriangles(const Shape& shape, SurfaceInterpolation interpolation);

struct SceneObject {
    std::string name;
    Shape shape;
    int materialIndex = 0;  // into Scene::materials
    SurfaceInterpolation interpolation = SurfaceInterpolation::Exact;  // see defaultInterpolation
};

struct Scene {
    Camera camera;
    std::vector<Light> lights;
    std::vector<Material> materials;
    std::vector<SceneObject> objects;
    Background background;  // radiance [W/(sr·m²)] seen where no object is hit (and by secondary rays)
    Environment environment;  // environment light (none by default); see scene/environment.h
    DisplaySettings display;
    int width = 960;   // output size in pixels
    int height = 720;
    int msaaSamples = 1;  // 1 = off
};

// Samples per pixel of the preview stage and of a scene file without "msaa": anti-aliased by
// default (4 is also the most llvmpipe offers).
inline constexpr int kDefaultMsaaSamples = 4;

// The scene Glint opens with no file: red plastic on the preview stage (scene/preview_stage.h).
Scene defaultScene();

}  // namespace glint
