"""The editor under the monkey: starts it with its output in a file (its frame log and any
sanitizer report), tells a crash, a sanitizer or Dear ImGui report and a hang apart, kills it
with SIGKILL and checks that the next start recovers exactly the last autosave. Sends no random
input (monkey_test.py does)."""
import glob
import json
import os
import signal
import subprocess
import time

# What a report in the editor's output starts with: AddressSanitizer, LeakSanitizer,
# UndefinedBehaviorSanitizer (halting: the build uses -fno-sanitize-recover), Dear ImGui's
# IM_ASSERT (assert(): "Assertion `…' failed") and Glint's own GLINT_CHECK.
REPORT_MARKERS = ("ERROR: AddressSanitizer", "ERROR: LeakSanitizer", "runtime error:", "Assertion `", "GLINT_CHECK")
NUDGE_SECONDS = 10.0  # between two pointer moves while waiting for a frame
# Lines the editor prints for every frame with GLINT_LOG_FRAMES=1 (app/editor/editor.cpp).
FRAME_MARKERS = (b"glint frame:", b"glint ui frame:", b"glint programs:")


class MonkeyFailure(AssertionError):
    """What the monkey found: a crash, a report, a hang or a lost edit."""


class MonkeyEditor:
    """One editor process at a time (restarted after each kill or quit) in the X server `x`."""

    def __init__(self, x, glint, output, state, env):
        self.x, self.glint, self.output, self.state, self.env = x, glint, output, state, env
        self.process = None
        self.window = None
        self.last_geometry = (0, 0, 1280, 800)
        self.log_path = None
        self.starts = 0
        self.late_frames = 0  # frames that came only after a second pointer move

    # --- lifecycle ------------------------------------------------------------------------------

    def start(self, timeout=120.0, attempts=2):
        """Starts the editor and waits for its window. An editor that cannot open a window renders
        headless and exits (seen once in a while on a loaded machine): it is started again."""
        for _ in range(attempts):
            self.starts += 1
            self.log_path = os.path.join(self.output, f"editor-{self.starts}.log")
            with open(self.log_path, "wb") as log:
                self.process = subprocess.Popen([self.glint], env=self.env, cwd=self.output, stdout=log,
                                                stderr=subprocess.STDOUT)
            deadline = time.time() + timeout
            while time.time() < deadline:
                # Visible only: the background compiler's hidden "glint worker" window matches too.
                found = self.x.run("xdotool", "search", "--onlyvisible", "--name", "^Glint", check=False).stdout.split()
                if found:
                    self.window = found[0]
                    return
                if not self.check_alive("starting"):
                    break  # rendered headless and exited: once more
                time.sleep(0.2)
        raise MonkeyFailure(f"no editor window within {timeout:.0f} s of start {self.starts} ({attempts} attempts)\n"
                            f"  output: {self.log_path}")

    def geometry(self):
        """(x, y, width, height) of the editor's window on the screen; the last one seen once the
        window is gone (the editor quit: the next check_alive says so)."""
        shell = self.x.run("xdotool", "getwindowgeometry", "--shell", self.window, check=False).stdout.split()
        values = dict(line.split("=") for line in shell)
        if all(key in values for key in ("X", "Y", "WIDTH", "HEIGHT")):
            self.last_geometry = int(values["X"]), int(values["Y"]), int(values["WIDTH"]), int(values["HEIGHT"])
        return self.last_geometry

    def log_text(self):
        with open(self.log_path, "rb") as log:
            return log.read().decode("utf-8", "replace")

    def reports(self):
        """Lines of the output that start a sanitizer, ImGui or GLINT_CHECK report."""
        return [line for line in self.log_text().splitlines() if any(m in line for m in REPORT_MARKERS)]

    def check_alive(self, during):
        """Raises when the editor ended by a signal or an error, or printed a report; returns
        True when it is running, False when it quit cleanly (exit 0, nothing reported)."""
        code = self.process.poll()
        found = self.reports()
        if found and code is None:  # let it finish its report (and its crash guard, its core dump)
            try:
                code = self.process.wait(timeout=60)
            except subprocess.TimeoutExpired:
                pass
            found = self.reports()
        if found or (code is not None and code != 0):
            how = "running" if code is None else (f"killed by signal {-code}" if code < 0 else f"exit status {code}")
            raise MonkeyFailure(f"editor start {self.starts} ({how}) during {during}: "
                                f"{found[0] if found else 'no report in its output'}\n  output: {self.log_path}")
        return code is None

    def frames(self):
        with open(self.log_path, "rb") as log:
            text = log.read()
        return sum(text.count(marker) for marker in FRAME_MARKERS)

    def wait_for_frame(self, during, timeout):
        """Moves the pointer within the window and waits for the frame it causes: a hang is an
        editor that draws nothing for `timeout` seconds. The pointer moves again every
        NUDGE_SECONDS: an editor that answers only a later move missed a wake-up (counted in
        late_frames), which is not a hang."""
        before = self.frames()
        deadline = time.time() + timeout
        nudges = 0
        while time.time() < deadline:
            left, top, width, height = self.geometry()
            x = left + 2 if self.pointer() != (left + 2, top + height - 2) else left + 3
            self.x.run("xdotool", "mousemove", str(x), str(top + height - 2), check=False)
            nudges += 1
            next_nudge = time.time() + NUDGE_SECONDS
            while time.time() < min(next_nudge, deadline):
                if not self.check_alive(during) or self.frames() > before:
                    self.late_frames += nudges > 1
                    return
                time.sleep(0.1)
        raise MonkeyFailure(f"hang: editor start {self.starts} drew no frame for {timeout:.0f} s after {during} "
                            f"({nudges} pointer moves; window {self.geometry()}, pointer {self.pointer()})\n"
                            f"  output: {self.log_path}\n  its threads: {self.write_stacks()}")

    def write_stacks(self):
        """Writes the stacks of the editor's threads (gdb, where installed) beside its output."""
        path = self.log_path.replace(".log", "-stacks.txt")
        try:
            with open(path, "w") as out:
                subprocess.run(["gdb", "-p", str(self.process.pid), "-batch", "-ex", "thread apply all bt 30"],
                               stdout=out, stderr=subprocess.STDOUT, timeout=120, check=False)
        except (OSError, subprocess.TimeoutExpired) as error:
            return f"not written ({error})"
        return path

    def pointer(self):
        """Where the pointer is; None when xdotool cannot say (it failed once in a long run)."""
        shell = self.x.run("xdotool", "getmouselocation", "--shell", check=False).stdout.split()
        values = dict(line.split("=") for line in shell if "=" in line)
        return (int(values["X"]), int(values["Y"])) if "X" in values and "Y" in values else None

    def close(self, close_tool):
        """A clean exit (the window's close request, "don't save"), so that LeakSanitizer runs;
        an editor that does not go within a minute is killed and its leaks are left unchecked."""
        if self.process.poll() is None:
            for _ in range(3):
                self.x.run("xdotool", "key", "Escape", check=False)
                time.sleep(0.3)
            subprocess.run([close_tool, self.window], env=self.x.env, check=False)
            deadline = time.time() + 60
            while self.process.poll() is None and time.time() < deadline:
                time.sleep(1.0)
                self.x.run("xdotool", "key", "n", check=False)  # the unsaved-changes prompt: don't save
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
            return False
        self.check_alive("the closing exit")
        return True

    # --- kill -9 and recovery -------------------------------------------------------------------

    def orphaned_recovery(self):
        """The recovery file the next start offers first (the newest not held by a running
        editor), or None."""
        running = f"recovery-{self.process.pid}.json" if self.process and self.process.poll() is None else None
        files = [path for path in glob.glob(os.path.join(self.state, "recovery*.json"))
                 if os.path.basename(path) != running]
        return max(files, key=os.path.getmtime) if files else None

    def kill_and_recover(self, during, hang_seconds, after_failure=False):
        """kill -9 (unless it ended already after a failure), restart, accept the recovery offer
        (Enter) and compare the scene the new editor autosaves with the last autosave (or crash
        copy) before the end. Returns what was recovered (a line)."""
        if not after_failure:
            self.check_alive(during)
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGKILL)
        self.process.wait()
        expected_path = self.orphaned_recovery()
        expected = _read_json(expected_path) if expected_path else None
        self.start()
        if expected is None:
            self.wait_for_frame("the restart after a kill with nothing to recover", hang_seconds)
            return "nothing to recover"
        mine = os.path.join(self.state, f"recovery-{self.process.pid}.json")
        deadline = time.time() + hang_seconds
        while os.path.exists(expected_path) or not os.path.exists(mine):  # accepted: renamed to this editor's
            if time.time() > deadline:
                raise MonkeyFailure(f"the restart did not offer or take the recovery file {expected_path} "
                                    f"within {hang_seconds:.0f} s\n  output: {self.log_path}")
            self.check_alive("the recovery offer")
            self.x.run("xdotool", "key", "Return", check=False)
            time.sleep(1.0)
        taken = os.stat(mine).st_ino
        while os.path.exists(mine) and os.stat(mine).st_ino == taken:  # autosave writes it afresh
            if time.time() > deadline:
                raise MonkeyFailure(f"the recovered editor did not autosave within {hang_seconds:.0f} s")
            self.check_alive("the autosave after recovery")
            time.sleep(0.2)
        held = _read_json(mine)
        if held is None or not _same(held["scene"], expected["scene"]) or held["scene_path"] != expected["scene_path"]:
            raise MonkeyFailure(f"lost edit: the recovered scene differs from the last autosave before the kill\n"
                                f"  before the kill: {expected_path}\n  after recovery: {mine}\n"
                                f"  {_first_difference(expected, held)}")
        scene = expected["scene"]
        return (f"recovered {len(scene.get('objects', []))} objects, {len(scene.get('lights', []))} lights "
                f"from {os.path.basename(expected_path)}")


