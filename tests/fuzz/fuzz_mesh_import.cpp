// libFuzzer target: mesh import from memory must never crash, hang or leak on any bytes; it
// either returns a mesh that is finite, indexed in range and inside the unit sphere, or a
// Diagnostic that says why. The first byte picks the format hint, the rest is the file.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/mesh_import.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 2) return 0;
    static const char* const hints[] = {"obj", "ply", "stl", "gltf", "glb", "fbx"};
    const std::string hint = hints[data[0] % 6];
    auto imported = glint::importMeshFromMemory(data + 1, size - 1, hint, "fuzz." + hint);
    if (!glint::fuzz::readOrExplained(imported)) return 0;
    const glint::Mesh& mesh = *imported->mesh;
    for (uint32_t index : mesh.indices)
        if (index >= mesh.vertices.size()) __builtin_trap();
    for (const glint::Vertex& vertex : mesh.vertices)
        if (!(glm::length(vertex.position) <= 1.0001f) || !std::isfinite(vertex.normal.x + vertex.normal.y + vertex.normal.z))
            __builtin_trap();
    return 0;
}
