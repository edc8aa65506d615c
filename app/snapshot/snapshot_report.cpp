// HTML and JUnit XML reports of a snapshot run (see snapshot_report.h).
// Sections: escaping · HTML · JUnit.
#include "snapshot/snapshot_report.h"

#include "util/text.h"

#include <algorithm>
#include <cstdio>

namespace glint {
namespace {

const char* outcomeName(CaseOutcome outcome) {
    switch (outcome) {
        case CaseOutcome::Passed: return "passed";
        case CaseOutcome::Failed: return "failed";
        case CaseOutcome::Error: break;
    }
    return "error";
}

// Failures first, then errors, then passes; by name within each group.
std::vector<const CaseResult*> reportOrder(const SnapshotReport& report) {
    std::vector<const CaseResult*> order;
    for (const CaseResult& result : report.cases) order.push_back(&result);
    auto rank = [](const CaseResult* result) {
        return result->outcome == CaseOutcome::Failed ? 0 : result->outcome == CaseOutcome::Error ? 1 : 2;
    };
    std::stable_sort(order.begin(), order.end(), [&](const CaseResult* a, const CaseResult* b) { return rank(a) < rank(b); });
    return order;
}

}  // namespace

// --- escaping -------------------------------------------------------------------------------

// --- HTML -----------------------------------------------------------------------------------

std::string htmlReport(const SnapshotReport& report) {
    std::string html =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<title>Glint snapshots: " + escapeMarkup(report.suiteName) + "</title>\n"
        "<style>\n"
        "body { font-family: sans-serif; margin: 1.5em; background: #fafafa; color: #222; }\n"
        ".case { border: 1px solid #ccc; border-radius: 4px; margin: 0 0 1em; padding: 0.6em 1em; background: #fff; }\n"
        ".failed { border-left: 6px solid #c62828; } .error { border-left: 6px solid #ef6c00; } .passed { border-left: 6px solid #2e7d32; }\n"
        ".figures td { padding: 0 1em 0 0; } .message { font-family: monospace; white-space: pre-wrap; }\n"
        ".images { display: flex; gap: 1em; flex-wrap: wrap; } figure { margin: 0; } figcaption { font-size: 0.85em; color: #555; }\n"
        ".swap { position: relative; display: inline-block; cursor: crosshair; }\n"
        ".swap img { display: block; image-rendering: pixelated; } .swap .expected { position: absolute; top: 0; left: 0; visibility: hidden; }\n"
        ".swap:hover .expected { visibility: visible; }\n"
        "</style>\n</head>\n<body>\n"
        "<h1>Glint snapshots: " + escapeMarkup(report.suiteName) + "</h1>\n"
        "<p class=\"summary\">" + escapeMarkup(report.summaryLine()) + "</p>\n";
    if (!report.suiteError.empty())
        html += "<div class=\"case error\"><h2>the suite could not be run</h2><p class=\"message\">" + escapeMarkup(report.suiteError) + "</p></div>\n";
    if (report.count(CaseOutcome::Failed) > 0)
        html += "<p>Hover an actual image to see the expected (golden) one in its place.</p>\n";
    for (const CaseResult* result : reportOrder(report)) {
        const std::string outcome = outcomeName(result->outcome);
        html += "<div class=\"case " + outcome + "\" id=\"" + escapeMarkup(result->name) + "\">\n<h2>" + escapeMarkup(result->name) +
                " — " + outcome + "</h2>\n";
        html += "<table class=\"figures\"><tr><td>file</td><td>" + escapeMarkup(result->file) + "</td></tr>\n";
        if (result->width > 0)
            html += "<tr><td>size</td><td>" + std::to_string(result->width) + "×" + std::to_string(result->height) + "</td></tr>\n";
        if (result->compared) {
            char figures[160];
            std::snprintf(figures, sizeof figures, "%ld of %ld (%.3f%%)", result->comparison.failingPixels,
                          result->comparison.totalPixels, 100.0 * result->comparison.failingFraction());
            html += "<tr><td>failing pixels</td><td>" + std::string(figures) + "</td></tr>\n";
            html += "<tr><td>max difference</td><td>" + std::to_string(result->comparison.maxChannelDifference) + "/255</td></tr>\n";
        }
        char tolerance[160];
        std::snprintf(tolerance, sizeof tolerance, "%d/255 per channel, at most %.3g%% of pixels%s", result->tolerance.channelTolerance,
                      100.0 * result->tolerance.failingFraction, result->tolerance.allowOnePixelShift ? ", one-pixel shift allowed" : "");
        html += "<tr><td>tolerance</td><td>" + std::string(tolerance) + "</td></tr>\n";
        if (!result->goldenWritten.empty())
            html += "<tr><td>golden written</td><td>" + escapeMarkup(result->goldenWritten) + "</td></tr>\n";
        html += "</table>\n";
        if (!result->message.empty()) html += "<p class=\"message\">" + escapeMarkup(result->message) + "</p>\n";
        if (!result->actualImage.empty()) {
            html += "<div class=\"images\">\n";
            html += "<figure><span class=\"swap\"><img class=\"actual\" src=\"" + escapeMarkup(result->actualImage) + "\" alt=\"actual\">";
            if (!result->expectedImage.empty())
                html += "<img class=\"expected\" src=\"" + escapeMarkup(result->expectedImage) + "\" alt=\"expected\">";
            html += "</span><figcaption>actual" + std::string(result->expectedImage.empty() ? "" : " (hover: expected)") + "</figcaption></figure>\n";
            if (!result->expectedImage.empty())
                html += "<figure><img src=\"" + escapeMarkup(result->expectedImage) + "\" alt=\"expected\"><figcaption>expected</figcaption></figure>\n";
            if (!result->diffImage.empty())
                html += "<figure><img src=\"" + escapeMarkup(result->diffImage) + "\" alt=\"difference\"><figcaption>|actual − expected| × 16</figcaption></figure>\n";
            html += "</div>\n";
        }
        html += "</div>\n";
    }
    html += "</body>\n</html>\n";
    return html;
}

// --- JUnit ----------------------------------------------------------------------------------

std::string junitReport(const SnapshotReport& report) {
    const bool suiteFailed = !report.suiteError.empty();
    const int tests = static_cast<int>(report.cases.size()) + (suiteFailed ? 1 : 0);
    const int errors = report.count(CaseOutcome::Error) + (suiteFailed ? 1 : 0);
    const std::string suite = escapeMarkup(report.suiteName);
    const std::string counts = "tests=\"" + std::to_string(tests) + "\" failures=\"" + std::to_string(report.count(CaseOutcome::Failed)) +
                               "\" errors=\"" + std::to_string(errors) + "\" skipped=\"0\"";
    std::string xml = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
    xml += "<testsuites name=\"glint snapshot\" " + counts + ">\n";
    xml += "  <testsuite name=\"" + suite + "\" " + counts + ">\n";
    if (suiteFailed) {
        xml += "    <testcase classname=\"glint.snapshot." + suite + "\" name=\"(suite)\">\n";
        xml += "      <error message=\"" + escapeMarkup(report.suiteError) + "\"/>\n    </testcase>\n";
    }
    for (const CaseResult& result : report.cases) {
        xml += "    <testcase classname=\"glint.snapshot." + suite + "\" name=\"" + escapeMarkup(result.name) + "\" file=\"" +
               escapeMarkup(result.file) + "\"";
        if (result.outcome == CaseOutcome::Passed && result.goldenWritten.empty()) {
            xml += "/>\n";
            continue;
        }
        xml += ">\n";
        if (result.outcome != CaseOutcome::Passed) {
            const char* element = result.outcome == CaseOutcome::Failed ? "failure" : "error";
            xml += std::string("      <") + element + " message=\"" + escapeMarkup(result.message) + "\">";
            // The images written for this case, relative to the report directory.
            std::string images;
            for (const auto& [label, path] : {std::pair{"actual", &result.actualImage}, std::pair{"expected", &result.expectedImage},
                                              std::pair{"difference", &result.diffImage}})
                if (!path->empty()) images += std::string(images.empty() ? "" : "\n") + label + ": " + escapeMarkup(*path);
            xml += images;
            xml += std::string("</") + element + ">\n";
        }
        if (!result.goldenWritten.empty()) xml += "      <system-out>golden written: " + escapeMarkup(result.goldenWritten) + "</system-out>\n";
        xml += "    </testcase>\n";
    }
    xml += "  </testsuite>\n</testsuites>\n";
    return xml;
}

}  // namespace glint
