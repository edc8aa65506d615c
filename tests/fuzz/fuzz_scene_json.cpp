// libFuzzer target: scene JSON parsing must never crash, hang or leak on any bytes; it either
// returns a Scene or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto scene = glint::parseScene(text, "fuzz.json");
    if (!scene && scene.error().message.empty()) __builtin_trap();  // every error says why
    if (scene) (void)glint::sceneToJson(*scene).dump();
    return 0;
}
