"""Editor figures under Xvfb (not a test; numbers for docs/performance.md and reports):
  1. idle CPU: utime+stime of the editor process over 10 s with nothing happening;
  2. edit-to-frame while dragging a material slider with 4 lights (1280×800 window), from the
     editor's GLINT_LOG_FRAMES log: time from the frame's input arriving to the frame presented,
     the frames per second drawn during the drag and their resolution, and the full frame after
     the release;
  3. frame time with both side columns closed (viewport 1280 × ~750), from mouse-wheel zooms.
--size WxH (e.g. 1920x1080) runs the same on a screen of that size with the window resized to
fill it (the right column's slider moves with the window's right edge). --motion-ms N sends the
drag's pointer motion from one xdotool process, one event every N ms (default: one process per
event, about 20 a second at most), so that the editor, not xdotool, bounds the frames per second.
usage: /usr/bin/python3 tests/bench/editor_figures.py build/app/glint [--size WxH] [--motion-ms N]"""
import argparse
import contextlib
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gui_test_support import XServer  # noqa: E402
from gui_editor_test import ADD_POINT_LIGHT, EXPONENT_SLIDER, lit_sphere  # noqa: E402


@contextlib.contextmanager
def logging_editor(glint, width, height, state):
    """The editor on a width×height Xvfb screen, logging its frames (GLINT_LOG_FRAMES) to
    state/frames.log; yields the X server, the editor's process and window, and the log's path."""
    log_path = os.path.join(state, "frames.log")
    with XServer(width, height) as x, open(log_path, "w") as log:
        env = dict(x.env, GLINT_STATE_DIR=state, GLINT_LOG_FRAMES="1")
        editor = subprocess.Popen([glint], env=env, stdout=log, stderr=log)
        try:
            yield x, editor, x.find_window("Glint"), log_path
        finally:
            editor.kill()
            editor.wait()


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
        frame = {"size": words[3], "scale": words[5], "render": float(words[7]), "total": float(words[13])}
        if "presented" in words[14:]:  # the phases: ui built, displayed, ui drawn, presented [ms]
            frame.update(ui=float(words[23]), display=float(words[26]), drawn=float(words[30]), present=float(words[33]))
        if "at" in words:  # when it was presented [s]
            frame["at"] = float(words[words.index("at") + 1])
        if "band" in words:
            frame["band"] = words[words.index("band") + 1].rstrip(",")
        parsed.append(frame)
    return parsed


def fast_drag(x, start, end, steps, step_seconds):
    """A drag whose motion events come from one chained xdotool command, step_seconds apart."""
    x.move(*start)
    time.sleep(0.1)
    chain = ["xdotool", "mousedown", "1"]
    for i in range(1, steps + 1):
        chain += ["sleep", f"{step_seconds:.3f}", "mousemove",
                  str(start[0] + (end[0] - start[0]) * i // steps), str(start[1] + (end[1] - start[1]) * i // steps)]
    x.run(*chain, "sleep", "0.1", "mouseup", "1")


def summary(name, values):
    if not values:
        return f"{name}: no frames"
    ordered = sorted(values)
    p90 = ordered[min(len(ordered) - 1, int(0.9 * len(ordered)))]
    return (f"{name}: median {statistics.median(values):.1f} ms, p90 {p90:.1f}, min {min(values):.1f}, "
            f"max {max(values):.1f} (n={len(values)})")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("glint")
    parser.add_argument("--size", default="1280x800")
    parser.add_argument("--motion-ms", type=float, default=0.0)
    args = parser.parse_args()
    glint = args.glint
    width, height = (int(v) for v in args.size.split("x"))
    slider = (EXPONENT_SLIDER[0] + width - 1280, EXPONENT_SLIDER[1])  # the material column is right-aligned
    state = tempfile.mkdtemp(prefix="glint-figures-")
    with logging_editor(glint, width, height, state) as (x, editor, window, log_path):
        if (width, height) != (1280, 800):
            x.run("xdotool", "windowmove", "--sync", window, "0", "0")
            x.run("xdotool", "windowsize", "--sync", window, str(width), str(height))
            time.sleep(8)  # the first full frames at the new size
        else:
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
        start = time.time()
        if args.motion_ms > 0:
            fast_drag(x, slider, (slider[0] - 80, slider[1]), steps=80, step_seconds=args.motion_ms / 1000)
        else:
            x.drag(slider, (slider[0] - 80, slider[1]), steps=40, step_seconds=0.05)
        drag_seconds = time.time() - start
        time.sleep(1.5)
        logged = frames(log_path, mark)
        # The drag's frames, then the full frame after the release (its bands, if any).
        last_preview = max((i for i, f in enumerate(logged) if f["scale"] != "1/1"), default=len(logged) - 1)
        dragged, released = logged[:last_preview + 2], logged[last_preview + 1:]
        previews = [f for f in dragged if f["scale"] != "1/1"]
        print(f"slider drag with 4 lights ({width}x{height} window): {len(dragged)} frames, "
              f"sizes {sorted(set(f['size'] + ' ' + f['scale'] for f in dragged))}")
        # The rate the editor drew at: the frames between the first and the last reduced one, by the
        # times they were presented; the pointer's whole gesture (xdotool's start, its pauses before
        # and after the motion) is longer.
        if len(previews) > 1 and "at" in previews[0]:
            drawing = previews[-1]["at"] - previews[0]["at"]
            print(f"  frames per second during the drag: {(len(previews) - 1) / drawing:.1f} "
                  f"({len(previews) - 1} frame intervals in {drawing:.2f} s between the first and the last reduced frame; "
                  f"{len(dragged) - 1} frames in {drag_seconds:.2f} s of the whole gesture)")
        else:
            print(f"  frames per second during the drag: {(len(dragged) - 1) / drag_seconds:.1f} "
                  f"({len(dragged) - 1} frames in {drag_seconds:.2f} s of the whole gesture)")
        print("  " + summary("input to presented frame during the drag", [f["total"] for f in dragged[:-1]]))
        print("  " + summary("render only during the drag", [f["render"] for f in dragged[:-1]]))
        for phase, name in (("ui", "ui built (input, panels)"), ("display", "display pass (clear, radiance to screen)"),
                            ("drawn", "ui drawn"), ("present", "presented (swap)")):
            print("  " + summary(name + " during the drag", [f[phase] for f in dragged[:-1] if phase in f]))
        print(f"  preview frames: {len(previews)}; last (refined) frame: {dragged[-1] if dragged else None}")
        if released:
            print(f"  full frame after the release: {len(released)} frame(s) (bands {[f.get('band') for f in released]}), "
                  f"first: render {released[0]['render']:.1f} ms, input to presented {released[0]['total']:.1f} ms; "
                  f"render of all {sum(f['render'] for f in released):.1f} ms, "
                  f"input to presented of all {sum(f['total'] for f in released):.1f} ms")

        x.click(316, 34)   # close the scene column
        time.sleep(1.5)
        x.click(1266 + width - 1280, 34)  # close the material column
        time.sleep(1.5)
        mark = len(frames(log_path, 0))
        for _ in range(8):
            x.click(width // 2, height // 2, button=5)  # wheel: zoom, one full-resolution frame each
            time.sleep(0.6)
        full = frames(log_path, mark)
        print(f"full viewport {sorted(set(f['size'] for f in full))}, 4 lights:")
        print("  " + summary("render", [f["render"] for f in full]))
        print("  " + summary("input to presented frame", [f["total"] for f in full]))


if __name__ == "__main__":
    main()
