// .bparam reading and writing (see bparam_file.h), after BRDF Explorer's BRDFBase::loadBRDF,
// createBRDFFromFile and saveParamsFile.
#include "interchange/bparam_file.h"

#include <algorithm>
#include <filesystem>

#include "scene/preview_stage.h"
#include "snapshot/case_source.h"
#include "util/file_io.h"
#include "util/reference_confinement.h"
#include "util/referenced_file_error.h"
#include "util/text.h"

namespace glint {

Result<BparamFile> parseBparamFile(std::string_view text, const std::string& path) {
    if (text.size() > kMaxBrdfFileBytes) return makeError("the file is larger than 1 MiB", {path, 1, 1});
    if (Status utf8 = checkUtf8(text, path); !utf8) return utf8.error();
    BparamFile file;
    file.path = path;
    bool sawHeader = false, sawBlock = false;
    std::string section;  // the open section's name; empty outside one
    int lineNumber = 0, sectionLine = 0;
    size_t position = 0;
    while (position < text.size()) {
        const size_t end = std::min(text.find('\n', position), text.size());
        const std::string_view line = text.substr(position, end - position);
        position = end + 1;
        ++lineNumber;
        const std::string_view content = trimmed(line);
        const SourceLocation here{path, lineNumber, static_cast<int>(content.data() - line.data()) + 1};
        if (content.empty() || content[0] == '#') continue;
        if (!sawHeader && section.empty()) {
            sawHeader = true;
            const std::string_view word = headerWord(content);
            if (word == "bparam") {  // `bparam PATH`: the rest of the line, as BRDF Explorer takes it
                file.brdfPath = std::string(trimmed(content.substr(word.size())));
                continue;
            }
            if (word == "analytic") continue;  // a .brdf file read for its parameters
            // Glint before 2026 wrote no header: a file that starts with its block is read as well.
        }
        if (content.rfind("::", 0) == 0) {
            const std::string_view words = trimmed(content.substr(2));
            const std::string_view verb = headerWord(words);
            const std::string name(headerWord(trimmed(words.substr(verb.size()))));
            if ((verb != "begin" && verb != "end") || name.empty())
                return makeError("expected '::begin SECTION' or '::end SECTION'", here);
            if (verb == "begin") {
                if (!section.empty())
                    return makeError("'::begin " + name + "' inside the section opened at line " + std::to_string(sectionLine) +
                                         " (close it with ::end first)",
                                     here);
                if (name == "parameters") {
                    if (sawBlock) return makeError("a second '::begin parameters' block", here);
                    sawBlock = true;
                } else {
                    file.warnings.push_back(makeError("warning: section '" + name + "' is skipped (a .bparam file's values are in 'parameters')", here));
                }
                section = name;
                sectionLine = lineNumber;
            } else {
                if (name != section) return makeError("'::end " + name + "' without '::begin " + name + "'", here);
                section.clear();
            }
            continue;
        }
        if (section.empty()) return makeError("text outside a section (expected '::begin parameters')", here);
        if (section != "parameters") continue;
        auto param = parseBrdfParamLine(line, path, lineNumber);
        if (!param) return param.error();
        file.params.push_back(std::move(*param));
    }
    if (!section.empty())
        return makeError("unterminated section: '::begin " + section + "' has no matching ::end", {path, sectionLine, 1});
    if (!sawBlock) return makeError("no '::begin parameters' block", {path, std::max(1, lineNumber), 1});
    return file;
}

std::vector<float> applyBparam(const BparamFile& file, const CustomBrdf& brdf, std::vector<float> values,
                               std::vector<Diagnostic>& warnings) {
    GLINT_CHECK(static_cast<int>(values.size()) == packedSize(brdf.table));
    for (const BrdfFileParam& param : file.params) {
        auto warn = [&](const std::string& message) {
            warnings.push_back(makeError("warning: " + message, {file.path, param.line, 1}));
        };
        const int index = findParam(brdf.table, param.name);
        if (index < 0) {
            warn("'" + param.name + "' is not a parameter of " + brdf.displayName + "; skipped");
            continue;
        }
        const ParamSpec& spec = brdf.table[index];
        if (spec.kind != param.kind) {
            warn("'" + param.name + "' has another type in " + brdf.displayName + "; skipped");
            continue;
        }
        float value[3] = {param.defaultValue[0], param.defaultValue[1], param.defaultValue[2]};
        if (spec.kind == ParamKind::Scalar && (value[0] < spec.validMin || value[0] > spec.validMax)) {
            const float clamped = std::clamp(value[0], spec.validMin, spec.validMax);
            warn(param.name + " = " + formatNumber(value[0]) + " lies outside the range of " + brdf.displayName + " [" +
                 formatNumber(spec.validMin) + ", " + formatNumber(spec.validMax) + "]; " + formatNumber(clamped) + " used");
            value[0] = clamped;
        }
        const int offset = packedOffset(brdf.table, index);
        for (int c = 0; c < componentCount(spec.kind); ++c) values[offset + c] = value[c];
    }
    return values;
}

Result<std::vector<float>> parseBparam(std::string_view text, const std::string& path, const CustomBrdf& brdf,
                                       std::vector<float> current, std::vector<Diagnostic>& warnings) {
    auto file = parseBparamFile(text, path);
    if (!file) return file.error();
    warnings.insert(warnings.end(), file->warnings.begin(), file->warnings.end());
    return applyBparam(*file, brdf, std::move(current), warnings);
}

Result<std::vector<float>> loadBparam(const std::string& path, const CustomBrdf& brdf, std::vector<float> current,
                                      std::vector<Diagnostic>& warnings) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    return parseBparam(*text, path, brdf, std::move(current), warnings);
}

