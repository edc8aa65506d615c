// Files assimp may open for one mesh (see mesh_io_system.h).
#include "geometry/mesh_io_system.h"

#include <filesystem>
#include <system_error>

#include "util/reference_confinement.h"
#include "util/text.h"

namespace glint {
namespace {

std::filesystem::path absoluteForm(const std::string& path) {
    std::error_code error;
    const std::filesystem::path absolute = std::filesystem::absolute(path, error);
    return (error ? std::filesystem::path(path) : absolute).lexically_normal();
}

}  // namespace

MeshIoSystem::MeshIoSystem(std::string meshFile) : meshFile_(std::move(meshFile)), isObj_(lowerExtension(meshFile_) == "obj") {}

bool MeshIoSystem::mayOpen(const char* file) const {
    if (!file) return false;
    const std::filesystem::path path = absoluteForm(file);
    if (!meshFile_.empty() && path == absoluteForm(meshFile_)) return true;
    if (meshFile_.empty() || isObj_) return false;
    auto confined = confinedReference(path.string(), {meshFile_});
    if (!confined && !refusal_) refusal_ = makeError("cannot load mesh: " + confined.error().message, {meshFile_});
    return confined.ok();
}

bool MeshIoSystem::Exists(const char* file) const { return mayOpen(file) && Assimp::DefaultIOSystem::Exists(file); }

Assimp::IOStream* MeshIoSystem::Open(const char* file, const char* mode) {
    if (!mayOpen(file)) return nullptr;
    if (absoluteForm(file) != absoluteForm(meshFile_)) referencedOpened_.push_back(file);
    return Assimp::DefaultIOSystem::Open(file, mode);
}

}  // namespace glint
