// The built-in environments' precomputed lighting, kept in the disk cache (util/disk_cache.h):
// the same numbers as makeEnvironmentMap, without its second of CPU at every start.
#pragma once

#include <memory>
#include <string>

#include "environment/environment_map.h"

namespace glint {

// makeEnvironmentMap(radiance, progress), or the lighting stored under `name` for the same
// radiance by an earlier run of this executable (progress is then offered 1 at once; null when
// it cancels).
std::shared_ptr<const EnvironmentMap> cachedEnvironmentMap(const std::string& name, EquirectImage radiance,
                                                           const EnvironmentProgress& progress);

}  // namespace glint
