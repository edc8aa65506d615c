// The editor's custom-BRDF bookkeeping: the one safety probe in flight (a child process checking
// a new or changed .brdf, see runtime/brdf_probe.h) and the modification times of the .brdf files the
// scene uses, for hot reload. Plain data; app/editor/custom_brdf_editor.h acts on it.
#pragma once

#include <functional>
#include <future>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "interchange/custom_brdf.h"

namespace glint {

struct PendingBrdfProbe {
    std::shared_ptr<const CustomBrdf> brdf;
    std::vector<float> values;  // probed with these
    bool reload = false;        // a changed file (true) or File ▸ Open (false)
    int materialIndex = 0;      // File ▸ Open: the material it goes into
    std::future<Status> result;
};

struct CustomBrdfEditorState {
    std::optional<PendingBrdfProbe> pending;
    std::map<std::string, long long> seenModification;  // .brdf path → the version in use or last tried
    double lastPollSeconds = -1e9;
    std::function<void()> wake;  // wakes the frame loop when a probe ends (glfwPostEmptyEvent)
};

}  // namespace glint
