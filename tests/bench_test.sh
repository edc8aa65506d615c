#!/usr/bin/env bash
# `glint bench` from outside: a --quick run writes a table and JSON of the documented shape (every
# standard scene with positive timings and a ratio to the bare pass; cold start, thumbnails, mesh
# load, peak memory), and bad options are refused with exit code 2 and a message. It does not judge the
# figures themselves (they depend on the machine). usage: bench_test.sh GLINT OUTDIR
set -euo pipefail
glint=$1
out=$2
rm -rf "$out" && mkdir -p "$out"
export DISPLAY=

refused() {  # refused EXPECTED_TEXT ARGS...: exit code 2 and the text on stderr
  local expected=$1; shift
  local code=0
  "$glint" bench "$@" >"$out/refused.out" 2>"$out/refused.err" || code=$?
  [[ $code -eq 2 ]] || { echo "glint bench $*: exit $code, expected 2"; exit 1; }
  grep -qF -- "$expected" "$out/refused.err" || { echo "glint bench $*: no '$expected' in:"; cat "$out/refused.err"; exit 1; }
}
refused "--frames needs a number from 1 to 1000" --frames 0
refused "--frames needs a number from 1 to 1000" --frames many
refused "--frames needs a number" --frames
refused "--json needs a file in an existing folder" --json "$out/no/such/folder/bench.json"
refused "--json needs a file in an existing folder" --json ""
refused "--json needs a file in an existing folder" --json "$out"
refused "no standard scene is named \"teapot\"" --scene teapot
refused "unknown option --fast" --fast
refused "takes no arguments" extra
refused "--scene-file: $out/no-such-scene.json: cannot open" --scene-file "$out/no-such-scene.json"
refused "--size needs WIDTHxHEIGHT" --size 0x5

# A scene file, timed against the hand-written textbook floor (docs/performance.md).
scenes=$(dirname "$0")/bench/scenes
"$glint" bench --scene-file "$scenes/peer_ggx.json" --scene-file "$scenes/peer_empty.json" --size 320x180 --frames 1 \
  --json "$out/file.json" >"$out/file.txt"
/usr/bin/python3 - "$out/file.json" <<'PY'
import json, sys
bench = json.load(open(sys.argv[1]))
assert (bench["width"], bench["height"]) == (320, 180) and bench["generic_programs"] is False
assert [(s["name"], s["family"], s["floor"]) for s in bench["scenes"]] == [("peer_ggx", "file", "textbook"),
                                                                            ("peer_empty", "file", "textbook")], bench["scenes"]
assert all(s["frame_ms"]["median"] > 0 and s["bare_ms"]["median"] > 0 and s["first_frame_ms"] > 0 for s in bench["scenes"])
assert "cold_start_ms" not in bench, "a scene file is timed alone"
PY

"$glint" bench --scene list >"$out/list.txt"
grep -q "^lambert/4 " "$out/list.txt" && grep -q "^glass/1 " "$out/list.txt"

start=$(date +%s)
"$glint" bench --quick --size 320x180 --json "$out/bench.json" | tee "$out/bench.txt"
echo "glint bench --quick took $(( $(date +%s) - start )) s"
grep -q "^lambert/4 .*diffuse" "$out/bench.txt"
grep -q "^cold start" "$out/bench.txt"
grep -q "^mesh load" "$out/bench.txt"
grep -q "^ggx_studio/0 .*environment" "$out/bench.txt"
grep -q "^mesh_1m_studio_shadows/2 .*combined" "$out/bench.txt"
grep -q "^mesh_1m_light_drag/2 .*drag" "$out/bench.txt"

/usr/bin/python3 - "$out/bench.json" "$out/list.txt" <<'PY'
import json, sys
bench = json.load(open(sys.argv[1]))
names = [line.split()[0] for line in open(sys.argv[2]) if line.strip()]
assert bench["format"] == "glint-bench" and bench["version"] == 1, bench.get("format")
assert (bench["width"], bench["height"]) == (320, 180)
assert bench["quick"] is True and bench["frames"] == 1
assert [scene["name"] for scene in bench["scenes"]] == names, "every standard scene, in table order"
for scene in bench["scenes"]:
    for key in ("frame_ms", "radiance_ms", "display_ms", "bare_ms"):
        timing = scene[key]
        assert 0 < timing["min"] <= timing["q1"] <= timing["median"] <= timing["q3"] <= timing["max"], (scene["name"], key, timing)
    assert abs(scene["ratio"] - scene["frame_ms"]["median"] / scene["bare_ms"]["median"]) < 1e-9, scene["name"]
    assert scene["family"] in ("diffuse", "phong", "microfacet", "anisotropic", "retroreflective", "specular", "mesh",
                               "environment", "shadows", "combined", "drag"), scene["family"]
    assert scene["mesh_detail"] == ("simplified" if scene["family"] == "drag" else "full"), scene["name"]
    assert scene["triangles"] > 0 and scene["shadow_maps_per_frame"] >= 0, scene["name"]
by_name = {scene["name"]: scene for scene in bench["scenes"]}
# The stand-in draws at most 100k of the million triangles; a moving light redraws its map each frame.
assert by_name["mesh_1m_triangles/4"]["triangles"] > 900000
assert 0 < by_name["mesh_1m_simplified/4"]["triangles"] <= 100000
assert by_name["mesh_1m_studio_shadows/2"]["shadow_maps_per_frame"] == 0
assert by_name["mesh_1m_light_drag/2"]["shadow_maps_per_frame"] == 1
assert bench["cold_start_ms"]["median"] > 0 and bench["cold_start_runs"] == 3 and bench["cold_start_peak_mb"] > 0
assert bench["thumbnails"] == 8 and bench["thumbnails_per_second"] > 0
assert bench["mesh_triangles"] > 900000 and bench["mesh_load_ms"]["median"] > 0 and bench["mesh_read_ms"]["median"] > 0
assert abs(bench["mesh_load_ratio"] - bench["mesh_load_ms"]["median"] / bench["mesh_read_ms"]["median"]) < 1e-9
assert bench["peak_memory_mb"] > 0 and bench["renderer"]
print("bench JSON: %d scenes, shape as documented" % len(bench["scenes"]))
PY
