"""Large-mesh editor figures under Xvfb (not a test; numbers for docs/performance.md and reports): the
editor (1280×800 window) opens the default stage with its sphere replaced by a 1,000,000-triangle
mesh (a binary PLY of a 1000 × 500 UV sphere, positions only, written here) and both lights
casting shadows (the key light a 2D map, the fill light a cube map), then drags the key light's
handle, the fill light's handle, the Blinn-Phong exponent slider and the camera (an orbit). From the editor's GLINT_LOG_FRAMES log it prints, for each drag, the frames drawn
during it (render time, input-to-presented time, resolution, whether the simplified stand-in and
new shadow maps were drawn) and the frame that followed the release with no further input.
usage: /usr/bin/python3 tests/bench/mesh_figures.py build/app/glint [--no-simplify]
(--no-simplify: with View ▸ Simplify meshes and shadows while dragging off, for comparison)"""
import json
import os
import statistics
import struct
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from gui_test_support import XServer, pixel  # noqa: E402
from gui_editor_test import EXPONENT_SLIDER  # noqa: E402

VIEWPORT_RECT = (330, 23, 590, 752)  # x, y, width, height of the viewport in the window [px]
CAMERA = {"position": (0.0, 0.9, 4.2), "target": (0.0, -0.1, 0.0), "fov_degrees": 40.0}
KEY_DIRECTION = (-0.5, -1.0, -0.6)
FILL_POSITION = (-0.4, 0.9, 1.5)  # in front of the sphere, where its handle shows


def write_sphere_ply(path, segments=1000, rings=500):
    """The bench's mesh: a UV sphere with the pole rows' degenerate triangles left out."""
    import math
    positions = []
    for ring in range(rings + 1):
        polar = math.pi * ring / rings
        for segment in range(segments + 1):
            azimuth = 2.0 * math.pi * segment / segments
            positions.append((math.sin(polar) * math.cos(azimuth), math.cos(polar), -math.sin(polar) * math.sin(azimuth)))
    faces = []
    stride = segments + 1
    for ring in range(rings):
        for segment in range(segments):
            a = ring * stride + segment
            b, d = a + stride, a + 1
            c = b + 1
            if ring != 0:
                faces.append((a, b, d))
            if ring != rings - 1:
                faces.append((d, b, c))
    with open(path, "wb") as out:
        out.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(positions)}\nproperty float x\n"
                  f"property float y\nproperty float z\nelement face {len(faces)}\n"
                  "property list uchar uint vertex_indices\nend_header\n".encode())
        out.write(b"".join(struct.pack("<3f", *p) for p in positions))
        out.write(b"".join(struct.pack("<B3I", 3, *f) for f in faces))
    return len(faces)


def write_scene(path, mesh_path):
    """The default scene (core/scene/scene.cpp) with the mesh for the sphere, both lights shadowed and
    the fill light moved in front of the sphere."""
    scene = {
        "format": "glint-scene", "version": 1,
        "camera": {"position": [0, 0.9, 4.2], "target": [0, -0.1, 0]},
        "background": [0.02, 0.022, 0.026],
        "lights": [
            {"name": "key", "type": "directional", "direction": [-0.5, -1, -0.6], "irradiance": 2.5, "casts_shadows": True},
            {"name": "fill", "type": "point", "position": list(FILL_POSITION), "power": 150, "color": [0.8, 0.9, 1],
             "casts_shadows": True},
        ],
        "materials": [{"name": "red plastic", "model": "blinn_phong"},
                      {"name": "grey floor", "model": "lambert", "albedo": 0.35}],
        "objects": [{"name": "sphere", "shape": "mesh", "path": mesh_path, "material": "red plastic"},
                    {"name": "floor", "shape": "plane", "material": "grey floor"}],
    }
    with open(path, "w") as out:
        json.dump(scene, out, indent=1)


def handle_at(shot, world):
    """A light handle drawn at `world` (editor/light_handles.cpp) on the initial camera, refined
    to the centroid of the yellow pixels around it."""
    import math

    def sub(a, b):
        return tuple(p - q for p, q in zip(a, b))

    def unit(v):
        length = math.sqrt(sum(c * c for c in v))
        return tuple(c / length for c in v)

    def cross(a, b):
        return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])

    def dot(a, b):
        return sum(p * q for p, q in zip(a, b))

    forward = unit(sub(CAMERA["target"], CAMERA["position"]))
    right = unit(cross(forward, (0.0, 1.0, 0.0)))
    up = cross(right, forward)
    relative = sub(world, CAMERA["position"])
    depth = dot(relative, forward)
    x0, y0, width, height = VIEWPORT_RECT
    tangent = math.tan(math.radians(CAMERA["fov_degrees"]) / 2)
    ndc_x = dot(relative, right) / (depth * tangent * width / height)
    ndc_y = dot(relative, up) / (depth * tangent)
    guess = (x0 + (ndc_x * 0.5 + 0.5) * width, y0 + (0.5 - ndc_y * 0.5) * height)
    hits = [(x_, y_) for y_ in range(int(guess[1]) - 30, int(guess[1]) + 30) for x_ in range(int(guess[0]) - 30, int(guess[0]) + 30)
            if pixel(shot, x_, y_) == (255, 220, 90)]
    if not hits:
        return None
    return sum(h[0] for h in hits) // len(hits), sum(h[1] for h in hits) // len(hits)


