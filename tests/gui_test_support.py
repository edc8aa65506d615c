"""Helpers for GUI tests: a private Xvfb server, the editor's window, real input through
xdotool, and screenshots read from xwd's format (standard library only; run with
/usr/bin/python3). Nothing here knows about Glint's panels."""
import os
import struct
import subprocess
import time
import zlib


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

    def find_window(self, name, timeout=30.0, process=None):
        """The id of the first window named `name`; raises EditorExited when `process` ends first."""
        deadline = time.time() + timeout
        while time.time() < deadline:
            found = self.run("xdotool", "search", "--name", name, check=False).stdout.split()
            if found:
                return found[0]
            if process is not None and process.poll() is not None:
                raise EditorExited(f"exit status {process.returncode}; its output:\n{process.communicate()[0][-2000:]}")
            time.sleep(0.2)
        raise RuntimeError(f"no window named {name!r} appeared in {timeout} s")

    def start_editor(self, command, env, cwd, attempts=2):
        """Starts the editor (command = [glint, arguments…]) and waits for its window; returns
        (process, window). An editor that cannot open a window renders headless and exits (seen
        once in a while on a loaded machine): it is started once more, and what it printed is
        shown either way."""
        for attempt in range(1, attempts + 1):
            process = subprocess.Popen(command, env=env, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                       text=True)
            try:
                return process, self.find_window("Glint", process=process)
            except EditorExited as exited:
                print(f"the editor exited before showing a window (attempt {attempt}): {exited}", flush=True)
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
        each chord for hold_seconds so applications that sample key state per frame see it."""
        for key in keys:
            parts = key.split("+")
            for part in parts:
                self.run("xdotool", "keydown", part)
            time.sleep(hold_seconds)
            for part in reversed(parts):
                self.run("xdotool", "keyup", part)
            time.sleep(0.05)

    def type_text(self, text):
        self.run("xdotool", "type", "--delay", "20", "--", text)

    def wait_for(self, condition, what, timeout=20.0, interval=0.25):
        """Polls screenshots until condition(shot) is true; returns the shot, or raises naming `what`."""
        deadline = time.time() + timeout
        shot = None
        while time.time() < deadline:
            shot = self.screenshot()
            if condition(shot):
                return shot
            time.sleep(interval)
        if shot is not None:
            write_png(shot, os.path.join(os.environ.get("GLINT_GUI_FAILURE_DIR", "."), "failure.png"))
        raise AssertionError(f"timed out after {timeout} s waiting for {what}")

    def wait_stable(self, box, timeout=20.0, interval=0.3):
        """Waits until two screenshots in a row agree over box (the application finished drawing)."""
        deadline = time.time() + timeout
        previous = self.screenshot()
        while time.time() < deadline:
            time.sleep(interval)
            shot = self.screenshot()
            if region_difference(shot, previous, box) == 0:
                return shot
            previous = shot
        raise AssertionError(f"the screen did not settle within {timeout} s")

    def screenshot(self, window="root"):
        """Returns (width, height, pixels) with pixels a bytes object of RGB triples."""
        target = ["-root"] if window == "root" else ["-id", window]
        data = subprocess.run(["xwd", "-silent", *target], env=self.env, check=True, capture_output=True).stdout
        return parse_xwd(data)


def parse_xwd(data):
    """Decodes a 24/32-bit TrueColor XWD image (X11 Window Dump, big-endian header)."""
    header = struct.unpack(">25I", data[:100])
    header_size, width, height = header[0], header[4], header[5]
    byte_order, bits_per_pixel, bytes_per_line = header[7], header[11], header[12]
    red_mask, green_mask, blue_mask = header[14], header[15], header[16]
    colors_in_file = header[19]  # XWDColor entries (12 bytes each) between header and pixels
    offset = header_size + colors_in_file * 12
    if bits_per_pixel != 32:
        raise ValueError(f"unsupported XWD depth {bits_per_pixel}")
    pixels = bytearray(width * height * 3)
    order = "<" if byte_order == 0 else ">"
    if byte_order == 0 and (red_mask, green_mask, blue_mask) == (0xFF0000, 0xFF00, 0xFF) and bytes_per_line == width * 4:
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
