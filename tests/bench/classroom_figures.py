"""Classroom figure under Xvfb (not a test; the number issue 7 asks for): frame time of the editor at
1920×1080 in presentation mode with the surface probe and the BRDF/Fresnel plots window open,
against the same editor with neither (the plain viewport), both on the default scene. Frames are
made by toggling the wireframe overlay (W; each a scene change and a full-resolution render, with
the probe and the plots recomputed); times come from GLINT_LOG_FRAMES.
usage: /usr/bin/python3 tests/bench/classroom_figures.py build/app/glint [TOGGLES]"""
import os
import statistics
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gui_test_support import write_png  # noqa: E402
from bench.editor_figures import frames, logging_editor  # noqa: E402

WIDTH, HEIGHT = 1920, 1080


def toggled_frames(x, log_path, toggles):
    """W (the wireframe overlay) pressed `toggles` times, on and off: each press is a scene change and
    so one full-resolution frame, wherever the mouse is; their logged frames."""
    mark = len(frames(log_path, 0))
    for _ in range(toggles):
        x.key("w")
        time.sleep(1.5)
    return frames(log_path, mark)


def report(name, logged):
    totals = [f["total"] for f in logged]
    renders = [f["render"] for f in logged]
    print(f"{name}: {len(logged)} frames {sorted(set(f['size'] + ' ' + f['scale'] for f in logged))}")
    print(f"  input to presented frame: median {statistics.median(totals):.1f} ms (min {min(totals):.1f}, max {max(totals):.1f})")
    print(f"  render: median {statistics.median(renders):.1f} ms")
    return statistics.median(totals)


def main():
    glint = sys.argv[1]
    toggles = int(sys.argv[2]) if len(sys.argv) > 2 else 10
    state = tempfile.mkdtemp(prefix="glint-classroom-figures-")
    with logging_editor(glint, WIDTH, HEIGHT, state) as (x, _, window, log_path):
        x.run("xdotool", "windowsize", window, str(WIDTH), str(HEIGHT))  # the editor opens at 1280×800
        time.sleep(4)
        plain = report("plain viewport", toggled_frames(x, log_path, toggles))

        x.key("F11")  # presentation mode: 2× UI, large font; the columns double in width
        time.sleep(2)
        centre = (930, 540)
        x.run("xdotool", "mousemove", "--sync", str(centre[0]), str(centre[1]))
        time.sleep(0.3)
        x.run("xdotool", "keydown", "shift")
        time.sleep(0.3)  # a frame that sees Shift held before the press
        x.run("xdotool", "click", "1")  # Shift+click: the surface probe on the sphere
        time.sleep(0.3)
        x.run("xdotool", "keyup", "shift")
        time.sleep(1.5)
        x.key("b")  # the BRDF and Fresnel plots window (polar, lobe, albedo, Fresnel)
        time.sleep(2)
        write_png(x.screenshot(), os.path.join(state, "classroom.png"))
        print(f"screenshot of the measured state: {os.path.join(state, 'classroom.png')}")
        classroom = report("presentation mode + probe + plots", toggled_frames(x, log_path, toggles))
        print(f"ratio (presentation + probe + plots) / plain: {classroom / plain:.2f}")


if __name__ == "__main__":
    main()
