// Paths that a JSON file names relative to its own folder (a .brdf or MERL file a material
// refers to): resolving them on reading and writing them relative again on saving. Pure path
// arithmetic; it neither reads nor checks the files.
#pragma once

#include <filesystem>
#include <string>

namespace glint {

// `written` resolved against the folder of `jsonFile` (kept as it is when absolute or when the
// JSON has no file), normalised lexically ("a/b/../x" is a/x even where a/b does not exist).
std::filesystem::path resolveReferencedPath(const std::string& written, const std::string& jsonFile);
// `path` relative to the folder of `savedTo` ("" or an impossible relation keeps `path`).
std::string referencedPathFor(const std::string& path, const std::string& savedTo);

}  // namespace glint
