// The scene's environment light: an equirectangular radiance map around the scene (an HDR file
// or a built-in: studio, sky, uniform white), its rotation about +y, an intensity scale and
// whether it shows as the background. Plain data; the map itself is shared, immutable and
// carries its precomputed lighting (environment/environment_map.h). No loading or drawing here.
#pragma once

#include <memory>
#include <string>

namespace glint {

struct EnvironmentMap;

enum class EnvironmentKind { None, File, Studio, Sky, White };

inline constexpr const char* kEnvironmentKindIds[] = {"none", "file", "studio", "sky", "white"};

struct Environment {
    EnvironmentKind kind = EnvironmentKind::None;
    std::string file;              // File: the .hdr/.exr path (absolute once loaded)
    float rotationDegrees = 0.0f;  // turns the map about +y (counter-clockwise seen from above)
    float intensity = 1.0f;        // scale on the map's radiance [W/(sr·m²) per map unit]
    bool showAsBackground = true;  // false: primary rays that miss see Scene::background
    std::shared_ptr<const EnvironmentMap> map;  // null only for None

    bool enabled() const { return kind != EnvironmentKind::None && map != nullptr; }
};

}  // namespace glint
