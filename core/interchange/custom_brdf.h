// CustomBrdf: a loaded .brdf file made into a Glint model: its parameters as a ParamSpec table
// (so the material panel, packing and .bparam files treat them like a built-in model's) and the
// file it came from. GPU only: the CPU reference cannot run GLSL (referenceCanRender says so).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "interchange/brdf_file.h"

namespace glint {

struct Scene;
struct Material;

struct CustomBrdf {
    BrdfFile file;
    std::vector<ParamSpec> table;  // names point into file.params: a CustomBrdf is never copied
    std::string displayName;       // the file name without folders, for the UI

    CustomBrdf() = default;
    CustomBrdf(const CustomBrdf&) = delete;
    CustomBrdf& operator=(const CustomBrdf&) = delete;
};

std::shared_ptr<const CustomBrdf> makeCustomBrdf(BrdfFile file);
// Parses and wraps a .brdf file.
Result<std::shared_ptr<const CustomBrdf>> loadCustomBrdf(const std::string& path);

// A material using the custom BRDF at its defaults, named after the file.
Material customBrdfMaterial(std::shared_ptr<const CustomBrdf> brdf);
bool isBrdfFilePath(const std::string& path);  // ends in .brdf (any case)
// `glint render foo.brdf`: the file's BRDF at its defaults on the preview stage (0: default size);
// the sections it skipped go to `warnings` when given.
Result<Scene> loadBrdfPreviewStage(const std::string& path, std::vector<Diagnostic>* warnings = nullptr, int width = 0,
                                   int height = 0);

// Refuses a scene that holds a custom BRDF: the CPU reference cannot run GLSL.
Status referenceCanRender(const Scene& scene);

}  // namespace glint
