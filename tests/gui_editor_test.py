"""GUI tests of the editor under Xvfb, driven with real input (xdotool) and checked in
screenshots. One scenario per ctest entry:
  undo         drag a material slider (the sphere changes), Ctrl+Z (it is back), Ctrl+Shift+Z,
               add a light and undo it; closing with unsaved changes asks first (N = don't save)
  save_reopen  edit, add a light, Ctrl+S through the file browser, reopen the file: same picture;
               Ctrl+S again saves to the same path without asking
  recovery     edit, wait for autosave, kill -9; the next start offers the work (Enter = recover)
               and the picture shows the edit; Ctrl+Q then asks about the unsaved work
  light_handle drag the key light's handle in the viewport (the lighting turns), undo, redo
  typed_values Ctrl+click a slider and type: a value outside the valid range is refused with a
               message; one past the slider's end but valid is kept
  typed_commit a value being typed changes nothing (picture, undo history); Enter commits -0.5,
               which is refused and changes nothing; a click elsewhere commits a valid value;
               the refusal goes with Ctrl+Z
  screenshot   F12 through the file browser writes the viewport as PNG and as EXR
  crash_signal SIGSEGV right after an edit (autosave 30 s away): the crash guard's copy is
               offered on the next start and restores the edit
  shadow_toggle tick the key light's "Casts shadows": its shadow darkens the floor beside the
               sphere; Ctrl+Z takes it away (one click = one step)
  corrupt_open open a corrupt scene from the UI (after the unsaved-changes prompt): an error
               naming file:line, the work and its undo history untouched
  environment  the Environment section: the built-in studio lights the sphere and shows behind it;
               "Show as background" off keeps the light and brings the old background back; two
               Ctrl+Z undo both steps
  texture      the texture menu beside the diffuse albedo: a checker draws squares on the sphere
               (Ctrl+Z removes it); an image file chosen in the file browser colours the sphere; a
               corrupt image is refused with a message naming it and changes nothing
  material_choice File ▸ Open of a .mtl with two materials asks which one: Down and Enter put the
               second (blue) on the sphere, Ctrl+Z takes it off; Esc in the same question changes nothing
  redraw_changes only what changed is drawn and presented: after a slider drag (reduced frames, the
               full frame in bands after it) the window is, pixel for pixel, the frame drawn whole
               (the window unmapped and mapped again)
  shader_error a shader broken on disk while the editor runs: its error (file:line) in the status
               bar and the material panel, printed once; the sphere keeps its last good program;
               the error goes when the file compiles again
  model_switch the Model combo from Blinn-Phong to Lambert: the sphere keeps its red (the diffuse
               albedo carries over) and loses its highlight, the panel says what was kept; one
               Ctrl+Z brings the Blinn-Phong material back
usage: gui_editor_test.py GLINT OUTPUT_DIR SCENARIO"""
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, pixel, region_difference, run_scenario_from_arguments, wait_until, write_png  # noqa: E402

# Layout of the 1280×800 window on the default scene (menu bar, scene column 330 px on the
# left, material column 360 px on the right, status bar at the bottom). The light handle, shadow,
# environment and texture scenarios open CLASSIC_SCENE instead: Glint's earlier default scene, a key and a
# fill light, no shadow and no environment, which the lines marked (classic) are measured on.
SHADER_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "shaders")
CLASSIC_SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "editor_classic.json")
VIEWPORT = (340, 40, 910, 760)
SPHERE_CENTRE = (625, 375)
BACKGROUND_SPOT = (350, 60)         # dark background inside the viewport, above the floor
EXPONENT_SLIDER = (1018, 240)        # Blinn-Phong exponent n (64) in the material column
ADD_POINT_LIGHT = (153, 119)         # "+ Point" in the lights section (one light: the stage's key)
CASTS_SHADOWS_BOX = (19, 388)        # the selected key light's "Casts shadows" checkbox (classic)
SHADOW_ON_FLOOR = (362, 556)         # a floor point in the key light's shadow (classic)
VIEWPORT_PIXELS = (590, 752)         # 1280 − 330 − 360 wide, between menu bar and status bar
ENVIRONMENT_COMBO = (70, 682)        # Display ▸ Environment: "none" (classic)
ENVIRONMENT_STUDIO = (34, 612)       # its "studio" item (the list opens upwards: no room below) (classic)
SHOW_AS_BACKGROUND_BOX = (19, 763)   # shown once an environment is chosen (classic)
BACKGROUND_BOX = (340, 40, 420, 120)  # viewport corner clear of the sphere, where the studio's softbox shows
DIFFUSE_TEXTURE_BUTTON = (1253, 165)  # "Tex" beside the diffuse albedo ρ_d (its label above); its menu opens at the mouse:
TEXTURE_MENU_IMAGE = (1230, 204)     #   None, Image file…, Checker, Marble, Wood
TEXTURE_MENU_CHECKER = (1219, 224)
IMAGE_TEXTURE_BUTTON = (975, 189)    # once textured, "Image" no longer fits: it opens the next line
IMAGE_TEXTURE_MENU_IMAGE = (1010, 227)
TEXTURE_MENU_BOX = (970, 173, 1275, 303)  # where either menu shows
DIALOG_BOX = (450, 370, 840, 430)
STATUS_BAR = (0, 780, 1280, 800)
ERROR_IN_MATERIAL_PANEL = (925, 460, 1275, 545)  # below the default sphere's Blinn-Phong sliders    # the middle of the window, where a centred dialog shows
SPHERE_ROW = (420, 830, 375)         # x from, x to, y: a row across the lit sphere
MODEL_COMBO = (1040, 117)            # the material column's Model combo; its list opens below:
MODEL_LAMBERT = (980, 145)           #   Lambert first
HIGHLIGHT = (735, 290)               # the red plastic's specular highlight on the sphere


