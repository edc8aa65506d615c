// The baseline for Glint's start-up figure: the least a headless render can do. Creates an
// OSMesa GL 4.1 core context, clears a framebuffer, reads it back and writes a PNG through
// OpenImageIO, like `glint render` but with no scene, shaders or display pass.
// usage: bare_osmesa_png OUT.png WIDTH HEIGHT
#include <glad/gl.h>  // before osmesa.h, which would pull in GL/gl.h
#include <GL/osmesa.h>
#include <OpenImageIO/imageio.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

int main(int argc, char** argv) {
    if (argc != 4) {
        std::fprintf(stderr, "usage: bare_osmesa_png OUT.png WIDTH HEIGHT\n");
        return 2;
    }
    const int width = std::atoi(argv[2]), height = std::atoi(argv[3]);
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 1, 0};
    OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
    std::vector<unsigned char> buffer(static_cast<size_t>(width) * height * 4);
    if (!context || !OSMesaMakeCurrent(context, buffer.data(), GL_UNSIGNED_BYTE, width, height)) return 2;
    if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(&OSMesaGetProcAddress))) return 2;
    glClearColor(0.5f, 0.25f, 0.125f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    std::vector<unsigned char> pixels(static_cast<size_t>(width) * height * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    auto output = OIIO::ImageOutput::create(argv[1]);
    if (!output || !output->open(argv[1], OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8)) ||
        !output->write_image(OIIO::TypeDesc::UINT8, pixels.data()) || !output->close())
        return 2;
    OSMesaDestroyContext(context);
    return 0;
}
