// The scenes of the classroom's compare panes: copies of one scene that differ only in the
// subject object's material (another material, a preset, the same material under another model)
// or in how it is interpolated (flat, Gouraud, Phong). Same camera, lights and everything else.
// No rendering or layout here (compare_layout.h, app/classroom/compare_render.h).
#pragma once

#include <optional>

#include "scene/scene.h"
#include "util/diagnostic.h"

namespace glint {

// The object the panes vary: the first object that is not a plane (floors keep their material),
// or the first object when every object is a plane. An error for a scene without objects.
Result<size_t> compareSubject(const Scene& scene);

// A copy of `scene` in which the subject wears `material` (appended to the scene's materials).
Scene withSubjectMaterial(const Scene& scene, size_t subject, const Material& material);

// `material` under another model: parameters that both tables name alike keep their values
// (carriedValues), the rest take the new model's defaults. A .brdf or measured material starts
// from defaults.
Material withModel(const Material& material, BrdfModel model);

// The segments × rings of a sphere or torus subject (other shapes have no tessellation).
struct Tessellation {
    int segments = 16;
    int rings = 8;
};

// A copy of `scene` in which the subject is drawn with `interpolation`, tessellated as given
// when the subject is a sphere or a torus.
Scene withSubjectInterpolation(const Scene& scene, size_t subject, SurfaceInterpolation interpolation,
                               const std::optional<Tessellation>& tessellation);

// The three interpolation lesson panes in order: flat, Gouraud, Phong.
inline constexpr SurfaceInterpolation kInterpolationLesson[3] = {SurfaceInterpolation::Flat, SurfaceInterpolation::Gouraud,
                                                                 SurfaceInterpolation::Phong};

}  // namespace glint