def lit_sphere(shot):
    red = pixel(shot, *SPHERE_CENTRE)
    return red[0] > 80 and red[0] > red[1] + 30


def differs(reference, threshold=1.0):
    return lambda shot: region_difference(shot, reference, VIEWPORT) > threshold


def matches(reference, threshold=0.3):
    return lambda shot: region_difference(shot, reference, VIEWPORT) < threshold


def dialog_shown(reference):
    """A centred dialog (error, unsaved changes) covers DIALOG_BOX; unlike modal_shown, this does not
    wait for ImGui's dimming, which fades in over frames that a quiet editor may not draw."""
    return lambda shot: region_difference(shot, reference, DIALOG_BOX) > 15


def modal_shown(reference):
    """ImGui lightens everything behind a modal; the dark background shows it."""
    return lambda shot: sum(pixel(shot, *BACKGROUND_SPOT)) > sum(pixel(reference, *BACKGROUND_SPOT)) + 60


def problem_text_shown(shot, box):
    """Whether the red of a problem the user should fix (panels/widgets.h) shows in box."""
    left, top, right, bottom = box
    return sum(1 for y in range(top, bottom) for x in range(left, right)
               if (lambda r, g, b: r > 200 and g < 150 and b < 130)(*pixel(shot, x, y))) > 20


def save(shot, output, name):
    write_png(shot, os.path.join(output, name + ".png"))


def close_window(x, editor):
    subprocess.run([os.environ["GLINT_X11_CLOSE"], editor.window], env=x.env, check=True)


def click_after_hover(x, where):
    """A checkbox or a menu item needs a frame that sees the hover before the press (frames are
    slow on llvmpipe)."""
    x.move(*where)
    time.sleep(0.5)
    x.click(*where)


def type_path(editor, before, path):
    """Once the file browser shows (the screen differs from `before`, a shot without it) and has
    finished drawing (its path field has the keyboard focus), replaces the field's text and confirms."""
    x = editor.x
    x.wait_for(dialog_shown(before), "the file browser")
    editor.settled("the file browser's first frames")
    x.key("ctrl+a")
    x.type_text(path)
    x.key("Return")


# --- scenarios ----------------------------------------------------------------------------------

def scenario_undo(x, glint, output, state):
    editor = LoggedEditor(x, glint, output, state)
    try:
        base = x.wait_for(lit_sphere, "the lit sphere")
        save(base, output, "undo_0_start")
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        x.wait_for(differs(base), "the sphere to change after the slider drag")
        x.move(1200, 10)  # off the slider (its tooltip follows the pointer), onto the menu bar's empty end
        edited = editor.settled("the slider's release")  # the full frame, not one drawn while it refines
        save(edited, output, "undo_1_dragged")
        x.key("ctrl+z")
        save(x.wait_for(matches(base), "Ctrl+Z to bring the sphere back (one drag = one step)"), output, "undo_2_undone")
        x.key("ctrl+shift+z")
        x.wait_for(matches(edited), "Ctrl+Shift+Z to redo the drag")
        x.click(*ADD_POINT_LIGHT)
        x.wait_for(differs(edited), "a new point light to change the picture")
        lit = editor.settled("the added light")
        save(lit, output, "undo_3_light_added")
        x.key("ctrl+z")
        x.wait_for(matches(edited), "Ctrl+Z to remove the added light")
        # Unsaved changes: a close request asks first and the editor stays open.
        close_window(x, editor)
        x.wait_for(modal_shown(edited), "the unsaved-changes prompt")
        time.sleep(0.5)
        assert editor.process.poll() is None, "the editor closed without asking about unsaved changes"
        x.key("n")  # Don't save
        code = editor.wait_exit()
        assert code == 0, f"editor exited with {code}"
        print("ok: drag changed the sphere, undo/redo restored it, added light undone, close asked first")
    finally:
        editor.stop()


