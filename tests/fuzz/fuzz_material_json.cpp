// libFuzzer target: material JSON parsing must never crash, hang or leak on any bytes; it either
// returns a Material or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene_json.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto material = glint::parseMaterial(text, "fuzz.json");
    if (!material && material.error().message.empty()) __builtin_trap();  // every error says why
    if (material) (void)glint::materialToJson(*material).dump();
    return 0;
}
