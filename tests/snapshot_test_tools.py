"""Helpers for snapshot_runner_test.sh (standard library only; run with /usr/bin/python3):
write a test PNG of known pixels, read a PNG's size, and summarise a JUnit XML report.
They check nothing themselves; the shell script compares what they print."""
import os
import struct
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import write_png  # noqa: E402


def uniform_png(path, width, height, value, block=None):
    """A grey image of `value`; block = (x, y, w, h, block_value) paints a square on it."""
    pixels = bytearray([value] * (width * height * 3))
    if block:
        bx, by, bw, bh, bvalue = block
        for y in range(by, by + bh):
            for x in range(bx, bx + bw):
                i = (y * width + x) * 3
                pixels[i:i + 3] = bytes([bvalue] * 3)
    write_png((width, height, bytes(pixels)), path)


def png_size(path):
    with open(path, "rb") as f:
        header = f.read(24)
    return struct.unpack(">II", header[16:24])


def junit_summary(path):
    """Parses the report (raising on invalid XML) and prints its counts, then one line a case."""
    import xml.etree.ElementTree as ElementTree
    root = ElementTree.parse(path).getroot()
    suite = root.find("testsuite")
    print("tests=%s failures=%s errors=%s" % (suite.get("tests"), suite.get("failures"), suite.get("errors")))
    for case in suite.findall("testcase"):
        outcome = "failure" if case.find("failure") is not None else "error" if case.find("error") is not None else "passed"
        print("%s %s" % (case.get("name"), outcome))


if __name__ == "__main__":
    command = sys.argv[1]
    if command == "uniform":
        path, width, height, value = sys.argv[2], int(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
        block = tuple(int(v) for v in sys.argv[6:11]) if len(sys.argv) > 6 else None
        uniform_png(path, width, height, value, block)
    elif command == "size":
        print("%dx%d" % png_size(sys.argv[2]))
    elif command == "junit":
        junit_summary(sys.argv[2])
