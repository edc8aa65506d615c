"""Editor figures under Xvfb (not a test; numbers for the README and reports):
  1. idle CPU: utime+stime of the editor process over 10 s with nothing happening;
  2. edit-to-frame while dragging a material slider with 4 lights (1280×800 window), from the
     editor's GLINT_LOG_FRAMES log: time from the frame's input arriving to the frame presented;
  3. frame time with both side columns closed (viewport 1280 × ~750), from mouse-wheel zooms.
usage: /usr/bin/python3 tests/bench/editor_figures.py build/app/glint"""
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gui_test_support import XServer  # noqa: E402
from gui_editor_test import ADD_POINT_LIGHT, EXPONENT_SLIDER, lit_sphere  # noqa: E402


def cpu_seconds(pid):
    with open(f"/proc/{pid}/stat") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime + stime


def frames(log_path, start_line):
    with open(log_path) as log:
        lines = [l for l in log.read().splitlines() if l.startswith("glint frame:")][start_line:]
    parsed = []
    for line in lines:
        words = line.split()
        parsed.append({"size": words[3], "scale": words[5], "render": float(words[7]), "total": float(words[13])})
    return parsed


def summary(name, values):
    if not values:
        return f"{name}: no frames"
    return f"{name}: median {statistics.median(values):.1f} ms, min {min(values):.1f}, max {max(values):.1f} (n={len(values)})"


def main():
    glint = sys.argv[1]
    state = tempfile.mkdtemp(prefix="glint-figures-")
    log_path = os.path.join(state, "frames.log")
    with XServer(1280, 800) as x, open(log_path, "w") as log:
        env = dict(x.env, GLINT_STATE_DIR=state, GLINT_LOG_FRAMES="1")
        editor = subprocess.Popen([glint], env=env, stdout=log, stderr=log)
        try:
            x.find_window("Glint")
            x.wait_for(lit_sphere, "the lit sphere")
            time.sleep(3)
            before = cpu_seconds(editor.pid)
            time.sleep(10)
            idle = cpu_seconds(editor.pid) - before
            print(f"idle CPU over 10 s: {idle:.2f} s of CPU time ({100 * idle / 10:.1f} % of one core)")

            x.click(*ADD_POINT_LIGHT)
            time.sleep(1.5)
            x.click(ADD_POINT_LIGHT[0], ADD_POINT_LIGHT[1] + 27)  # the buttons moved down one row
            time.sleep(1.5)
            mark = len(frames(log_path, 0))
            x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]), steps=40, step_seconds=0.05)
            time.sleep(1.5)
            dragged = frames(log_path, mark)
            previews = [f for f in dragged if f["scale"] != "1/1"]
            print(f"slider drag with 4 lights: {len(dragged)} frames, sizes {sorted(set(f['size'] + ' ' + f['scale'] for f in dragged))}")
            print("  " + summary("input to presented frame during the drag", [f["total"] for f in dragged[:-1]]))
            print("  " + summary("render only during the drag", [f["render"] for f in dragged[:-1]]))
            print(f"  preview frames: {len(previews)}; last (refined) frame: {dragged[-1] if dragged else None}")

            x.click(316, 34)   # close the scene column
            time.sleep(1.5)
            x.click(1266, 34)  # close the material column
            time.sleep(1.5)
            mark = len(frames(log_path, 0))
            for _ in range(8):
                x.click(640, 400, button=5)  # wheel: zoom, one full-resolution frame each
                time.sleep(0.6)
            full = frames(log_path, mark)
            print(f"full viewport {sorted(set(f['size'] for f in full))}, 4 lights:")
            print("  " + summary("render", [f["render"] for f in full]))
            print("  " + summary("input to presented frame", [f["total"] for f in full]))
        finally:
            editor.kill()
            editor.wait()


if __name__ == "__main__":
    main()
