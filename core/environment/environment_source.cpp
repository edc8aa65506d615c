// HDR files and built-in environments (see environment_source.h).
// Sections: files · built-ins · loading.
#include "environment/environment_source.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <mutex>

#include <OpenImageIO/imageio.h>

#include "environment/environment_cache.h"
#include "math/constants.h"
#include "scene/background.h"

namespace glint {

// --- files ----------------------------------------------------------------------------------

Result<EquirectImage> readEquirectFile(const std::string& path) {
    const SourceLocation where{path};
    auto input = OIIO::ImageInput::open(path);
    if (!input) return makeError("cannot read the environment image: " + OIIO::geterror(), where);
    const OIIO::ImageSpec spec = input->spec();
    if (spec.nchannels < 3)
        return makeError("the environment image has " + std::to_string(spec.nchannels) +
                             " channel(s); it needs red, green and blue", where);
    if (spec.width != 2 * spec.height || spec.height < 2 || spec.height > 4096)
        return makeError("the environment image is " + std::to_string(spec.width) + "×" + std::to_string(spec.height) +
                             "; an equirectangular map is twice as wide as it is high (from 4×2 to 8192×4096)",
                         where);
    std::vector<float> all(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        return makeError("cannot read the environment image to its end (truncated or damaged?): " + input->geterror(),
                         where);
    EquirectImage image(spec.width, spec.height);
    for (int y = 0; y < spec.height; ++y) {
        for (int x = 0; x < spec.width; ++x) {
            const float* texel = &all[(static_cast<size_t>(y) * spec.width + x) * spec.nchannels];
            for (int c = 0; c < 3; ++c) {
                if (!std::isfinite(texel[c]) || texel[c] < 0.0f)
                    return makeError("texel (" + std::to_string(x) + ", " + std::to_string(y) + ") channel " +
                                         std::to_string(c) + " is " + std::to_string(texel[c]) +
                                         "; radiance must be finite and non-negative", where);
            }
            image.at(x, y) = {texel[0], texel[1], texel[2]};
        }
    }
    return image;
}

// --- built-ins ------------------------------------------------------------------------------

namespace {

// A soft rectangular area light seen from the centre: `radiance` inside half angles
// (halfWidth, halfHeight) [rad] around `centre`, fading to 0 over `edge` [rad] (smoothstep).
struct SoftBox {
    glm::vec3 centre;
    float halfWidth, halfHeight, edge;
    glm::vec3 radiance;
};

float smoothFall(float offset, float half, float edge) {
    const float t = std::clamp((half + edge - offset) / edge, 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

glm::vec3 softBoxRadiance(const SoftBox& box, glm::vec3 direction) {
    const glm::vec3 forward = glm::normalize(box.centre);
    const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0) + glm::vec3(0, 0, 1e-3f)));
    const glm::vec3 up = glm::cross(right, forward);
    const float along = glm::dot(direction, forward);
    if (along <= 0.0f) return glm::vec3(0.0f);
    const float horizontal = std::abs(std::atan(glm::dot(direction, right) / along));
    const float vertical = std::abs(std::atan(glm::dot(direction, up) / along));
    return box.radiance * smoothFall(horizontal, box.halfWidth, box.edge) * smoothFall(vertical, box.halfHeight, box.edge);
}

constexpr float kDegree = kPi / 180.0f;

// The studio: a dark dome (a little brighter overhead) with a large key soft box front right, a
// dimmer fill front left, a rim light behind and a long strip overhead. The camera of the default
// scenes looks along −z from +z, so "front" is +z.
glm::vec3 studioRadiance(glm::vec3 direction) {
    static const SoftBox kBoxes[] = {
        {{0.8f, 0.6f, 0.7f}, 20 * kDegree, 14 * kDegree, 6 * kDegree, {12.0f, 11.5f, 11.0f}},   // key
        {{-0.9f, 0.25f, 0.6f}, 16 * kDegree, 16 * kDegree, 8 * kDegree, {2.5f, 2.6f, 2.8f}},    // fill
        {{-0.3f, 0.35f, -1.0f}, 8 * kDegree, 20 * kDegree, 3 * kDegree, {8.0f, 8.0f, 8.0f}},    // rim
        {{0.0f, 1.0f, 0.05f}, 45 * kDegree, 5 * kDegree, 3 * kDegree, {5.0f, 5.0f, 5.0f}},     // strip
    };
    const float elevation = direction.y;
    glm::vec3 radiance = glm::vec3(0.03f) + glm::vec3(0.02f) * std::max(elevation, 0.0f);
    for (const SoftBox& box : kBoxes) radiance += softBoxRadiance(box, direction);
    return radiance;
}

EquirectImage bake(int width, int height, auto&& radianceAt) {
    EquirectImage image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = radianceAt(equirectDirection({(x + 0.5f) / width, (y + 0.5f) / height}));
    return image;
}

}  // namespace

EquirectImage bakeBuiltinEnvironment(EnvironmentKind kind) {
    switch (kind) {
        case EnvironmentKind::Studio: return bake(512, 256, studioRadiance);
        case EnvironmentKind::Sky: {
            Background sky;  // the background's procedural sky gradient, default colours
            sky.kind = BackgroundKind::Sky;
            return bake(128, 64, [&](glm::vec3 direction) { return backgroundRadiance(sky, direction); });
        }
        default: return bake(32, 16, [](glm::vec3) { return glm::vec3(1.0f); });  // uniform white
    }
}

// --- loading --------------------------------------------------------------------------------

namespace {
constexpr const char* kCancelledMessage = "environment precompute cancelled";
EnvironmentProgressReport gProgressReport;
}  // namespace

Result<std::shared_ptr<const EnvironmentMap>> loadEnvironmentMap(EnvironmentKind kind, const std::string& file,
                                                                 const EnvironmentProgress& progress) {
    if (kind == EnvironmentKind::None) return std::shared_ptr<const EnvironmentMap>();
    std::shared_ptr<const EnvironmentMap> map;
    if (kind == EnvironmentKind::File) {
        auto image = readEquirectFile(file);
        if (!image) return image.error();
        map = makeEnvironmentMap(std::move(*image), progress);
    } else {
        static std::mutex mutex;
        static std::shared_ptr<const EnvironmentMap> builtins[5];
        std::lock_guard lock(mutex);
        auto& cached = builtins[static_cast<int>(kind)];
        if (!cached)
            cached = cachedEnvironmentMap(std::string("environment-") + kEnvironmentKindIds[static_cast<int>(kind)],
                                          bakeBuiltinEnvironment(kind), progress);
        map = cached;
    }
    if (!map) return makeError(kCancelledMessage, {file});
    return map;
}

bool isEnvironmentCancellation(const Diagnostic& diagnostic) { return diagnostic.message == kCancelledMessage; }

std::string environmentName(EnvironmentKind kind, const std::string& file) {
    if (kind == EnvironmentKind::File) return std::filesystem::path(file).filename().string();
    return kEnvironmentKindIds[static_cast<int>(kind)];
}

void setEnvironmentProgressReport(EnvironmentProgressReport report) { gProgressReport = std::move(report); }

std::string absoluteEnvironmentFile(const Environment& environment) {
    if (environment.kind != EnvironmentKind::File || environment.file.empty()) return environment.file;
    return std::filesystem::absolute(environment.file).lexically_normal().string();
}

Status loadEnvironment(Environment& environment) {
    const std::string file = absoluteEnvironmentFile(environment);
    auto map = loadEnvironmentMap(environment.kind, file,
                                  gProgressReport ? gProgressReport(environmentName(environment.kind, file)) : nullptr);
    if (!map) return map.error();
    environment.file = file;
    environment.map = std::move(*map);
    return success();
}

}  // namespace glint
