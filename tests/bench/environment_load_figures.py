"""The longest UI-thread frame while an environment map is precomputed (not a test; a figure for
docs/environment-lighting.md and reports). Under Xvfb the editor opens the classic scene (no
environment) with GLINT_LOG_FRAMES=1, picks Display ▸ Environment ▸ HDR file… and types the map's
path; every frame the editor logs from the confirm until the map shows behind the sphere (and 1 s
after) is timed by when its log line arrives: the longest input-to-presented time among them, and
how many frames were drawn meanwhile. An editor that precomputes on the UI thread logs one frame as
long as the precompute; one that does it on a worker keeps drawing (the progress bar).
usage: /usr/bin/python3 tests/bench/environment_load_figures.py build/app/glint MAP.hdr [--runs N]"""
import argparse
import os
import re
import sys
import tempfile
import threading
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gui_test_support import XServer, region_difference  # noqa: E402
from gui_editor_test import (BACKGROUND_BOX, CLASSIC_SCENE, ENVIRONMENT_COMBO, ENVIRONMENT_STUDIO,  # noqa: E402
                             click_after_hover, dialog_shown, lit_sphere, type_path)

ENVIRONMENT_FILE_ITEM = (ENVIRONMENT_STUDIO[0], ENVIRONMENT_STUDIO[1] - 21)  # "HDR file…", one row above "studio"
FRAME_TIME = re.compile(r"input to presented(?: frame)? ([0-9.]+) ms")


def one_run(x, glint, hdr, state):
    env = dict(x.env, GLINT_STATE_DIR=state, GLINT_LOG_FRAMES="1")
    process, _ = x.start_editor([glint, CLASSIC_SCENE], env, os.path.dirname(CLASSIC_SCENE))
    stamped = []  # (arrival time, line)
    reader = threading.Thread(target=lambda: stamped.extend((time.monotonic(), line) for line in process.stdout),
                              daemon=True)
    reader.start()
    try:
        base = x.wait_for(lit_sphere, "the lit sphere", timeout=60)
        click_after_hover(x, ENVIRONMENT_COMBO)
        time.sleep(0.5)
        click_after_hover(x, ENVIRONMENT_FILE_ITEM)
        x.wait_for(dialog_shown(base), "the file browser")
        picked = time.monotonic()
        type_path(x, hdr)
        x.move(1100, 700)
        x.wait_for(lambda shot: region_difference(shot, base, BACKGROUND_BOX) > 20, "the map behind the sphere",
                   timeout=120, interval=0.1)
        shown = time.monotonic()
        time.sleep(1.0)
    finally:
        process.kill()
        process.wait(timeout=30)
    reader.join(timeout=5)
    during = [float(FRAME_TIME.search(line).group(1)) for at, line in stamped
              if picked <= at <= shown + 1.0 and FRAME_TIME.search(line)]
    if os.environ.get("VERBOSE"):
        for at, line in stamped:
            if picked <= at <= shown + 1.0:
                print(f"{at - picked:6.2f} s {line.strip()[:150]}")
    if not during:
        raise RuntimeError("no frame was logged from the confirm until the map showed (a missed click?); run again")
    return max(during), len(during), shown - picked


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("glint")
    parser.add_argument("hdr")
    parser.add_argument("--runs", type=int, default=1)
    arguments = parser.parse_args()
    with tempfile.TemporaryDirectory() as state, XServer() as x:
        for run in range(arguments.runs):
            longest, count, seconds = one_run(x, os.path.abspath(arguments.glint), os.path.abspath(arguments.hdr), state)
            print(f"{arguments.glint}: longest frame {longest:.0f} ms of {count} frames from the confirm until the map "
                  f"showed ({seconds:.1f} s later) and 1 s after", flush=True)


if __name__ == "__main__":
    main()
