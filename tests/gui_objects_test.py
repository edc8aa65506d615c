"""GUI tests of the editor's object tools under Xvfb, driven with real input (xdotool) and checked
in screenshots. One scenario per ctest entry:
  overlays     W shows the wireframe (the sphere's proxy tessellation), W again hides it; the
               View menu's item does the same
  add_object   Add… ▸ Plane, Cube and Torus in the object panel: each changes the picture and the
               triangle count; Ctrl+Z removes the last again
  shading      the sphere's shading mode to flat changes the picture (facets), moving its
               segments slider changes it again; Ctrl+Z brings the first faceted picture back
  open_mesh    Ctrl+M, type the path of a small OBJ the test writes in the file browser: the mesh
               shows and the triangle count grows by its triangles
usage: gui_objects_test.py GLINT OUTPUT_DIR SCENARIO"""
import os
import re
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_editor_test import close_window, differs, lit_sphere, matches, save, type_path  # noqa: E402
from gui_test_support import LoggedEditor, region_difference, run_scenario_from_arguments  # noqa: E402

# The object section of the material column on the default scene (1280×800 window). The "Add…"
# button sits below the material panel, so it moves with the selected object's material: the
# default sphere's Blinn-Phong, or the Lambert material every added object gets (and selects).
ADD_BUTTON = {"blinn_phong": (953, 515), "lambert": (953, 324)}
ADD_MENU_OFFSET = {"Sphere": 16, "Plane": 37, "Cube": 58, "Torus": 79}  # below the button [px]


def triangle_counts(log):
    """Triangles of each rendered frame, from the GLINT_LOG_FRAMES lines."""
    return [int(m.group(1)) for m in re.finditer(r"^glint frame:.*, (\d+) triangles$", log, re.MULTILINE)]


def slow_click(x, position, hold_seconds=0.6):
    """A click held for longer than a frame (frames take up to ~0.5 s on llvmpipe), so that ImGui
    sees the hover, the press and the release in separate frames."""
    x.move(*position)
    time.sleep(0.4)
    x.run("xdotool", "mousedown", "1")
    time.sleep(hold_seconds)
    x.run("xdotool", "mouseup", "1")


def add_from_menu(x, kind, selected_material):
    """Add… opens a popup under the mouse; its item is clicked once the popup has been drawn."""
    button = ADD_BUTTON[selected_material]
    before = x.screenshot()
    slow_click(x, button)
    popup = (button[0] + 5, button[1] + 14, button[0] + 90, button[1] + 95)  # below the button itself
    x.wait_for(lambda shot: region_difference(shot, before, popup) > 1.0, "the Add… popup")
    slow_click(x, (button[0] + 22, button[1] + ADD_MENU_OFFSET[kind]))
    park_mouse(x)


def park_mouse(x):
    """Moves the pointer to an empty spot of the material column, so no tooltip covers the viewport."""
    x.move(1100, 740)


def start(x, glint, output, state):
    return LoggedEditor(x, glint, output, state, env={"GLINT_LOG_FRAMES": "1"})


def finish(x, editor):
    close_window(x, editor)
    x.key("n")  # the unsaved-changes prompt, if any: don't save
    code = editor.wait_exit()
    assert code == 0, f"editor exited with {code}"


