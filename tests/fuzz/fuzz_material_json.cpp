// libFuzzer target: material JSON parsing must never crash, hang or leak on any bytes; it either
// returns a Material or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "scene/scene_json.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto material = glint::parseMaterial(glint::fuzz::text(data, size), "fuzz.json");
    if (glint::fuzz::readOrExplained(material)) (void)glint::materialToJson(*material).dump();
    return 0;
}
