// A sphere that encloses some geometry: what shadow maps fit their projections to and what a
// shape reports as its extent. Only the type; the functions that compute one live with their data.
#pragma once

#include <glm/glm.hpp>

namespace glint {

struct BoundingSphere {
    glm::vec3 center{0.0f};
    float radius = 0.0f;  // [m]
};

}  // namespace glint
