// An X error after keepXErrorsNonFatal() is printed and counted, and the process goes on; without
// it Xlib's default handler would exit (app/platform/x11_errors.h). Run under xvfb-run.
#include <X11/Xlib.h>

#include <cstdio>

#include "platform/x11_errors.h"

int main() {
    Display* display = XOpenDisplay(nullptr);
    if (!display) {
        std::fprintf(stderr, "FAIL: no X display (run under xvfb-run)\n");
        return 1;
    }
    glint::keepXErrorsNonFatal();
    XMapWindow(display, 0x3fffff);  // no such window: BadWindow, reported asynchronously
    XSync(display, False);
    const int errors = glint::takeXErrors();
    XCloseDisplay(display);
    if (errors != 1) {
        std::fprintf(stderr, "FAIL: %d X errors counted, expected 1\n", errors);
        return 1;
    }
    std::printf("ok: a BadWindow error was printed and counted; the process went on\n");
    return 0;
}
