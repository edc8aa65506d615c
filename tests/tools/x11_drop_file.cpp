// Drops a file on an X11 window the way a file manager does (the XDND protocol, version 5:
// enter, position, drop, then the path handed over as text/uri-list). Used by the monkey soak;
// xdotool cannot drag files. It does not move the pointer or press buttons.
// usage: x11_drop_file WINDOW_ID PATH ROOT_X ROOT_Y
#include <X11/Xatom.h>
#include <X11/Xlib.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

namespace {

struct Atoms {
    Atom enter, position, status, drop, finished, selection, actionCopy, uriList;
};

Atoms internAtoms(Display* display) {
    const auto atom = [display](const char* name) { return XInternAtom(display, name, False); };
    return {atom("XdndEnter"),    atom("XdndPosition"),  atom("XdndStatus"),     atom("XdndDrop"),
            atom("XdndFinished"), atom("XdndSelection"), atom("XdndActionCopy"), atom("text/uri-list")};
}

void sendMessage(Display* display, Window target, Atom type, long l0, long l1, long l2, long l3, long l4) {
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.window = target;
    event.xclient.message_type = type;
    event.xclient.format = 32;
    event.xclient.data.l[0] = l0;
    event.xclient.data.l[1] = l1;
    event.xclient.data.l[2] = l2;
    event.xclient.data.l[3] = l3;
    event.xclient.data.l[4] = l4;
    XSendEvent(display, target, False, NoEventMask, &event);
    XFlush(display);
}

// Hands over `uri` to the target's conversion request.
void answerSelectionRequest(Display* display, const XSelectionRequestEvent& request, const Atoms& atoms, const std::string& uri) {
    XEvent reply{};
    reply.xselection.type = SelectionNotify;
    reply.xselection.requestor = request.requestor;
    reply.xselection.selection = request.selection;
    reply.xselection.target = request.target;
    reply.xselection.time = request.time;
    reply.xselection.property = None;
    if (request.target == atoms.uriList) {
        XChangeProperty(display, request.requestor, request.property, atoms.uriList, 8, PropModeReplace,
                        reinterpret_cast<const unsigned char*>(uri.data()), static_cast<int>(uri.size()));
        reply.xselection.property = request.property;
    }
    XSendEvent(display, request.requestor, False, NoEventMask, &reply);
    XFlush(display);
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: x11_drop_file WINDOW_ID PATH ROOT_X ROOT_Y\n");
        return 2;
    }
    Display* display = XOpenDisplay(nullptr);
    if (!display) {
        std::fprintf(stderr, "x11_drop_file: cannot open the display\n");
        return 2;
    }
    const Window target = std::strtoul(argv[1], nullptr, 0);
    const std::string uri = std::string("file://") + argv[2] + "\r\n";
    const long x = std::atol(argv[3]), y = std::atol(argv[4]);
    const Atoms atoms = internAtoms(display);
    const Window source = XCreateSimpleWindow(display, DefaultRootWindow(display), 0, 0, 1, 1, 0, 0, 0);
    XSetSelectionOwner(display, atoms.selection, source, CurrentTime);

    constexpr long kVersion = 5;
    sendMessage(display, target, atoms.enter, static_cast<long>(source), kVersion << 24, static_cast<long>(atoms.uriList), 0, 0);
    sendMessage(display, target, atoms.position, static_cast<long>(source), 0, (x << 16) | (y & 0xFFFF), CurrentTime,
                static_cast<long>(atoms.actionCopy));
    // The target answers the position (XdndStatus), asks for the data after the drop
    // (SelectionRequest) and says it finished (XdndFinished); an editor that is busy answers late.
    enum class Stage { WaitingForStatus, WaitingForFinish } stage = Stage::WaitingForStatus;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    int outcome = 1;
    while (std::chrono::steady_clock::now() < deadline) {
        if (!XPending(display)) {
            struct timespec pause{0, 10'000'000};
            nanosleep(&pause, nullptr);
            continue;
        }
        XEvent event;
        XNextEvent(display, &event);
        if (event.type == SelectionRequest) {
            answerSelectionRequest(display, event.xselectionrequest, atoms, uri);
        } else if (event.type == ClientMessage && event.xclient.message_type == atoms.status &&
                   stage == Stage::WaitingForStatus) {
            const bool accepted = event.xclient.data.l[1] & 1;
            if (!accepted) {
                std::fprintf(stderr, "x11_drop_file: the window refused the drop\n");
                sendMessage(display, target, XInternAtom(display, "XdndLeave", False), static_cast<long>(source), 0, 0, 0, 0);
                break;
            }
            sendMessage(display, target, atoms.drop, static_cast<long>(source), 0, CurrentTime, 0, 0);
            stage = Stage::WaitingForFinish;
        } else if (event.type == ClientMessage && event.xclient.message_type == atoms.finished) {
            outcome = 0;
            break;
        }
    }
    if (outcome != 0 && stage == Stage::WaitingForStatus) std::fprintf(stderr, "x11_drop_file: no answer from the window\n");
    XDestroyWindow(display, source);
    XCloseDisplay(display);
    return outcome;
}
