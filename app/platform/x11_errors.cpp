// X11 errors printed and counted instead of ending the process (see x11_errors.h). Its own file:
// Xlib's macros (Status, None, Bool) must not reach the rest of the code.
#include "platform/x11_errors.h"

#include <X11/Xlib.h>

#include <atomic>
#include <cstdio>

namespace glint {
namespace {

std::atomic<int> gErrors{0};

int printAndCount(Display* display, XErrorEvent* error) {
    char text[160] = {};
    XGetErrorText(display, error->error_code, text, sizeof text);
    std::fprintf(stderr, "glint: X error %s (request %d.%d); the window is drawn again\n", text, error->request_code,
                 error->minor_code);
    ++gErrors;
    return 0;
}

}  // namespace

void keepXErrorsNonFatal() { XSetErrorHandler(printAndCount); }

int takeXErrors() { return gErrors.exchange(0); }

}  // namespace glint
