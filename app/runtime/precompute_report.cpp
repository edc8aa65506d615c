// Progress of slow environment precomputes on stderr (see precompute_report.h).
#include "runtime/precompute_report.h"

#include <chrono>
#include <cstdlib>
#include <memory>
#include <string>

#include "environment/environment_source.h"
#include "runtime/progress_line.h"

namespace glint {

void reportSlowEnvironmentPrecomputes() {
    const char* after = std::getenv("GLINT_PROGRESS_AFTER_SECONDS");
    const std::chrono::duration<double> quiet(after ? std::atof(after) : 0.5);
    setEnvironmentProgressReport([=](const std::string& name) -> EnvironmentProgress {
        const auto start = std::chrono::steady_clock::now();
        auto line = std::make_shared<std::unique_ptr<ProgressLine>>();  // made once the precompute is slow
        return [=](float fraction) {
            if (!*line && std::chrono::steady_clock::now() - start < quiet) return true;
            if (!*line) *line = std::make_unique<ProgressLine>("precomputing " + name);
            (*line)->update(fraction);
            return true;
        };
    });
}

}  // namespace glint
