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
    std::string mapped = mapCompileLog(log.data(), source);
    if (!mapped.empty() && mapped.back() == '\n') mapped.pop_back();
    return makeError("shader compile failed:\n" + mapped, {path});
}

struct StageFile {
    GLenum stage;
    std::string path;
};

// Assembles, compiles and links the stages in order; the first failure is returned.
Result<GLuint> linkStages(const ShaderSources& sources, const std::vector<StageFile>& stages,
                          const std::string& prelude, const GeneratedShaderFiles& generated) {
    std::vector<GLuint> compiled;
    auto release = [&] {
        for (GLuint shader : compiled) glDeleteShader(shader);
    };
    for (const StageFile& stage : stages) {
        auto source = assembleShader(sources, stage.path, prelude, generated);
        auto shader = source ? compileStage(stage.stage, *source, stage.path) : Result<GLuint>(source.error());
        if (!shader) {
            release();
            return shader.error();
        }
        compiled.push_back(*shader);
    }
    const GLuint program = glCreateProgram();
    for (GLuint shader : compiled) glAttachShader(program, shader);
    glLinkProgram(program);
    release();
    GLint linked = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        glDeleteProgram(program);
        return makeError("shader link failed: " + std::string(log.data()), {stages.back().path});
    }
    return program;
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
    auto linked = linkStages(sources, {{GL_VERTEX_SHADER, vertexPath}, {GL_FRAGMENT_SHADER, fragmentPath}}, prelude,
                             generated);
    if (!linked) return linked.error();
    ShaderProgram program;
    program.program_ = *linked;
    return program;
}

Result<ShaderProgram> ShaderProgram::buildWithGeometry(const ShaderSources& sources, const std::string& vertexPath,
                                                       const std::string& geometryPath,
                                                       const std::string& fragmentPath) {
    auto linked = linkStages(sources,
                             {{GL_VERTEX_SHADER, vertexPath}, {GL_GEOMETRY_SHADER, geometryPath},
                              {GL_FRAGMENT_SHADER, fragmentPath}},
                             {}, {});
    if (!linked) return linked.error();
    ShaderProgram program;
    program.program_ = *linked;
    return program;
}

void ShaderProgram::bindBlock(const char* name, GLuint binding) const {
    const GLuint index = glGetUniformBlockIndex(program_, name);
    if (index != GL_INVALID_INDEX) glUniformBlockBinding(program_, index, binding);
}

}  // namespace glint
