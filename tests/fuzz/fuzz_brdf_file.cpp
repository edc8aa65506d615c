// libFuzzer target: the BRDF Explorer .brdf reader must never crash, hang or leak on any bytes;
// it returns a BrdfFile or a located Diagnostic with a message, and so does the .bparam reader on
// the same bytes. A file that parses also goes through the .bparam writer and reader, which must
// give its values back.
#include <cstddef>
#include <cstdint>
#include <string>

#include "interchange/bparam_file.h"
#include "interchange/brdf_file.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    auto bparam = glint::parseBparamFile(text, "fuzz.bparam");  // the same bytes as a .bparam file
    if (!bparam && (bparam.error().message.empty() || bparam.error().where.line < 1)) __builtin_trap();
    auto file = glint::parseBrdfFile(text, "fuzz.brdf");
    if (!file) {
        if (file.error().message.empty() || file.error().where.line < 1) __builtin_trap();  // located, says why
        return 0;
    }
    auto brdf = glint::makeCustomBrdf(std::move(*file));
    const std::vector<float> values = glint::defaultValues(brdf->table);
    std::vector<glint::Diagnostic> warnings;
    auto reread = glint::parseBparam(glint::formatBparam(*brdf, values), "fuzz.bparam", *brdf, values, warnings);
    if (!reread || *reread != values || !warnings.empty()) __builtin_trap();  // the round trip keeps every value
    return 0;
}