def _read_json(path):
    try:
        with open(path) as source:
            return json.load(source)
    except (OSError, ValueError):
        return None


def _same(a, b):
    """JSON equality, numbers within float32 rounding: the scene holds floats, and a value the
    writer derives in double (a light's normalised direction) is read back rounded to float."""
    if isinstance(a, bool) or isinstance(b, bool):
        return a is b
    if isinstance(a, (int, float)) and isinstance(b, (int, float)):
        return abs(a - b) <= 1e-6 * max(1.0, abs(a), abs(b))
    if isinstance(a, dict) and isinstance(b, dict):
        return a.keys() == b.keys() and all(_same(a[key], b[key]) for key in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(_same(p, q) for p, q in zip(a, b))
    return a == b


def _first_difference(a, b, where="$"):
    if type(a) is not type(b):
        return f"{where}: {json.dumps(a)[:200]} became {json.dumps(b)[:200]}"
    if isinstance(a, dict):
        for key in sorted(set(a) | set(b)):
            if not _same(a.get(key), b.get(key)):
                return _first_difference(a.get(key), b.get(key), f"{where}.{key}")
    if isinstance(a, list) and len(a) == len(b):
        for i, (p, q) in enumerate(zip(a, b)):
            if not _same(p, q):
                return _first_difference(p, q, f"{where}[{i}]")
    return f"{where}: {json.dumps(a)[:200]} became {json.dumps(b)[:200]}"