def scenario_overlays(x, glint, output, state):
    with start(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.key("w")
        wire = x.wait_for(differs(base, 2.0), "W to draw the wireframe over the sphere")
        wire = editor.settled("W")
        save(wire, output, "overlays_1_wireframe")
        x.key("w")
        x.wait_for(matches(base), "W again to hide the wireframe")
        assert matches(base)(editor.settled("W again")), "the wireframe came back after W hid it"
        x.key("n")
        normals = x.wait_for(differs(base, 0.5), "N to draw the vertex normals")
        save(normals, output, "overlays_2_normals")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to undo the normals toggle")
        finish(x, editor)
        print("ok: W toggled the wireframe, N the normals, Ctrl+Z undid the toggle")


def scenario_add_object(x, glint, output, state):
    with start(x, glint, output, state) as editor:
        shot = x.wait_for(lit_sphere, "the lit sphere")
        pictures = [shot]
        for kind in ("Plane", "Cube", "Torus"):
            add_from_menu(x, kind, "blinn_phong" if kind == "Plane" else "lambert")
            x.wait_for(differs(pictures[-1]), f"the added {kind.lower()} to show")
            pictures.append(editor.settled(f"the added {kind.lower()}"))
            save(pictures[-1], output, f"add_object_{len(pictures) - 1}_{kind.lower()}")
        x.key("ctrl+z")
        x.wait_for(matches(pictures[-2]), "Ctrl+Z to remove the added torus")
        finish(x, editor)
        counts = triangle_counts(editor.output())
        steps = sorted(set(counts))
        assert counts[0] + 2 in counts, f"a plane adds two triangles: {counts}"
        assert counts[0] + 2 + 12 in counts, f"a cube adds twelve: {counts}"
        assert max(counts) > counts[0] + 14, f"a torus adds its tessellation: {counts}"
        assert counts[-1] == counts[0] + 14, f"undo should take the torus away again: {counts}"
        print(f"ok: plane, cube and torus showed; triangle counts {steps}; Ctrl+Z removed the torus")


SHADING_COMBO = (1018, 590)
SEGMENTS_SLIDER = (1018, 671)
SHADING_ITEM = {"exact": (975, 617), "flat": (975, 638)}
SHADING_LIST = (935, 628, 1000, 690)  # under the combo, where its list opens: "flat", "Gouraud", "Phong"


def scenario_shading(x, glint, output, state):
    with start(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        before = x.screenshot()
        slow_click(x, SHADING_COMBO)
        x.wait_for(lambda shot: region_difference(shot, before, SHADING_LIST) > 1.0, "the shading combo's list")
        slow_click(x, SHADING_ITEM["flat"])
        park_mouse(x)
        x.wait_for(differs(base, 1.0), "flat shading to change the sphere")
        flat = editor.settled("flat shading")
        save(flat, output, "shading_1_flat")
        x.drag(SEGMENTS_SLIDER, (SEGMENTS_SLIDER[0] - 120, SEGMENTS_SLIDER[1]))
        x.wait_for(differs(flat, 1.0), "fewer segments to change the faceted sphere")
        coarse = editor.settled("the segments drag")
        save(coarse, output, "shading_2_fewer_segments")
        x.key("ctrl+z")
        x.wait_for(matches(flat), "Ctrl+Z to bring the finer tessellation back")
        finish(x, editor)
        counts = triangle_counts(editor.output())
        assert min(counts) < counts[0], f"fewer segments should draw fewer triangles: {counts}"
        print(f"ok: flat shading and the segments slider changed the sphere; triangles {sorted(set(counts))}")


# A regular octahedron: 6 vertices, 8 triangles.
OCTAHEDRON_OBJ = """v 1 0 0\nv -1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 0 0 -1
f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6
"""


def scenario_open_mesh(x, glint, output, state):
    path = os.path.join(output, "octahedron.obj")
    with open(path, "w") as obj:
        obj.write(OCTAHEDRON_OBJ)
    with start(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.key("ctrl+m")  # File ▸ Open mesh…: the file browser
        type_path(editor, base, path)
        x.wait_for(differs(base), "the octahedron to show")
        loaded = editor.settled("the mesh load")
        save(loaded, output, "open_mesh_1_octahedron")
        finish(x, editor)
        counts = triangle_counts(editor.output())
        assert counts[-1] == counts[0] + 8, f"the octahedron adds 8 triangles: {counts}"
        print(f"ok: the OBJ loaded through the file browser; triangles {counts[0]} → {counts[-1]}")


if __name__ == "__main__":
    run_scenario_from_arguments(globals())
