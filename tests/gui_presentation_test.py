"""GUI tests of presentation mode under Xvfb (`glint present lessons/lessons.json`), reading the
rectangles the editor prints with GLINT_LOG_LAYOUT=1. One scenario per ctest entry:
  layout_1920  at 1920×1080: the window fills the screen, the viewport takes ≥ 70 % of the width;
               with the Plots, Lessons and help windows open (B, L, F1), every window lies inside
               the screen above the status bar and none covers the lesson note, the probe's angles,
               the probe readout or the plot; B, I and W toggle in presentation mode
  layout_1024  the same at 1024×768 (a projector)
  lessons      steps through every lesson with PageDown, orbiting the camera in each: no prompt
               appears and no lesson file changes (bytes and mtimes); GLINT_LESSON_SHOTS=DIR keeps
               a screenshot of each lesson there (docs/lessons/)
  prompt       an edited scene: Ctrl+N asks, and Enter does not save (the file is unchanged, the
               prompt stays); Escape cancels
  remembered   the editor window fits the 1024×768 screen; a window moved by the user opens at the
               same place in the next run (imgui.ini)
usage: gui_presentation_test.py GLINT OUTPUT_DIR SCENARIO"""
import glob
import hashlib
import json
import os
import shutil
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, region_difference, run_scenario_from_arguments, write_png  # noqa: E402

LESSONS_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lessons")
LESSONS = os.path.join(LESSONS_DIR, "lessons.json")
# Rectangles no floating window may cover (editor/window_placement.h names them).
RESERVED = ("lesson note", "probe angles", "Surface probe", "BRDF and Fresnel plots")


def start(x, glint, output, state, arguments):
    return LoggedEditor(x, glint, output, state, arguments, env={"GLINT_LESSONS": LESSONS})


def overlap(a, b):
    w = min(a[0] + a[2], b[0] + b[2]) - max(a[0], b[0])
    h = min(a[1] + a[3], b[1] + b[3]) - max(a[1], b[1])
    return w > 1 and h > 1


def check_layout(layout, width, height, reserved_free=True):
    """Every window inside the screen and above the status bar; with reserved_free, no floating
    window over the note, the probe's angles, the probe readout or the plot."""
    screen = layout["screen"]
    assert screen[2] == width and screen[3] == height, f"the window does not fill the {width}×{height} screen: {screen}"
    viewport = layout["viewport"]
    assert viewport[2] >= 0.7 * width, f"the viewport is {viewport[2]:.0f} of {width} px wide (< 70 %)"
    status = layout["window"]["##status"]
    frame = ("##status", "##MainMenuBar", "Scene", "Material", "##scene strip", "##material strip", "##lesson note")
    for name, rect in layout["window"].items():
        x, y, w, h = rect
        assert x >= -0.5 and y >= -0.5 and x + w <= width + 0.5 and y + h <= height + 0.5, f"{name} leaves the screen: {rect}"
        if name not in ("##status", "##MainMenuBar") and not name.startswith("##Tooltip"):
            assert y + h <= status[1] + 0.5, f"{name} spills onto the status bar: {rect}, status bar at y {status[1]}"
        if name in frame or name.startswith("##Tooltip") or not reserved_free:
            continue
        for reserved in RESERVED:
            area = layout["reserved"].get(reserved)
            if area and name.split("###")[0] != reserved:
                assert not overlap(rect, area), f"{name} {rect} covers the {reserved} {area}"
    if reserved_free:
        note, angles = layout["reserved"].get("lesson note"), layout["reserved"].get("probe angles")
        assert not (note and angles and overlap(note, angles)), f"the lesson note {note} covers the probe's angles {angles}"


