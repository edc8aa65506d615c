// "environment" in scene files (see environment_json.h).
#include "scene/environment_json.h"

#include <cmath>

#include "environment/environment_source.h"
#include "util/referenced_file_error.h"
#include "util/referenced_path.h"

namespace glint {

Environment readEnvironment(ObjectReader& root, EnvironmentMapLoading loading) {
    Environment environment;
    if (!root.has("environment")) return environment;
    ObjectReader reader = root.object("environment");
    environment.kind = static_cast<EnvironmentKind>(reader.choice("type", kEnvironmentKindIds, 0));
    if (environment.kind == EnvironmentKind::File) {
        if (reader.requiredString("file").empty()) reader.fail("file", "names no file");
        environment.file = reader.referencedFile("file").string();
    }
    environment.rotationDegrees =
        static_cast<float>(reader.number("rotation_degrees", environment.rotationDegrees, Bounds::between(-360, 360)));
    environment.intensity = static_cast<float>(reader.number("intensity", environment.intensity, Bounds::nonNegative()));
    environment.showAsBackground = reader.boolean("show_as_background", environment.showAsBackground);
    reader.rejectUnknownKeys();
    if (loading == EnvironmentMapLoading::Later) environment.file = absoluteEnvironmentFile(environment);
    else if (Status loaded = loadEnvironment(environment); !loaded && environment.kind == EnvironmentKind::File)
        reader.fail("file", referencedFileProblem(environment.file, loaded.error(), "environment map"));
    else if (!loaded)
        reader.fail("type", loaded.error().format());
    return environment;
}

nlohmann::json environmentToJson(const Environment& environment, const std::string& sceneFile) {
    if (environment.kind == EnvironmentKind::None) return nullptr;
    nlohmann::json out = {{"type", kEnvironmentKindIds[static_cast<int>(environment.kind)]}};
    if (environment.kind == EnvironmentKind::File) out["file"] = referencedPathFor(environment.file, sceneFile);
    out["rotation_degrees"] = environment.rotationDegrees;
    out["intensity"] = environment.intensity;
    out["show_as_background"] = environment.showAsBackground;
    return out;
}

}  // namespace glint
