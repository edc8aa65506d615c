"""The editor's first frame is anti-aliased: across the red sphere's silhouette against the
studio backdrop, on the rows of its upper flanks, the sphere's coverage (from the linear red
channel) rises over several pixels. Without anti-aliasing it jumps from 0 to 1 between two
neighbouring pixels on every row. usage: gui_stage_test.py GLINT OUTPUT_DIR [SCENE]
(a SCENE is opened instead of the default one: with "msaa": 1 the test must fail.)"""
import math
import os
import statistics
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from gui_test_support import LoggedEditor, XServer, pixel, write_png  # noqa: E402

# The largest coverage step between neighbouring pixels across the edge, median over the rows:
# 1 without anti-aliasing; about 0.5 with 4× MSAA.
MAX_MEDIAN_STEP = 0.7


def linear_red(p):
    """The red channel decoded from sRGB: coverage blends radiance linearly, before encoding."""
    value = p[0] / 255.0
    return value / 12.92 if value <= 0.04045 else ((value + 0.055) / 1.055) ** 2.4


def red(p):
    return p[0] > 80 and p[0] > p[1] + 30


def find_sphere(shot):
    """Centre and radius of the largest red area: the bounding box of the red pixels' densest rows."""
    width, height, _ = shot
    reds = [(x, y) for y in range(0, height, 2) for x in range(0, width, 2) if red(pixel(shot, x, y))]
    if len(reds) < 200:
        return None
    xs = sorted(x for x, _ in reds)
    ys = sorted(y for _, y in reds)
    x0, x1 = xs[len(xs) // 200], xs[-1 - len(xs) // 200]
    y0, y1 = ys[len(ys) // 200], ys[-1 - len(ys) // 200]
    return (x0 + x1) / 2, (y0 + y1) / 2, (x1 - x0) / 2


def edge_steps(shot, centre_x, centre_y, radius, side):
    """Per row of the sphere's upper flank (30° to 60° from the top): the largest coverage step
    between neighbouring pixels across the silhouette. The edge is found by scanning the row from
    outside inwards to the first red pixel; coverage runs from the backdrop's linear red 6 px
    outside (0) to the sphere's 6 px inside (1)."""
    steps = []
    for y in range(int(centre_y - radius * math.cos(math.radians(30))), int(centre_y - radius * math.cos(math.radians(60)))):
        x = int(centre_x + side * (radius + 20))
        while x != int(centre_x) and not red(pixel(shot, x, y)):
            x -= side
        inside = linear_red(pixel(shot, x - 6 * side, y))
        outside = linear_red(pixel(shot, x + 6 * side, y))
        if abs(inside - outside) < 0.1:
            continue  # too little contrast to measure coverage
        coverage = [min(max((linear_red(pixel(shot, x + k * side, y)) - outside) / (inside - outside), 0.0), 1.0)
                    for k in range(-5, 6)]
        steps.append(max(abs(coverage[k + 1] - coverage[k]) for k in range(len(coverage) - 1)))
    return steps


def main():
    glint, output = sys.argv[1], sys.argv[2]
    scene = sys.argv[3:]
    os.makedirs(output, exist_ok=True)
    with XServer(1280, 800) as x, tempfile.TemporaryDirectory() as state:
        editor = LoggedEditor(x, glint, output, state, scene)
        try:
            shot = x.wait_for(lambda image: find_sphere(image) is not None, "the red sphere")
            shot = editor.settled("the first frames")  # the full-resolution frame after the first
            write_png(shot, os.path.join(output, "gui_stage.png"))
            centre_x, centre_y, radius = find_sphere(shot)
            assert radius > 40, f"the sphere is {radius:.0f} px across: too small to measure"
            steps = edge_steps(shot, centre_x, centre_y, radius, -1) + edge_steps(shot, centre_x, centre_y, radius, 1)
            assert len(steps) >= 40, f"only {len(steps)} rows of silhouette to measure"
            median = statistics.median(steps)
            assert median <= MAX_MEDIAN_STEP, f"the silhouette jumps by {median:.2f} of its contrast between neighbouring pixels (aliased)"
            print(f"ok: sphere r={radius:.0f} px at ({centre_x:.0f}, {centre_y:.0f}); coverage step across its edge: "
                  f"median {median:.2f}, largest {max(steps):.2f} over {len(steps)} rows")
        finally:
            editor.stop()


if __name__ == "__main__":
    main()
