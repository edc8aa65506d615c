// OSMesa offscreen platform (see osmesa_platform.h).
#include "platform/osmesa_platform.h"

#include <GL/osmesa.h>

namespace glint {

Result<std::unique_ptr<OsMesaPlatform>> OsMesaPlatform::create() {
    const int attributes[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE, OSMESA_CONTEXT_MAJOR_VERSION, 4,
                              OSMESA_CONTEXT_MINOR_VERSION, 1, 0};
    OSMesaContext context = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context) return makeError("OSMesa could not create an OpenGL 4.1 core context (is libosmesa6 installed?)");
    std::unique_ptr<OsMesaPlatform> platform(new OsMesaPlatform());
    platform->context_ = context;
    platform->makeCurrent();
    return platform;
}

OsMesaPlatform::~OsMesaPlatform() {
    if (context_) OSMesaDestroyContext(static_cast<OSMesaContext>(context_));
}

GetProcAddress OsMesaPlatform::procAddressLoader() const {
    return reinterpret_cast<GetProcAddress>(&OSMesaGetProcAddress);
}

void OsMesaPlatform::makeCurrent() {
    if (OSMesaGetCurrentContext() == static_cast<OSMesaContext>(context_)) return;
    OSMesaMakeCurrent(static_cast<OSMesaContext>(context_), placeholder_, GL_UNSIGNED_BYTE, 1, 1);
}

}  // namespace glint
