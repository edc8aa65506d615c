// MERL .binary loading and lookup (see merl.h), after the reference reader BRDFRead.cpp that
// ships with the MERL database (Matusik et al. 2003). Sections: file · coordinates · lookup.
#include "interchange/merl.h"

#include <cmath>
#include <algorithm>
#include <cstring>

#include "math/constants.h"
#include "util/file_io.h"

namespace glint {

// --- file -----------------------------------------------------------------------------------

glm::vec3 MerlTable::at(int thetaHalf, int thetaDifference, int phiDifference) const {
    const size_t index = (size_t(thetaHalf) * kMerlThetaDifferenceBins + thetaDifference) * kMerlPhiDifferenceBins + phiDifference;
    return {reflectance[index], reflectance[index + kMerlSamplesPerChannel], reflectance[index + 2 * kMerlSamplesPerChannel]};
}

Result<MerlTable> parseMerl(std::string_view bytes, const std::string& file) {
    // A repository that keeps MERL files in Git LFS checks out a small text pointer in their place
    // when git-lfs is not installed (https://github.com/git-lfs/git-lfs/blob/main/docs/spec.md).
    if (bytes.substr(0, 24) == "version https://git-lfs.")
        return makeError("not a MERL BRDF but a Git LFS pointer (" + std::to_string(bytes.size()) +
                             " bytes of text naming the real file): fetch the real file with `git lfs pull` in its "
                             "repository (install git-lfs first), or download it from the MERL database",
                         {file, 1, 1});
    if (bytes.size() < 3 * sizeof(int32_t))
        return makeError("not a MERL BRDF: " + std::to_string(bytes.size()) +
                         " bytes is too short for the header (three int32 dimensions)", {file});
    int32_t dimensions[3];
    std::memcpy(dimensions, bytes.data(), sizeof dimensions);
    if (dimensions[0] != kMerlThetaHalfBins || dimensions[1] != kMerlThetaDifferenceBins ||
        dimensions[2] != kMerlPhiDifferenceBins)
        return makeError("not a MERL BRDF: the header says " + std::to_string(dimensions[0]) + "×" +
                             std::to_string(dimensions[1]) + "×" + std::to_string(dimensions[2]) +
                             " samples; MERL files are 90×90×180 (θ_h × θ_d × φ_d)", {file});
    if (bytes.size() != kMerlFileBytes)
        return makeError("the file is " + std::to_string(bytes.size()) + " bytes, but 90×90×180 samples × 3 channels × 8 bytes + "
                         "12 header bytes make " + std::to_string(kMerlFileBytes) +
                         (bytes.size() < kMerlFileBytes ? " (truncated)" : " (trailing data)"), {file});
    MerlTable table;
    table.reflectance.resize(3 * kMerlSamplesPerChannel);
    const char* samples = bytes.data() + sizeof dimensions;
    for (size_t i = 0; i < table.reflectance.size(); ++i) {
        double value;
        std::memcpy(&value, samples + i * sizeof(double), sizeof value);
        if (!std::isfinite(value))
            return makeError("sample " + std::to_string(i % kMerlSamplesPerChannel) + " of channel " +
                                 std::to_string(i / kMerlSamplesPerChannel) + " is not a finite number", {file});
        if (value < 0.0) {  // the database marks unmeasured bins with negative values
            ++table.negativeSamples;
            value = 0.0;
        }
        table.reflectance[i] = static_cast<float>(value * kMerlChannelScale[i / kMerlSamplesPerChannel]);
    }
    return table;
}

Result<MerlTable> loadMerl(const std::string& path) {
    auto bytes = readTextFile(path);  // reads bytes as they are
    if (!bytes) return bytes.error();
    return parseMerl(*bytes, path);
}

std::string makeConstantMerl(glm::vec3 reflectance) {
    std::string bytes(kMerlFileBytes, '\0');
    const int32_t dimensions[3] = {kMerlThetaHalfBins, kMerlThetaDifferenceBins, kMerlPhiDifferenceBins};
    std::memcpy(bytes.data(), dimensions, sizeof dimensions);
    for (int channel = 0; channel < 3; ++channel) {
        const double stored = reflectance[channel] / kMerlChannelScale[channel];
        for (size_t i = 0; i < kMerlSamplesPerChannel; ++i)
            std::memcpy(bytes.data() + sizeof dimensions + (channel * kMerlSamplesPerChannel + i) * sizeof(double), &stored,
                        sizeof stored);
    }
    return bytes;
}

// --- coordinates ----------------------------------------------------------------------------

namespace {

// Rotates v about a unit axis by angle (Rodrigues), as the reference rotate_vector.
glm::vec3 rotate(glm::vec3 v, glm::vec3 axis, float angle) {
    const float c = std::cos(angle), s = std::sin(angle);
    return v * c + axis * (glm::dot(v, axis) * (1.0f - c)) + glm::cross(axis, v) * s;
}

}  // namespace

HalfDifference toHalfDifference(glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    const glm::vec3 in = frame.toLocal(wi), out = frame.toLocal(wo);
    const glm::vec3 half = glm::normalize(in + out);
    const float thetaHalf = std::acos(std::clamp(half.z, -1.0f, 1.0f));
    const float phiHalf = std::atan2(half.y, half.x);
    // The incoming direction in the frame where h is the pole: rotate by −φ_h about n, then −θ_h about b.
    const glm::vec3 difference = rotate(rotate(in, {0, 0, 1}, -phiHalf), {0, 1, 0}, -thetaHalf);
    const float thetaDifference = std::acos(std::clamp(difference.z, -1.0f, 1.0f));
    float phiDifference = std::atan2(difference.y, difference.x);
    if (phiDifference < 0.0f) phiDifference += kPi;  // reciprocity: φ_d and φ_d + π hold the same value
    return {thetaHalf, thetaDifference, phiDifference};
}

glm::vec3 merlBinCoordinates(const HalfDifference& angles) {
    return {kMerlThetaHalfBins * std::sqrt(std::max(angles.thetaHalf, 0.0f) / (kPi / 2)),
            kMerlThetaDifferenceBins * angles.thetaDifference / (kPi / 2),
            kMerlPhiDifferenceBins * angles.phiDifference / kPi};
}

// --- lookup ---------------------------------------------------------------------------------

glm::vec3 lookupMerlNearest(const MerlTable& table, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    if (!(frame.cosTheta(wi) > 0.0f && frame.cosTheta(wo) > 0.0f)) return glm::vec3(0.0f);  // also refuses NaN
    const glm::vec3 bins = merlBinCoordinates(toHalfDifference(wi, wo, frame));
    if (glm::any(glm::isnan(bins)) || glm::any(glm::isinf(bins))) return glm::vec3(0.0f);  // a degenerate pair (wi = −wo, NaN input)
    const int thetaHalf = std::clamp(static_cast<int>(bins.x), 0, kMerlThetaHalfBins - 1);
    const int thetaDifference = std::clamp(static_cast<int>(bins.y), 0, kMerlThetaDifferenceBins - 1);
    const int phiDifference = std::clamp(static_cast<int>(bins.z), 0, kMerlPhiDifferenceBins - 1);
    return table.at(thetaHalf, thetaDifference, phiDifference);
}

glm::vec3 lookupMerlTrilinear(const MerlTable& table, glm::vec3 wi, glm::vec3 wo, const ShadingFrame& frame) {
    if (!(frame.cosTheta(wi) > 0.0f && frame.cosTheta(wo) > 0.0f)) return glm::vec3(0.0f);  // also refuses NaN
    const glm::vec3 bins = merlBinCoordinates(toHalfDifference(wi, wo, frame));
    if (glm::any(glm::isnan(bins)) || glm::any(glm::isinf(bins))) return glm::vec3(0.0f);
    // θ_h and θ_d clamp at the last sample; φ_d wraps (sample 180 is sample 0).
    const float u = std::clamp(bins.x, 0.0f, float(kMerlThetaHalfBins - 1));
    const float v = std::clamp(bins.y, 0.0f, float(kMerlThetaDifferenceBins - 1));
    const float w = std::clamp(bins.z, 0.0f, float(kMerlPhiDifferenceBins));
    const int u0 = std::min(static_cast<int>(u), kMerlThetaHalfBins - 2), v0 = std::min(static_cast<int>(v), kMerlThetaDifferenceBins - 2);
    const int w0 = std::min(static_cast<int>(w), kMerlPhiDifferenceBins - 1);
    const float tu = u - u0, tv = v - v0, tw = w - w0;
    const int w1 = (w0 + 1) % kMerlPhiDifferenceBins;
    glm::vec3 sum(0.0f);
    for (int du = 0; du < 2; ++du)
        for (int dv = 0; dv < 2; ++dv)
            for (int dw = 0; dw < 2; ++dw) {
                const float weight = (du ? tu : 1 - tu) * (dv ? tv : 1 - tv) * (dw ? tw : 1 - tw);
                sum += weight * table.at(u0 + du, v0 + dv, dw ? w1 : w0);
            }
    return sum;
}

}  // namespace glint
