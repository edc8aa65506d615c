// The safety probe for custom BRDFs: llvmpipe has no GPU watchdog, so a .brdf shader that loops
// forever would freeze the process that draws it. Before the editor or a headless render uses a
// new or changed .brdf, a child process (`glint probe-brdf`, hidden) compiles it and draws a
// 32×32 preview; the parent kills it after a timeout. It proves nothing about values not probed.
#pragma once

#include <string>
#include <vector>

#include "interchange/custom_brdf.h"

namespace glint {

// Seconds a probe may take: $GLINT_BRDF_TIMEOUT_S when set (0.5 to 600), else 8.
double brdfProbeTimeoutSeconds();

// The program run as the probe's child: this executable (/proc/self/exe) unless set, e.g. by a
// test binary, which is not `glint`.
void setBrdfProbeExecutable(std::string executable);

// Runs `executable probe-brdf` on the .brdf text with `values`; success when it drew and exited
// within `timeoutSeconds`. Errors: the child's compile errors (with the .brdf's line numbers),
// or "the shader did not finish in N s".
Status probeCustomBrdf(const CustomBrdf& brdf, const std::vector<float>& values, double timeoutSeconds);

// Every custom BRDF of a scene, each probed with its material's values.
Status probeSceneBrdfs(const Scene& scene, double timeoutSeconds);

// The child's side: `glint probe-brdf NAME --values=V,V,…` (or none) with the .brdf text on stdin.
// Exit 0 when it drew, 1 with the error on stderr otherwise.
int runProbeBrdfCommand(const std::string& name, const std::string& valueList);

}  // namespace glint
