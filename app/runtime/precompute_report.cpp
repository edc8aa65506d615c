// Progress of slow environment precomputes on stderr (see precompute_report.h).
#include "runtime/precompute_report.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "environment/environment_source.h"

namespace glint {

void reportSlowEnvironmentPrecomputes() {
    const char* after = std::getenv("GLINT_PROGRESS_AFTER_SECONDS");
    const std::chrono::duration<double> quiet(after ? std::atof(after) : 0.5);
    const bool terminal = isatty(STDERR_FILENO);
    const int step = terminal ? 1 : 25;  // percent
    setEnvironmentProgressReport([=](const std::string& name) -> EnvironmentProgress {
        const auto start = std::chrono::steady_clock::now();
        auto shown = std::make_shared<int>(-1);  // steps shown; -1 before the first line
        return [=](float fraction) {
            if (*shown < 0 && std::chrono::steady_clock::now() - start < quiet) return true;
            if (*shown < 0) std::fprintf(stderr, terminal ? "precomputing %s …" : "precomputing %s …\n", name.c_str());
            const int steps = static_cast<int>(std::lround(100.0f * fraction)) / step;
            if (steps > *shown && steps > 0) {
                if (terminal) std::fprintf(stderr, "\rprecomputing %s %3d%%%s", name.c_str(), steps, steps == 100 ? "\n" : "");
                else std::fprintf(stderr, "precomputing %s %d%%\n", name.c_str(), steps * step);
            }
            *shown = std::max(*shown, std::max(steps, 0));
            return true;
        };
    });
}

}  // namespace glint
