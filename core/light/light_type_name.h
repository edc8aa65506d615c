// A light type's name as written in scene files ("directional", "point", "spot", "ambient") and
// shown in panels and the surface probe's text. Names only; parsing lives in scene_json.cpp.
#pragma once

#include "light/light.h"

namespace glint {

inline const char* lightTypeName(LightType type) {
    switch (type) {
        case LightType::Directional: return "directional";
        case LightType::Point: return "point";
        case LightType::Spot: return "spot";
        case LightType::Ambient: return "ambient";
    }
    return "";
}

}  // namespace glint
