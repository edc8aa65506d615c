// BRDF Explorer .bparam files: saved parameter values for a .brdf file, written as a
// `::begin parameters` block in the .brdf syntax, the current value in the default's place.
// Reading applies them to a CustomBrdf's packed values; it does not load the .brdf itself.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "interchange/custom_brdf.h"

namespace glint {

// Values from .bparam text for `brdf`, starting from `current` (parameters the file leaves out
// keep their current value). Unknown names, other kinds and values outside the .brdf file's
// range are refused with their line and column.
Result<std::vector<float>> parseBparam(std::string_view text, const std::string& path, const CustomBrdf& brdf,
                                       std::vector<float> current);
Result<std::vector<float>> loadBparam(const std::string& path, const CustomBrdf& brdf, std::vector<float> current);

std::string formatBparam(const CustomBrdf& brdf, const std::vector<float>& values);
Status saveBparam(const std::string& path, const CustomBrdf& brdf, const std::vector<float>& values);

}  // namespace glint
