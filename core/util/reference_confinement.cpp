// Confinement of referenced files (see reference_confinement.h).
#include "util/reference_confinement.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <set>
#include <system_error>
#include <utility>

#include "util/referenced_path.h"

namespace glint {

const char* const kAllowOutsideReferencesSetting = "Read files outside a file's folder";

namespace {

namespace fs = std::filesystem;

std::atomic<bool> allowedBySetting{false};
thread_local int allowances = 0;  // OutsideReferencesAllowance: this thread's only

std::mutex mutex;  // guards the two below
std::set<std::string> allowedReferencingFiles;
std::vector<RefusedReference> refusals;

// The end of every refusal's message: how to allow it.
const std::string& allowingAdvice() {
    static const std::string advice = std::string("to read it anyway, run with --allow-outside-references, or tick View > '") +
                                      kAllowOutsideReferencesSetting + "' in the editor";
    return advice;
}

fs::path canonicalForm(const fs::path& path) {
    std::error_code error;
    fs::path canonical = fs::weakly_canonical(path, error);  // follows the symlinks of the part that exists
    return error ? path.lexically_normal() : canonical;
}

// Whether `path` lies in `folder` or below, both made canonical (symlinks followed) first.
bool liesWithin(const fs::path& path, const fs::path& folder) {
    const fs::path canonicalPath = canonicalForm(path);
    auto inside = canonicalPath.begin();
    for (const fs::path& part : canonicalForm(folder)) {
        if (part.empty()) continue;  // the trailing "" of "dir/"
        if (inside == canonicalPath.end() || *inside != part) return false;
        ++inside;
    }
    return true;
}

}  // namespace

void setOutsideReferencesAllowed(bool allowed) { allowedBySetting = allowed; }

OutsideReferencesAllowance::OutsideReferencesAllowance() { ++allowances; }

OutsideReferencesAllowance::~OutsideReferencesAllowance() { --allowances; }

void allowOutsideReferencesOf(const std::string& referencingFile) {
    std::lock_guard lock(mutex);
    allowedReferencingFiles.insert(resolveReferencedPath(referencingFile, "").string());
}

Result<fs::path> confinedReference(const std::string& written, const SourceLocation& namedAt) {
    const fs::path resolved = resolveReferencedPath(written, namedAt.file);
    if (namedAt.file.empty() || allowedBySetting || allowances > 0) return resolved;
    const fs::path referencingFile = resolveReferencedPath(namedAt.file, "");
    const fs::path folder = referencingFile.parent_path();
    if (liesWithin(resolved, folder)) return resolved;
    {
        std::lock_guard lock(mutex);
        if (allowedReferencingFiles.count(referencingFile.string())) return resolved;
        const RefusedReference refused{referencingFile.string(), written};
        if (refusals.size() < kMaxRecordedRefusals && std::find(refusals.begin(), refusals.end(), refused) == refusals.end())
            refusals.push_back(refused);
    }
    return makeError("refused '" + written + "': it lies outside the folder of the file that names it (" +
                         folder.string() + "), and Glint reads referenced files only from there and below; " +
                         allowingAdvice(),
                     namedAt);
}

bool isReferenceRefusal(const Diagnostic& error) { return error.message.find(allowingAdvice()) != std::string::npos; }

std::vector<RefusedReference> takeRefusedReferences() {
    std::lock_guard lock(mutex);
    return std::exchange(refusals, {});
}

}  // namespace glint
