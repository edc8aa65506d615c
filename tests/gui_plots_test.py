"""GUI test of the classroom Plots window under Xvfb, driven with real input (xdotool) and
checked in screenshots. Not a test of the plots' numbers (core_tests) or drawings (goldens).
  plots_window  B opens the BRDF and Fresnel plots window over the viewport; dragging the
                material's exponent slider changes the plots live; B closes it again
usage: gui_plots_test.py GLINT OUTPUT_DIR SCENARIO"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import region_difference, run_scenario_from_arguments, write_png  # noqa: E402

# The 1280×800 window on the default scene: ImGui opens the new window near (60, 60), about
# 660×510 pixels; the Blinn-Phong exponent slider sits in the material column on the right.
PLOTS_REGION = (80, 120, 640, 540)
EXPONENT_SLIDER = (1018, 240)


def plots_scenario_editor(x, glint, output, state):
    environment = dict(x.env, GLINT_STATE_DIR=state, GLINT_GUI_FAILURE_DIR=output)
    process, _ = x.start_editor([glint], environment, output)
    return process


def scenario_plots_window(x, glint, output, state):
    process = plots_scenario_editor(x, glint, output, state)
    try:
        base = x.wait_stable(PLOTS_REGION)
        x.key("b")
        opened = x.wait_for(lambda shot: region_difference(shot, base, PLOTS_REGION) > 5.0, "B to open the plots window")
        opened = x.wait_stable(PLOTS_REGION)
        write_png(opened, os.path.join(output, "plots_1_open.png"))
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        changed = x.wait_for(lambda shot: region_difference(shot, opened, PLOTS_REGION) > 0.5,
                             "the plots to follow the exponent slider")
        write_png(x.wait_stable(PLOTS_REGION), os.path.join(output, "plots_2_exponent.png"))
        x.key("b")
        x.wait_for(lambda shot: region_difference(shot, changed, PLOTS_REGION) > 5.0, "B to close the plots window")
        print("ok: B opened the plots, the exponent slider changed them, B closed them")
    finally:
        if process.poll() is None:
            process.kill()
        process.communicate()


if __name__ == "__main__":
    run_scenario_from_arguments(globals())
