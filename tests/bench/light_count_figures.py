"""Frame time against the number of lights (not a test; the curve in docs/performance.md): the GGX
peer sphere (tests/bench/scenes/peer_ggx.json) under its directional light and N − 1 point lights
spread over a sphere of radius 3 m around it, timed by `glint bench --scene-file` for each N. With
several binaries, their runs alternate count by count in one command, so that they share the
machine's load; each row gives every binary's median frame, the floor pass's and their ratio, and
the step from the row before divided by the lights added (the cost of one light), and the untimed
first frame (which compiles the programs).
usage: /usr/bin/python3 tests/bench/light_count_figures.py LABEL=GLINT [LABEL=GLINT ...]
           [--lights 1,2,4,6,7,8,9,12,16,32,64] [--rounds 3] [--frames 11] [--size 1280x720]
A binary that refuses a count (more lights than it supports) shows "refused" in that row."""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

PEER_SCENE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "scenes", "peer_ggx.json")


def scene_with_lights(count):
    """The peer scene with its sun and count − 1 point lights on a Fibonacci sphere of radius 3 m,
    each with the same share of 200 W, so that the picture's brightness does not grow with count."""
    with open(PEER_SCENE) as f:
        scene = json.load(f)
    sun = scene["lights"][0]
    points = count - 1
    golden_angle = math.pi * (3 - math.sqrt(5))
    lights = [sun]
    for i in range(points):
        y = 1 - 2 * (i + 0.5) / points
        ring = math.sqrt(1 - y * y)
        x, z = ring * math.cos(golden_angle * i), ring * math.sin(golden_angle * i)
        lights.append({"name": f"point {i + 1}", "type": "point", "position": [3 * x, 3 * y, 3 * z],
                       "power": 200 / points, "color": [1, 0.9 + 0.1 * (i % 2), 0.9 + 0.1 * (i % 3 == 0)]})
    scene["lights"] = lights
    return scene


def bench(glint, paths, size, frames):
    """Median frame and floor per scene file, or None and the message of a binary that refuses them."""
    with tempfile.TemporaryDirectory(prefix="glint-lights-") as folder:
        out = os.path.join(folder, "bench.json")
        command = [glint, "bench", "--size", size, "--frames", str(frames), "--json", out]
        for path in paths:
            command += ["--scene-file", path]
        run = subprocess.run(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                             env=dict(os.environ, DISPLAY=""))
        if run.returncode != 0:
            return None, run.stderr.strip()
        with open(out) as f:
            rows = json.load(f)["scenes"]
        return [(row["frame_ms"]["median"], row["bare_ms"]["median"], row["first_frame_ms"]) for row in rows], ""


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("binaries", nargs="+", help="LABEL=PATH of a glint binary (or a script that runs one)")
    parser.add_argument("--lights", default="1,2,4,6,7,8,9,12,16,32,64")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=11)
    parser.add_argument("--size", default="1280x720")
    args = parser.parse_args()
    binaries = [entry.split("=", 1) for entry in args.binaries]
    if any(len(entry) != 2 for entry in binaries):
        sys.exit("light_count_figures: each binary is LABEL=PATH")
    counts = [int(n) for n in args.lights.split(",")]
    with tempfile.TemporaryDirectory(prefix="glint-lights-scenes-") as folder:
        paths = {}
        for count in counts:
            paths[count] = os.path.join(folder, f"lights_{count}.json")
            with open(paths[count], "w") as f:
                json.dump(scene_with_lights(count), f)
        # frames[label][count]: each round's (frame median, floor median, first frame).
        frames = {label: {count: [] for count in counts} for label, _ in binaries}
        for round_index in range(args.rounds):
            for count in counts:  # one process per count and binary: a binary may refuse the larger counts
                for label, glint in binaries:
                    medians, refusal = bench(glint, [paths[count]], args.size, args.frames)
                    if medians is None:
                        print(f"round {round_index + 1}: {label}, {count} lights: refused: {refusal}", flush=True)
                        continue
                    frames[label][count].append(medians[0])
            print(f"round {round_index + 1} done", flush=True)
    with open("/proc/loadavg") as f:
        load = " ".join(f.read().split()[:3])
    print(f"{args.size}, {args.rounds} rounds of {args.frames} frames, median of the rounds' medians; load average {load}")
    header = f"{'lights':>6}"
    for label, _ in binaries:
        header += f" | {label + ' ms':>12} {'floor ms':>9} {'ratio':>6} {'ms/light':>8} {'first ms':>8}"
    print(header)
    previous = {}
    for count in counts:
        line = f"{count:>6}"
        for label, _ in binaries:
            rounds = frames[label][count]
            if not rounds:
                line += f" | {'refused':>12} {'':>9} {'':>6} {'':>8} {'':>8}"
                continue
            frame = statistics.median(r[0] for r in rounds)
            floor = statistics.median(r[1] for r in rounds)
            first = statistics.median(r[2] for r in rounds)
            step = ""
            if label in previous:
                before_count, before_frame = previous[label]
                step = f"{(frame - before_frame) / (count - before_count):8.2f}"
            previous[label] = (count, frame)
            line += f" | {frame:12.2f} {floor:9.2f} {frame / floor:6.2f} {step:>8} {first:8.0f}"
        print(line)


if __name__ == "__main__":
    main()
