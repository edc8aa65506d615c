// libFuzzer target: MaterialX (.mtlx) parsing must never crash or hang on any bytes; it returns
// materials (which must then write back and read again) or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "interchange/materialx.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto file = glint::parseMaterialX(glint::fuzz::text(data, size), "fuzz.mtlx");
    if (!glint::fuzz::readOrExplained(file)) return 0;
    // What Glint writes it must read back.
    if (!glint::parseMaterialX(glint::writeMaterialX(file->materials, "").text, "fuzz-out.mtlx")) __builtin_trap();
    return 0;
}
