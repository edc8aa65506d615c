// Confinement of referenced files (a material library, a texture, a buffer, a mesh a scene
// names): the path a file names must lie, once canonical (symlinks followed), in that file's
// own folder or below, unless the user allows outside references (--allow-outside-references, the
// editor's setting, or its prompt). It decides and records refusals; it reads no file.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "util/diagnostic.h"

namespace glint {

// The process-wide choice, from the command line or the editor's settings; refused by default.
void setOutsideReferencesAllowed(bool allowed);

// Allows outside references while it lives, whatever the setting, on this thread only (a file
// opened meanwhile on a worker stays confined): for Glint's own recovery file, which names the
// user's files by absolute path and is read whole on one thread, meshes included.
class OutsideReferencesAllowance {
public:
    OutsideReferencesAllowance();
    ~OutsideReferencesAllowance();
    OutsideReferencesAllowance(const OutsideReferencesAllowance&) = delete;
    OutsideReferencesAllowance& operator=(const OutsideReferencesAllowance&) = delete;
};

// Allows, for the rest of this run, the outside references of one referencing file (the editor's
// "Allow once" for a file it refused).
void allowOutsideReferencesOf(const std::string& referencingFile);

// The editor's setting (View menu), named in messages that refuse.
extern const char* const kAllowOutsideReferencesSetting;

// `written`, as the file `namedAt.file` names it at `namedAt` (a line, or a JSON pointer the
// caller adds), resolved against that file's folder (util/referenced_path.h). A path outside the
// folder, unless allowed, is a Diagnostic located at `namedAt` that names the path and how to allow
// it, and is recorded for takeRefusedReferences(). With no referencing file, nothing confines it.
Result<std::filesystem::path> confinedReference(const std::string& written, const SourceLocation& namedAt);

// Whether `error` is, or wraps, a refusal of confinedReference (its message names the path
// refused, which the naming file holds).
bool isReferenceRefusal(const Diagnostic& error);

struct RefusedReference {
    std::string referencingFile;  // absolute
    std::string written;          // as the referencing file names it
    bool operator==(const RefusedReference&) const = default;
};
// The distinct refusals since the last call (the editor asks the user about them), oldest first;
// at most kMaxRecordedRefusals are kept between calls (a command line never takes them).
constexpr size_t kMaxRecordedRefusals = 32;
std::vector<RefusedReference> takeRefusedReferences();

}  // namespace glint
