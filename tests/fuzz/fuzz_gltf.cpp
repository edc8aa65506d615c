// libFuzzer target: glTF material and light import must never crash or hang on any bytes; it
// returns materials and lights (which must export and import again) or a Diagnostic. Inputs that
// start with the .glb magic "glTF" go through the binary reader (glb.h), the rest through the JSON one.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "interchange/glb.h"
#include "interchange/gltf.h"
#include "fuzz_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const std::string text = glint::fuzz::text(data, size);
    const bool binary = size >= 4 && std::memcmp(data, "glTF", 4) == 0;
    auto file = binary ? glint::parseGlb(text, "fuzz.glb") : glint::parseGltf(text, "fuzz.gltf");
    if (!glint::fuzz::readOrExplained(file)) return 0;
    const glint::ImportedMaterial material =
        file->materials.empty() ? glint::ImportedMaterial{glint::Material::withDefaults("m", glint::BrdfModel::CookTorrance), {}}
                                : file->materials.front();
    if (!glint::parseGltf(glint::writeGltf(material, file->lights).text, "fuzz-out.gltf")) __builtin_trap();
    return 0;
}
