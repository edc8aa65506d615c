// `glint snapshot` (see commands.h).
// Sections: options · one case · reports · the command.
#include "cli/commands.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <regex>
#include <set>

#include "cli/command_line.h"
#include "cli/render_pool.h"
#include "image/image_io.h"
#include "snapshot/case_source.h"
#include "snapshot/golden_check.h"
#include "snapshot/snapshot_report.h"
#include "snapshot/snapshot_suite.h"
#include "util/file_io.h"

namespace glint {
namespace {

namespace fs = std::filesystem;

// --- options --------------------------------------------------------------------------------

struct SnapshotOptions {
    std::string suitePath;
    std::string outputDirectory = "snapshot-report";
    bool updateFailing = false;
    std::set<std::string> updateNamed;
    int jobs = 1;
    Shard shard;
    bool sharded = false;
};

// --- one case -------------------------------------------------------------------------------

CaseResult runCase(HeadlessRenderer& headless, const SnapshotSuite& suite, const SnapshotCase& snapshotCase,
                   const SnapshotOptions& options) {
    CaseResult result;
    result.name = snapshotCase.name;
    result.file = snapshotCase.file;
    result.tolerance = snapshotCase.tolerance;
    auto scene = loadRenderable(snapshotCase.file, snapshotCase.width, snapshotCase.height);
    if (!scene) {
        result.message = scene.error().format();
        return result;
    }
    auto images = headless.render(*scene, scene->width, scene->height);
    if (!images) {
        result.message = "render failed: " + images.error().format();
        return result;
    }
    result.width = scene->width, result.height = scene->height;
    const std::string goldenPath = suite.goldenPath(snapshotCase);
    GoldenCheck check = checkAgainstGolden(images->display, goldenPath, snapshotCase.tolerance);
    result.compared = check.compared;
    result.comparison = check.comparison;

    if (options.updateNamed.count(snapshotCase.name) || (options.updateFailing && check.outcome == CaseOutcome::Failed)) {
        if (Status written = writeDisplayImage(images->display, goldenPath); !written) {
            result.message = written.error().format();
            return result;
        }
        result.outcome = CaseOutcome::Passed;
        result.goldenWritten = goldenPath;
        result.message = check.outcome == CaseOutcome::Failed ? "golden written; before: " + check.message : "golden rewritten";
        return result;
    }
    result.outcome = check.outcome;
    result.message = check.message;
    if (check.outcome != CaseOutcome::Failed) return result;

    // A failing case leaves its images for a person (and the HTML report) to look at.
    const fs::path imageDirectory = fs::path(options.outputDirectory) / "images";
    auto save = [&](const DisplayImage& image, const std::string& kind, std::string& reportPath) {
        const std::string relative = "images/" + snapshotCase.name + "." + kind + ".png";
        if (Status written = writeDisplayImage(image, (imageDirectory / (snapshotCase.name + "." + kind + ".png")).string()); !written)
            result.message += "; " + written.error().format();
        else
            reportPath = relative;
    };
    save(images->display, "actual", result.actualImage);
    if (check.golden) save(*check.golden, "expected", result.expectedImage);
    if (check.compared) save(differenceImage(images->display, *check.golden), "diff", result.diffImage);
    return result;
}

// --- reports --------------------------------------------------------------------------------

// Removes the images an earlier run left (only the names this command writes).
void removeOldImages(const fs::path& imageDirectory) {
    static const std::regex ours(R"(.+\.(actual|expected|diff)\.png)");
    std::error_code error;
    std::vector<fs::path> stale;
    for (auto entry = fs::directory_iterator(imageDirectory, error); !error && entry != fs::directory_iterator(); entry.increment(error))
        if (std::regex_match(entry->path().filename().string(), ours)) stale.push_back(entry->path());
    for (const fs::path& path : stale) fs::remove(path, error);
}

Status writeReports(const SnapshotReport& report, const std::string& outputDirectory) {
    const fs::path directory(outputDirectory);
    if (Status html = writeFileAtomically((directory / "index.html").string(), htmlReport(report)); !html) return html;
    return writeFileAtomically((directory / "junit.xml").string(), junitReport(report));
}

// The suite could not be run: say why, still leave a report for CI, exit 2.
int suiteFailure(SnapshotReport& report, const std::string& message, const SnapshotOptions& options) {
    report.suiteError = message;
    std::fprintf(stderr, "glint snapshot: %s\n", message.c_str());
    std::error_code error;
    fs::create_directories(options.outputDirectory, error);
    if (Status written = writeReports(report, options.outputDirectory); !written)
        std::fprintf(stderr, "glint snapshot: %s\n", written.error().format().c_str());
    std::printf("%s\n", report.summaryLine().c_str());
    return 2;
}

// --- the command ----------------------------------------------------------------------------

int runSnapshot(const SnapshotOptions& options) {
    SnapshotReport report;
    report.suiteName = fs::path(options.suitePath).filename().string();
    auto suite = loadSnapshotSuite(options.suitePath);
    if (!suite) return suiteFailure(report, suite.error().format(), options);
    report.suiteName = suite->name;
    if (options.sharded)
        report.suiteName += " (shard " + std::to_string(options.shard.index) + "/" + std::to_string(options.shard.count) + ")";
    for (const std::string& name : options.updateNamed)
        if (std::none_of(suite->cases.begin(), suite->cases.end(), [&](const SnapshotCase& c) { return c.name == name; }))
            return suiteFailure(report, "--update-case " + name + ": the suite has no case of that name", options);

    const std::vector<SnapshotCase> cases = casesOfShard(suite->cases, options.shard);
    std::error_code error;
    fs::create_directories(fs::path(options.outputDirectory) / "images", error);
    if (error) return suiteFailure(report, "cannot create the report directory " + options.outputDirectory + ": " + error.message(), options);
    removeOldImages(fs::path(options.outputDirectory) / "images");
    if (options.updateFailing || !options.updateNamed.empty()) fs::create_directories(fs::path(suite->directory) / "goldens", error);

    report.cases.resize(cases.size());
    const Status rendered = renderInParallel(options.jobs, cases.size(), [&](HeadlessRenderer& headless, size_t index) {
        report.cases[index] = runCase(headless, *suite, cases[index], options);
    });
    if (!rendered) {
        report.cases.clear();
        return suiteFailure(report, rendered.error().format(), options);
    }

    for (const CaseResult& result : report.cases) {
        if (!result.goldenWritten.empty()) std::printf("wrote golden %s\n", result.goldenWritten.c_str());
        if (result.outcome != CaseOutcome::Passed)
            std::fprintf(stderr, "%s %s: %s\n", result.outcome == CaseOutcome::Failed ? "FAIL " : "ERROR", result.name.c_str(),
                         result.message.c_str());
    }
    if (Status written = writeReports(report, options.outputDirectory); !written) {
        std::fprintf(stderr, "glint snapshot: %s\n", written.error().format().c_str());
        std::printf("%s\n", report.summaryLine().c_str());
        return 2;
    }
    std::fprintf(stderr, "glint snapshot: report in %s/index.html and %s/junit.xml\n", options.outputDirectory.c_str(),
                 options.outputDirectory.c_str());
    std::printf("%s\n", report.summaryLine().c_str());
    return report.count(CaseOutcome::Passed) == static_cast<int>(report.cases.size()) ? 0 : 1;
}

}  // namespace

void addSnapshotCommand(CLI::App& glint) {
    auto options = std::make_shared<SnapshotOptions>();
    CLI::App* command = addCommand(glint, "snapshot", "compare a suite of scenes and materials with their goldens",
                                   [options] { return runSnapshot(*options); });
    command->footer("exit code: 0 all passed, 1 some case failed or errored, 2 the suite could not be run");
    command->add_option("SUITE", options->suitePath,
                        "a suite directory (scenes and materials *.json, goldens/NAME.png, optional snapshot.json) or its "
                        "manifest file")
        ->required();
    command->add_option("-o,--out", options->outputDirectory,
                        "where the report goes (default: snapshot-report): index.html, junit.xml, "
                        "images/NAME.{actual,expected,diff}.png for each failing case")
        ->type_name("DIR");
    command->add_flag("--update", options->updateFailing, "write the goldens of failing cases (missing, other size, different)");
    command->add_option("--update-case", options->updateNamed, "write the golden of case NAME, passing or not (repeatable)")
        ->allow_extra_args(false)  // one name per --update-case
        ->type_name("NAME");
    command->add_option("-j,--jobs", options->jobs, "render on N threads, each with its own OSMesa context (default 1)")
        ->check(needsWholeNumber("a number from 1 to 999", 1, 999))
        ->type_name("N");
    command
        ->add_option_function<std::string>(
            "--shard",
            [options](const std::string& value) {
                auto shard = parseShard(value);
                if (!shard) refuse(shard.error().message);
                options->shard = *shard;
                options->sharded = true;
            },
            "run only shard I of N (0 <= I < N): case k of the sorted list goes to shard k mod N")
        ->type_name("I/N");
}

}  // namespace glint
