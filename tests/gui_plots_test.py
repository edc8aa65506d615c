"""GUI test of the classroom Plots window under Xvfb, driven with real input (xdotool) and
checked in screenshots. Not a test of the plots' numbers (core_tests) or drawings (goldens).
  plots_window  B opens the BRDF and Fresnel plots window over the viewport; dragging the
                material's exponent slider changes the plots live; B closes it again
usage: gui_plots_test.py GLINT OUTPUT_DIR SCENARIO"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, region_difference, run_scenario_from_arguments, write_png  # noqa: E402

# The 1280×800 window on the default scene: ImGui opens the new window near (60, 60), about
# 660×510 pixels; the Blinn-Phong exponent slider sits in the material column on the right.
PLOTS_REGION = (80, 120, 640, 540)
EXPONENT_SLIDER = (1018, 240)


def scenario_plots_window(x, glint, output, state):
    with LoggedEditor(x, glint, output, state) as editor:
        base = editor.settled("the first frames")
        x.key("b")
        x.wait_for(lambda shot: region_difference(shot, base, PLOTS_REGION) > 5.0, "B to open the plots window")
        opened = editor.settled("B")
        write_png(opened, os.path.join(output, "plots_1_open.png"))
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        changed = x.wait_for(lambda shot: region_difference(shot, opened, PLOTS_REGION) > 0.5,
                             "the plots to follow the exponent slider")
        write_png(editor.settled("the slider drag"), os.path.join(output, "plots_2_exponent.png"))
        x.key("b")
        x.wait_for(lambda shot: region_difference(shot, changed, PLOTS_REGION) > 5.0, "B to close the plots window")
        print("ok: B opened the plots, the exponent slider changed them, B closed them")


if __name__ == "__main__":
    run_scenario_from_arguments(globals())
