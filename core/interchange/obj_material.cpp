// An .obj file's `mtllib` and `usemtl` statements (see obj_material.h).
#include "interchange/obj_material.h"

#include <algorithm>
#include <sstream>

#include "interchange/mtl.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"
#include "util/referenced_file_error.h"
#include "util/text.h"

namespace glint {
namespace {

struct MaterialStatements {
    std::vector<std::pair<std::string, int>> libraries;  // file name as written, its line
    std::vector<std::string> used;  // distinct names, in order of first use
    int firstUsedLine = 0;          // of used.front()
};

// The text after `keyword` on a line that starts with it (leading blanks allowed), trimmed; or
// nothing when the line is another statement.
std::optional<std::string> statementArgument(std::string_view line, std::string_view keyword) {
    line = trimmed(line);
    if (!line.starts_with(keyword)) return std::nullopt;
    line.remove_prefix(keyword.size());
    if (!line.empty() && line.front() != ' ' && line.front() != '\t') return std::nullopt;
    return std::string(trimmed(line));
}

MaterialStatements scanStatements(const std::string& text) {
    MaterialStatements found;
    std::istringstream lines(text);
    std::string line;
    for (int number = 1; std::getline(lines, line); ++number) {
        if (line.empty() || line[0] == 'v' || line[0] == 'f') continue;  // most lines of a big mesh
        if (auto library = statementArgument(line, "mtllib"); library && !library->empty()) {
            found.libraries.emplace_back(*library, number);
        } else if (auto name = statementArgument(line, "usemtl"); name && !name->empty()) {
            if (found.used.empty()) found.firstUsedLine = number;
            if (std::find(found.used.begin(), found.used.end(), *name) == found.used.end()) found.used.push_back(*name);
        }
    }
    return found;
}

// Library `library` (written at `line` of the .obj) read, or a warning about why not.
std::optional<ImportedFile> loadLibrary(const std::string& objPath, const std::string& library, int line,
                                        std::vector<Diagnostic>& warnings) {
    // One name per statement here (names with spaces are common; several libraries on one line are rare).
    const SourceLocation statement{objPath, line, 0};
    auto confined = confinedReference(library, statement);
    if (!confined) {
        warnings.push_back(makeError("material library not used: " + confined.error().message, statement));
        return std::nullopt;
    }
    auto loaded = loadMtl(confined->string());
    if (!loaded) {
        const std::string problem = referencedFileProblem(confined->string(), loaded.error(), ".mtl file");
        warnings.push_back(makeError("material library '" + library + "' not used: " + problem, statement));
        return std::nullopt;
    }
    return std::move(*loaded);
}

std::optional<MaterialStatements> readStatements(const std::string& objPath) {
    if (lowerExtension(objPath) != "obj") return std::nullopt;
    auto text = readTextFile(objPath);
    if (!text) return std::nullopt;  // the mesh importer reports an unreadable file
    return scanStatements(*text);
}

}  // namespace

ObjMaterial readObjMaterial(const std::string& objPath) {
    ObjMaterial result;
    const std::optional<MaterialStatements> statements = readStatements(objPath);
    if (!statements || statements->used.empty()) return result;  // faces without a material: Glint's default
    const std::string& firstUsed = statements->used.front();
    for (const auto& [library, line] : statements->libraries) {
        if (result.material) break;  // found in an earlier library
        std::optional<ImportedFile> loaded = loadLibrary(objPath, library, line, result.warnings);
        if (!loaded) continue;
        auto named = std::find_if(loaded->materials.begin(), loaded->materials.end(),
                                  [&](const ImportedMaterial& material) { return material.material.name == firstUsed; });
        if (named == loaded->materials.end()) continue;
        const std::vector<Diagnostic> warnings = warningsFor(*loaded, static_cast<size_t>(named - loaded->materials.begin()));
        result.warnings.insert(result.warnings.end(), warnings.begin(), warnings.end());
        result.material = std::move(*named);
    }
    const SourceLocation used{objPath, statements->firstUsedLine, 0};
    if (!result.material) {
        result.warnings.push_back(makeError("'usemtl " + firstUsed +
                                                "': no such material in the file's libraries; the mesh gets Glint's default",
                                            used));
    } else if (statements->used.size() > 1) {
        result.warnings.push_back(makeError("the file uses " + std::to_string(statements->used.size()) +
                                                " materials; a Glint mesh has one: '" + firstUsed +
                                                "', the first, covers it all",
                                            used));
    }
    return result;
}

ObjMaterialLibraries readObjMaterialLibraries(const std::string& objPath) {
    ObjMaterialLibraries result;
    const std::optional<MaterialStatements> statements = readStatements(objPath);
    if (!statements) return result;
    for (const auto& [library, line] : statements->libraries) {
        std::optional<ImportedFile> loaded = loadLibrary(objPath, library, line, result.warnings);
        if (!loaded) continue;
        result.warnings.insert(result.warnings.end(), loaded->warnings.begin(), loaded->warnings.end());
        for (ImportedMaterial& material : loaded->materials) {
            const bool known = std::any_of(result.materials.begin(), result.materials.end(), [&](const ImportedMaterial& earlier) {
                return earlier.material.name == material.material.name;
            });
            if (!known) result.materials.push_back(std::move(material));
        }
    }
    return result;
}

}  // namespace glint