def scenario_save_reopen(x, glint, output, state):
    path = os.path.join(output, "saved_scene.json")
    if os.path.exists(path):
        os.remove(path)
    with LoggedEditor(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        x.wait_for(differs(base), "the slider drag to show")
        dragged = editor.settled("the slider drag")
        x.click(*ADD_POINT_LIGHT)
        x.wait_for(differs(dragged), "the added light to show")  # a slow frame: not the picture before the click
        before_save = editor.settled("the edits")
        save(before_save, output, "save_1_before")
        x.key("ctrl+s")  # untitled: the file browser asks for a name
        type_path(editor, before_save, path)
        wait_until(lambda: os.path.exists(path), f"Ctrl+S to write {path}")
        with open(path) as saved:
            scene = json.load(saved)
        assert len(scene["lights"]) == 2, f"expected 2 lights (the key and the added one) in the saved scene, found {len(scene['lights'])}"
        exponent = scene["materials"][0]["exponent"]
        assert exponent < 60, f"the dragged exponent was not saved: {exponent}"
        close_window(x, editor)  # saved: no prompt
        assert editor.wait_exit() == 0

    with LoggedEditor(x, glint, output, state, arguments=[path]) as editor:
        reopened = x.wait_for(matches(before_save, 0.5), "the reopened scene to look as it did when saved")
        save(reopened, output, "save_2_reopened")
        first_write = os.stat(path).st_mtime_ns
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] + 60, EXPONENT_SLIDER[1]))
        x.wait_for(differs(reopened), "the second drag to show")
        time.sleep(0.3)
        x.key("ctrl+s")  # the scene has a path now: no dialog
        wait_until(lambda: os.stat(path).st_mtime_ns != first_write, f"Ctrl+S to write {path} again")
        with open(path) as saved:
            second = json.load(saved)["materials"][0]["exponent"]
        assert second > exponent, f"Ctrl+S did not save the second edit ({second} vs {exponent})"
        close_window(x, editor)
        assert editor.wait_exit() == 0
        print(f"ok: saved through the file browser (exponent {exponent:.3g}, 2 lights), reopened identical, re-saved {second:.3g}")


def recovery_files(state):
    """The editors' recovery files (one per running editor, recovery-PID.json)."""
    return glob.glob(os.path.join(state, "recovery*.json"))


def scenario_recovery(x, glint, output, state):
    with LoggedEditor(x, glint, output, state, env={"GLINT_AUTOSAVE_SECONDS": "1"}) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        x.wait_for(differs(base), "the slider drag to show")
        edited = editor.settled("the edit")
        wait_until(lambda: recovery_files(state), "autosave to write a recovery file")
        editor.process.send_signal(signal.SIGKILL)
        editor.process.wait(timeout=10)

    with LoggedEditor(x, glint, output, state) as editor:
        offer = x.wait_for(modal_shown(base), "the offer to recover the unsaved work")
        save(offer, output, "recovery_1_offer")
        x.key("Return")  # Recover
        recovered = x.wait_for(matches(edited, 0.5), "the recovered scene to show the edit")
        save(recovered, output, "recovery_2_recovered")
        # Recovered work counts as unsaved: Ctrl+Q asks, and "don't save" leaves no recovery file.
        x.key("ctrl+q")
        x.wait_for(modal_shown(edited), "the unsaved-changes prompt for recovered work")
        x.key("n")
        assert editor.wait_exit() == 0
        assert not recovery_files(state), "a clean exit must remove the recovery file"
        print("ok: kill -9 after an edit, the next start offered the work and restored the edit")


def scenario_crash_signal(x, glint, output, state):
    """SIGSEGV right after an edit, with autosave far off: the crash guard writes the copy."""
    with LoggedEditor(x, glint, output, state, env={"GLINT_AUTOSAVE_SECONDS": "30"}) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        time.sleep(1.0)  # past the first autosave check (a clean scene writes nothing)
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        x.wait_for(differs(base), "the slider drag to show")
        edited = editor.settled("the edit")
        assert not recovery_files(state), "autosave should not have run yet (30 s interval)"
        editor.process.send_signal(signal.SIGSEGV)
        code = editor.process.wait(timeout=10)
        assert code == -signal.SIGSEGV, f"the editor should still die of SIGSEGV, exit status {code}"
        assert recovery_files(state), "the crash guard wrote no recovery file"
        with open(recovery_files(state)[0]) as saved:
            exponent = json.load(saved)["scene"]["materials"][0]["exponent"]
        assert exponent < 60, f"the recovery file lacks the edit (exponent {exponent})"
    with LoggedEditor(x, glint, output, state) as editor:
        x.wait_for(modal_shown(base), "the offer to recover")
        x.key("Return")
        x.wait_for(matches(edited, 0.5), "the recovered edit")
        x.key("ctrl+q")
        x.wait_for(modal_shown(edited), "the unsaved-changes prompt")
        x.key("n")
        assert editor.wait_exit() == 0
        print(f"ok: SIGSEGV after an edit left a recovery file with exponent {exponent:.3g}, recovered on restart")


