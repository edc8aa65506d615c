// Referenced paths in JSON files (see referenced_path.h).
#include "util/referenced_path.h"

#include <system_error>

namespace glint {

std::filesystem::path resolveReferencedPath(const std::string& written, const std::string& jsonFile) {
    std::filesystem::path path(written);
    if (path.is_relative() && !jsonFile.empty()) path = std::filesystem::path(jsonFile).parent_path() / path;
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return (error ? path : absolute).lexically_normal();
}

std::string referencedPathFor(const std::string& path, const std::string& savedTo) {
    if (path.empty()) return path;
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error).lexically_normal();
    if (error) return path;
    if (savedTo.empty()) return absolute.generic_string();
    const std::filesystem::path base = std::filesystem::absolute(savedTo, error).parent_path();
    const std::filesystem::path relative = absolute.lexically_relative(base);
    return error || relative.empty() ? absolute.generic_string() : relative.generic_string();
}

}  // namespace glint
