"""GUI test of the classroom surface probe under Xvfb, driven with real input (xdotool):
  probe  Shift+click the sphere: the probe's white N and yellow L arrows appear over it (and the
         camera does not move); I hides it (the picture is back); I then a plain click on the
         background marks the point "no surface"; closing asks nothing (the scene is unchanged)
usage: gui_probe_test.py GLINT OUTPUT_DIR SCENARIO"""
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, pixel, run_scenario_from_arguments  # noqa: E402
from gui_editor_test import (BACKGROUND_SPOT, SPHERE_CENTRE, VIEWPORT, close_window, lit_sphere,  # noqa: E402
                             matches, save)

PROBE_NORMAL = (255, 255, 255)  # app/classroom/probe_overlay.cpp
PROBE_LIGHT = (255, 214, 60)
PROBE_POINT = (SPHERE_CENTRE[0] - 80, SPHERE_CENTRE[1] - 60)  # on the sphere, its normal tilted up-left


def probe_pixels(shot, colour, centre, radius=120):
    """How many pixels of exactly `colour` lie within `radius` of `centre` (every second pixel)."""
    left, top = max(VIEWPORT[0], centre[0] - radius), max(VIEWPORT[1], centre[1] - radius)
    right, bottom = min(VIEWPORT[2], centre[0] + radius), min(VIEWPORT[3], centre[1] + radius)
    return sum(1 for y in range(top, bottom, 2) for x in range(left, right, 2) if pixel(shot, x, y) == colour)


def scenario_probe(x, glint, output, state):
    editor = LoggedEditor(x, glint, output, state)
    try:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.move(*PROBE_POINT)
        time.sleep(0.3)
        x.run("xdotool", "keydown", "shift")
        time.sleep(0.3)  # a frame that sees Shift held before the press
        x.run("xdotool", "click", "1")
        time.sleep(0.3)
        x.run("xdotool", "keyup", "shift")
        probed = x.wait_for(lambda shot: probe_pixels(shot, PROBE_NORMAL, PROBE_POINT) > 10 and
                            probe_pixels(shot, PROBE_LIGHT, PROBE_POINT) > 10,
                            "Shift+click to draw the probe's N (white) and L (yellow) arrows on the sphere")
        save(probed, output, "probe_1_on")
        x.move(1100, 745)
        x.key("i")
        x.wait_for(matches(base), "I to hide the probe (and the click must not have moved the camera)")
        x.key("i")  # armed: the next plain click sets the point
        x.click(*BACKGROUND_SPOT)
        missed = x.wait_for(lambda shot: probe_pixels(shot, PROBE_NORMAL, BACKGROUND_SPOT, 20) > 3,
                            "I then a click on the background to mark 'no surface'")
        save(missed, output, "probe_2_miss")
        close_window(x, editor)  # the probe changes no scene value: no unsaved-changes prompt
        assert editor.wait_exit() == 0
        print(f"ok: probe arrows drawn ({probe_pixels(probed, PROBE_NORMAL, PROBE_POINT)} N pixels, "
              f"{probe_pixels(probed, PROBE_LIGHT, PROBE_POINT)} L pixels), hidden with I, miss marked")
    finally:
        editor.stop()


if __name__ == "__main__":
    run_scenario_from_arguments(globals())