def scenario_layout(x, glint, output, state, width, height):
    editor = start(x, glint, output, state, ["present", LESSONS])
    try:
        first = editor.settled_layout(lambda l: "lesson note" in l["reserved"] and "Surface probe" in l["window"]
                                      and l["screen"][2] == width, "lesson 1 with its note and the probe, full screen")
        check_layout(first, width, height)
        # The strips open one column at a time; the viewport keeps 70 %, and no window hides under a column.
        layout = first
        for strip, column, other in (("##material strip", "Material", "Scene"), ("##scene strip", "Scene", "Material")):
            sx, sy, sw, sh = editor.wait_layout(lambda l: strip in l["window"], f"the {strip}")["window"][strip]
            x.click(sx + sw / 2, sy + sh / 2)
            layout = editor.settled_layout(lambda l: column in l["window"] and other not in l["window"], f"the {column} column")
            check_layout(layout, width, height)
            for name, rect in layout["window"].items():
                if name in ("Surface probe", "BRDF and Fresnel plots", "Lessons"):
                    assert not overlap(rect, layout["window"][column]), f"{name} {rect} is under the {column} column"
        write_png(x.screenshot(), os.path.join(output, "column.png"))
        cx, cy, cw, _ = layout["window"]["Scene"]
        bar = layout["window"]["##MainMenuBar"][3]  # a title bar is about as tall as the menu bar
        x.click(cx + cw - 0.6 * bar, cy + 0.5 * bar)  # the column's close button: back to a strip
        editor.wait_layout(lambda l: "Scene" not in l["window"] and "##scene strip" in l["window"], "the Scene column to collapse")
        # Each window alone (B and L work in presentation mode), then all of them: inside the screen.
        windows = (("b", "BRDF and Fresnel plots"), ("l", "Lessons"), ("F1", "Keyboard and mouse (F1)"))
        for key, name in windows:
            x.key(key)
            layout = editor.settled_layout(lambda l: name in l["window"], f"the {name} window ({key})")
            write_png(x.screenshot(), os.path.join(output, f"{key}.png"))
            check_layout(layout, width, height)
            x.key(key)
            editor.wait_layout(lambda l: name not in l["window"], f"the {name} window to close ({key})")
        for key, name in windows:
            x.key(key)
            editor.wait_layout(lambda l: name in l["window"], f"the {name} window ({key})")
        layout = editor.settled_layout(lambda l: all(name in l["window"] for _, name in windows), "all three windows")
        write_png(x.screenshot(), os.path.join(output, "all.png"))
        check_layout(layout, width, height, reserved_free=False)
        for key, _ in windows:
            x.key(key)
        x.key("i")  # the probe off …
        editor.wait_layout(lambda l: "Surface probe" not in l["window"], "the probe to go (I)")
        v = layout["viewport"]
        middle = (int(v[0] + v[2] * 0.3), int(v[1] + v[3] * 0.3), int(v[0] + v[2] * 0.7), int(v[1] + v[3] * 0.7))
        before = editor.settled("the probe going")
        x.key("w")  # … and the wireframe on: the picture changes
        x.wait_for(lambda shot: region_difference(shot, before, middle) > 0.5, "the wireframe (W)")
        assert "●" not in x.run("xdotool", "getwindowname", editor.window).stdout, "W counted as an edit of the lesson"
        print(f"ok: at {width}×{height} the viewport is {first['viewport'][2]:.0f} px wide; each window keeps off "
              f"{sorted(r for r in first['reserved'] if r in RESERVED)}; B, L, F1, I and W work")
    finally:
        editor.stop()


def scenario_layout_1920(x, glint, output, state):
    scenario_layout(x, glint, output, state, 1920, 1080)


def scenario_layout_1024(x, glint, output, state):
    scenario_layout(x, glint, output, state, 1024, 768)


def lesson_files():
    files = sorted(glob.glob(os.path.join(LESSONS_DIR, "*.json")))
    return {path: (os.stat(path).st_mtime_ns, hashlib.sha256(open(path, "rb").read()).hexdigest()) for path in files}


def free_point(layout):
    """A point of the viewport under no window and no reserved rectangle, where a drag orbits."""
    vx, vy, vw, vh = layout["viewport"]
    taken = list(layout["window"].values()) + list(layout["reserved"].values())
    for fy in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8):
        for fx in (0.5, 0.4, 0.6, 0.3, 0.7, 0.2, 0.8):
            px, py = vx + vw * fx, vy + vh * fy
            if not any(r[0] - 20 <= px <= r[0] + r[2] + 100 and r[1] - 40 <= py <= r[1] + r[3] + 40 for r in taken):
                return px, py
    raise AssertionError(f"no free point to orbit from in {layout}")


