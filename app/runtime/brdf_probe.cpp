// Child-process probe of custom BRDF shaders (see brdf_probe.h).
// Sections: the parent (spawn, feed, wait, kill) · the child (probe-brdf).
#include "runtime/brdf_probe.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <iterator>
#include <sstream>

#include "runtime/headless.h"
#include "scene/preview_stage.h"
#include "util/text.h"

namespace glint {

// --- the parent -----------------------------------------------------------------------------

double brdfProbeTimeoutSeconds() {
    if (const char* text = std::getenv("GLINT_BRDF_TIMEOUT_S")) {
        char* end = nullptr;
        const double seconds = std::strtod(text, &end);
        if (end != text && *end == '\0' && seconds >= 0.5 && seconds <= 600.0) return seconds;
    }
    return 8.0;
}

namespace {

std::string& probeExecutable() {
    static std::string executable = "/proc/self/exe";
    return executable;
}

std::string joinValues(const std::vector<float>& values) {
    std::string joined;
    for (float value : values) joined += (joined.empty() ? "" : ",") + formatNumber(value, "%.9g");
    return joined.empty() ? "none" : joined;
}

}  // namespace

void setBrdfProbeExecutable(std::string executable) { probeExecutable() = std::move(executable); }

Status probeCustomBrdf(const CustomBrdf& brdf, const std::vector<float>& values, double timeoutSeconds) {
    const std::string executable = probeExecutable();
    int toChild[2], fromChild[2];
    if (pipe(toChild) != 0) return makeError("cannot start the shader probe (pipe failed)");
    if (pipe(fromChild) != 0) {
        close(toChild[0]), close(toChild[1]);
        return makeError("cannot start the shader probe (pipe failed)");
    }
    const std::string valueOption = "--values=" + joinValues(values);  // "=": a value may start with "-"
    const pid_t child = fork();
    if (child < 0) {
        close(toChild[0]), close(toChild[1]), close(fromChild[0]), close(fromChild[1]);
        return makeError("cannot start the shader probe (fork failed)");
    }
    if (child == 0) {
        dup2(toChild[0], STDIN_FILENO);
        dup2(fromChild[1], STDOUT_FILENO);
        dup2(fromChild[1], STDERR_FILENO);
        close(toChild[0]), close(toChild[1]), close(fromChild[0]), close(fromChild[1]);
        execl(executable.c_str(), executable.c_str(), "probe-brdf", brdf.file.path.c_str(), valueOption.c_str(),
              static_cast<char*>(nullptr));
        _exit(127);
    }
    close(toChild[0]);
    close(fromChild[1]);
    // The child reads all of stdin before it draws, so this write cannot wait on its output.
    const std::string& payload = brdf.file.sourceText;
    const auto sigpipe = signal(SIGPIPE, SIG_IGN);
    size_t written = 0;
    while (written < payload.size()) {
        const ssize_t n = write(toChild[1], payload.data() + written, payload.size() - written);
        if (n <= 0) break;
        written += static_cast<size_t>(n);
    }
    close(toChild[1]);
    signal(SIGPIPE, sigpipe);

    std::string output;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
    bool finished = false;
    while (true) {
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) break;
        pollfd readable{fromChild[0], POLLIN, 0};
        const int ready = poll(&readable, 1, static_cast<int>(std::min<long long>(left.count(), 200)));
        if (ready > 0) {
            char buffer[4096];
            const ssize_t n = read(fromChild[0], buffer, sizeof buffer);
            if (n <= 0) {
                finished = true;  // end of output: the child is exiting
                break;
            }
            if (output.size() < 65536) output.append(buffer, static_cast<size_t>(n));
        }
    }
    close(fromChild[0]);
    int status = 0;
    if (finished) {
        // Output closed; give the exit the rest of the time.
        while (waitpid(child, &status, WNOHANG) == 0) {
            if (std::chrono::steady_clock::now() >= deadline) {
                finished = false;
                break;
            }
            usleep(10000);
        }
    }
    if (!finished) {
        kill(child, SIGKILL);
        waitpid(child, &status, 0);
        return makeError("the shader did not finish in " + formatNumber(timeoutSeconds) +
                             " s (an endless loop?); it is not used",
                         {brdf.file.path, brdf.file.shaderLine, 1});
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return success();
    while (!output.empty() && output.back() == '\n') output.pop_back();
    if (output.empty()) output = "the shader probe failed (exit status " + std::to_string(status) + ")";
    return makeError(output);
}

Status probeSceneBrdfs(const Scene& scene, double timeoutSeconds) {
    for (const Material& material : scene.materials)
        if (const CustomMaterial* custom = material.custom())
            if (Status probed = probeCustomBrdf(*custom->brdf, custom->values, timeoutSeconds); !probed)
                return probed;
    return success();
}

// --- the child ------------------------------------------------------------------------------

int runProbeBrdfCommand(const std::string& name, const std::string& valueList) {
    const std::string text{std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>()};
    auto file = parseBrdfFile(text, name);
    if (!file) {
        std::fprintf(stderr, "%s\n", file.error().format().c_str());
        return 1;
    }
    Material material = customBrdfMaterial(makeCustomBrdf(std::move(*file)));
    material.name = "probe";
    if (valueList != "none") {
        std::vector<float> values;
        std::stringstream list(valueList);
        for (std::string item; std::getline(list, item, ',');) values.push_back(std::strtof(item.c_str(), nullptr));
        if (values.size() == material.custom()->values.size()) material.custom()->values = values;
    }
    auto headless = HeadlessRenderer::create();
    if (!headless) {
        std::fprintf(stderr, "%s\n", headless.error().format().c_str());
        return 1;
    }
    auto rendered = (*headless)->render(previewStage(material, 32, 32), 32, 32);
    if (!rendered) {
        std::fprintf(stderr, "%s\n", rendered.error().format().c_str());
        return 1;
    }
    return 0;
}

}  // namespace glint
