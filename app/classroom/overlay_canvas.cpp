// The offscreen ImGui canvas (see overlay_canvas.h): the image underneath is blitted into an
// offscreen framebuffer, then ImGui's draw data is rendered over it with its own alpha blending.
#include "classroom/overlay_canvas.h"

#include <glad/gl.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include <cstdio>
#include <cstring>

#include "gl/display_texture.h"
#include "gl/gl_loader.h"

namespace glint {
namespace {

constexpr const char* kCanvasFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

ImFont* loadCanvasFont(float pixelSize) {
    static const ImWchar ranges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x209F, 0x2190, 0x22FF, 0x25CF, 0x25CF, 0};
    ImGuiIO& io = ImGui::GetIO();
    if (std::FILE* file = std::fopen(kCanvasFontPath, "rb")) {
        std::fclose(file);
        return io.Fonts->AddFontFromFileTTF(kCanvasFontPath, pixelSize, nullptr, ranges);
    }
    ImFontConfig config;
    config.SizePixels = pixelSize;
    return io.Fonts->AddFontDefault(&config);
}

}  // namespace

Result<std::unique_ptr<OverlayCanvas>> OverlayCanvas::create(float fontPixelSize) {
    return create(std::span(&fontPixelSize, 1));
}

Result<std::unique_ptr<OverlayCanvas>> OverlayCanvas::create(std::span<const float> fontPixelSizes) {
    GLINT_CHECK(!fontPixelSizes.empty());
    std::unique_ptr<OverlayCanvas> canvas(new OverlayCanvas());
    ImGuiContext* previous = ImGui::GetCurrentContext();
    canvas->context_ = ImGui::CreateContext();
    ImGui::SetCurrentContext(canvas->context_);
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.LogFilename = nullptr;
    ImGui::StyleColorsDark();
    for (float pixelSize : fontPixelSizes) canvas->fonts_.push_back(loadCanvasFont(pixelSize));
    const bool initialised = ImGui_ImplOpenGL3_Init("#version 410 core");
    ImGui::SetCurrentContext(previous);
    if (!initialised) return Diagnostic{{}, "the overlay canvas could not set up ImGui's OpenGL renderer"};
    return canvas;
}

OverlayCanvas::~OverlayCanvas() {
    ImGuiContext* previous = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(context_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext(context_);
    ImGui::SetCurrentContext(previous == context_ ? nullptr : previous);
}

void OverlayCanvas::begin(int width, int height) {
    previousContext_ = ImGui::GetCurrentContext();
    ImGui::SetCurrentContext(context_);
    width_ = width;
    height_ = height;
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
}

Result<DisplayImage> OverlayCanvas::finish(const DisplayImage& under) {
    ImGui::Render();
    GLuint framebuffer = 0, colour = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    glViewport(0, 0, width_, height_);
    glClearColor(0, 0, 0, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    if (under.width == width_ && under.height == height_ && !under.pixels.empty()) {
        // The image underneath, blitted upside down: its top row was uploaded as GL's bottom row.
        const GLuint background = uploadDisplayTexture(under, GL_NEAREST);
        GLuint readFramebuffer = 0;
        glGenFramebuffers(1, &readFramebuffer);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, readFramebuffer);
        glFramebufferTexture2D(GL_READ_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, background, 0);
        glBlitFramebuffer(0, 0, width_, height_, 0, height_, width_, 0, GL_COLOR_BUFFER_BIT, GL_NEAREST);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer);
        glDeleteFramebuffers(1, &readFramebuffer);
        glDeleteTextures(1, &background);
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    DisplayImage out(width_, height_);
    std::vector<uint8_t> rows(static_cast<size_t>(width_) * height_ * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, rows.data());
    const size_t rowBytes = static_cast<size_t>(width_) * 3;
    for (int y = 0; y < height_; ++y)  // GL's rows run bottom to top
        std::memcpy(out.pixels.data() + y * rowBytes, rows.data() + (height_ - 1 - y) * rowBytes, rowBytes);

    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteRenderbuffers(1, &colour);
    glDeleteFramebuffers(1, &framebuffer);
    ImGui::SetCurrentContext(previousContext_);
    if (Status errors = takeGlErrors("the overlay canvas"); !errors) return errors.error();
    return out;
}

}  // namespace glint