def scenario_lessons(x, glint, output, state):
    before = lesson_files()
    with open(LESSONS) as file:
        count = len(json.load(file)["lessons"])
    shots = os.environ.get("GLINT_LESSON_SHOTS")
    x.run("xset", "r", "off")  # a PageDown held while the machine is busy must not auto-repeat into two steps
    editor = start(x, glint, output, state, ["present", LESSONS])
    try:
        for index in range(1, count + 1):
            if index > 1:
                x.key("Next")
            editor.wait_for_title(f"Lesson {index} —")
            layout = editor.settled_layout(lambda l: "lesson note" in l["reserved"] and l["screen"][2] > 0,
                                           f"lesson {index} with its note")
            if shots:
                write_png(editor.settled(f"lesson {index}"), os.path.join(shots, f"lesson_{index:02d}.png"))
            cx, cy = free_point(layout)
            x.drag((cx, cy), (cx + 80, cy + 20))  # orbit: looking around, not an edit
            layout = editor.settled_layout(lambda l: True, f"lesson {index} after the orbit")
            assert "Unsaved changes" not in layout["window"], f"orbiting lesson {index} asked to save"
            assert "●" not in x.window_title(editor.window), f"orbiting lesson {index} counted as an edit"
        x.key("Next")  # past the last lesson: stays, asks nothing
        x.key("ctrl+q")  # quits at once: nothing asked, as nothing was edited
        code = editor.wait_exit()
        assert code == 0, f"the editor exited with {code}"
        assert editor.process.returncode == 0, f"the editor exited with {editor.process.returncode}"
    finally:
        editor.stop()
    assert lesson_files() == before, "a lesson file changed"
    print(f"ok: {count} lessons stepped through with camera moves; no prompt, no lesson file written")


def scenario_prompt(x, glint, output, state):
    scene = os.path.join(output, "edited.json")
    shutil.copy(os.path.join(LESSONS_DIR, "01_lambert.json"), scene)
    stamp = (os.stat(scene).st_mtime_ns, open(scene, "rb").read())
    editor = start(x, glint, output, state, [scene])
    try:
        editor.settled_layout(lambda l: "##status" in l["window"], "the editor")
        x.key("w")  # the wireframe overlay is saved with the scene: an edit
        editor.wait_for_title("●")
        x.key("ctrl+n")
        editor.wait_layout(lambda l: "Unsaved changes" in l["window"], "the unsaved-changes prompt")
        # Enter, then Escape: had Enter answered (saved, or started the new scene), Escape would find
        # no prompt, and the file or the title would show it.
        x.key("Return", "Escape")
        editor.wait_layout(lambda l: "Unsaved changes" not in l["window"], "Escape to cancel")
        assert (os.stat(scene).st_mtime_ns, open(scene, "rb").read()) == stamp, "Enter saved the scene"
        title = x.window_title(editor.window)
        assert "edited.json" in title and "●" in title, f"Enter answered the prompt: the title is {title!r}"
    finally:
        editor.stop()
    print("ok: Enter does not answer the unsaved-changes prompt; the file stayed as it was")


def scenario_remembered(x, glint, output, state):
    def lessons_window(editor):
        x.key("l")
        return editor.settled_layout(lambda l: "Lessons" in l["window"], "the Lessons window (L)")["window"]["Lessons"]

    editor = start(x, glint, output, state, [])
    try:
        screen = editor.settled_layout(lambda l: "##status" in l["window"], "the editor")["screen"]
        assert screen[2] <= 1024 and screen[3] <= 768, f"the window ({screen}) is larger than the 1024×768 screen"
        wx, wy, ww, wh = lessons_window(editor)
        target = (max(10, wx - 200), wy + 60)
        x.drag((wx + 60, wy + 10), (target[0] + 60, target[1] + 10))  # by the title bar
        moved = editor.wait_layout(lambda l: "Lessons" in l["window"] and abs(l["window"]["Lessons"][0] - target[0]) < 2, "the window to move")
        moved = moved["window"]["Lessons"]
        x.key("ctrl+q")
        editor.wait_exit()
    finally:
        editor.stop()
    editor = start(x, glint, output, state, [])
    try:
        editor.settled_layout(lambda l: "##status" in l["window"], "the editor again")
        again = lessons_window(editor)
        assert abs(again[0] - moved[0]) < 2 and abs(again[1] - moved[1]) < 2, f"moved to {moved}, reopened at {again}"
    finally:
        editor.stop()
    print(f"ok: the window fits the screen; the Lessons window moved from {(wx, wy)} to {moved[:2]} and reopened there "
          "in the next run")


if __name__ == "__main__":
    run_scenario_from_arguments(globals(), 1024, 768, screens={"layout_1920": (1920, 1080)})
