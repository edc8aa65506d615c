// The GL side of measured (MERL) materials: one surface program per variant (MSAA samples, Gouraud,
// lights; bounded as the built-in models' programs) built around shaders/brdf/merl.glsl, and each table uploaded once as a 3D RGB32F texture
// (180 × 90 × 90: φ_d, θ_d, θ_h), kept while a material holds the table. It does not evaluate anything itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>

#include "gl/bounded_program_cache.h"
#include "gl/shader_program.h"
#include "gl/surface_variant.h"
#include "interchange/measured_brdf.h"

namespace glint {

// Texture unit of the table (material textures use 1..12, the environment 13..15, shadows 24..31).
inline constexpr int kMeasuredTableUnit = 16;

class MeasuredBrdfGpu {
public:
    MeasuredBrdfGpu() = default;
    ~MeasuredBrdfGpu();  // the context must be current
    MeasuredBrdfGpu(const MeasuredBrdfGpu&) = delete;
    MeasuredBrdfGpu& operator=(const MeasuredBrdfGpu&) = delete;

    // Programs kept; `frame` is the caller's frame count, whose programs are never evicted while
    // it draws (gl/bounded_program_cache.h).
    static constexpr size_t kProgramCapacity = 16;

    Result<const ShaderProgram*> program(const ShaderSources& sources, SurfaceVariant variant, std::uint64_t frame);
    size_t programCount() const { return programs_.size(); }
    // Binds `brdf`'s table (uploading it the first time) and sets the albedo uniforms of the bound program.
    void bind(const ShaderProgram& program, const std::shared_ptr<const MeasuredBrdf>& brdf);
    int uploads() const { return uploads_; }

private:
    struct Upload {
        std::weak_ptr<const MeasuredBrdf> owner;  // expired: the texture is freed on the next bind
        unsigned texture = 0;
    };
    BoundedProgramCache<SurfaceVariant, ShaderProgram> programs_{kProgramCapacity};
    std::map<const MeasuredBrdf*, Upload> textures_;
    int uploads_ = 0;
};

}  // namespace glint
