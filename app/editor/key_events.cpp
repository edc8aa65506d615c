// Per-frame key press record (see key_events.h).
#include "editor/key_events.h"

#include <GLFW/glfw3.h>

#include <vector>

namespace glint {
namespace {

struct KeyPress {
    int key;
    int mods;
};
std::vector<KeyPress> gPresses;

constexpr int kModifierMask = GLFW_MOD_SHIFT | GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER;

}  // namespace

void recordKeyPress(int key, int mods) { gPresses.push_back({key, mods & kModifierMask}); }

bool keyPressed(int key, int mods) {
    for (const KeyPress& press : gPresses)
        if (press.key == key && press.mods == mods) return true;
    return false;
}

bool takeKeyPress(int key, int mods) {
    for (auto it = gPresses.begin(); it != gPresses.end(); ++it)
        if (it->key == key && it->mods == mods) {
            gPresses.erase(it);
            return true;
        }
    return false;
}

void clearKeyPresses() { gPresses.clear(); }

}  // namespace glint
