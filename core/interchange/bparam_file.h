// BRDF Explorer .bparam files: saved parameter values for a .brdf file. BRDF Explorer writes a
// first line `bparam PATH` (the .brdf it was made for), then a `::begin parameters` block in the
// .brdf syntax with the current value in the default's place (BRDFBase::saveParamsFile); it reads
// the first line's first word (`bparam` or `analytic`), warns about sections it does not know and
// takes the values whose names the .brdf declares (createBRDFFromFile, syncParametersIntoBRDF).
// Glint reads and writes the same, warning (located) where BRDF Explorer would silently skip.
#pragma once

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "interchange/custom_brdf.h"
#include "scene/scene.h"

namespace glint {

struct BparamFile {
    std::string path;                    // the .bparam file, for messages
    std::string brdfPath;                // the first line's PATH, as written; empty when it names none
    std::vector<BrdfFileParam> params;   // the parameters block's lines, in order
    std::vector<Diagnostic> warnings;    // sections skipped, located
};

// Parses .bparam text; `path` names it in messages. A broken line, an unterminated or mismatched
// section, or no parameters block is an error.
Result<BparamFile> parseBparamFile(std::string_view text, const std::string& path);

// The file's values applied to `brdf`'s packed values, starting from `current` (parameters the file
// leaves out keep theirs). Names the .brdf does not declare, another kind, and values outside its
// range (clamped into it) are warnings, added to `warnings`.
std::vector<float> applyBparam(const BparamFile& file, const CustomBrdf& brdf, std::vector<float> current,
                               std::vector<Diagnostic>& warnings);

// parseBparamFile and applyBparam on a file's text; the file's own warnings go to `warnings`.
Result<std::vector<float>> parseBparam(std::string_view text, const std::string& path, const CustomBrdf& brdf,
                                       std::vector<float> current, std::vector<Diagnostic>& warnings);
Result<std::vector<float>> loadBparam(const std::string& path, const CustomBrdf& brdf, std::vector<float> current,
                                      std::vector<Diagnostic>& warnings);

// The .brdf a .bparam file names, found as BRDF Explorer would (the path as written, from the
// working folder) or, for a file moved with its .brdf, beside the .bparam (the path relative to
// it, then the same file name there).
Result<std::string> findBparamBrdf(const BparamFile& file, const std::string& bparamPath);

// `glint render x.bparam`: the .brdf it names with its values, on the preview stage (0: default size).
Result<Scene> loadBparamPreviewStage(const std::string& path, std::vector<Diagnostic>& warnings, int width = 0,
                                     int height = 0);
bool isBparamFilePath(const std::string& path);  // ends in .bparam (any case)

// Text BRDF Explorer reads: `bparam PATH` naming the .brdf (its path as loaded), then the block.
std::string formatBparam(const CustomBrdf& brdf, const std::vector<float>& values);
Status saveBparam(const std::string& path, const CustomBrdf& brdf, const std::vector<float>& values);

}  // namespace glint
