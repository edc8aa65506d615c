"""GUI tests of the editor's object tools under Xvfb, driven with real input (xdotool) and checked
in screenshots. One scenario per ctest entry:
  overlays     W shows the wireframe (the sphere's proxy tessellation), W again hides it; the
               View menu's item does the same
  add_object   Add… ▸ Plane in the object panel: the picture and the triangle count change;
               Ctrl+Z removes it again
usage: gui_objects_test.py GLINT OUTPUT_DIR SCENARIO"""
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_editor_test import VIEWPORT, Editor, close_window, differs, lit_sphere, matches, save  # noqa: E402
from gui_test_support import XServer, region_difference  # noqa: E402

# The object section of the material column on the default scene (1280×800 window).
ADD_BUTTON = (953, 356)
ADD_MENU_ITEM = {"Sphere": (975, 372), "Plane": (975, 393)}
POPUP_BOX = (955, 362, 1020, 405)


def triangle_counts(log):
    """Triangles of each rendered frame, from the GLINT_LOG_FRAMES lines."""
    return [int(m.group(1)) for m in re.finditer(r"^glint frame:.*, (\d+) triangles$", log, re.MULTILINE)]


def add_from_menu(x, kind):
    """Add… opens a popup under the mouse; its item is clicked once the popup has been drawn."""
    before = x.screenshot()
    x.click(*ADD_BUTTON)
    x.wait_for(lambda shot: region_difference(shot, before, POPUP_BOX) > 1.0, "the Add… popup")
    x.click(*ADD_MENU_ITEM[kind])


def start(x, glint, output, state):
    return Editor(x, glint, output, state, env={"GLINT_LOG_FRAMES": "1"})


def finish(x, editor):
    close_window(x, editor)
    x.key("n")  # the unsaved-changes prompt, if any: don't save
    code = editor.wait_exit()
    assert code == 0, f"editor exited with {code}"


def scenario_overlays(x, glint, output, state):
    editor = start(x, glint, output, state)
    try:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.key("w")
        wire = x.wait_for(differs(base, 2.0), "W to draw the wireframe over the sphere")
        wire = x.wait_stable(VIEWPORT)
        save(wire, output, "overlays_1_wireframe")
        x.key("w")
        x.wait_for(matches(base), "W again to hide the wireframe")
        x.key("n")
        normals = x.wait_for(differs(base, 0.5), "N to draw the vertex normals")
        save(normals, output, "overlays_2_normals")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to undo the normals toggle")
        finish(x, editor)
        print("ok: W toggled the wireframe, N the normals, Ctrl+Z undid the toggle")
    finally:
        editor.kill()


def scenario_add_object(x, glint, output, state):
    editor = start(x, glint, output, state)
    try:
        base = x.wait_for(lit_sphere, "the lit sphere")
        add_from_menu(x, "Plane")
        added = x.wait_for(differs(base), "the added plane to show")
        added = x.wait_stable(VIEWPORT)
        save(added, output, "add_object_1_plane")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to remove the added plane")
        finish(x, editor)
        counts = triangle_counts(editor.log)
        assert counts and max(counts) == counts[0] + 2, f"a plane adds two triangles: {counts}"
        assert counts[-1] == counts[0], f"undo should bring the count back: {counts}"
        print(f"ok: the plane showed and added 2 triangles ({counts[0]} → {max(counts)}), Ctrl+Z removed it")
    finally:
        editor.kill()


def main():
    glint, output, scenario = sys.argv[1], sys.argv[2], sys.argv[3]
    output = os.path.join(output, scenario)
    os.makedirs(output, exist_ok=True)
    os.environ["GLINT_GUI_FAILURE_DIR"] = output
    state = os.path.join(output, "state")
    shutil.rmtree(state, ignore_errors=True)
    with XServer(1280, 800) as x:
        globals()["scenario_" + scenario](x, glint, output, state)


if __name__ == "__main__":
    main()
