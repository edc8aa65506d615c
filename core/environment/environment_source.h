// Where environment maps come from: equirectangular HDR files (.hdr, .exr) read through
// OpenImageIO and checked (readable to the end, 2:1 size, finite non-negative texels), and the
// built-ins that need no file (studio, sky, uniform white), baked procedurally and made once per
// process. Returns the map with its lighting precomputed. No JSON here (environment_json.h).
#pragma once

#include <functional>
#include <memory>
#include <string>

#include "environment/environment_map.h"
#include "scene/environment.h"
#include "util/diagnostic.h"

namespace glint {

// An equirectangular image from an HDR file; the Diagnostic names the file and what is wrong
// (cannot open, truncated, not 2:1, a NaN, infinite or negative texel and where it is).
Result<EquirectImage> readEquirectFile(const std::string& path);

// The procedural radiance of a built-in environment (kind Studio, Sky or White).
EquirectImage bakeBuiltinEnvironment(EnvironmentKind kind);

// The map of an environment kind: a file read (and precomputed) each call, a built-in made once
// and shared. None has no map. `progress` follows the precompute (environment_map.h); when it
// cancels, the result is an error for which isEnvironmentCancellation() holds.
Result<std::shared_ptr<const EnvironmentMap>> loadEnvironmentMap(EnvironmentKind kind, const std::string& file,
                                                                 const EnvironmentProgress& progress = {});
bool isEnvironmentCancellation(const Diagnostic& diagnostic);

// What progress reports call a map: the file's name, or the built-in's ("studio").
std::string environmentName(EnvironmentKind kind, const std::string& file);

// Follows every map loadEnvironment() makes: given the map's name before it is read, returns the
// progress to offer its precompute (e.g. headless runs report slow maps on stderr). Set once at
// start-up, before any thread loads a map; none by default.
using EnvironmentProgressReport = std::function<EnvironmentProgress(const std::string& name)>;
void setEnvironmentProgressReport(EnvironmentProgressReport report);

// The file an environment names made absolute (as loadEnvironment stores it); others unchanged.
std::string absoluteEnvironmentFile(const Environment& environment);

// Fills `environment.map` for its kind and file (making `file` absolute); on failure the
// environment is left as it was.
Status loadEnvironment(Environment& environment);

}  // namespace glint
