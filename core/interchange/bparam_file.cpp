// .bparam reading and writing (see bparam_file.h).
#include "interchange/bparam_file.h"

#include <algorithm>
#include <cctype>

#include "util/file_io.h"
#include "util/text.h"

namespace glint {

Result<std::vector<float>> parseBparam(std::string_view text, const std::string& path, const CustomBrdf& brdf,
                                       std::vector<float> values) {
    GLINT_CHECK(static_cast<int>(values.size()) == packedSize(brdf.table));
    if (text.size() > kMaxBrdfFileBytes) return makeError("the file is larger than 1 MiB", {path, 1, 1});
    if (Status utf8 = checkUtf8(text, path); !utf8) return utf8.error();
    bool inBlock = false, sawBlock = false;
    int lineNumber = 0, blockLine = 0;
    size_t position = 0;
    while (position < text.size()) {
        const size_t end = std::min(text.find('\n', position), text.size());
        const std::string_view line = text.substr(position, end - position);
        position = end + 1;
        ++lineNumber;
        const std::string_view content = trimmed(line);
        const SourceLocation here{path, lineNumber, static_cast<int>(content.data() - line.data()) + 1};
        if (content.empty() || content[0] == '#') continue;
        if (content == "::begin parameters") {
            if (sawBlock) return makeError("a second '::begin parameters' block", here);
            inBlock = sawBlock = true;
            blockLine = lineNumber;
            continue;
        }
        if (content == "::end parameters") {
            if (!inBlock) return makeError("'::end parameters' without '::begin parameters'", here);
            inBlock = false;
            continue;
        }
        if (!inBlock)
            return makeError("expected '::begin parameters' (a .bparam file holds one parameters block)", here);
        auto param = parseBrdfParamLine(line, path, lineNumber);
        if (!param) return param.error();
        const int index = findParam(brdf.table, param->name);
        if (index < 0)
            return makeError("'" + param->name + "' is not a parameter of " + brdf.displayName, here);
        const ParamSpec& spec = brdf.table[index];
        if (spec.kind != param->kind)
            return makeError("'" + param->name + "' has another type in " + brdf.displayName, here);
        const float value = param->defaultValue[0];
        if (spec.kind == ParamKind::Scalar && (value < spec.validMin || value > spec.validMax))
            return makeError(param->name + ": " + std::to_string(value) + " lies outside the range of " +
                                 brdf.displayName + " [" + std::to_string(spec.validMin) + ", " +
                                 std::to_string(spec.validMax) + "]",
                             here);
        const int offset = packedOffset(brdf.table, index);
        for (int c = 0; c < componentCount(spec.kind); ++c) values[offset + c] = param->defaultValue[c];
    }
    if (inBlock) return makeError("unterminated block: '::begin parameters' has no matching ::end", {path, blockLine, 1});
    if (!sawBlock) return makeError("no '::begin parameters' block", {path, 1, 1});
    return values;
}

Result<std::vector<float>> loadBparam(const std::string& path, const CustomBrdf& brdf, std::vector<float> current) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parseBparam(*text, path, brdf, std::move(current));
}

std::string formatBparam(const CustomBrdf& brdf, const std::vector<float>& values) {
    std::string text = "# Parameter values for " + brdf.displayName + " (BRDF Explorer .bparam, written by Glint)\n"
                       "::begin parameters\n";
    for (size_t i = 0; i < brdf.file.params.size(); ++i)
        text += formatBrdfParamLine(brdf.file.params[i], values.data() + packedOffset(brdf.table, static_cast<int>(i))) + "\n";
    return text + "::end parameters\n";
}

Status saveBparam(const std::string& path, const CustomBrdf& brdf, const std::vector<float>& values) {
    return writeFileAtomically(path, formatBparam(brdf, values));
}

}  // namespace glint
