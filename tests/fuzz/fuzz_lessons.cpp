// libFuzzer target: the lesson list (lessons/lessons.json, core/classroom/lessons.h) must never
// crash, hang or leak on any bytes; it either returns a list or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "classroom/lessons.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto lessons = glint::parseLessonList(text, "fuzz/lessons.json");
    if (!lessons && lessons.error().message.empty()) __builtin_trap();  // every error says why
    return 0;
}