Result<std::string> findBparamBrdf(const BparamFile& file, const std::string& bparamPath) {
    namespace fs = std::filesystem;
    if (file.brdfPath.empty())
        return makeError("the file does not name its .brdf (BRDF Explorer writes a first line 'bparam NAME.brdf'); "
                         "open the .brdf file first, then this file",
                         {bparamPath, 1, 1});
    // As written (relative to this file), else beside it; an absolute path (BRDF Explorer writes
    // them) only when there is none beside it, so that a folder moved whole keeps working. A path
    // outside this file's folder is refused by name (util/reference_confinement.h).
    const SourceLocation header{bparamPath, 1, 1};
    const fs::path written(file.brdfPath);
    std::error_code code;
    const auto beside = confinedReference(written.filename().string(), header);  // in the folder: never refused
    const bool besideExists = beside && fs::is_regular_file(beside.value(), code);
    if (written.is_absolute() && besideExists) return beside->string();
    const auto named = confinedReference(file.brdfPath, header);
    if (named && fs::is_regular_file(named.value(), code)) return named->string();
    if (besideExists) return beside->string();
    if (!named) return named.error();
    return makeError("the .brdf file it names, '" + file.brdfPath + "', is neither there nor beside this file",
                     {bparamPath, 1, 1});
}

Result<Scene> loadBparamPreviewStage(const std::string& path, std::vector<Diagnostic>& warnings, int width, int height) {
    auto text = readTextFile(path);
    if (!text) return text.error();
    auto file = parseBparamFile(*text, path);
    if (!file) return file.error();
    auto brdfPath = findBparamBrdf(*file, path);
    if (!brdfPath) return brdfPath.error();
    auto brdf = loadCustomBrdf(*brdfPath);
    if (!brdf) return makeError(referencedFileProblem(*brdfPath, brdf.error(), ".brdf file"), {path, 1, 1});
    warnings.insert(warnings.end(), (*brdf)->file.warnings.begin(), (*brdf)->file.warnings.end());
    warnings.insert(warnings.end(), file->warnings.begin(), file->warnings.end());
    Material material = customBrdfMaterial(*brdf);
    material.custom()->values = applyBparam(*file, **brdf, std::move(material.custom()->values), warnings);
    return previewStage(material, width > 0 ? width : kDefaultMaterialPreviewSize,
                        height > 0 ? height : kDefaultMaterialPreviewSize);
}

bool isBparamFilePath(const std::string& path) { return lowerExtension(path) == "bparam"; }

std::string formatBparam(const CustomBrdf& brdf, const std::vector<float>& values) {
    // BRDF Explorer opens the named file from its working folder: the path is written absolute.
    std::string text = "bparam " + std::filesystem::absolute(brdf.file.path).lexically_normal().string() +
                       "\n\n::begin parameters\n";
    for (size_t i = 0; i < brdf.file.params.size(); ++i)
        text += formatBrdfParamLine(brdf.file.params[i], values.data() + packedOffset(brdf.table, static_cast<int>(i))) + "\n";
    return text + "::end parameters\n";
}

Status saveBparam(const std::string& path, const CustomBrdf& brdf, const std::vector<float>& values) {
    return writeFileAtomically(path, formatBparam(brdf, values));
}

}  // namespace glint
