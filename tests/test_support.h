// Helpers shared by Glint's tests: where the test data lives, a per-test output folder, a scene
// loaded from the test data, a material with some parameters set, and bad files an importer refuses.
#pragma once

#include <filesystem>
#include <initializer_list>
#include <string>
#include <utility>

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include "interchange/material_values.h"
#include "scene/scene_json.h"

namespace glint::test {

inline std::string dataPath(const std::string& relative) { return std::string(GLINT_TEST_DATA_DIR) + "/" + relative; }

// A fresh folder under the build tree for files a test writes.
inline std::string outputDirectory(const std::string& name) {
    const std::filesystem::path directory = std::filesystem::path(GLINT_TEST_OUTPUT_DIR) / name;
    std::filesystem::create_directories(directory);
    return directory.string();
}

inline Scene loadTestScene(const std::string& relative) {
    auto scene = loadScene(dataPath(relative));
    if (!scene) ADD_FAILURE() << scene.error().format();
    return scene ? *scene : Scene{};
}

// One parameter by name: a scalar (or an enum option's index) or a colour.
struct Setting {
    const char* param;
    glm::vec3 value;
    Setting(const char* param, float value) : param(param), value(value) {}
    Setting(const char* param, glm::vec3 value) : param(param), value(value) {}
};

// A material of `model` with `settings` over the model's defaults.
inline Material materialWith(std::string name, BrdfModel model, std::initializer_list<Setting> settings) {
    Material material = Material::withDefaults(std::move(name), model);
    for (const Setting& setting : settings) setParam(material, setting.param, setting.value);
    return material;
}

// Text an importer must refuse, with a message that contains `expected`.
struct BadText {
    std::string text;
    const char* expected;
};

// Each case's text fails to parse as `file` (parse: an importer's parseGltf, parseMtl, …).
template <class Parse>
void expectParseErrors(Parse parse, const std::string& file, std::initializer_list<BadText> cases) {
    for (const BadText& c : cases) {
        auto parsed = parse(c.text, file);
        ASSERT_FALSE(parsed.ok()) << c.text;
        EXPECT_NE(parsed.error().format().find(c.expected), std::string::npos)
            << "input: " << c.text << "\nmessage: " << parsed.error().format();
    }
}

}  // namespace glint::test
