// Declaring and applying `glint render`'s classroom options (see classroom_options.h).
#include "cli/classroom_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "brdf/model_registry.h"
#include "brdf/presets.h"
#include "cli/command_line.h"
#include "display/quantisation.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

// The index of `value` in `names`, or −1.
template <size_t N>
int classroomChoice(const std::string& value, const char* const (&names)[N]) {
    for (size_t i = 0; i < N; ++i)
        if (value == names[i]) return static_cast<int>(i);
    return -1;
}

std::optional<float> classroomNumber(const std::string& text) {
    char* end = nullptr;
    const float value = std::strtof(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(value)) return std::nullopt;
    return value;
}

// A number in [low, high].
CLI::Validator numberIn(const std::string& what, float low, float high) {
    return needs(what, [low, high](const std::string& value) {
        const auto number = classroomNumber(value);
        return number && *number >= low && *number <= high;
    });
}

// One of `names`, stored as the enum `Choice` of the same order.
template <typename Choice, size_t N>
void addChoice(CLI::App& command, const std::string& name, std::optional<Choice>& out, const char* const (&names)[N],
               const std::string& what, const std::string& description) {
    command
        .add_option_function<std::string>(
            name, [&out, &names](const std::string& value) { out = static_cast<Choice>(classroomChoice(value, names)); }, description)
        ->check(needs(what, [&names](const std::string& value) { return classroomChoice(value, names) >= 0; }));
}

std::vector<std::string> commaSeparated(const std::string& value) {
    std::vector<std::string> items;
    std::stringstream list(value);
    for (std::string item; std::getline(list, item, ',');) items.push_back(item);
    return items;
}

const std::regex kTessellationPattern(R"(([0-9]{1,4})x([0-9]{1,3}))");

constexpr const char* kClassroomTransfers[] = {"srgb", "gamma", "linear"};  // order of enum Transfer
constexpr const char* kClassroomLayouts[] = {"split", "grid"};

}  // namespace

void ClassroomOptions::addTo(CLI::App& command) {
    addChoice(command, "--transfer", transfer, kClassroomTransfers, "srgb, gamma or linear", "the display encoding (linear: gamma off)");
    command.add_option("--gamma", gamma, "encode with value^(1/G), G in [0.1, 10] (sets --transfer gamma)")
        ->check(numberIn("a number in [0.1, 10]", 0.1f, 10.0f))
        ->type_name("G");
    command.add_option("--levels", levels, "quantise each channel to N intensity levels, 2..256 (256: plain 8-bit)")
        ->check(needsWholeNumber("a whole number in [2, 256]", 2, 256))
        ->type_name("N");
    addChoice(command, "--dither", dither, kDitherIds, "none, bayer2, bayer4 or halftone", "ordered dither before quantising to the levels");
    command.add_flag("--levels-ramp", levelsRamp, "draw a grey radiance ramp 0..1 through the display chain along the bottom");
    command
        .add_option_function<std::string>(
            "--compare", [this](const std::string& value) { compare = commaSeparated(value); },
            "panes of the same scene whose subject (first non-plane object) wears the material file A, B, ... or "
            "preset:NAME (see glint presets) or model:ID (the subject's own material under another model)")
        ->check(needs("2 to 4 comma-separated materials", [](const std::string& value) {
            const std::vector<std::string> items = commaSeparated(value);
            return items.size() >= 2 && items.size() <= 4 && std::find(items.begin(), items.end(), "") == items.end();
        }))
        ->type_name("A,B[,C,D]");
    addChoice(command, "--layout", layout, kClassroomLayouts, "split or grid",
              "split: two panes and a divider (default for 2); grid: 2x2 (default for 3, 4)");
    command.add_option("--divider", divider, "the split's divider as a fraction of the width (default 0.5)")
        ->check(numberIn("a number in [0, 1]", 0.0f, 1.0f))
        ->type_name("F");
    command.add_flag("--compare-interpolation", compareInterpolation, "flat, Gouraud and Phong side by side on the subject");
    command
        .add_option_function<std::string>(
            "--tessellation",
            [this](const std::string& value) {
                std::smatch match;
                std::regex_match(value, match, kTessellationPattern);
                tessellation = Tessellation{std::stoi(match[1]), std::stoi(match[2])};
            },
            "the subject's segments x rings for --compare-interpolation (sphere or torus)")
        ->check(needs("SEGMENTSxRINGS, 3..1024 x 3..512", [](const std::string& value) {
            std::smatch match;
            return std::regex_match(value, match, kTessellationPattern) && std::stoi(match[1]) >= 3 && std::stoi(match[1]) <= 1024 &&
                   std::stoi(match[2]) >= 3 && std::stoi(match[2]) <= 512;
        }))
        ->type_name("SxR");
}

std::string ClassroomOptions::check() const {
    if (!compare.empty() && compareInterpolation) return "--compare and --compare-interpolation are two different views: pick one";
    if ((layout || divider) && compare.empty()) return "--layout and --divider go with --compare";
    if (tessellation && !compareInterpolation) return "--tessellation goes with --compare-interpolation";
    if (layout == CompareLayout::Split && compare.size() != 2) return "--layout split shows two panes; --compare gave " + std::to_string(compare.size());
    if (divider && chosenLayout() != CompareLayout::Split) return "--divider moves the split's divider; the grid has none to move";
    if (transfer && gamma && *transfer != Transfer::Gamma) return "--gamma sets the gamma encoding; it contradicts --transfer";
    return "";
}

CompareLayout ClassroomOptions::chosenLayout() const {
    if (compareInterpolation) return CompareLayout::Row;
    if (layout) return *layout;
    return compare.size() == 2 ? CompareLayout::Split : CompareLayout::Grid;
}

void ClassroomOptions::applyDisplay(Scene& scene) const {
    if (transfer) scene.display.transfer = *transfer;
    if (gamma) scene.display.transfer = Transfer::Gamma, scene.display.gamma = *gamma;
    if (levels) scene.display.levels = *levels;
    if (dither) scene.display.dither = *dither;
    scene.display.levelsRamp |= levelsRamp;
}

Result<std::vector<ComparePaneScene>> ClassroomOptions::paneScenes(const Scene& scene) const {
    auto subject = compareSubject(scene);
    if (!subject) return subject.error();
    std::vector<ComparePaneScene> panes;
    if (compareInterpolation) {
        const char* labels[3] = {"flat", "Gouraud", "Phong"};
        for (int i = 0; i < 3; ++i)
            panes.push_back({withSubjectInterpolation(scene, *subject, kInterpolationLesson[i], tessellation), labels[i]});
        return panes;
    }
    const Material& own = scene.materials.at(scene.objects[*subject].materialIndex);
    for (const std::string& source : compare) {
        Material material;
        if (source.rfind("preset:", 0) == 0) {
            const Preset* preset = findPreset(source.substr(7));
            if (!preset) return Diagnostic{{}, "--compare: no preset named \"" + source.substr(7) + "\" (glint presets lists them)"};
            material = preset->material();
        } else if (source.rfind("model:", 0) == 0) {
            const ModelInfo* found = nullptr;
            for (const ModelInfo& info : allModels())
                if (source.substr(6) == info.id) found = &info;
            if (!found) return Diagnostic{{}, "--compare: no model with the id \"" + source.substr(6) + "\""};
            material = withModel(own, found->model);
        } else {
            auto loaded = loadMaterial(source);
            if (!loaded) return loaded.error();
            material = std::move(*loaded);
        }
        panes.push_back({withSubjectMaterial(scene, *subject, material), material.name});
    }
    return panes;
}

}  // namespace glint
