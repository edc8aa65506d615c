// Files from the wild (tests/files/README.md): each row of the README's table is opened as it
// says and gives the outcome it says, with the message it names.
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "geometry/mesh_import.h"
#include "interchange/bparam_file.h"
#include "interchange/brdf_file.h"
#include "interchange/asset.h"
#include "interchange/import_formats.h"
#include "util/text.h"

namespace glint {
namespace {

const std::string kFiles = std::string(GLINT_TEST_DATA_DIR) + "/files/";

struct Row {
    std::string file, as, outcome, message;
};

// The rows of the first table in the README (the one whose header starts `| file | as |`).
std::vector<Row> expectedOutcomes() {
    std::ifstream readme(kFiles + "README.md");
    std::vector<Row> rows;
    bool inTable = false;
    for (std::string line; std::getline(readme, line);) {
        if (line.rfind("| file | as |", 0) == 0) {
            inTable = true;
            continue;
        }
        if (!inTable || line.rfind("|---", 0) == 0) continue;
        if (line.empty() || line[0] != '|') break;
        std::vector<std::string> cells;
        std::stringstream stream(line.substr(1));
        for (std::string cell; std::getline(stream, cell, '|');) cells.emplace_back(trimmed(cell));
        if (cells.size() >= 4) rows.push_back({cells[0], cells[1], cells[2], cells[3]});
    }
    return rows;
}

// Opens `path` as `as` says: the error, or nothing, and the warnings.
std::optional<Diagnostic> open(const std::string& path, const std::string& as, std::vector<Diagnostic>& warnings) {
    if (as == "brdf") {
        auto file = loadBrdfFile(path);
        if (!file) return file.error();
        warnings = file->warnings;
    } else if (as == "bparam") {
        auto scene = loadBparamPreviewStage(path, warnings);
        if (!scene) return scene.error();
    } else if (as == "material") {
        const ImportFormat* format = findImportFormat(path);
        if (!format) return makeError("no interchange format for the file", {path});
        auto file = format->load(path);
        if (!file) return file.error();
        warnings = allWarnings(*file);
    } else if (as == "asset") {
        auto asset = loadAsset(path);
        if (!asset) return asset.error();
        warnings = asset->warnings;
    } else {
        auto mesh = importMesh(path);
        if (!mesh) return mesh.error();
    }
    return std::nullopt;
}

TEST(WildFiles, EachGivesTheOutcomeItsTableRowNames) {
    const std::vector<Row> rows = expectedOutcomes();
    ASSERT_GE(rows.size(), 15u);
    for (const Row& row : rows) {
        SCOPED_TRACE(row.file + " as " + row.as);
        std::vector<Diagnostic> warnings;
        const std::optional<Diagnostic> error = open(kFiles + row.file, row.as, warnings);
        std::string said;
        for (const Diagnostic& warning : warnings) said += warning.format() + "\n";
        if (row.outcome == "refused") {
            ASSERT_TRUE(error) << "loaded; warnings:\n" << said;
            EXPECT_NE(error->format().find(row.message), std::string::npos) << error->format();
            EXPECT_GT(error->where.line, 0) << error->format();  // located
        } else {
            ASSERT_FALSE(error) << error->format();
            if (row.outcome == "loads") EXPECT_TRUE(warnings.empty()) << said;
            else EXPECT_NE(said.find(row.message), std::string::npos) << said;
        }
    }
}

}  // namespace
}  // namespace glint
