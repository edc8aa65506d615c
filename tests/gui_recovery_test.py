"""GUI tests of the recovery offer in every way the editor starts, under Xvfb. Each scenario
leaves an ended editor's work in the state folder (its recovery file, its lock file and a
half-written crash copy), starts Glint and answers the offer; the leftovers beside the work go at
start. One scenario per ctest entry:
  present_recover  `glint present LIST`: Enter recovers (the title names the recovered scene;
                   Ctrl+S writes the recovered scene to its file)
  present_discard  `glint present LIST`: Delete discards (lesson 1 stays, the recovery file goes)
  editor_recover   `glint`: Enter recovers, as above
  file_discard     `glint FILE`: Delete discards (FILE stays open, unchanged; the recovery file goes)
  corrupt_file     `glint BROKEN`: the offer comes first, alone; once Enter recovers, the error
                   naming BROKEN's line follows, and the recovered scene stays
usage: gui_recovery_test.py GLINT OUTPUT_DIR SCENARIO"""
import glob
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, run_scenario_from_arguments, wait_until  # noqa: E402

TESTS = os.path.dirname(os.path.abspath(__file__))
LESSONS = os.path.join(TESTS, "..", "lessons", "lessons.json")
RECOVERED_SCENE = os.path.join(TESTS, "scenes", "editor_classic.json")  # two lights: key and fill
OFFER = "Recover unsaved work"


def leave_ended_editors_work(state, output):
    """The files an editor killed after an autosave leaves; returns (recovery file, leftovers)."""
    os.makedirs(state, exist_ok=True)
    ended = subprocess.Popen(["true"])
    ended.wait()  # its id belongs to no running editor
    stem = os.path.join(state, f"recovery-{ended.pid}")
    with open(RECOVERED_SCENE) as file:
        scene = json.load(file)
    document = {"format": "glint-recovery", "version": 1, "scene_path": os.path.join(output, "recovered.json"), "scene": scene}
    with open(stem + ".json", "w") as file:
        json.dump(document, file)
    leftovers = [stem + ".lock", stem + ".json.crash"]
    for path in leftovers:
        with open(path, "w") as file:
            file.write('{"format": ')
    return stem + ".json", leftovers


def offered(x, glint, output, state, arguments):
    """Starts Glint with an ended editor's work waiting; returns the editor, the recovery file and
    the settled layout showing the offer."""
    recovery, leftovers = leave_ended_editors_work(state, output)
    editor = LoggedEditor(x, glint, output, state, arguments, env={"GLINT_LESSONS": LESSONS})
    layout = editor.settled_layout(lambda l: OFFER in l["window"], "the offer to recover the unsaved work")
    left = [path for path in leftovers if os.path.exists(path)]
    assert not left, f"the ended editor's leftovers are still there: {left}"
    return editor, recovery, layout


def editor_files(state):
    return sorted(os.path.basename(p) for p in glob.glob(os.path.join(state, "recovery*")))


def quit_cleanly(x, editor, state):
    x.key("ctrl+q")
    code = editor.wait_exit()
    assert code == 0, f"the editor exited with {code}"
    assert not editor_files(state), f"a clean exit left {editor_files(state)}"


def recover(x, glint, output, state, arguments):
    saved = os.path.join(output, "recovered.json")
    if os.path.exists(saved):
        os.remove(saved)  # an earlier run's
    editor, _, _ = offered(x, glint, output, state, arguments)
    try:
        x.key("Return")
        editor.wait_layout(lambda l: OFFER not in l["window"], "the offer to close (Enter)")
        title = editor.wait_for_title("recovered.json ●")
        x.key("ctrl+s")  # the recovered scene keeps the path it belongs to
        wait_until(lambda: os.path.exists(saved), f"Ctrl+S to write {saved}")
        with open(saved) as file:
            lights = [light["name"] for light in json.load(file)["lights"]]
        assert lights == ["key", "fill"], f"the saved scene is not the recovered one: its lights are {lights}"
        editor.wait_for_title("recovered.json")
        quit_cleanly(x, editor, state)
    finally:
        editor.stop()
    print(f"ok: {' '.join(arguments) or 'the editor'} offered the ended editor's work; Enter recovered it "
          f"({title!r}), Ctrl+S saved it; the stale lock and crash copy went at start")


def discard(x, glint, output, state, arguments, expected_title):
    editor, recovery, _ = offered(x, glint, output, state, arguments)
    try:
        x.key("Delete")
        editor.wait_layout(lambda l: OFFER not in l["window"], "the offer to close (Delete)")
        wait_until(lambda: not os.path.exists(recovery), f"Discard to remove {recovery}")
        title = editor.wait_for_title(expected_title)
        assert "●" not in title, f"discarding changed the scene: {title!r}"
        quit_cleanly(x, editor, state)
    finally:
        editor.stop()
    print(f"ok: {' '.join(arguments)} offered the ended editor's work; Delete discarded it and {title!r} stayed")


def scenario_present_recover(x, glint, output, state):
    recover(x, glint, output, state, ["present", LESSONS])


def scenario_present_discard(x, glint, output, state):
    discard(x, glint, output, state, ["present", LESSONS], "Lesson 1 —")


def scenario_editor_recover(x, glint, output, state):
    recover(x, glint, output, state, [])


def scenario_file_discard(x, glint, output, state):
    opened = os.path.join(output, "opened.json")
    shutil.copy(RECOVERED_SCENE, opened)
    before = open(opened, "rb").read()
    discard(x, glint, output, state, [opened], "opened.json")
    assert open(opened, "rb").read() == before, "the opened file changed"


def scenario_corrupt_file(x, glint, output, state):
    broken = os.path.join(output, "broken.json")
    with open(broken, "w") as file:
        file.write('{\n  "format": "glint-scene",\n  "version": 1,\n  "lights": [{"type": "point", "power": -5}]\n}\n')
    editor, _, layout = offered(x, glint, output, state, [broken])
    try:
        assert "Error" not in layout["window"], "the error shows beside the recovery offer"
        x.key("Return")
        layout = editor.wait_layout(lambda l: "Error" in l["window"], "the error about the broken file after the offer")
        assert OFFER not in layout["window"], "the offer and the error show at once"
        said = editor.output()
        assert "broken.json:4" in said, f"the error does not name broken.json's line 4: {said[-400:]!r}"
        x.key("Return")  # OK
        editor.wait_layout(lambda l: "Error" not in l["window"], "the error to close (Enter)")
        title = editor.wait_for_title("recovered.json ●")
    finally:
        editor.stop()
    print(f"ok: the offer came first; after Enter recovered ({title!r}) the error named broken.json:4")


if __name__ == "__main__":
    run_scenario_from_arguments(globals(), 1024, 768)
