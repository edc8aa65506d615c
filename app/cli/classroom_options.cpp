// Parsing and applying `glint render`'s classroom options (see classroom_options.h).
#include "cli/classroom_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <regex>
#include <sstream>

#include "brdf/model_registry.h"
#include "brdf/presets.h"
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

ClassroomOptions::Parsed classroomRefuse(std::string& error, std::string message) {
    error = std::move(message);
    return ClassroomOptions::Parsed::Refused;
}

constexpr const char* kClassroomTransfers[] = {"srgb", "gamma", "linear"};  // order of enum Transfer
constexpr const char* kClassroomLayouts[] = {"split", "grid"};

}  // namespace

ClassroomOptions::Parsed ClassroomOptions::parse(const std::vector<std::string>& arguments, size_t& i, std::string& error) {
    const std::string& option = arguments[i];
    static const char* const withValue[] = {"--transfer", "--gamma", "--levels", "--dither", "--compare", "--layout", "--divider", "--tessellation"};
    if (option == "--levels-ramp" || option == "--compare-interpolation") {
        (option == "--levels-ramp" ? levelsRamp : compareInterpolation) = true;
        return Parsed::Taken;
    }
    if (classroomChoice(option, withValue) < 0) return Parsed::NotClassroom;
    if (i + 1 >= arguments.size()) return classroomRefuse(error, option + " needs a value");
    const std::string& value = arguments[++i];
    if (option == "--transfer") {
        const int index = classroomChoice(value, kClassroomTransfers);
        if (index < 0) return classroomRefuse(error, "--transfer needs srgb, gamma or linear (got " + value + ")");
        transfer = static_cast<Transfer>(index);
    } else if (option == "--gamma") {
        const auto number = classroomNumber(value);
        if (!number || *number < 0.1f || *number > 10.0f) return classroomRefuse(error, "--gamma needs a number in [0.1, 10] (got " + value + ")");
        gamma = *number;
    } else if (option == "--levels") {
        if (!std::regex_match(value, std::regex("[0-9]{1,3}")) || std::stoi(value) < 2 || std::stoi(value) > 256)
            return classroomRefuse(error, "--levels needs a whole number in [2, 256] (got " + value + ")");
        levels = std::stoi(value);
    } else if (option == "--dither") {
        const int index = classroomChoice(value, kDitherIds);
        if (index < 0) return classroomRefuse(error, "--dither needs none, bayer2, bayer4 or halftone (got " + value + ")");
        dither = static_cast<Dither>(index);
    } else if (option == "--compare") {
        std::stringstream list(value);
        for (std::string item; std::getline(list, item, ',');) compare.push_back(item);
        if (compare.size() < 2 || compare.size() > 4 || std::find(compare.begin(), compare.end(), "") != compare.end())
            return classroomRefuse(error, "--compare needs 2 to 4 comma-separated materials (got " + value + ")");
    } else if (option == "--layout") {
        const int index = classroomChoice(value, kClassroomLayouts);
        if (index < 0) return classroomRefuse(error, "--layout needs split or grid (got " + value + ")");
        layout = static_cast<CompareLayout>(index);
    } else if (option == "--divider") {
        const auto number = classroomNumber(value);
        if (!number || *number < 0.0f || *number > 1.0f) return classroomRefuse(error, "--divider needs a number in [0, 1] (got " + value + ")");
        divider = *number;
    } else {  // --tessellation
        std::smatch match;
        static const std::regex pattern(R"(([0-9]{1,4})x([0-9]{1,3}))");
        if (!std::regex_match(value, match, pattern) || std::stoi(match[1]) < 3 || std::stoi(match[1]) > 1024 ||
            std::stoi(match[2]) < 3 || std::stoi(match[2]) > 512)
            return classroomRefuse(error, "--tessellation needs SEGMENTSxRINGS, 3..1024 x 3..512 (got " + value + ")");
        tessellation = Tessellation{std::stoi(match[1]), std::stoi(match[2])};
    }
    return Parsed::Taken;
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
