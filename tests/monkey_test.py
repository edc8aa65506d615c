"""The monkey soak: the editor under Xvfb receiving a seeded stream of random input (see
monkey_events.py), killed with SIGKILL at random moments and restarted, each restart's recovered
scene checked against the last autosave. Fails on a crash, a sanitizer or Dear ImGui report, a
hang or a lost edit, naming the seed and the event; OUTPUT/SEED/events.log holds every event.

usage: monkey_test.py GLINT OUTPUT (--seed N [--events N] [--kills N] [--until I] | --seeds FILE)
  --until I      replays a run's events up to event I only (the failing one)
  --keep-going   logs a failure, starts the editor again and goes on (a long run's count)
  --seeds FILE   one run per line "SEED EVENTS KILLS [UNTIL]  # why it is kept" (tests/monkey_seeds.txt)
Environment: GLINT_X11_CLOSE and GLINT_X11_DROP name tests/tools' x11_close_window and
x11_drop_file. Started as root, the editor runs as nobody: a random Save as can then write only
under OUTPUT."""
import argparse
import glob
import json
import os
import shutil
import signal
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import XServer  # noqa: E402
from monkey_editor import MonkeyEditor, MonkeyFailure  # noqa: E402
from monkey_events import LARGEST_WINDOW, generate  # noqa: E402

TESTS = os.path.dirname(os.path.abspath(__file__))
REPOSITORY = os.path.dirname(TESTS)
MESH_EXTENSIONS = (".obj", ".ply", ".stl", ".gltf", ".glb", ".fbx")
HANG_SECONDS = 90.0  # a frame of the sanitizer build on a busy machine takes a few seconds at most
PROBE_EVERY = 25     # events between two checks that the editor still draws frames


# --- the files a hand opens: tests/files, tests/scenes and damaged copies -------------------------

