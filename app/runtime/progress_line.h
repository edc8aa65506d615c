// ProgressLine: one long operation's progress on stderr, fitted to where stderr goes. On a
// terminal, one live line rewritten in place with a carriage return at each whole percent;
// otherwise (a CI log, a file) a new line at the start and each time another kLogStepPercent is
// done, so that a log holds at most 100 / kLogStepPercent + 1 lines of one operation. It measures
// nothing itself: the operation reports its fraction done.
#pragma once

#include <cstdio>
#include <string>

namespace glint {

class ProgressLine {
public:
    static constexpr int kLogStepPercent = 5;

    // Lines read "LABEL N%".
    explicit ProgressLine(std::string label, std::FILE* stream = stderr);
    ~ProgressLine();  // ends a live line left unfinished (a cancelled operation)
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    // `fraction` of the work is done (0..1; 1 writes the last line).
    void update(float fraction);

private:
    std::string label_;
    std::FILE* stream_;
    bool live_;  // the stream is a terminal
    int shown_ = -1;  // the percentage written last; -1 before the first line
};

}  // namespace glint