def key_handle(shot):
    """A directional light's handle: 1.5 m from the camera target against the light's travel."""
    length = sum(c * c for c in KEY_DIRECTION) ** 0.5
    return handle_at(shot, tuple(t - 1.5 * d / length for t, d in zip(CAMERA["target"], KEY_DIRECTION)))


def frames(log_path):
    with open(log_path) as log:
        lines = [line for line in log.read().splitlines() if line.startswith("glint frame:")]
    parsed = []
    for line in lines:
        words = line.split()
        frame = {"size": words[3], "scale": words[5], "render": float(words[7]), "total": float(words[13]),
                 "simplified": False, "maps": "?", "triangles": int(words[-2])}
        if len(words) >= 23:  # editors before the stand-ins logged neither
            frame.update(simplified=int(words[15]) > 0, maps=words[20].rstrip(","))
        parsed.append(frame)
    return parsed


def describe(name, during, after):
    if not during:
        print(f"{name}: no frames during the drag")
        return
    renders = [f["render"] for f in during]
    totals = [f["total"] for f in during]
    print(f"{name}: {len(during)} frames during the drag, scales {sorted(set(f['scale'] for f in during))}, "
          f"{sum(f['simplified'] for f in during)} with the stand-in, {sum(f['maps'] == 'redrawn' for f in during)} with new shadow maps")
    print(f"  render median {statistics.median(renders):.0f} ms (min {min(renders):.0f}, max {max(renders):.0f}); "
          f"input to presented frame median {statistics.median(totals):.0f} ms; triangles {sorted(set(f['triangles'] for f in during))}")
    for frame in after:
        print(f"  then, with no input: {frame['scale']} render {frame['render']:.0f} ms, {frame['triangles']} triangles, "
              f"stand-in {'yes' if frame['simplified'] else 'no'}, shadow maps {frame['maps']}")


def main():
    glint = sys.argv[1]
    simplify = "--no-simplify" not in sys.argv[2:]
    work = tempfile.mkdtemp(prefix="glint-mesh-figures-")
    triangles = write_sphere_ply(os.path.join(work, "sphere_1m.ply"))
    write_scene(os.path.join(work, "scene.json"), "sphere_1m.ply")
    state = os.path.join(work, "state")
    os.makedirs(state)
    with open(os.path.join(state, "settings.json"), "w") as out:
        json.dump({"simplify_meshes_while_dragging": simplify}, out)
    log_path = os.path.join(work, "frames.log")
    print(f"mesh: {triangles} triangles; stand-ins while dragging: {'on' if simplify else 'off'}")
    with XServer(1280, 800) as x, open(log_path, "w") as log:
        env = dict(x.env, GLINT_STATE_DIR=state, GLINT_LOG_FRAMES="1")
        editor = subprocess.Popen([glint, os.path.join(work, "scene.json")], env=env, stdout=log, stderr=log)
        try:
            x.find_window("Glint", timeout=120)
            deadline = time.time() + 120
            while not frames(log_path) and time.time() < deadline:
                time.sleep(0.5)
            time.sleep(8)  # the first full frames, and the stand-in made on its worker thread
            first = frames(log_path)
            print(f"full frames before any drag: render {[round(f['render']) for f in first]} ms at {first[-1]['size']}")

            def measure(name, action):
                mark = len(frames(log_path))
                action()
                released = len(frames(log_path))
                time.sleep(6)  # the full frame after the release, with no input
                logged = frames(log_path)
                describe(name, logged[mark:released], logged[released:])

            # First the handles, found from the initial camera.
            shot = x.screenshot()
            for name, handle, to in (("key light handle (directional, 2D shadow map)", key_handle(shot), (-150, 30)),
                                     ("fill light handle (point, cube shadow map)", handle_at(shot, FILL_POSITION), (60, -20))):
                if handle:
                    measure(name, lambda: x.drag(handle, (handle[0] + to[0], handle[1] + to[1]), steps=30, step_seconds=0.05))
                else:
                    print(f"{name}: not found in the viewport")
            measure("material slider (Blinn-Phong exponent)",
                    lambda: x.drag(EXPONENT_SLIDER, (EXPONENT_SLIDER[0] - 80, EXPONENT_SLIDER[1]), steps=30, step_seconds=0.05))
            measure("camera orbit (viewport drag)", lambda: x.drag((500, 200), (700, 260), steps=30, step_seconds=0.05))
        finally:
            editor.terminate()
            editor.wait(timeout=30)


if __name__ == "__main__":
    main()
