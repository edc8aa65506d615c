// Snapshot suites and their manifest (see snapshot_suite.h; format in docs/snapshot-testing.md).
// Sections: manifest reading · suite loading · sharding.
#include "snapshot/snapshot_suite.h"

#include <algorithm>
#include <filesystem>
#include <regex>

#include "scene/json_object_reader.h"
#include "snapshot/case_source.h"
#include "util/file_io.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

constexpr const char* kManifestFormat = "glint-snapshot-suite";
constexpr int kManifestVersion = 1;

// --- manifest reading -----------------------------------------------------------------------

// Overrides the fields of `tolerance` that the "tolerance" object names.
void readTolerance(ObjectReader& owner, CompareTolerance& tolerance) {
    if (!owner.has("tolerance")) {
        owner.expect({"tolerance"});
        return;
    }
    ObjectReader reader = owner.object("tolerance");
    tolerance.channelTolerance = reader.integer("channel", tolerance.channelTolerance, 0, 255);
    tolerance.failingFraction = reader.number("failing_percent", tolerance.failingFraction * 100.0, Bounds::between(0, 100)) / 100.0;
    tolerance.allowOnePixelShift = reader.boolean("allow_shift", tolerance.allowOnePixelShift);
    reader.rejectUnknownKeys();
}

void readSize(ObjectReader& reader, int& width, int& height) {
    width = reader.integer("width", width, 1, 16384);
    height = reader.integer("height", height, 1, 16384);
    if ((width > 0) != (height > 0)) reader.failHere("give both \"width\" and \"height\", or neither");
}

bool validCaseName(const std::string& name) {
    static const std::regex pattern(R"([A-Za-z0-9_][A-Za-z0-9_.\-]*)");
    return std::regex_match(name, pattern);
}

std::string checkedName(ObjectReader& reader, const std::string& key, const std::string& name) {
    if (!validCaseName(name))
        reader.fail(key, "case name '" + name + "' may hold only letters, digits, '_', '-' and '.' (it names goldens/NAME.png)");
    return name;
}

struct Manifest {
    CompareTolerance tolerance;
    int width = 0, height = 0;
    bool listsCases = false;
    std::vector<SnapshotCase> cases;
    std::vector<std::string> caseLocations;  // JSON pointers of the cases, for duplicate-name messages
};

Manifest readManifest(const JsonDocument& document, const fs::path& directory) {
    ObjectReader root = readRoot(document, "snapshot manifest");
    const std::string format = root.requiredString("format");
    if (format != kManifestFormat) root.fail("format", "expected \"" + std::string(kManifestFormat) + "\", found \"" + format + "\"");
    const int version = root.integer("version", -1, 1, 1'000'000);
    if (version < 0) root.failHere("the manifest needs a \"version\" (this Glint reads version 1)");
    if (version > kManifestVersion) root.fail("version", "version " + std::to_string(version) + " is newer than this Glint reads (1)");
    Manifest manifest;
    readSize(root, manifest.width, manifest.height);
    readTolerance(root, manifest.tolerance);
    manifest.listsCases = root.has("cases");
    for (ObjectReader& entry : root.objectArray("cases")) {
        SnapshotCase snapshotCase;
        const std::string file = entry.requiredString("file");
        snapshotCase.file = (directory / file).lexically_normal().string();
        snapshotCase.name = checkedName(entry, entry.has("name") ? "name" : "file",
                                        entry.string("name", fs::path(file).stem().string()));
        snapshotCase.width = manifest.width, snapshotCase.height = manifest.height;
        readSize(entry, snapshotCase.width, snapshotCase.height);
        snapshotCase.tolerance = manifest.tolerance;
        readTolerance(entry, snapshotCase.tolerance);
        entry.rejectUnknownKeys();
        manifest.cases.push_back(snapshotCase);
        manifest.caseLocations.push_back(entry.pointer());
    }
    // Names must be unique: each owns one golden.
    for (size_t i = 0; i < manifest.cases.size(); ++i)
        for (size_t j = 0; j < i; ++j)
            if (manifest.cases[i].name == manifest.cases[j].name)
                throw JsonReadError{makeError("case name '" + manifest.cases[i].name + "' is used twice (each case owns goldens/NAME.png)",
                                              document.locate(manifest.caseLocations[i]))};
    root.rejectUnknownKeys();
    return manifest;
}

}  // namespace

// --- suite loading --------------------------------------------------------------------------

std::string SnapshotSuite::goldenPath(const SnapshotCase& snapshotCase) const {
    return (fs::path(directory) / "goldens" / (snapshotCase.name + ".png")).string();
}

Result<SnapshotSuite> loadSnapshotSuite(const std::string& path) {
    std::error_code error;
    const bool isDirectory = fs::is_directory(path, error);
    if (!isDirectory && !fs::exists(path, error)) return makeError("no such suite directory or manifest", {path});
    const fs::path directory = isDirectory ? fs::path(path) : fs::path(path).parent_path();
    const fs::path manifestPath = isDirectory ? directory / kSnapshotManifestName : fs::path(path);

    SnapshotSuite suite;
    suite.directory = directory.empty() ? "." : directory.string();
    suite.name = fs::absolute(suite.directory).lexically_normal().filename().string();
    if (suite.name.empty()) suite.name = fs::absolute(suite.directory).lexically_normal().parent_path().filename().string();

    Manifest manifest;
    if (!isDirectory || fs::exists(manifestPath, error)) {
        auto text = readTextFile(manifestPath.string());
        if (!text) return text.error();
        auto document = JsonDocument::parse(*text, manifestPath.string());
        if (!document) return document.error();
        try {
            manifest = readManifest(*document, directory);
        } catch (const JsonReadError& readError) {
            return readError.diagnostic;
        }
    }
    if (manifest.listsCases) {
        suite.cases = std::move(manifest.cases);
    } else {
        auto files = listJsonFiles(suite.directory, {manifestPath.filename().string()});
        if (!files) return files.error();
        for (const std::string& file : *files) {
            SnapshotCase snapshotCase{fs::path(file).stem().string(), file, manifest.tolerance, manifest.width, manifest.height};
            if (!validCaseName(snapshotCase.name))
                return makeError("file name '" + snapshotCase.name + "' cannot name a golden: use letters, digits, '_', '-' and '.'", {file});
            suite.cases.push_back(std::move(snapshotCase));
        }
    }
    std::sort(suite.cases.begin(), suite.cases.end(), [](const SnapshotCase& a, const SnapshotCase& b) { return a.name < b.name; });
    if (suite.cases.empty()) return makeError("the suite has no cases (no *.json scene or material files)", {suite.directory});
    return suite;
}

// --- sharding -------------------------------------------------------------------------------

Result<Shard> parseShard(const std::string& text) {
    static const std::regex pattern(R"((\d{1,6})/(\d{1,6}))");
    std::smatch match;
    if (!std::regex_match(text, match, pattern)) return makeError("--shard needs I/N, e.g. 0/2 (shards are numbered from 0)");
    Shard shard{std::stoi(match[1]), std::stoi(match[2])};
    if (shard.count < 1 || shard.index >= shard.count)
        return makeError("--shard " + text + ": I must be between 0 and N-1 (shards are numbered from 0)");
    return shard;
}

std::vector<SnapshotCase> casesOfShard(const std::vector<SnapshotCase>& cases, Shard shard) {
    std::vector<SnapshotCase> slice;
    for (size_t k = 0; k < cases.size(); ++k)
        if (static_cast<int>(k % shard.count) == shard.index) slice.push_back(cases[k]);
    return slice;
}

}  // namespace glint
