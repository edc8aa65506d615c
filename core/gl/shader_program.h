// ShaderProgram: compiles and links a vertex + fragment pair (optionally with a geometry stage)
// assembled by shader_sources.h,
// and reports failures as Diagnostics naming the shader file and line. Owns the GL program.
#pragma once

#include <string>

#include <glad/gl.h>

#include "gl/shader_sources.h"

namespace glint {

class ShaderProgram {
public:
    ShaderProgram() = default;
    ~ShaderProgram();
    ShaderProgram(ShaderProgram&& other) noexcept : program_(other.program_) { other.program_ = 0; }
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ShaderProgram(const ShaderProgram&) = delete;
    ShaderProgram& operator=(const ShaderProgram&) = delete;

    static Result<ShaderProgram> build(const ShaderSources& sources, const std::string& vertexPath,
                                       const std::string& fragmentPath, const std::string& prelude = {},
                                       const GeneratedShaderFiles& generated = {});
    // Vertex → geometry → fragment (the overlay passes).
    static Result<ShaderProgram> buildWithGeometry(const ShaderSources& sources, const std::string& vertexPath,
                                                   const std::string& geometryPath, const std::string& fragmentPath);

    GLuint id() const { return program_; }
    GLint uniform(const char* name) const { return glGetUniformLocation(program_, name); }
    // Binds a named uniform block to a binding point, if the program uses it.
    void bindBlock(const char* name, GLuint binding) const;

private:
    GLuint program_ = 0;
};

}  // namespace glint
