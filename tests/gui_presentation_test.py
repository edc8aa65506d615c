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
  remembered   a window moved by the user opens at the same place in the next run (imgui.ini)
usage: gui_presentation_test.py GLINT OUTPUT_DIR SCENARIO"""
import glob
import hashlib
import json
import os
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import region_difference, run_scenario_from_arguments, write_png  # noqa: E402

LESSONS_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lessons")
LESSONS = os.path.join(LESSONS_DIR, "lessons.json")
# Rectangles no floating window may cover (editor/window_placement.h names them).
RESERVED = ("lesson note", "probe angles", "Surface probe", "BRDF and Fresnel plots")


class Editor:
    """The editor with its stderr in a file, so the layout log can be read while it runs."""

    def __init__(self, x, glint, output, state, arguments):
        self.log_path = os.path.join(output, "editor.log")
        self.log = open(self.log_path, "w")
        environment = dict(x.env, GLINT_STATE_DIR=state, GLINT_GUI_FAILURE_DIR=output, GLINT_LESSONS=LESSONS,
                           GLINT_LOG_LAYOUT="1")
        self.process = subprocess.Popen([glint, *arguments], env=environment, cwd=output, stdout=self.log,
                                        stderr=subprocess.STDOUT)
        self.window = x.find_window("Glint", process=self.process)

    def layout(self):
        """The last complete block of rectangles: {"screen": …, "viewport": …, "window": {name: rect}, "reserved": {…}}."""
        with open(self.log_path, errors="replace") as log:
            text = log.read()
        blocks = text.split("glint layout: end\n")
        if len(blocks) < 2:
            return None
        result = {"window": {}, "reserved": {}}
        for line in blocks[-2].splitlines():
            if not line.startswith("glint layout: "):
                continue
            kind, rest = line[len("glint layout: "):].split(" ", 1)
            name, numbers = rest[1:].rsplit('" ', 1)
            rect = tuple(float(v) for v in numbers.split())
            if kind in ("screen", "viewport"):
                result[kind] = rect
            else:
                result[kind][name] = rect
        return result

    def wait_layout(self, condition, what, timeout=30.0):
        deadline = time.time() + timeout
        layout = None
        while time.time() < deadline:
            layout = self.layout()
            if layout and condition(layout):
                return layout
            time.sleep(0.25)
        raise AssertionError(f"timed out waiting for {what}; the last layout: {layout}")

    def stop(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait(timeout=10)
        self.log.close()


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
    editor = Editor(x, glint, output, state, ["present", LESSONS])
    try:
        first = editor.wait_layout(lambda l: "lesson note" in l["reserved"] and "Surface probe" in l["window"]
                                   and l["screen"][2] == width, "lesson 1 with its note and the probe, full screen")
        time.sleep(1.0)
        check_layout(editor.layout(), width, height)
        # The strips open one column at a time; the viewport keeps 70 %, and no window hides under a column.
        for strip, column, other in (("##material strip", "Material", "Scene"), ("##scene strip", "Scene", "Material")):
            sx, sy, sw, sh = editor.layout()["window"][strip]
            x.click(sx + sw / 2, sy + sh / 2)
            layout = editor.wait_layout(lambda l: column in l["window"] and other not in l["window"], f"the {column} column")
            time.sleep(1.0)
            layout = editor.layout()
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
            editor.wait_layout(lambda l: name in l["window"], f"the {name} window ({key})")
            time.sleep(1.0)  # windows settle over a few frames
            layout = editor.layout()
            write_png(x.screenshot(), os.path.join(output, f"{key}.png"))
            check_layout(layout, width, height)
            x.key(key)
            editor.wait_layout(lambda l: name not in l["window"], f"the {name} window to close ({key})")
        for key, name in windows:
            x.key(key)
            editor.wait_layout(lambda l: name in l["window"], f"the {name} window ({key})")
        time.sleep(1.0)
        layout = editor.layout()
        write_png(x.screenshot(), os.path.join(output, "all.png"))
        check_layout(layout, width, height, reserved_free=False)
        for key, _ in windows:
            x.key(key)
        x.key("i")  # the probe off …
        editor.wait_layout(lambda l: "Surface probe" not in l["window"], "the probe to go (I)")
        time.sleep(0.5)
        before = x.screenshot()
        x.key("w")  # … and the wireframe on: the picture changes
        v = layout["viewport"]
        middle = (int(v[0] + v[2] * 0.3), int(v[1] + v[3] * 0.3), int(v[0] + v[2] * 0.7), int(v[1] + v[3] * 0.7))
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
    editor = Editor(x, glint, output, state, ["present", LESSONS])
    try:
        for index in range(1, count + 1):
            if index > 1:
                x.key("Next")
            editor.wait_layout(lambda l: "lesson note" in l["reserved"] and l["screen"][2] > 0, f"lesson {index}")
            deadline = time.time() + 20
            while f"Lesson {index} —" not in x.run("xdotool", "getwindowname", editor.window, check=False).stdout:
                assert time.time() < deadline, f"lesson {index} did not open"
                time.sleep(0.2)
            cx, cy = free_point(editor.layout())
            if shots:
                time.sleep(1.5)
                x.wait_stable((0, 0, 400, 300))
                write_png(x.screenshot(), os.path.join(shots, f"lesson_{index:02d}.png"))
            x.drag((cx, cy), (cx + 80, cy + 20))  # orbit: looking around, not an edit
            time.sleep(0.3)
            layout = editor.layout()
            assert "Unsaved changes" not in layout["window"], f"orbiting lesson {index} asked to save"
        x.key("Next")  # past the last lesson: stays, asks nothing
        time.sleep(0.5)
        assert "Unsaved changes" not in editor.layout()["window"]
        x.key("ctrl+q")
        editor.process.wait(timeout=20)
        assert editor.process.returncode == 0, f"the editor exited with {editor.process.returncode}"
    finally:
        editor.stop()
    assert lesson_files() == before, "a lesson file changed"
    print(f"ok: {count} lessons stepped through with camera moves; no prompt, no lesson file written")


def scenario_prompt(x, glint, output, state):
    scene = os.path.join(output, "edited.json")
    shutil.copy(os.path.join(LESSONS_DIR, "01_lambert.json"), scene)
    stamp = (os.stat(scene).st_mtime_ns, open(scene, "rb").read())
    editor = Editor(x, glint, output, state, [scene])
    try:
        editor.wait_layout(lambda l: "##status" in l["window"], "the editor")
        time.sleep(1.0)
        x.key("w")  # the wireframe overlay is saved with the scene: an edit
        time.sleep(0.5)
        x.key("ctrl+n")
        editor.wait_layout(lambda l: "Unsaved changes" in l["window"], "the unsaved-changes prompt")
        x.key("Return")
        time.sleep(1.0)
        assert "Unsaved changes" in editor.layout()["window"], "Enter answered the prompt"
        assert (os.stat(scene).st_mtime_ns, open(scene, "rb").read()) == stamp, "Enter saved the scene"
        x.key("Escape")
        editor.wait_layout(lambda l: "Unsaved changes" not in l["window"], "Escape to cancel")
        assert (os.stat(scene).st_mtime_ns, open(scene, "rb").read()) == stamp
    finally:
        editor.stop()
    print("ok: Enter does not answer the unsaved-changes prompt; the file stayed as it was")


def scenario_remembered(x, glint, output, state):
    def lessons_window(editor):
        x.key("l")
        return editor.wait_layout(lambda l: "Lessons" in l["window"], "the Lessons window (L)")["window"]["Lessons"]

    editor = Editor(x, glint, output, state, [])
    try:
        editor.wait_layout(lambda l: "##status" in l["window"], "the editor")
        time.sleep(1.0)
        wx, wy, ww, wh = lessons_window(editor)
        time.sleep(1.0)
        target = (max(10, wx - 200), wy + 60)
        x.drag((wx + 60, wy + 10), (target[0] + 60, target[1] + 10))  # by the title bar
        moved = editor.wait_layout(lambda l: abs(l["window"]["Lessons"][0] - target[0]) < 2, "the window to move")
        moved = moved["window"]["Lessons"]
        x.key("ctrl+q")
        editor.process.wait(timeout=20)
    finally:
        editor.stop()
    editor = Editor(x, glint, output, state, [])
    try:
        editor.wait_layout(lambda l: "##status" in l["window"], "the editor again")
        time.sleep(1.0)
        again = lessons_window(editor)
        time.sleep(0.5)
        again = editor.layout()["window"]["Lessons"]
        assert abs(again[0] - moved[0]) < 2 and abs(again[1] - moved[1]) < 2, f"moved to {moved}, reopened at {again}"
    finally:
        editor.stop()
    print(f"ok: the Lessons window moved from {(wx, wy)} to {moved[:2]} and reopened there in the next run")


if __name__ == "__main__":
    run_scenario_from_arguments(globals(), 1024, 768, screens={"layout_1920": (1920, 1080)})
