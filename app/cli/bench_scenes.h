// The standard scenes of `glint bench`: a table of named scene builders, one row per scene. Each
// scene's first object is what the bare shading pass is compared with (its material, its lights).
// To add a scene, add a row to the table in bench_scenes.cpp. It does not time anything
// (bench_command.cpp does).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "gl/gpu_mesh_cache.h"
#include "scene/scene.h"

namespace glint {

struct BenchScene {
    std::string name;     // short, unique: "lambert/4" (model id / lights)
    std::string family;   // the model family it stands for, for the table
    std::function<Scene()> build;
    MeshDetail detail = MeshDetail::Full;  // Simplified: large meshes' stand-ins, as the editor draws a drag
    std::function<void(Scene&)> beforeEachFrame;  // a change each timed frame makes (a light dragged); may be empty
};

// Every standard scene, in table order: a unit sphere filling a 1280×720 frame under 1 and under
// 4 lights, for two models of each family (one for retroreflection); the same sphere as a
// 1M-triangle mesh; lit by the studio environment alone (Lambert, GGX); on a floor with two of
// four lights casting shadows; the 1M-triangle sphere with the studio and two shadowed lights;
// and the two 1M-triangle scenes as the editor draws them during a drag (the stand-in), once with
// a shadowed light moving every frame.
const std::vector<BenchScene>& benchScenes();

}  // namespace glint
