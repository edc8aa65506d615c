"""The longest UI-thread frame while an environment map is precomputed (not a test; a figure for
docs/environment-lighting.md and reports). Under Xvfb the editor opens the classic scene (no
environment) with GLINT_LOG_FRAMES=1 and either picks Display ▸ Environment ▸ HDR file… and types
the map's path, or (--open) opens with Ctrl+O a copy of the classic scene that names the map; every
frame the editor logs from the confirm until the map shows behind the sphere (and 1 s after) is
timed by when its log line arrives: the longest input-to-presented time among them, how many frames
were drawn meanwhile and the longest time without a new frame. An editor that precomputes on the
UI thread logs one frame as long as the precompute; one that does it on a worker keeps drawing.
usage: /usr/bin/python3 tests/bench/environment_load_figures.py build/app/glint MAP.hdr [--open] [--runs N]"""
import argparse
import json
import os
import re
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gui_test_support import XServer, region_difference  # noqa: E402
from gui_editor_test import (BACKGROUND_BOX, CLASSIC_SCENE, ENVIRONMENT_COMBO, ENVIRONMENT_STUDIO,  # noqa: E402
                             click_after_hover, dialog_shown, lit_sphere)

ENVIRONMENT_FILE_ITEM = (ENVIRONMENT_STUDIO[0], ENVIRONMENT_STUDIO[1] - 21)  # "HDR file…", one row above "studio"
FRAME_TIME = re.compile(r"input to presented(?: frame)? ([0-9.]+) ms")


# Each brings up the file browser and returns the path to type there.
def pick_in_panel(x, hdr, base, state):
    click_after_hover(x, ENVIRONMENT_COMBO)
    time.sleep(0.5)
    click_after_hover(x, ENVIRONMENT_FILE_ITEM)
    x.wait_for(dialog_shown(base), "the file browser")
    return hdr


def open_scene_naming(x, hdr, base, state):
    with open(CLASSIC_SCENE) as classic:
        scene = json.load(classic)
    scene["environment"] = {"type": "file", "file": hdr}
    path = os.path.join(state, "classic_lit.json")
    with open(path, "w") as out:
        json.dump(scene, out)
    x.key("ctrl+o")
    x.wait_for(dialog_shown(base), "the file browser")
    return path


def one_run(x, glint, hdr, state, choose):
    env = dict(x.env, GLINT_STATE_DIR=state, GLINT_LOG_FRAMES="1")
    process, _ = x.start_editor([glint, CLASSIC_SCENE], env, os.path.dirname(CLASSIC_SCENE))
    stamped = []  # (arrival time, line)
    reader = threading.Thread(target=lambda: stamped.extend((time.monotonic(), line) for line in process.stdout),
                              daemon=True)
    reader.start()
    try:
        base = x.wait_for(lit_sphere, "the lit sphere", timeout=60)
        path = choose(x, hdr, base, state)
        time.sleep(0.5)
        x.key("ctrl+a")
        x.type_text(path)
        picked = time.monotonic()
        x.key("Return")
        x.move(1100, 700)
        # A viewport frame drawn since the confirm (not the file browser, frozen on screen by an
        # editor that precomputes on the UI thread) shows the map.
        x.wait_for(lambda shot: region_difference(shot, base, BACKGROUND_BOX) > 20 and
                   any(at > picked and "glint frame: viewport" in line for at, line in list(stamped)),
                   "the map behind the sphere", timeout=120, interval=0.1)
        shown = time.monotonic()
        time.sleep(1.0)
    finally:
        process.kill()
        process.wait(timeout=30)
    reader.join(timeout=5)
    arrivals = [at for at, line in stamped if picked <= at <= shown + 1.0 and FRAME_TIME.search(line)]
    during = [float(FRAME_TIME.search(line).group(1)) for at, line in stamped
              if picked <= at <= shown + 1.0 and FRAME_TIME.search(line)]
    # The longest time the window showed no new frame: a frozen UI thread.
    before = [at for at in arrivals if at <= shown]
    still = max(b - a for a, b in zip([picked] + before, before + [shown]))
    if os.environ.get("VERBOSE"):
        for at, line in stamped:
            if picked <= at <= shown + 1.0:
                print(f"{at - picked:6.2f} s {line.strip()[:150]}")
    if not during:
        raise RuntimeError("no frame was logged from the confirm until the map showed (a missed click?); run again")
    return max(during), len(during), shown - picked, still


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("glint")
    parser.add_argument("hdr")
    parser.add_argument("--open", action="store_true", help="open a scene naming the map instead of picking it")
    parser.add_argument("--runs", type=int, default=1)
    arguments = parser.parse_args()
    with tempfile.TemporaryDirectory() as state, XServer() as x:
        for run in range(arguments.runs):
            longest, count, seconds, still = one_run(x, os.path.abspath(arguments.glint), os.path.abspath(arguments.hdr), state,
                                             open_scene_naming if arguments.open else pick_in_panel)
            print(f"{arguments.glint}: longest frame {longest:.0f} ms of {count} frames from the confirm until the map "
                  f"showed ({seconds:.1f} s later) and 1 s after; at most {still * 1000:.0f} ms without a new frame", flush=True)


if __name__ == "__main__":
    main()
