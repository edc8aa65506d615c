// Warnings and choice among an imported file's materials (see imported.h).
#include "interchange/imported.h"

#include <charconv>

namespace glint {

std::vector<Diagnostic> warningsFor(const ImportedFile& file, size_t index) {
    std::vector<Diagnostic> warnings = file.warnings;
    if (index < file.materials.size())
        warnings.insert(warnings.end(), file.materials[index].warnings.begin(), file.materials[index].warnings.end());
    return warnings;
}

std::vector<Diagnostic> allWarnings(const ImportedFile& file) {
    std::vector<Diagnostic> warnings = file.warnings;
    for (const ImportedMaterial& material : file.materials)
        warnings.insert(warnings.end(), material.warnings.begin(), material.warnings.end());
    return warnings;
}

Result<size_t> chooseMaterial(const ImportedFile& file, const std::string& selector, const std::string& path) {
    if (file.materials.empty()) return makeError("the file has no material", {path});
    if (selector.empty()) return size_t{0};
    for (size_t i = 0; i < file.materials.size(); ++i)
        if (file.materials[i].material.name == selector) return i;
    size_t index = 0;
    const auto [end, error] = std::from_chars(selector.data(), selector.data() + selector.size(), index);
    if (error == std::errc() && end == selector.data() + selector.size() && index < file.materials.size()) return index;
    std::string names;
    for (size_t i = 0; i < file.materials.size(); ++i)
        names += (i ? ", " : "") + std::to_string(i) + " '" + file.materials[i].material.name + "'";
    return makeError("no material '" + selector + "' in the file; it holds " + names, {path});
}

}  // namespace glint
