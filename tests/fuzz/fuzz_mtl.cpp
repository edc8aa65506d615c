// libFuzzer target: .mtl parsing must never crash or hang on any bytes; it returns materials
// (which must then write back and read again) or a Diagnostic with a message.
#include <cstddef>
#include <cstdint>
#include <string>

#include "interchange/mtl.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    auto file = glint::parseMtl(glint::fuzz::text(data, size), "fuzz.mtl");
    if (!glint::fuzz::readOrExplained(file)) return 0;
    // What Glint writes it must read back.
    if (!glint::parseMtl(glint::writeMtl(file->materials).text, "fuzz-out.mtl")) __builtin_trap();
    return 0;
}
