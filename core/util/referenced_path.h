// Paths that a JSON file names (meshes, texture images, environments, .brdf and MERL files):
// resolving them on reading and writing them on saving. In memory every such path is absolute,
// so a scene means the same files whichever folder it is written to: a saved file names them
// relative to its own folder, the recovery file (written with no folder) names them absolute.
// Pure path arithmetic; it neither reads nor checks the files.
#pragma once

#include <filesystem>
#include <string>

namespace glint {

// `written` resolved against the folder of `jsonFile` (against the working directory when it is
// relative and the JSON has no file), made absolute and normalised lexically ("a/b/../x" is a/x
// even where a/b does not exist).
std::filesystem::path resolveReferencedPath(const std::string& written, const std::string& jsonFile);
// `path` (a relative one is taken from the working directory) as a file saved to `savedTo` names
// it: relative to the folder of `savedTo`, or absolute when `savedTo` is "" (the recovery file).
std::string referencedPathFor(const std::string& path, const std::string& savedTo);

}  // namespace glint
