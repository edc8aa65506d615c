"""Helpers for GUI tests: a private Xvfb server, the editor's window, real input through
xdotool, and screenshots read from xwd's format (standard library only; run with
/usr/bin/python3). Nothing here knows about Glint's panels."""
import os
import struct
import subprocess
import time
import zlib


# How long a wait may take before it fails. Every wait returns as soon as the state it needs is
# there, so this only bounds a failure: generous, as a machine running other work (load average
# 5-7 on two cores) may take seconds for what takes milliseconds on an idle one.
WAIT_SECONDS = 90.0


def wait_until(check, what, timeout=WAIT_SECONDS, interval=0.25):
    """Polls check() until it returns something true and returns that; raises naming `what` (a
    string, or a function giving one that can say what was seen instead)."""
    deadline = time.time() + timeout
    while True:
        value = check()
        if value:
            return value
        if time.time() >= deadline:
            raise AssertionError(f"timed out after {timeout:.0f} s waiting for {what() if callable(what) else what}")
        time.sleep(interval)


def read_text(path):
    with open(path, errors="replace") as text:
        return text.read()


class EditorExited(RuntimeError):
    """The editor process ended before its window appeared."""


class XServer:
    """An Xvfb server on a free display number, stopped on exit."""

    def __init__(self, width=1280, height=800):
        read_end, write_end = os.pipe()
        self.process = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_end), "-screen", "0", f"{width}x{height}x24", "-nolisten", "tcp"],
            pass_fds=[write_end], stderr=subprocess.DEVNULL)
        os.close(write_end)
        with os.fdopen(read_end) as reader:
            number = reader.readline().strip()
        if not number:
            raise RuntimeError("Xvfb did not start")
        self.display = ":" + number
        self.env = dict(os.environ, DISPLAY=self.display)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.process.terminate()
        self.process.wait(timeout=10)

    def run(self, *args, check=True):
        return subprocess.run(list(args), env=self.env, check=check, capture_output=True, text=True)

    def find_window(self, name, timeout=WAIT_SECONDS, process=None):
        """The id of the first window named `name`; raises EditorExited when `process` ends first."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            found = self.run("xdotool", "search", "--name", name, check=False).stdout.split()
            if found:
                return found[0]
            if process is not None and process.poll() is not None:
                said = process.communicate()[0] or ""  # empty where the output goes to a file
                raise EditorExited(f"exit status {process.returncode}; its output:\n{said[-2000:]}")
            time.sleep(0.2)
        raise RuntimeError(f"no window named {name!r} appeared in {timeout} s")

    def start_editor(self, command, env, cwd, log_path=None, attempts=2):
        """Starts the editor (command = [glint, arguments…]) with its output in a pipe
        (process.stdout) or in the file log_path, and waits for its window; returns (process, window).
        An editor that cannot open a window renders headless and exits (seen once in a while on a
        loaded machine): it is started once more, and what it printed is shown either way."""
        for attempt in range(1, attempts + 1):
            output = open(log_path, "w") if log_path else subprocess.PIPE
            process = subprocess.Popen(command, env=env, cwd=cwd, stdout=output, stderr=subprocess.STDOUT, text=True)
            if log_path:
                output.close()  # the editor holds its own copy
            try:
                return process, self.find_window("Glint", process=process)
            except EditorExited as exited:
                said = read_text(log_path)[-2000:] if log_path else ""
                print(f"the editor exited before showing a window (attempt {attempt}): {exited}{said}", flush=True)
        raise RuntimeError(f"the editor did not open a window in {attempts} attempts")

    # --- real input through xdotool ------------------------------------------------------------

    def move(self, x, y):
        """Moves the pointer to (x, y) and waits until it is there. A --sync move to where the
        pointer already is would wait for motion that never comes (until xdotool gives up)."""
        here = self.run("xdotool", "getmouselocation", "--shell").stdout.split()
        if f"X={int(x)}" in here and f"Y={int(y)}" in here:
            return
        self.run("xdotool", "mousemove", "--sync", str(int(x)), str(int(y)))

    def click(self, x, y, button=1):
        self.move(x, y)
        time.sleep(0.05)
        self.run("xdotool", "click", str(button))

    def drag(self, start, end, button=1, steps=12, step_seconds=0.03):
        """Presses at start, moves in steps (the application sees motion events), releases at end."""
        self.move(*start)
        time.sleep(0.1)
        self.run("xdotool", "mousedown", str(button))
        for i in range(1, steps + 1):
            x = start[0] + (end[0] - start[0]) * i // steps
            y = start[1] + (end[1] - start[1]) * i // steps
            self.move(x, y)
            time.sleep(step_seconds)
        time.sleep(0.1)
        self.run("xdotool", "mouseup", str(button))

    def key(self, *keys, hold_seconds=0.15):
        """Presses keys such as "ctrl+z" or "Return" (xdotool names), one after another, holding
        each chord for hold_seconds so applications that sample key state per frame see it. A key
        that closes the window (Ctrl+Q, "Don't save") may leave its release no window to go to:
        a release that fails is no error."""
        for key in keys:
            parts = key.split("+")
            for part in parts:
                self.run("xdotool", "keydown", part)
            time.sleep(hold_seconds)
            for part in reversed(parts):
                self.run("xdotool", "keyup", part, check=False)
            time.sleep(0.05)

    def type_text(self, text):
        self.run("xdotool", "type", "--delay", "20", "--", text)

    def wait_for(self, condition, what, timeout=WAIT_SECONDS, interval=0.25):
        """Polls screenshots until condition(shot) is true; returns the shot, or raises naming `what`
        (the last screenshot is kept as failure.png)."""
        shots = []

        def shown():
            shots[:] = [self.screenshot()]
            return shots[0] if condition(shots[0]) else None
        try:
            return wait_until(shown, what, timeout, interval)
        except AssertionError:
            write_png(shots[0], os.path.join(os.environ.get("GLINT_GUI_FAILURE_DIR", "."), "failure.png"))
            raise

    def window_title(self, window):
        return self.run("xdotool", "getwindowname", window, check=False).stdout.strip()

    def wait_for_title(self, window, fragment, timeout=WAIT_SECONDS, running=lambda what: True):
        """Waits until the window's title holds `fragment`; returns the title. running(what) may
        raise to end the wait early (the application has ended)."""
        what = f"a window title naming {fragment!r}"
        return wait_until(lambda: running(what) and fragment in self.window_title(window) and self.window_title(window),
                          lambda: f"{what} (it is {self.window_title(window)!r})", timeout)

    def screenshot(self, window="root"):
        """Returns (width, height, pixels) with pixels a bytes object of RGB triples."""
        target = ["-root"] if window == "root" else ["-id", window]
        data = subprocess.run(["xwd", "-silent", *target], env=self.env, check=True, capture_output=True).stdout
        return parse_xwd(data)


class LoggedEditor:
    """The editor with its output in OUTPUT/editor.log, GLINT_LOG_LAYOUT=1 and GLINT_LOG_IDLE=1, so
    the rectangles it prints each time the layout changes and the moments it sleeps with everything
    drawn can be read while it runs."""

    def __init__(self, x, glint, output, state, arguments=(), env=None):
        self.x = x
        self.log_path = os.path.join(output, "editor.log")
        environment = dict(x.env, GLINT_STATE_DIR=state, GLINT_GUI_FAILURE_DIR=output, GLINT_LOG_LAYOUT="1",
                           GLINT_LOG_IDLE="1", **(env or {}))
        self.process, self.window = x.start_editor([glint, *arguments], environment, output, self.log_path)

    def __enter__(self):
        return self

    def __exit__(self, *exception):
        self.stop()

    def output(self):
        return read_text(self.log_path)

    def layout(self):
        """The last complete block of rectangles: {"screen": …, "viewport": …, "window": {name: rect},
        "reserved": {…}}, or None before the first."""
        blocks = self.output().split("glint layout: end\n")
        if len(blocks) < 2:
            return None
        result = {"window": {}, "reserved": {}}
        for line in blocks[-2].splitlines():
            if not line.startswith("glint layout: "):
                continue
            kind, rest = line[len("glint layout: "):].split(" ", 1)
            name, numbers = rest[1:].rsplit('" ', 1)
            rect = tuple(float(v) for v in numbers.split())
            if kind in ("screen", "viewport"):
                result[kind] = rect
            else:
                result[kind][name] = rect
        return result

    def running(self, what):
        """Raises, naming `what` and the end of the editor's output, where the editor has ended."""
        if self.process.poll() is not None:
            said = [line for line in self.output().splitlines() if not line.startswith("glint layout: ")]
            raise AssertionError(f"the editor exited with {self.process.returncode} while the test waited for {what}; "
                                 f"its output ends:\n" + "\n".join(said[-10:]))
        return True

    def wait_layout(self, condition, what, timeout=WAIT_SECONDS):
        """The first layout for which condition(layout) holds."""
        seen = [None]

        def met():
            self.running(what)
            seen[0] = self.layout()
            return seen[0] if seen[0] and condition(seen[0]) else None
        return wait_until(met, lambda: f"{what}; the last layout: {seen[0]}", timeout)

    def settled_layout(self, condition, what, timeout=WAIT_SECONDS):
        """A layout for which condition holds, once the editor has drawn all it was asked for
        (windows settle over a few frames)."""
        self.wait_layout(condition, what, timeout)
        self.settled(what, timeout)
        layout = self.layout()
        assert condition(layout), f"{what} went again once the editor settled; the last layout: {layout}"
        return layout

    def idle(self):
        """(events, pointer) of the editor's last "glint idle N X Y" line (GLINT_LOG_IDLE=1): the window
        events it had handled and where the pointer was when it last slept with everything drawn."""
        lines = [line.split() for line in self.output().splitlines() if line.startswith("glint idle ")]
        return (int(lines[-1][2]), (int(lines[-1][3]), int(lines[-1][4]))) if lines else None

    def wait_idle(self, what, after=-1, pointer=None, timeout=WAIT_SECONDS):
        """Waits until the editor sleeps with everything drawn, having handled more than `after` window
        events (the count this returned before the input was sent) and, where given, with the pointer
        at `pointer`: a move made after the input, so that a sleep before the input's last event
        (a drag's release, with the pointer held still) is not taken for one after it. A screenshot
        then shows the input's result. Returns the count of events handled."""
        def met():
            self.running(what)
            idle = self.idle()
            return idle and idle[0] > after and (pointer is None or idle[1] == tuple(pointer)) and idle[0]
        return wait_until(met, lambda: f"the editor idle after {what} (last: {self.idle()})", timeout)

    def settled(self, what, timeout=WAIT_SECONDS):
        """A screenshot once the editor has handled and drawn all input sent so far (GLINT_LOG_IDLE=1).
        A one-pixel pointer nudge marks "so far": the editor reports the nudged pointer only when
        it sleeps after handling the nudge, and so everything sent before it."""
        here = self.x.run("xdotool", "getmouselocation", "--shell").stdout.split()
        px, py = (int(field.split("=")[1]) for field in here[:2])
        nudged = (px + 1 if px < 100 else px - 1, py)
        last = self.idle()
        self.x.move(*nudged)
        self.wait_idle(what, after=last[0] if last else -1, pointer=nudged, timeout=timeout)
        return self.x.screenshot()

    def wait_for_title(self, fragment, timeout=WAIT_SECONDS):
        return self.x.wait_for_title(self.window, fragment, timeout, running=self.running)

    def wait_exit(self, timeout=WAIT_SECONDS):
        return self.process.wait(timeout=timeout)

    def stop(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait(timeout=10)


def parse_xwd(data):
    """Decodes a depth-24 TrueColor XWD image (X11 Window Dump, big-endian header), its pixels
    stored in 32 bits, or packed in 24 as xwd writes some windows of a large screen."""
    header = struct.unpack(">25I", data[:100])
    header_size, width, height = header[0], header[4], header[5]
    byte_order, bits_per_pixel, bytes_per_line = header[7], header[11], header[12]
    red_mask, green_mask, blue_mask = header[14], header[15], header[16]
    colors_in_file = header[19]  # XWDColor entries (12 bytes each) between header and pixels
    offset = header_size + colors_in_file * 12
    pixels = bytearray(width * height * 3)
    standard = byte_order == 0 and (red_mask, green_mask, blue_mask) == (0xFF0000, 0xFF00, 0xFF)
    if bits_per_pixel == 24 and standard:  # little-endian BGR, row by row (rows may be padded)
        for y in range(height):
            row = data[offset + y * bytes_per_line:offset + y * bytes_per_line + width * 3]
            start = y * width * 3
            pixels[start:start + width * 3:3], pixels[start + 1:start + width * 3:3], pixels[start + 2:start + width * 3:3] = \
                row[2::3], row[1::3], row[0::3]
        return width, height, bytes(pixels)
    if bits_per_pixel != 32:
        raise ValueError(f"unsupported XWD pixel size: {bits_per_pixel} bits")
    order = "<" if byte_order == 0 else ">"
    if standard and bytes_per_line == width * 4:
        # The common case (little-endian BGRX): slice whole channels at once.
        body = data[offset:offset + height * bytes_per_line]
        pixels[0::3], pixels[1::3], pixels[2::3] = body[2::4], body[1::4], body[0::4]
        return width, height, bytes(pixels)

    def shift(mask):
        return (mask & -mask).bit_length() - 1

    shifts = [shift(m) for m in (red_mask, green_mask, blue_mask)]
    for y in range(height):
        row = struct.unpack_from(f"{order}{width}I", data, offset + y * bytes_per_line)
        for x, value in enumerate(row):
            i = (y * width + x) * 3
            pixels[i] = (value >> shifts[0]) & 0xFF
            pixels[i + 1] = (value >> shifts[1]) & 0xFF
            pixels[i + 2] = (value >> shifts[2]) & 0xFF
    return width, height, bytes(pixels)


def region_difference(a, b, box, step=4):
    """Mean absolute difference (0-255) of two screenshots over box = (x0, y0, x1, y1)."""
    width = a[0]
    total, count = 0, 0
    x0, y0, x1, y1 = box
    for y in range(y0, y1, step):
        for x in range(x0, x1, step):
            i = (y * width + x) * 3
            total += abs(a[2][i] - b[2][i]) + abs(a[2][i + 1] - b[2][i + 1]) + abs(a[2][i + 2] - b[2][i + 2])
            count += 3
    return total / max(count, 1)


def region_mean(image, box, step=4):
    """Mean of all channels (0-255) over box = (x0, y0, x1, y1)."""
    width = image[0]
    values = [image[2][(y * width + x) * 3 + c] for y in range(box[1], box[3], step) for x in range(box[0], box[2], step) for c in range(3)]
    return sum(values) / max(len(values), 1)


def pixel(image, x, y):
    width, _, pixels = image
    i = (y * width + x) * 3
    return pixels[i], pixels[i + 1], pixels[i + 2]


def write_png(image, path):
    """Saves a screenshot as an 8-bit RGB PNG, for a person to look at."""
    width, height, pixels = image
    stride = width * 3
    raw = b"".join(b"\x00" + pixels[y * stride:(y + 1) * stride] for y in range(height))

    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF)

    with open(path, "wb") as out:
        out.write(b"\x89PNG\r\n\x1a\n")
        out.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        out.write(chunk(b"IDAT", zlib.compress(raw, 6)))
        out.write(chunk(b"IEND", b""))


def run_scenario_from_arguments(namespace, width=1280, height=800, screens=None):
    """argv: GLINT OUTPUT_DIR SCENARIO. Runs namespace["scenario_" + SCENARIO](x, glint, output,
    state) (a test module passes its globals()) in a fresh Xvfb, width×height or the size
    screens[SCENARIO] names, with its own output folder (failure screenshots go there) and an
    empty state folder."""
    import shutil
    import sys
    glint, output, scenario = sys.argv[1], sys.argv[2], sys.argv[3]
    output = os.path.join(output, scenario)
    os.makedirs(output, exist_ok=True)
    os.environ["GLINT_GUI_FAILURE_DIR"] = output
    state = os.path.join(output, "state")
    shutil.rmtree(state, ignore_errors=True)
    with XServer(*(screens or {}).get(scenario, (width, height))) as x:
        namespace["scenario_" + scenario](x, glint, output, state)
