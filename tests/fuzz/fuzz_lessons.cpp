// libFuzzer target: the lesson list (lessons/lessons.json, core/classroom/lessons.h) must never
// crash, hang or leak on any bytes; it either returns a list or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "classroom/lessons.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    glint::fuzz::readOrExplained(glint::parseLessonList(glint::fuzz::text(data, size), "fuzz/lessons.json"));
    return 0;
}
