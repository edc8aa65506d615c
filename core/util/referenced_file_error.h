// What went wrong with a file that another file names (a mesh or texture a scene names, a material
// library an .obj names), said without quoting its bytes: the user opened the naming file, not
// this one, and a parser's message may quote a line of it (a CI log then shows what a hostile
// file made Glint read). A message that cannot quote it is kept: the file could not be read (the
// system's reason), or the message is about the whole file (a size, a limit); any other says
// where the file is not valid and how to see the details. It does not confine paths
// (util/reference_confinement.h does).
#pragma once

#include <string>

#include "util/diagnostic.h"

namespace glint {

// `error`, met while reading `file` as `kind` ("mesh", ".mtl file", "image"), reworded so that it
// quotes nothing of the file.
std::string referencedFileProblem(const std::string& file, const Diagnostic& error, const std::string& kind);

}  // namespace glint
