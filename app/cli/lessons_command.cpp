// `glint lessons`: list, check (every scene loads) or render (one PNG per lesson, headless) the
// classroom lesson list. It parses nothing itself: lists and scenes load through core.
#include "cli/commands.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "classroom/lessons.h"
#include "cli/command_line.h"
#include "runtime/headless.h"
#include "scene/scene_json.h"

namespace glint {
namespace {

struct LessonsOptions {
    std::string listPath = defaultLessonListPath();
    bool check = false;
    std::string renderDirectory;
    int width = 320;
};

int runLessons(const LessonsOptions& options) {
    auto list = loadLessonList(options.listPath);
    if (!list) return commandFailed("lessons", list.error().format());

    std::unique_ptr<HeadlessRenderer> headless;
    if (!options.renderDirectory.empty()) {
        auto created = HeadlessRenderer::create();
        if (!created) return commandFailed("lessons", created.error().format());
        headless = std::move(*created);
        std::error_code error;
        std::filesystem::create_directories(options.renderDirectory, error);
    }
    int failures = 0;
    for (size_t index = 0; index < list->lessons.size(); ++index) {
        const Lesson& lesson = list->lessons[index];
        std::printf("%2zu  %-45s %s\n", index + 1, lesson.title.c_str(), lesson.scenePath.c_str());
        if (!options.check && !headless) continue;
        auto scene = loadScene(lesson.scenePath);
        if (!scene) {
            std::fprintf(stderr, "glint lessons: lesson %zu (%s): %s\n", index + 1, lesson.title.c_str(), scene.error().format().c_str());
            ++failures;
            continue;
        }
        if (!headless) continue;
        const int height = std::max(1, options.width * scene->height / std::max(scene->width, 1));
        auto images = headless->render(*scene, options.width, height);
        const std::string number = (index + 1 < 10 ? "0" : "") + std::to_string(index + 1);
        const std::string output = (std::filesystem::path(options.renderDirectory) /
                                    (number + "_" + std::filesystem::path(lesson.scenePath).stem().string() + ".png")).string();
        const Status written = images ? writeRenderedImage(*images, output) : Status(images.error());
        if (!written) {
            std::fprintf(stderr, "glint lessons: lesson %zu (%s): %s\n", index + 1, lesson.title.c_str(), written.error().format().c_str());
            ++failures;
        }
    }
    if (options.check || headless)
        std::printf("%zu lessons, %zu %s, %d failed\n", list->lessons.size(), list->lessons.size() - failures,
                    headless ? "rendered" : "load", failures);
    return failures == 0 ? 0 : 1;
}

}  // namespace

void addLessonsCommand(CLI::App& glint) {
    auto options = std::make_shared<LessonsOptions>();
    CLI::App* command = addCommand(glint, "lessons", "list the classroom lessons, check that they load, or render them",
                                   [options] { return runLessons(*options); });
    command->add_option("LIST", options->listPath, "a lesson list (default: the lessons shipped with Glint, or $GLINT_LESSONS)")
        ->type_name("LIST.json");
    command->add_flag("--check", options->check, "load every lesson's scene; exit 1 naming each one that fails");
    command->add_option("--render", options->renderDirectory, "render every lesson headless to DIR/NN_<scene>.png")->type_name("DIR");
    command->add_option("--width", options->width, "width of the rendered images in pixels (default 320; height keeps the scene's aspect)")
        ->check(needsWholeNumber("a number of pixels from 8 to 4096", 8, 4096))
        ->type_name("N");
}

}  // namespace glint