def damaged_copies(folder):
    """Broken files of the kinds the editor opens, written into `folder` (the same every run)."""
    os.makedirs(folder, exist_ok=True)
    sources = {"scene.json": os.path.join(TESTS, "scenes", "shapes.json"),
               "mesh.obj": os.path.join(TESTS, "files", "obj", "cube.obj"),
               "box.gltf": os.path.join(TESTS, "files", "gltf", "Box.gltf"),
               "material.mtl": os.path.join(TESTS, "files", "mtl", "blender_empty_newmtl.mtl"),
               "lambert.brdf": os.path.join(TESTS, "files", "brdf", "lambert.brdf")}
    for name, source in sources.items():
        with open(source, "rb") as original:
            data = original.read()
        stem, extension = os.path.splitext(name)
        with open(os.path.join(folder, f"{stem}_half{extension}"), "wb") as out:
            out.write(data[:len(data) // 2])
        with open(os.path.join(folder, f"{stem}_flipped{extension}"), "wb") as out:
            out.write(bytes(b ^ 0x5A if i % 7 == 3 else b for i, b in enumerate(data)))
        with open(os.path.join(folder, f"{stem}_empty{extension}"), "wb"):
            pass
    with open(os.path.join(folder, "scene_wrong_types.json"), "w") as out:
        json.dump({"format": "glint-scene", "version": 1, "lights": "many", "objects": [{"material": -3}],
                   "camera": {"fov": "wide"}}, out)


def prepare_files(folder):
    """Copies the files the monkey opens into `folder` (a save over one harms no source file);
    returns (all files, meshes) as sorted paths relative to `folder`."""
    shutil.rmtree(folder, ignore_errors=True)
    shutil.copytree(os.path.join(TESTS, "files"), os.path.join(folder, "files"))
    shutil.copytree(os.path.join(TESTS, "scenes"), os.path.join(folder, "scenes"))
    damaged_copies(os.path.join(folder, "damaged"))
    files = sorted(os.path.relpath(os.path.join(root, name), folder)
                   for root, _, names in os.walk(folder) for name in names
                   if not name.startswith(("LICENSE", "README")))
    return files, [f for f in files if f.endswith(MESH_EXTENSIONS)]


# --- one event -------------------------------------------------------------------------------------

class Hand:
    """Runs events on the editor's window through xdotool (and x11_drop_file)."""

    def __init__(self, x, editor, files_folder, drop_tool):
        self.x, self.editor, self.files_folder, self.drop_tool = x, editor, files_folder, drop_tool

    def at(self, fraction):
        left, top, width, height = self.window
        return (left + min(width - 1, int(fraction[0] * width)), top + min(height - 1, int(fraction[1] * height)))

    def xdotool(self, *args):
        self.x.run("xdotool", *(str(a) for a in args), check=False)

    def path_into_browser(self, shortcut, name):
        """Ctrl+O / Ctrl+M, then the file browser's path field: replace its text and confirm."""
        self.xdotool("key", shortcut)
        time.sleep(0.4)
        self.xdotool("key", "ctrl+a")
        self.xdotool("type", "--delay", "5", "--", os.path.join(self.files_folder, name))
        self.xdotool("key", "Return")

    def drop(self, name, where):
        subprocess.run([self.drop_tool, self.editor.window, os.path.join(self.files_folder, name), *map(str, where)],
                       env=self.x.env, check=False, capture_output=True, timeout=30)

    def run(self, event):
        kind = event["kind"]
        self.window = self.editor.geometry()  # where the window is now (resizes, F11, restarts move it)
        if kind == "click":
            x, y = self.at(event["at"])
            modifiers = ["keydown", "shift"] if event["shift"] else []
            if modifiers:
                self.xdotool(*modifiers)
            self.xdotool("mousemove", x, y, "click", "--repeat", 2 if event["double"] else 1, event["button"])
            if modifiers:
                self.xdotool("keyup", "shift")
        elif kind in ("drag", "drop_mid_drag"):
            (x0, y0), (x1, y1) = self.at(event["from"]), self.at(event["to"])
            steps = event["steps"]
            moves = [["mousemove", x0 + (x1 - x0) * step // steps, y0 + (y1 - y0) * step // steps, "sleep", 0.02]
                     for step in range(1, steps + 1)]
            half = steps // 2 if kind == "drop_mid_drag" else steps  # the file is dropped half way
            self.xdotool("mousemove", x0, y0, "mousedown", event["button"], *sum(moves[:half], []))
            if kind == "drop_mid_drag":
                self.drop(event["file"], (x1, y1))
            self.xdotool(*sum(moves[half:], []), "mouseup", event["button"])
        elif kind == "wheel":
            x, y = self.at(event["at"])
            self.xdotool("mousemove", x, y, "click", "--repeat", event["clicks"], event["button"])
        elif kind == "key":
            self.xdotool("key", "--delay", "60", event["key"])
        elif kind == "type":
            self.xdotool("type", "--delay", "15", "--", event["text"])
        elif kind == "undo_storm":
            self.xdotool("key", "--delay", "40", *["ctrl+z"] * event["undo"], *["ctrl+shift+z"] * event["redo"])
        elif kind == "open_file":
            self.path_into_browser("ctrl+o", event["file"])
        elif kind == "open_mesh":
            self.path_into_browser("ctrl+m", event["file"])
        elif kind == "drop_file":
            self.drop(event["file"], self.at(event["at"]))
        elif kind == "resize":
            self.xdotool("windowsize", self.editor.window, *event["size"])
        else:
            raise ValueError(f"unknown event kind {kind}")


# --- a run -------------------------------------------------------------------------------------------

def editor_environment(x, state, home):
    """Sanitizers halt and report; a quick autosave (the kills test it); the frame log tells a
    hang; settings and recovery files in the run's own folder. Mesa's GLX driver is preloaded:
    GLFW unloads it at exit, before LeakSanitizer runs, which would leave its allocations
    nameless and so beyond tests/sanitizer/lsan.supp. AddressSanitizer keeps SIGSEGV: the
    editor's crash guard (editor/crash_guard.h) would take it over, write its copy and die of the
    signal with no report of where the fault was."""
    drivers = glob.glob("/usr/lib/*/dri/swrast_dri.so")
    return dict(x.env, GLINT_STATE_DIR=state, HOME=home, XDG_STATE_HOME=home, GLINT_AUTOSAVE_SECONDS="1",
                GLINT_LOG_FRAMES="1", LP_NUM_THREADS="2", LD_PRELOAD=":".join(drivers[:1]),
                ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:handle_abort=1:allow_user_segv_handler=0",
                LSAN_OPTIONS="suppressions=" + os.path.join(TESTS, "sanitizer", "lsan.supp"),
                UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1")


def as_nobody_when_root(glint, folder):
    """The command that starts the editor; as root, the editor is nobody, who can write only
    `folder` (made writable for it)."""
    if os.geteuid() != 0:
        return glint
    for root, directories, names in os.walk(folder):
        os.chmod(root, 0o777)
        for name in names:
            os.chmod(os.path.join(root, name), 0o666)
    wrapper = os.path.join(folder, "glint-as-nobody")
    with open(wrapper, "w") as out:
        out.write(f"#!/bin/sh\nexec setpriv --reuid=65534 --regid=65534 --clear-groups {glint} \"$@\"\n")
    os.chmod(wrapper, 0o755)
    return wrapper


def run_seed(glint, output, seed, count, kills, until=None, keep_going=False):
    """Runs one seed's events (those up to `until` only, when given); returns a summary line, or
    raises MonkeyFailure naming the event. With keep_going, a failure is logged and the editor
    started again (its work recovered), and the summary counts the failures."""
    folder = os.path.join(output, f"seed-{seed}")
    shutil.rmtree(folder, ignore_errors=True)
    state, home = os.path.join(folder, "state"), os.path.join(folder, "home")
    for made in (state, home):
        os.makedirs(made)
    files, meshes = prepare_files(os.path.join(folder, "open"))
    events = generate(seed, count, kills, files, meshes)[:None if until is None else until + 1]
    started = time.time()
    recoveries, clean_exits, failures = [], 0, []
    with XServer(*LARGEST_WINDOW) as x, open(os.path.join(folder, "events.log"), "w") as log:
        print(f"monkey: seed {seed}, {count} events, {kills} kills; log {log.name}", flush=True)
        log.write(json.dumps({"seed": seed, "events": count, "kills": kills}) + "\n")
        command = as_nobody_when_root(glint, folder)
        editor = MonkeyEditor(x, command, folder, state, editor_environment(x, state, home))
        hand = Hand(x, editor, os.path.join(folder, "open"), os.environ["GLINT_X11_DROP"])
        event = {"i": -1}  # before the first event
        try:
            editor.start()
            editor.wait_for_frame("the first start", HANG_SECONDS)
            for event in events:
                log.write(json.dumps({**event, "t": round(time.time() - started, 2)}) + "\n")
                log.flush()
                during = f"event {event['i']} ({event['kind']})"
                try:
                    if not editor.check_alive(during):  # quit cleanly (Ctrl+Q, "don't save"): start again
                        clean_exits += 1
                        editor.start()
                        editor.wait_for_frame(f"the restart before {during}", HANG_SECONDS)
                    if event["kind"] == "kill":
                        time.sleep(event["pause"])
                        recovered = editor.kill_and_recover(during, HANG_SECONDS)
                        recoveries.append(recovered)
                        log.write(json.dumps({"i": event["i"], "recovery": recovered}) + "\n")
                        continue
                    hand.run(event)
                    time.sleep(event["pause"])
                    if event["i"] % PROBE_EVERY == PROBE_EVERY - 1:
                        editor.wait_for_frame(during, HANG_SECONDS)
                except MonkeyFailure as failure:
                    if not keep_going:
                        raise
                    failures.append(f"event {event['i']}: {failure}")
                    print(f"monkey: seed {seed}: {failures[-1]}", flush=True)
                    log.write(json.dumps({"i": event["i"], "failure": str(failure)}) + "\n")
                    editor.kill_and_recover(during, HANG_SECONDS, after_failure=True)
            editor.wait_for_frame("the last event", HANG_SECONDS)
            closed = editor.close(os.environ["GLINT_X11_CLOSE"])
        except MonkeyFailure as failure:
            log.write(json.dumps({"failure": str(failure)}) + "\n")
            raise MonkeyFailure(f"seed {seed}: {failure}\n  events: {log.name} (replay: --seed {seed} --events "
                                f"{count} --kills {kills} --until {event['i']})") from None
        finally:
            if editor.process and editor.process.poll() is None:
                editor.process.kill()
    minutes = (time.time() - started) / 60
    if failures:
        raise MonkeyFailure(f"seed {seed}: {len(failures)} failures in {len(events)} events ({minutes:.1f} min):\n  "
                            + "\n  ".join(failures))
    return (f"ok: seed {seed}: {len(events)} events, {len(recoveries)} kills each recovered exactly "
            f"({sum(r != 'nothing to recover' for r in recoveries)} with unsaved work), {clean_exits} quits, "
            f"{editor.starts} starts, 0 crashes, 0 sanitizer reports, 0 hangs ({editor.late_frames} frames came only "
            f"after a second pointer move), "
            f"{'leaks checked at the last exit' if closed else 'last exit not clean (leaks unchecked)'}; "
            f"{minutes:.1f} min")


def seeds_from_file(path):
    runs = []
    with open(path) as listing:
        for line in listing:
            fields = line.split("#", 1)[0].split()
            if fields:
                runs.append(tuple(int(f) for f in fields))
    return runs


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("glint")
    parser.add_argument("output")
    parser.add_argument("--seed", type=int)
    parser.add_argument("--events", type=int, default=10000)
    parser.add_argument("--kills", type=int, default=20)
    parser.add_argument("--until", type=int)
    parser.add_argument("--keep-going", action="store_true", help="after a failure, log it and go on")
    parser.add_argument("--seeds")
    arguments = parser.parse_args()
    if (arguments.seed is None) == (arguments.seeds is None):
        parser.error("give --seed or --seeds")
    runs = (seeds_from_file(arguments.seeds) if arguments.seeds
            else [(arguments.seed, arguments.events, arguments.kills, arguments.until, arguments.keep_going)])
    os.makedirs(arguments.output, exist_ok=True)
    for run in runs:
        print(run_seed(os.path.abspath(arguments.glint), os.path.abspath(arguments.output), *run), flush=True)


if __name__ == "__main__":
    # ctest's timeout and Ctrl+C end the run through the same clean-up as a failure (the editor
    # killed, Xvfb stopped).
    signal.signal(signal.SIGTERM, lambda *_: sys.exit("monkey: terminated"))
    try:
        main()
    except MonkeyFailure as failure:
        print(f"monkey: FAILED {failure}", flush=True)
        sys.exit(1)
