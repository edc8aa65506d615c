// Shader compilation and linking with located errors (see shader_program.h).
#include "gl/shader_program.h"

#include <vector>

namespace glint {
namespace {

Result<GLuint> compileStage(GLenum stage, const AssembledShader& source, const std::string& path) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint compiled = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &compiled);
    if (compiled) return shader;
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    // The mapped log already starts with file:line:column for each message.
    std::string mapped = mapCompileLog(log.data(), source.files);
    if (!mapped.empty() && mapped.back() == '\n') mapped.pop_back();
    return makeError("shader compile failed:\n" + mapped, {path});
}

}  // namespace

ShaderProgram::~ShaderProgram() {
    if (program_) glDeleteProgram(program_);
}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (program_) glDeleteProgram(program_);
        program_ = other.program_;
        other.program_ = 0;
    }
    return *this;
}

Result<ShaderProgram> ShaderProgram::build(const ShaderSources& sources, const std::string& vertexPath,
                                           const std::string& fragmentPath, const std::string& prelude,
                                           const GeneratedShaderFiles& generated) {
    auto vertexSource = assembleShader(sources, vertexPath, prelude, generated);
    if (!vertexSource) return vertexSource.error();
    auto fragmentSource = assembleShader(sources, fragmentPath, prelude, generated);
    if (!fragmentSource) return fragmentSource.error();
    auto vertex = compileStage(GL_VERTEX_SHADER, *vertexSource, vertexPath);
    if (!vertex) return vertex.error();
    auto fragment = compileStage(GL_FRAGMENT_SHADER, *fragmentSource, fragmentPath);
    if (!fragment) {
        glDeleteShader(*vertex);
        return fragment.error();
    }
    ShaderProgram program;
    program.program_ = glCreateProgram();
    glAttachShader(program.program_, *vertex);
    glAttachShader(program.program_, *fragment);
    glLinkProgram(program.program_);
    glDeleteShader(*vertex);
    glDeleteShader(*fragment);
    GLint linked = GL_FALSE;
    glGetProgramiv(program.program_, GL_LINK_STATUS, &linked);
    if (!linked) {
        GLint length = 0;
        glGetProgramiv(program.program_, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
        glGetProgramInfoLog(program.program_, length, nullptr, log.data());
        return makeError("shader link failed: " + std::string(log.data()), {fragmentPath});
    }
    return program;
}

void ShaderProgram::bindBlock(const char* name, GLuint binding) const {
    const GLuint index = glGetUniformBlockIndex(program_, name);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(program_, index, binding);
}

}  // namespace glint
