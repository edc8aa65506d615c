// PLY triangle strips (`element tristrips`, as in the Stanford 3D Scanning Repository's files):
// assimp 5.2.5 reads a strip as one polygon, so Glint rewrites such a file as the same PLY with a
// `face` element of the strips' triangles (alternate triangles flipped to keep the winding; a
// -1 starts a new strip; triangles that repeat an index, the strips' stitches, left out) before
// assimp reads it. ASCII and both binary byte orders; the other elements are copied as they are.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "util/diagnostic.h"

namespace glint {

// Whether the header (in the file's first bytes) declares `element tristrips`.
bool plyHasTristrips(std::string_view start);

// The file with its strips as faces, or a Diagnostic naming the header line or the strip that is
// malformed or cut short.
Result<std::string> plyStripsToFaces(std::string_view bytes, const std::string& name);

}  // namespace glint
