"""The three.js peer benchmark (run by tests/bench/threejs_peer.sh, which installs what it needs):
serves peer.html and three.js on 127.0.0.1, runs headless Chromium on Mesa's llvmpipe (ANGLE's
OpenGL backend) for each scene, then `glint bench --scene-file` on the same scene, interleaved
round by round, and prints the medians and the ratio Glint / three.js.
usage: peer.py GLINT THREE_DIR [--rounds N] [--frames N] [--size WxH] [--scenes ggx,lambert,empty]"""
import argparse
import http.server
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import threading

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = os.path.join(HERE, "..", "scenes")
CHROMIUM_FLAGS = [
    "--headless", "--no-sandbox",
    # Mesa llvmpipe through ANGLE's OpenGL ES-on-EGL backend (not SwiftShader): gl-egl with the
    # headless Ozone platform needs no X display (plain `gl` does). llvmpipe is on Chromium's GPU
    # blocklist as a software renderer, hence --ignore-gpu-blocklist. WebGL reports
    # "ANGLE (Mesa/X.org, llvmpipe (LLVM ...), OpenGL ES 3.2)"; main() refuses anything else.
    "--use-gl=angle", "--use-angle=gl-egl", "--ozone-platform=headless", "--ignore-gpu-blocklist",
    # Nothing else: the network is closed and the timings should be of the page alone.
    "--disable-background-networking", "--disable-component-update", "--disable-sync", "--no-first-run",
    "--disable-quic", "--disable-extensions", "--disable-default-apps", "--mute-audio",
    "--disable-renderer-backgrounding", "--disable-background-timer-throttling",
]


class Results:
    def __init__(self):
        self.condition = threading.Condition()
        self.latest = None


def serve(three_dir, results):
    class Handler(http.server.SimpleHTTPRequestHandler):
        def translate_path(self, path):
            path = path.split("?", 1)[0]
            if path.startswith("/three/"):
                return os.path.join(three_dir, path[len("/three/"):])
            return os.path.join(HERE, path.lstrip("/"))

        def do_POST(self):
            body = self.rfile.read(int(self.headers["Content-Length"]))
            self.send_response(204)
            self.end_headers()
            with results.condition:
                results.latest = json.loads(body)
                results.condition.notify_all()

        def log_message(self, *args):
            pass

    server = http.server.ThreadingHTTPServer(("127.0.0.1", 0), Handler)
    threading.Thread(target=server.serve_forever, daemon=True).start()
    return server


def open_page(chromium, url, results, width, height, failure, timeout=300):
    """Opens url in a fresh headless Chromium profile and returns what the page posts back;
    exits with `failure` when nothing comes within timeout seconds."""
    profile = tempfile.mkdtemp(prefix="glint-peer-chromium-")
    with results.condition:
        results.latest = None
    browser = subprocess.Popen([chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", f"--window-size={width},{height}", url],
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        with results.condition:
            if not results.condition.wait_for(lambda: results.latest is not None, timeout):
                sys.exit(f"{failure} within {timeout} s")
            return results.latest
    finally:
        browser.kill()
        browser.wait()
        shutil.rmtree(profile, ignore_errors=True)


def run_three(chromium, port, results, scene, width, height, frames):
    url = f"http://127.0.0.1:{port}/peer.html?scene={scene}&width={width}&height={height}&frames={frames}&warmup=3"
    return open_page(chromium, url, results, width, height, f"threejs_peer: no result from Chromium for {scene}")


def run_glint(glint, scene, width, height, frames):
    with tempfile.TemporaryDirectory(prefix="glint-peer-") as folder:
        out = os.path.join(folder, "bench.json")
        subprocess.run([glint, "bench", "--scene-file", os.path.join(SCENES, f"peer_{scene}.json"), "--size",
                        f"{width}x{height}", "--frames", str(frames), "--json", out],
                       check=True, stdout=subprocess.DEVNULL, env=dict(os.environ, DISPLAY=""))
        with open(out) as f:
            return json.load(f)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("glint")
    parser.add_argument("three_dir")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--size", default="1280x720")
    parser.add_argument("--scenes", default="ggx,lambert,empty")
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    results = Results()
    server = serve(args.three_dir, results)
    port = server.server_address[1]
    three_times = {scene: [] for scene in args.scenes.split(",")}
    glint_frames = {scene: [] for scene in three_times}
    glint_floor = {scene: [] for scene in three_times}
    description = {}
    for round_index in range(args.rounds):
        for scene in three_times:
            three = run_three(args.chromium, port, results, scene, width, height, args.frames)
            if "llvmpipe" not in three["renderer"]:
                sys.exit(f"threejs_peer: Chromium's WebGL runs on '{three['renderer']}', not llvmpipe")
            three_times[scene] += three["times"]
            description["three"] = f"three.js r{three['three']} on {three['renderer']}"
            bench = run_glint(args.glint, scene, width, height, args.frames)
            row = bench["scenes"][0]
            glint_frames[scene].append(row["frame_ms"]["median"])
            if row["floor"] != "none":
                glint_floor[scene].append(row["bare_ms"]["median"])
            description["glint"] = f"Glint on {bench['renderer']}"
            print(f"round {round_index + 1}: {scene}: three.js median {statistics.median(three['times']):.2f} ms, "
                  f"Glint median {row['frame_ms']['median']:.2f} ms", flush=True)
    print(f"{description['three']}; {description['glint']}; {width}x{height}, {args.rounds} rounds of {args.frames} frames")
    print(f"{'scene':<10} {'three.js ms':>12} {'Glint ms':>10} {'Glint/three':>12} {'floor ms':>9}")
    for scene in three_times:
        three = statistics.median(three_times[scene])
        glint = statistics.median(glint_frames[scene])
        floor = f"{statistics.median(glint_floor[scene]):9.2f}" if glint_floor[scene] else f"{'-':>9}"
        print(f"{scene:<10} {three:12.2f} {glint:10.2f} {glint / three:12.2f} {floor}")
    server.shutdown()


if __name__ == "__main__":
    main()
