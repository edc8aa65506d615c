"""Side by side with three.js (run by tests/bench/threejs_compare.sh, which installs what it
needs): each scene below, an OpenPBR sphere in front of a grey wall under the peer benchmark's
lights, drawn by three.js's MeshPhysicalMaterial in headless Chromium (compare.html) and by
`glint render`, the same size, no tone mapping, sRGB; writes three.js | Glint as one PNG per scene.
usage: compare.py GLINT THREE_DIR OUTPUT_DIR [--size WxH]"""
import argparse
import base64
import json
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from peer import Results, open_page, serve  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PEER_SCENE = os.path.join(HERE, "..", "scenes", "peer_ggx.json")
# OpenPBR parameters away from their defaults; the rest are the table's defaults (below).
SCENES = {
    "car_paint": {"base_color": [0.45, 0.02, 0.03], "base_metalness": 0.4, "specular_roughness": 0.4,
                  "coat_weight": 1, "coat_roughness": 0.05, "coat_ior": 1.5},
    "velvet": {"base_color": [0.2, 0.01, 0.05], "specular_roughness": 0.8, "fuzz_weight": 1,
               "fuzz_color": [0.9, 0.35, 0.55], "fuzz_roughness": 0.5},
    "gold": {"base_color": [1.0, 0.785, 0.343], "base_metalness": 1, "specular_roughness": 0.25},
    "glass": {"specular_ior": 1.5, "specular_roughness": 0.05, "transmission_weight": 1,
              "transmission_color": [0.85, 0.95, 0.93], "transmission_depth": 0.5},
    "iridescence": {"base_color": [0.02, 0.02, 0.02], "specular_roughness": 0.15, "thin_film_weight": 1,
                    "thin_film_thickness": 0.4, "thin_film_ior": 1.33},
}
DEFAULTS = {"base_weight": 1, "base_color": [0.8, 0.8, 0.8], "base_metalness": 0, "specular_weight": 1,
            "specular_color": [1, 1, 1], "specular_roughness": 0.3, "specular_roughness_anisotropy": 0, "specular_ior": 1.5,
            "transmission_weight": 0, "transmission_color": [1, 1, 1], "transmission_depth": 0, "fuzz_weight": 0,
            "fuzz_color": [1, 1, 1], "fuzz_roughness": 0.5, "coat_weight": 0, "coat_roughness": 0, "thin_film_weight": 0,
            "thin_film_thickness": 0.5, "thin_film_ior": 1.4, "emission_luminance": 0, "emission_color": [1, 1, 1],
            "geometry_thin_walled": False}


def run_three(chromium, port, results, material, width, height):
    url = f"http://127.0.0.1:{port}/compare.html?width={width}&height={height}&material={json.dumps(material)}"
    return open_page(chromium, url, results, width, height, "threejs_compare: no picture from Chromium")


def glint_scene(material, width, height):
    with open(PEER_SCENE) as f:
        scene = json.load(f)
    scene["output"] = {"width": width, "height": height, "msaa": 4}
    scene["display"] = {"exposure": 0, "transfer": "srgb", "tone_map": "none"}
    scene["materials"] = [dict(material, name="sphere", model="openpbr"), {"name": "wall", "model": "lambert", "albedo": [0.5, 0.5, 0.5]}]
    scene["objects"] = [{"name": "ball", "shape": "sphere", "center": [0, 0, 0], "radius": 1, "material": "sphere"},
                        {"name": "wall", "shape": "plane", "center": [0, 0, -2], "normal": [0, 0, 1], "size": [12, 12], "material": "wall"}]
    return scene


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("glint")
    parser.add_argument("three_dir")
    parser.add_argument("output")
    parser.add_argument("--chromium", default="chromium")
    parser.add_argument("--size", default="400x300")
    parser.add_argument("--scenes", default=",".join(SCENES))
    args = parser.parse_args()
    width, height = (int(v) for v in args.size.split("x"))
    results = Results()
    server = serve(args.three_dir, results)
    os.makedirs(args.output, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="glint-compare-") as folder:
        for name in args.scenes.split(","):
            material = dict(DEFAULTS, **SCENES[name])
            three = run_three(args.chromium, server.server_address[1], results, material, width, height)
            three_png = os.path.join(folder, f"{name}_three.png")
            with open(three_png, "wb") as f:
                f.write(base64.b64decode(three["png"].split(",", 1)[1]))
            scene_path = os.path.join(folder, f"{name}.json")
            with open(scene_path, "w") as f:
                json.dump(glint_scene(SCENES[name], width, height), f)
            glint_png = os.path.join(folder, f"{name}_glint.png")
            subprocess.run([args.glint, "render", scene_path, "-o", glint_png], check=True, stdout=subprocess.DEVNULL,
                           env=dict(os.environ, DISPLAY=""))
            out = os.path.join(args.output, f"openpbr-vs-threejs-{name.replace('_', '-')}.png")
            subprocess.run(["/usr/bin/convert", "(", three_png, "-gravity", "north", "-fill", "white", "-pointsize", "14",
                            "-annotate", "+0+6", f"three.js r{three['three']} MeshPhysicalMaterial", ")",
                            "(", glint_png, "-gravity", "north", "-fill", "white", "-pointsize", "14",
                            "-annotate", "+0+6", "Glint openpbr", ")", "+append", out], check=True)
            print(f"threejs_compare: wrote {out}", flush=True)
    server.shutdown()


if __name__ == "__main__":
    main()
