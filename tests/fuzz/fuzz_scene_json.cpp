// libFuzzer target: scene JSON parsing must never crash, hang or leak on any bytes; it either
// returns a Scene or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene_json.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto scene = glint::parseScene(glint::fuzz::text(data, size), "fuzz.json");
    if (glint::fuzz::readOrExplained(scene)) (void)glint::sceneToJson(*scene).dump();
    return 0;
}