MATERIAL_COLUMN = (925, 40, 1275, 520)


def refusal_shown(shot):
    """The material panel's refusal message is orange text (255, 153, 76) under the widgets."""
    return any(abs(r - 255) < 3 and abs(g - 153) < 3 and abs(b - 76) < 3
               for r, g, b in (pixel(shot, x_, y_) for y_ in range(MATERIAL_COLUMN[1], MATERIAL_COLUMN[3])
                               for x_ in range(MATERIAL_COLUMN[0], MATERIAL_COLUMN[2], 2)))


def start_typing(x, where, text):
    """Ctrl+click turns an ImGui slider or drag field into a text field (its text selected); type
    without confirming."""
    x.move(*where)
    x.run("xdotool", "keydown", "ctrl")
    time.sleep(0.15)
    x.run("xdotool", "click", "1")
    time.sleep(0.15)
    x.run("xdotool", "keyup", "ctrl")
    time.sleep(0.3)
    x.key("ctrl+a")
    x.type_text(text)


def type_into_slider(x, where, text):
    """Type into a slider and confirm with Enter."""
    start_typing(x, where, text)
    x.key("Return")


def scenario_typed_values(x, glint, output, state):
    with LoggedEditor(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        assert not refusal_shown(base)
        type_into_slider(x, EXPONENT_SLIDER, "-5")
        refused = x.wait_for(refusal_shown, "a message refusing exponent -5")
        save(refused, output, "typed_1_refused")
        assert region_difference(refused, base, VIEWPORT) < 0.3, "a refused value must not change the sphere"
        type_into_slider(x, EXPONENT_SLIDER, "20000")  # past the slider's 10000, inside the valid range
        x.wait_for(differs(base), "exponent 20000 (beyond the slider) to be kept")
        kept = editor.settled("the typed value")
        assert not refusal_shown(kept), "the message should go once a valid value is typed"
        save(kept, output, "typed_2_kept")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to undo the typed value")
        close_window(x, editor)
        assert editor.wait_exit() == 0
        print("ok: -5 refused with a message, 20000 kept beyond the slider, undone")


ALBEDO_RED_FIELD = (960, 165)    # the diffuse albedo's red channel (its label above)
PANEL_EMPTY_SPOT = (1100, 700)     # empty material column: a click there ends the typing


def window_title(x, editor):
    return x.run("xdotool", "getwindowname", editor.window).stdout.strip()


def scenario_typed_commit(x, glint, output, state):
    with LoggedEditor(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        assert "●" not in window_title(x, editor)
        start_typing(x, ALBEDO_RED_FIELD, "-0.5")
        time.sleep(2)  # frames enough for a keystroke to have been applied, were it applied
        typing = x.screenshot()
        save(typing, output, "commit_1_typing")
        assert region_difference(typing, base, VIEWPORT) < 0.3, "a value being typed must not reach the scene"
        assert not refusal_shown(typing), "nothing is refused before Enter"
        assert "●" not in window_title(x, editor), "typing must not record an undo step"
        x.key("Return")
        refused = x.wait_for(refusal_shown, "Enter to commit -0.5, which is refused")
        save(refused, output, "commit_2_refused")
        assert region_difference(refused, base, VIEWPORT) < 0.3, "a refused value must not change the sphere"
        assert "●" not in window_title(x, editor), "a refused value must not record an undo step"

        start_typing(x, EXPONENT_SLIDER, "5")
        time.sleep(2)
        assert region_difference(x.screenshot(), base, VIEWPORT) < 0.3, "exponent 5 is not committed yet"
        click_after_hover(x, PANEL_EMPTY_SPOT)
        x.wait_for(differs(base), "a click elsewhere to commit exponent 5")
        committed = editor.settled("the click that commits the value")
        save(committed, output, "commit_3_focus_lost")
        assert not refusal_shown(committed), "a valid value clears the refusal"
        assert "●" in window_title(x, editor), "the committed value is an unsaved change"

        start_typing(x, ALBEDO_RED_FIELD, "-0.5")
        x.key("Return")
        x.wait_for(refusal_shown, "-0.5 refused again")
        x.key("ctrl+z")
        undone = x.wait_for(lambda shot: matches(base)(shot) and not refusal_shown(shot),
                            "Ctrl+Z to undo exponent 5 and take the refusal with it")
        save(undone, output, "commit_4_undone")
        assert "●" not in window_title(x, editor)
        close_window(x, editor)
        assert editor.wait_exit() == 0
        print("ok: typing changed nothing, -0.5 refused on Enter, 5 committed by a click elsewhere, refusal gone after undo")


def scenario_corrupt_open(x, glint, output, state):
    corrupt = os.path.join(output, "corrupt_scene.json")
    with open(corrupt, "w") as out:
        out.write('{\n  "format": "glint-scene",\n  "version": 1,\n  "lights": [{"type": "point", "power": -5}]\n}\n')
    with LoggedEditor(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        x.wait_for(differs(base), "the slider drag to show")
        edited = editor.settled("the edit")
        x.key("ctrl+o")
        type_path(editor, edited, corrupt)
        x.wait_for(modal_shown(edited), "the unsaved-changes prompt before opening")
        time.sleep(0.3)
        x.key("n")  # don't save: open the other scene (which will fail)
        time.sleep(0.5)
        error = x.wait_for(modal_shown(edited), "the error dialog")
        save(error, output, "corrupt_1_error")
        x.key("Return")  # OK
        x.wait_for(matches(edited), "the edited scene to stay on screen")
        x.key("ctrl+z")
        x.wait_for(matches(base), "the undo history to survive the failed open")
        x.key("ctrl+shift+z")
        close_window(x, editor)
        x.wait_for(modal_shown(edited), "the unsaved-changes prompt (the work is still unsaved)")
        x.key("n")
        assert editor.wait_exit() == 0
        assert "corrupt_scene.json:4:" in editor.output(), f"the error should name file:line, log was:\n{editor.output()}"
        print("ok: corrupt scene refused with", [l for l in editor.output().splitlines() if "corrupt_scene" in l][0])


def scenario_screenshot(x, glint, output, state):
    png, exr = os.path.join(output, "viewport.png"), os.path.join(output, "viewport.exr")
    for path in (png, exr):
        if os.path.exists(path):
            os.remove(path)
    with LoggedEditor(x, glint, output, state) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        for path in (png, exr):
            x.key("F12")
            type_path(editor, base, path)
            wait_until(lambda: os.path.exists(path), f"F12 to write {path}")
            x.wait_for(lambda shot: not modal_shown(base)(shot), "the file browser to close")
        with open(png, "rb") as image:
            header = image.read(24)
        assert header[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
        width, height = int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")
        assert (width, height) == (VIEWPORT_PIXELS), f"the screenshot should be the viewport, got {width}x{height}"
        with open(exr, "rb") as image:
            assert image.read(4) == b"\x76\x2f\x31\x01", "not an OpenEXR file"
        close_window(x, editor)  # nothing changed: no prompt
        assert editor.wait_exit() == 0
        print(f"ok: F12 wrote the viewport as a {width}x{height} PNG and as an EXR")


def find_handle(shot):
    """The centroid of the light handles' yellow pixels (dot and stroke) in the viewport, or None."""
    hits = [(x_, y_) for y_ in range(VIEWPORT[1], VIEWPORT[3], 2) for x_ in range(VIEWPORT[0], VIEWPORT[2], 2)
            if pixel(shot, x_, y_) == (255, 220, 90)]
    if not hits:
        return None
    return sum(h[0] for h in hits) // len(hits), sum(h[1] for h in hits) // len(hits)


def scenario_light_handle(x, glint, output, state):
    with LoggedEditor(x, glint, output, state, arguments=(CLASSIC_SCENE,)) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        handle = find_handle(base)
        assert handle, "no light handle drawn in the viewport"
        x.drag(handle, (handle[0] - 250, handle[1] + 40))
        x.wait_for(differs(base), "dragging the key light's handle to relight the sphere")
        turned = editor.settled("the handle drag")  # the full-resolution frame after the drag's previews
        save(turned, output, "handle_1_turned")
        moved_to = find_handle(turned)
        assert moved_to and abs(moved_to[0] - (handle[0] - 250)) < 25, f"the handle should follow the mouse: {handle} -> {moved_to}"
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to turn the light back (one drag = one step)")
        x.key("ctrl+shift+z")
        x.wait_for(matches(turned), "Ctrl+Shift+Z to redo the turn")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z again")
        close_window(x, editor)  # back at the opened state: nothing to save, no prompt
        assert editor.wait_exit() == 0
        print(f"ok: handle at {handle} dragged to {moved_to}, undone and redone")


def scenario_shadow_toggle(x, glint, output, state):
    with LoggedEditor(x, glint, output, state, arguments=(CLASSIC_SCENE,)) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        save(base, output, "shadow_0_start")
        unshadowed = sum(pixel(base, *SHADOW_ON_FLOOR))
        click_after_hover(x, CASTS_SHADOWS_BOX)
        x.move(1100, 745)  # an empty spot below the material column: no tooltip over the viewport
        shadowed = x.wait_for(lambda shot: sum(pixel(shot, *SHADOW_ON_FLOOR)) < unshadowed - 60,
                              "the key light's shadow to darken the floor beside the sphere")
        save(shadowed, output, "shadow_1_on")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to take the shadow away again (one click = one step)")
        close_window(x, editor)
        assert editor.wait_exit() == 0
        print(f"ok: shadow on darkened the floor {pixel(base, *SHADOW_ON_FLOOR)} -> "
              f"{pixel(shadowed, *SHADOW_ON_FLOOR)}, undone")


def scenario_environment(x, glint, output, state):
    with LoggedEditor(x, glint, output, state, arguments=(CLASSIC_SCENE,)) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        save(base, output, "environment_0_start")
        click_after_hover(x, ENVIRONMENT_COMBO)
        time.sleep(0.5)
        click_after_hover(x, ENVIRONMENT_STUDIO)
        x.move(1100, 700)  # no tooltip over the viewport
        x.wait_for(lambda shot: region_difference(shot, base, BACKGROUND_BOX) > 20, "the studio behind the sphere")
        studio = editor.settled("the studio environment")
        save(studio, output, "environment_1_studio")
        lit_by_studio = sum(pixel(studio, *SPHERE_CENTRE))
        assert lit_by_studio > sum(pixel(base, *SPHERE_CENTRE)) + 30, "the studio should add light to the sphere"
        click_after_hover(x, SHOW_AS_BACKGROUND_BOX)
        x.move(1100, 700)
        hidden = x.wait_for(lambda shot: region_difference(shot, base, BACKGROUND_BOX) < 1.0,
                            "the constant background back once the studio is not shown")
        hidden = editor.settled("the background switch")
        save(hidden, output, "environment_2_not_shown")
        assert abs(sum(pixel(hidden, *SPHERE_CENTRE)) - lit_by_studio) < 6, "hiding the studio must keep its light"
        x.key("ctrl+z")
        x.wait_for(matches(studio), "Ctrl+Z to show the studio again")
        x.key("ctrl+z")
        x.wait_for(matches(base), "a second Ctrl+Z to take the studio away")
        close_window(x, editor)  # back at the saved state: no unsaved-changes prompt
        assert editor.wait_exit() == 0
        print(f"ok: studio lit the sphere {pixel(base, *SPHERE_CENTRE)} -> {pixel(studio, *SPHERE_CENTRE)} and "
              "showed behind it; hidden background kept the light; both steps undone")


def edges_across_sphere(shot):
    """Jumps of more than 20 in red between neighbouring pixels along SPHERE_ROW: a smooth shaded
    sphere has none, a checker has one per square boundary."""
    x0, x1, y = SPHERE_ROW
    reds = [pixel(shot, x_, y)[0] for x_ in range(x0, x1)]
    return sum(1 for a, b in zip(reds, reds[1:]) if abs(a - b) > 20)


def choose_texture(x, menu_item, button=DIFFUSE_TEXTURE_BUTTON):
    """Opens the diffuse albedo's texture menu, waits until it shows, and picks `menu_item`."""
    before = x.screenshot()
    click_after_hover(x, button)
    x.wait_for(lambda shot: region_difference(shot, before, TEXTURE_MENU_BOX) > 5, "the texture menu")
    click_after_hover(x, menu_item)
    x.move(1100, 700)


def open_texture_file(editor, current, path, button=DIFFUSE_TEXTURE_BUTTON, menu_item=TEXTURE_MENU_IMAGE):
    choose_texture(editor.x, menu_item, button)
    type_path(editor, current, path)


def scenario_texture(x, glint, output, state):
    green = os.path.join(output, "green.png")
    write_png((4, 4, bytes([40, 200, 40]) * 16), green)
    corrupt = os.path.join(output, "corrupt.png")
    with open(corrupt, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n" + b"not a PNG body" * 4)
    with LoggedEditor(x, glint, output, state, arguments=(CLASSIC_SCENE,)) as editor:
        base = x.wait_for(lit_sphere, "the lit sphere")
        assert edges_across_sphere(base) == 0, "the untextured sphere should shade smoothly"
        choose_texture(x, TEXTURE_MENU_CHECKER)
        checker = x.wait_for(lambda shot: edges_across_sphere(shot) >= 2, "checker squares on the sphere")
        checker = editor.settled("the checker texture")
        save(checker, output, "texture_1_checker")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to take the checker away")
        open_texture_file(editor, base, green)
        tinted = x.wait_for(lambda shot: pixel(shot, *SPHERE_CENTRE)[1] > pixel(shot, *SPHERE_CENTRE)[0] + 30,
                            "the green image to colour the sphere")
        tinted = editor.settled("the image texture")
        save(tinted, output, "texture_2_image")
        open_texture_file(editor, tinted, corrupt, IMAGE_TEXTURE_BUTTON, IMAGE_TEXTURE_MENU_IMAGE)
        refused = x.wait_for(dialog_shown(tinted), "a message refusing the corrupt image")
        save(refused, output, "texture_3_refused")
        x.key("Escape")
        x.wait_for(matches(tinted), "the green sphere, unchanged by the refused image")
        close_window(x, editor)
        x.wait_for(dialog_shown(tinted), "the unsaved-changes prompt")
        x.key("n")
        assert editor.wait_exit() == 0
        assert "corrupt.png" in editor.output(), "the refusal should name the file:\n" + editor.output()
        print(f"ok: checker drew {edges_across_sphere(checker)} edges across the sphere, undone; "
              f"the image tinted it {pixel(tinted, *SPHERE_CENTRE)}; the corrupt image was refused")


def blue_sphere(shot):
    colour = pixel(shot, *SPHERE_CENTRE)
    return colour[2] > 60 and colour[2] > colour[0] + 30 and colour[2] > colour[1] + 30


def scenario_material_choice(x, glint, output, state):
    library = os.path.join(output, "two_paints.mtl")
    with open(library, "w") as out:
        out.write("newmtl green\nKd 0.1 0.8 0.1\nillum 1\n\nnewmtl blue\nKd 0.1 0.1 0.8\nillum 1\n")
    with LoggedEditor(x, glint, output, state) as editor:
        x.wait_for(lit_sphere, "the lit sphere (red plastic)")
        base = editor.settled("the first frames")  # before the modal dims it
        x.key("ctrl+o")
        type_path(editor, base, library)
        asked = x.wait_for(modal_shown(base), "the material question")
        save(asked, output, "material_choice_1_asked")
        time.sleep(0.3)
        x.key("Down")
        time.sleep(0.3)
        x.key("Return")
        chosen = x.wait_for(blue_sphere, "the second (blue) material on the sphere")
        save(chosen, output, "material_choice_2_blue")
        x.key("ctrl+z")
        x.wait_for(matches(base), "Ctrl+Z to take the material off again")
        x.key("ctrl+o")
        type_path(editor, base, library)
        x.wait_for(modal_shown(base), "the material question again")
        time.sleep(0.3)
        x.key("Escape")
        x.wait_for(matches(base), "Esc to change nothing")
        print("ok: two materials offered, the second applied and undone, Esc changed nothing")


def scenario_outside_reference(x, glint, output, state):
    """A glTF whose blue texture lies outside its folder: after the warning, the editor asks; Esc
    keeps it refused (the material comes without it), Allow once (O) opens the file again with it."""
    asset, outside = os.path.join(output, "asset"), os.path.join(output, "outside")
    os.makedirs(asset, exist_ok=True)
    os.makedirs(outside, exist_ok=True)
    write_png((4, 4, bytes([20, 40, 230] * 16)), os.path.join(outside, "blue.png"))
    gltf = os.path.join(asset, "blue.gltf")
    with open(gltf, "w") as out:
        json.dump({"asset": {"version": "2.0"}, "images": [{"uri": "../outside/blue.png"}], "textures": [{"source": 0}],
                   "materials": [{"name": "blue", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}}]}, out)

    def open_and_answer(key, name):
        before = editor.settled("the first frames")  # the screen without the file browser
        x.key("ctrl+o")
        type_path(editor, before, gltf)
        warned = x.wait_for(modal_shown(base), "the warning naming ../outside/blue.png")
        time.sleep(0.3)
        x.key("Escape")
        asked = x.wait_for(lambda shot: modal_shown(base)(shot) and region_difference(shot, warned, DIALOG_BOX) > 15,
                           "the question about ../outside/blue.png, after the warning")
        save(asked, output, name)
        time.sleep(0.3)
        x.key(key)

    with LoggedEditor(x, glint, output, state) as editor:
        x.wait_for(lit_sphere, "the lit sphere (red plastic)")
        base = editor.settled("the first frames")  # before the modal dims it
        open_and_answer("Escape", "outside_reference_1_asked")
        kept = x.wait_for(lambda shot: not modal_shown(base)(shot) and not lit_sphere(shot),
                          "Esc: the glTF's material without its refused texture")
        assert not blue_sphere(kept), "Esc should keep the texture refused"
        open_and_answer("o", "outside_reference_2_asked_again")
        allowed = x.wait_for(blue_sphere, "Allow once: the blue texture on the sphere")
        save(allowed, output, "outside_reference_3_allowed")
        print("ok: the outside texture was asked about, kept refused with Esc, read after Allow once")


def scenario_model_switch(x, glint, output, state):
    with LoggedEditor(x, glint, output, state) as editor:
        x.wait_for(lit_sphere, "the lit sphere (red plastic)")
        base = editor.settled("the first frames")
        x.click(*MODEL_COMBO)
        time.sleep(0.5)
        click_after_hover(x, MODEL_LAMBERT)

        def lambert_keeps_red(shot):
            centre, before = pixel(shot, *SPHERE_CENTRE), pixel(base, *SPHERE_CENTRE)
            highlight_gone = sum(pixel(shot, *HIGHLIGHT)) < sum(pixel(base, *HIGHLIGHT)) - 30
            # Lambert's default albedo is grey 0.5: a switch that reset the material would turn it grey.
            same_hue = abs(centre[1] / centre[0] - before[1] / before[0]) < 0.08
            return highlight_gone and lit_sphere(shot) and same_hue
        switched = x.wait_for(lambert_keeps_red, "a red Lambert sphere without the highlight")
        save(switched, output, "model_switch_1_lambert")
        x.move(625, 700)
        x.key("ctrl+z")
        x.wait_for(matches(base), "one Ctrl+Z to bring the Blinn-Phong material back")
        print("ok: Blinn-Phong → Lambert kept the red albedo, one Ctrl+Z undid the switch")


def scenario_shader_error(x, glint, output, state):
    shaders = os.path.join(output, "shaders")
    shutil.rmtree(shaders, ignore_errors=True)
    shutil.copytree(SHADER_DIR, shaders)
    shader = os.path.join(shaders, "brdf", "blinn_phong.glsl")
    with open(shader) as text:
        good = text.read()
    with LoggedEditor(x, glint, output, state, env={"GLINT_SHADER_DIR": shaders}) as editor:
        x.wait_for(lit_sphere, "the lit sphere")
        x.move(1200, 10)  # the menu bar's empty end
        base = editor.settled("the first frames")
        with open(shader, "w") as text:  # as a shader writer's editor saves it: no event reaches Glint
            text.write(good.replace("vec3 evalBlinnPhong(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {",
                                    "vec3 evalBlinnPhong(MaterialParams p, vec3 wi, vec3 wo, ShadingFrame frame) {\n"
                                    "    undefinedThing;", 1))
        wait_until(lambda: editor.running("the error") and "blinn_phong.glsl:6:" in editor.output(),
                   "the shader error naming blinn_phong.glsl:6 in the editor's output")
        assert not problem_text_shown(base, STATUS_BAR)
        broken = x.wait_for(lambda shot: problem_text_shown(shot, STATUS_BAR), "the error in the status bar")
        save(broken, output, "shader_error_1_shown")
        assert matches(base)(broken), "the last good program should keep drawing the sphere"
        assert problem_text_shown(broken, ERROR_IN_MATERIAL_PANEL), "the material panel should show the error"
        with open(shader, "w") as text:
            text.write(good)
        fixed = x.wait_for(lambda shot: not problem_text_shown(shot, STATUS_BAR), "the error to go once the shader compiles")
        assert not problem_text_shown(fixed, ERROR_IN_MATERIAL_PANEL)
        save(fixed, output, "shader_error_2_fixed")
        assert editor.output().count("blinn_phong.glsl:6:") == 1, "the error should be printed once, not each frame"
        print("ok: a broken shader saved while the editor ran was named in the status bar and the material panel; "
              "the sphere kept its last good program; the error went when the file compiled again")


def scenario_redraw_changes(x, glint, output, state):
    window = (0, 0, 1280, 800)
    editor = LoggedEditor(x, glint, output, state)
    try:
        base = x.wait_for(lit_sphere, "the lit sphere")
        x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]))
        x.wait_for(differs(base), "the sphere to change after the slider drag")
        rest = (1200, 10)  # off the slider (its tooltip follows the pointer), onto the menu bar's empty end
        x.move(*rest)
        events = editor.wait_idle("the slider's release and the pointer's move", pointer=rest)
        drawn = x.screenshot()
        x.run("xdotool", "windowunmap", "--sync", editor.window)
        x.run("xdotool", "windowmap", "--sync", editor.window)
        editor.wait_idle("the window mapped again", after=events)
        whole = x.screenshot()
        save(drawn, output, "redraw_changes_1_drawn")
        save(whole, output, "redraw_changes_2_whole")
        difference = region_difference(drawn, whole, window, step=1)
        assert difference == 0, f"the frame drawn in changed parts differs from the whole frame by {difference:.4f} on average"
        print("ok: after a slider drag the window equals the frame drawn whole")
    finally:
        editor.stop()


if __name__ == "__main__":
    run_scenario_from_arguments(globals())
