// Progress on stderr, live on a terminal and a line every few percent elsewhere (see progress_line.h).
#include "runtime/progress_line.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace glint {

ProgressLine::ProgressLine(std::string label, std::FILE* stream)
    : label_(std::move(label)), stream_(stream), live_(isatty(fileno(stream)) == 1) {}

ProgressLine::~ProgressLine() {
    if (live_ && shown_ >= 0 && shown_ < 100) std::fputc('\n', stream_);
}

void ProgressLine::update(float fraction) {
    const float done = fraction >= 0.0f ? std::min(fraction, 1.0f) : 0.0f;  // NaN: nothing done
    // Whole percents done; the 0.05 absorbs rounding in fractions summed from shares (0.99999 is done).
    const int percent = static_cast<int>(std::floor(100.0f * done + 0.05f));
    const int shown = live_ || percent == 100 ? percent : percent / kLogStepPercent * kLogStepPercent;
    if (shown <= shown_) return;
    shown_ = shown;
    if (live_) std::fprintf(stream_, "\r%s %3d%%%s", label_.c_str(), shown, shown == 100 ? "\n" : "");
    else std::fprintf(stream_, "%s %d%%\n", label_.c_str(), shown);
    std::fflush(stream_);
}

}  // namespace glint
