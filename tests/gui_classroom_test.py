"""GUI tests of classroom mode under Xvfb, driven with real keys (xdotool). One scenario per
ctest entry:
  lessons       PageDown opens lesson 1 (the window title names 01_lambert.json and the picture
                changes), Right steps to lesson 2 (Phong), Left back to lesson 1
  presentation  F11 turns presentation mode on (the left column changes: larger text, high
                contrast; settings.json says so), F11 again brings the normal look back
usage: gui_classroom_test.py GLINT OUTPUT_DIR SCENARIO"""
import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, pixel, region_difference, run_scenario_from_arguments, write_png  # noqa: E402

VIEWPORT = (340, 40, 910, 760)
LEFT_COLUMN = (10, 60, 320, 700)
SPHERE_CENTRE = (625, 375)  # the default scene's red sphere
LESSONS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "lessons", "lessons.json")


def start_editor(x, glint, output, state):
    return LoggedEditor(x, glint, output, state, env={"GLINT_LESSONS": LESSONS})


def drawn(editor):
    """Waits for the default scene's lit red sphere (the first frames are black), then for all of
    the first frames."""
    def lit(shot):
        red = pixel(shot, *SPHERE_CENTRE)
        return red[0] > 80 and red[0] > red[1] + 30
    editor.x.wait_for(lit, "the editor's first picture")
    return editor.settled("the first frames")


def finish(x, editor):
    x.key("ctrl+q")  # nothing unsaved: quits at once
    code = editor.wait_exit()
    assert code == 0, f"editor exited with {code}"


def scenario_lessons(x, glint, output, state):
    with start_editor(x, glint, output, state) as editor:
        window = editor.window
        start = drawn(editor)
        x.key("Next")  # PageDown: the first lesson
        x.wait_for_title(window, "01_lambert.json")
        x.wait_for(lambda shot: region_difference(shot, start, VIEWPORT) > 1.0, "lesson 1's picture")
        first = editor.settled("lesson 1")
        write_png(first, os.path.join(output, "lesson_1.png"))
        x.key("Right")
        x.wait_for_title(window, "02_phong.json")
        second = editor.settled("lesson 2")
        write_png(second, os.path.join(output, "lesson_2.png"))
        assert region_difference(second, first, VIEWPORT) > 1.0, "lesson 2 looks like lesson 1"
        x.key("Left")
        x.wait_for_title(window, "01_lambert.json")
        finish(x, editor)
        print("ok: PageDown opened lesson 1, Right lesson 2, Left lesson 1 again")


def scenario_presentation(x, glint, output, state):
    with start_editor(x, glint, output, state) as editor:
        normal = drawn(editor)
        write_png(normal, os.path.join(output, "normal.png"))
        x.key("F11")
        x.wait_for(lambda shot: region_difference(shot, normal, LEFT_COLUMN) > 2.0, "the panels to change in presentation mode")
        presenting = editor.settled("F11")
        write_png(presenting, os.path.join(output, "presentation.png"))
        with open(os.path.join(state, "settings.json")) as file:
            settings = json.load(file)
        assert settings["presentation_mode"] is True, settings
        x.key("F11")
        x.wait_for(lambda shot: region_difference(shot, normal, LEFT_COLUMN) < 0.5, "the normal look to return")
        with open(os.path.join(state, "settings.json")) as file:
            assert json.load(file)["presentation_mode"] is False
        finish(x, editor)
        print("ok: F11 switched presentation mode on (saved) and off again")


if __name__ == "__main__":
    run_scenario_from_arguments(globals())
