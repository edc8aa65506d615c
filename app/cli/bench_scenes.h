// The standard scenes of `glint bench`: a table of named scene builders, one row per scene. Each
// scene's first object is what the bare shading pass is compared with (its material, its lights).
// To add a scene, add a row to the table in bench_scenes.cpp. It does not time anything
// (bench_command.cpp does).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace glint {

struct BenchScene {
    std::string name;     // short, unique: "lambert/4" (model id / lights)
    std::string family;   // the model family it stands for, for the table
    std::function<Scene()> build;
};

// Every standard scene, in table order: a unit sphere filling a 1280×720 frame under 1 and under
// 4 lights, for two models of each family (one for retroreflection); the same sphere as a
// 1M-triangle mesh; lit by the studio environment alone (Lambert, GGX); on a floor with two of
// four lights casting shadows; and the 1M-triangle sphere with the studio and two shadowed lights.
const std::vector<BenchScene>& benchScenes();

}  // namespace glint
