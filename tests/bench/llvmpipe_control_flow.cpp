// What control flow costs on llvmpipe: a 1230×1032 full-screen fragment shader runs a block of
// arithmetic (or texture lookups) under different control flow, and the median draw time of each is
// printed. The rules it shows, which the shaders follow (docs/performance.md, "How llvmpipe runs a
// shader"): the body of an `if` that no pixel takes costs as much as running it; a for loop runs its
// body once more, masked, after its last pass (a loop of 0 passes costs one body); a do-while loop
// runs exactly its passes; a choice between samplers fetches from every arm.
// usage: llvmpipe_control_flow (OSMesa, no display needed)
#include <glad/gl.h>  // before osmesa.h, which would pull in GL/gl.h
#include <GL/osmesa.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "frame_timing.h"

namespace glint {
namespace {

constexpr int kWidth = 1230, kHeight = 1032;  // the editor's viewport at 1920×1080

// Ten steps of arithmetic, repeated: the block whose cost each case shows.
const char* kBlock = "#define STEP a = sin(a * 1.3 + a.yzx);\n#define BLOCK STEP STEP STEP STEP STEP STEP STEP STEP STEP STEP\n";

struct Case {
    const char* name;
    const char* code;  // runs in main() with `vec3 a`, `int zero` (a uniform 0) and `sampler2D maps[4]`
};

const Case kCases[] = {
    {"nothing", ""},
    {"block", "BLOCK BLOCK BLOCK BLOCK BLOCK BLOCK"},
    {"if no pixel takes", "if (zero == 1) { BLOCK BLOCK BLOCK BLOCK BLOCK BLOCK }"},
    {"for loop, 0 passes", "for (int i = 0; i < zero; ++i) { BLOCK BLOCK BLOCK BLOCK BLOCK BLOCK }"},
    {"for loop, 1 pass", "for (int i = 0; i < zero + 1; ++i) { BLOCK BLOCK BLOCK BLOCK BLOCK BLOCK }"},
    {"do-while loop, 1 pass", "int i = 0; do { BLOCK BLOCK BLOCK BLOCK BLOCK BLOCK } while (++i < zero + 1);"},
    {"16 lookups, constant sampler", "for (int i = 0; i < 16; ++i) a += texture(maps[0], a.xy + float(i) * 0.01).rgb;"},
    {"16 lookups, 4-way sampler choice", "for (int i = 0; i < 16; ++i) a += lookup(zero, a.xy + float(i) * 0.01).rgb;"},
};

GLuint compile(GLenum kind, const std::string& source) {
    const GLuint shader = glCreateShader(kind);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[4096];
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        std::fprintf(stderr, "shader compile failed:\n%s\n", log);
        std::exit(1);
    }
    return shader;
}

GLuint program(const Case& c) {
    const std::string vertex =
        "#version 410 core\nvoid main() { vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);"
        " gl_Position = vec4(p * 2.0 - 1.0, 0.5, 1.0); }";
    const std::string fragment = std::string("#version 410 core\n") + kBlock +
                                 "out vec4 color;\nuniform int zero;\nuniform sampler2D maps[4];\n"
                                 "vec4 lookup(int slot, vec2 uv) {\n"
                                 "    if (slot == 0) return texture(maps[0], uv);\n"
                                 "    if (slot == 1) return texture(maps[1], uv);\n"
                                 "    if (slot == 2) return texture(maps[2], uv);\n"
                                 "    return texture(maps[3], uv);\n}\n"
                                 "void main() {\n    vec3 a = vec3(gl_FragCoord.xy * 0.001, 0.5);\n    " +
                                 c.code + "\n    color = vec4(a, 1.0);\n}\n";
    const GLuint id = glCreateProgram();
    glAttachShader(id, compile(GL_VERTEX_SHADER, vertex));
    glAttachShader(id, compile(GL_FRAGMENT_SHADER, fragment));
    glLinkProgram(id);
    return id;
}

// Median of 9 draws (after one untimed draw that makes the machine code), each ended by glFinish.
double medianDrawMs(GLuint id) {
    glUseProgram(id);
    glUniform1i(glGetUniformLocation(id, "zero"), 0);
    for (int unit = 0; unit < 4; ++unit)
        glUniform1i(glGetUniformLocation(id, ("maps[" + std::to_string(unit) + "]").c_str()), unit);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();
    std::vector<double> times;
    for (int i = 0; i < 9; ++i) times.push_back(timeFrame([] { glDrawArrays(GL_TRIANGLES, 0, 3); }));
    return medianMs(times);
}

}  // namespace
}  // namespace glint

int main() {
    using namespace glint;
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 1, 0};
    OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
    std::vector<unsigned char> buffer(static_cast<size_t>(kWidth) * kHeight * 4);
    if (!context || !OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, kWidth, kHeight)) return 2;
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(&OSMesaGetProcAddress))) return 2;

    // A float colour target like Glint's radiance target, and four small textures to look up.
    GLuint framebuffer = 0, colour = 0, vertexArray = 0, textures[4];
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA32F, kWidth, kHeight);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    glGenTextures(4, textures);
    const std::vector<float> texels(64 * 64 * 4, 0.5f);
    for (int unit = 0; unit < 4; ++unit) {
        glActiveTexture(GL_TEXTURE0 + unit);
        glBindTexture(GL_TEXTURE_2D, textures[unit]);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA16F, 64, 64, 0, GL_RGBA, GL_FLOAT, texels.data());
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    }
    glGenVertexArrays(1, &vertexArray);
    glBindVertexArray(vertexArray);
    glViewport(0, 0, kWidth, kHeight);

    std::printf("%s\n%-36s %10s\n", reinterpret_cast<const char*>(glGetString(GL_RENDERER)), "case", "median ms");
    for (const Case& c : kCases) std::printf("%-36s %10.1f\n", c.name, medianDrawMs(program(c)));
    OSMesaDestroyContext(context);
    return 0;
}
