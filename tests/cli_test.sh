#!/usr/bin/env bash
# `glint render` on good and bad input: bad input must exit with code 2 and a message naming
# the file and the line or key; nothing may crash. usage: cli_test.sh GLINT OUTPUT_DIR
source "$(dirname "$0")/cli_checks.sh" "$@"

# light_error NAME LIGHT_JSON PATTERN: rendering NAME.json, a scene whose light (line 4) is LIGHT_JSON,
# fails with an error at that line matching PATTERN.
light_error() {
  cat >"$out/$1.json" <<JSON
{
  "format": "glint-scene", "version": 1,
  "lights": [
    $2
  ],
  "materials": [{"name": "m", "model": "lambert"}],
  "objects": [{"shape": "sphere", "material": "m"}]
}
JSON
  expect_error "$1" "$1\.json:4:[0-9]+: $3" -- render "$out/$1.json" -o "$out/x.png"
}

expect_error missing_file "/no/such/scene.json: cannot open" -- render /no/such/scene.json -o "$out/x.png"
printf '{\n  "format": "glint-scene",\n  "version": 1\n  "lights": []\n}\n' >"$out/invalid.json"
expect_error invalid_json "invalid\.json:4:[0-9]+: invalid JSON" -- render "$out/invalid.json" -o "$out/x.png"
light_error unknown_key '{"type": "point", "power": 10, "watts": 5}' ".*'watts': unknown key"
light_error wrong_type '{"type": "point", "power": [10]}' ".*'power': expected a number"
light_error negative_irradiance '{"type": "directional", "irradiance": -3.14}' ".*'irradiance': -3\.14 is out of range"
light_error nan '{"type": "directional", "irradiance": NaN}' "invalid JSON"
light_error unknown_light_type '{"type": "laser"}' ".*unknown value 'laser'"
light_error spot_cone '{"type": "spot", "cone_half_angle_degrees": 120}' ".*'cone_half_angle_degrees': 120 is out of range"
light_error zero_attenuation '{"type": "point", "attenuation": [0, 0, 0]}' ".*'attenuation'.*must not all be zero"
light_error negative_shadow_bias '{"type": "directional", "casts_shadows": true, "shadow": {"depth_bias": -1}}' ".*'depth_bias': -1 is out of range"
light_error zero_shadow_resolution '{"type": "point", "casts_shadows": true, "shadow": {"map_resolution": 0}}' ".*'map_resolution'"
printf '{"format": "glint-scene", "version": 1,\n "materials": [{"name": "g", "model": "glass",\n   "ior": -1.5}],\n "objects": [{"shape": "sphere", "material": "g"}]}\n' >"$out/negative_ior.json"
expect_error negative_ior "negative_ior\.json:3:[0-9]+: .*'ior': -1\.5 is out of range" -- render "$out/negative_ior.json" -o "$out/x.png"
mkdir -p "$out/a_directory.json"
expect_error directory "is a directory" -- render "$out/a_directory.json" -o "$out/x.png"
expect_error no_output "no output file" -- render "$here/scenes/lambert_sun.json"
expect_error bad_size "--size needs" -- render "$here/scenes/lambert_sun.json" -o "$out/x.png" --size 12by7
expect_error unwritable "cannot write|could not open" -- render "$here/scenes/lambert_sun.json" -o "/no/such/dir/x.png"
expect_error unknown_option "unknown option --frobnicate" -- render "$here/scenes/lambert_sun.json" --frobnicate
expect_error overlays_reference "not with --reference" -- render "$here/scenes/lambert_sun.json" -o "$out/x.png" --reference --wireframe
expect_error editor_bad_scene "invalid\.json:4:" -- "$out/invalid.json"
printf '{"format": "glint-scene", "version": 1,\n "materials": [{"name": "m", "model": "cook_torrance",\n   "ior": [1.5, 0, 1.5]}],\n "objects": [{"shape": "sphere", "material": "m"}]}\n' >"$out/zero_ior.json"
expect_error zero_ior "zero_ior\.json:3:[0-9]+: .*'ior\[1\]': 0 is out of range: must be greater than 0" -- render "$out/zero_ior.json" -o "$out/x.png"
# An environment image that is not one: a truncated Radiance header, named at the scene's "file" key.
printf '#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n\x02\x02' >"$out/truncated.hdr"
printf '{\n  "format": "glint-scene", "version": 1,\n  "environment": {"type": "file", "file": "truncated.hdr"},\n  "materials": [{"name": "m", "model": "lambert"}],\n  "objects": [{"shape": "sphere", "material": "m"}]\n}\n' >"$out/bad_hdr.json"
expect_error truncated_hdr "bad_hdr\.json:3:[0-9]+: environment 'file': .*truncated\.hdr: cannot read the environment image" -- render "$out/bad_hdr.json" -o "$out/x.png"
# A built-in environment renders with no file at all.
printf '{\n  "format": "glint-scene", "version": 1,\n  "environment": {"type": "studio"},\n  "materials": [{"name": "m", "model": "cook_torrance"}],\n  "objects": [{"shape": "sphere", "material": "m"}]\n}\n' >"$out/studio.json"
if ! "$glint" render "$out/studio.json" -o "$out/studio.png" --size 64x64 || [[ ! -s "$out/studio.png" ]]; then
  fail "studio environment: no image"
else
  pass "studio environment renders"
fi
# A slow map's precompute is reported on stderr (after 0.5 s: GLINT_PROGRESS_AFTER_SECONDS=0 makes
# any map slow), as stderr is no terminal a line every 5% (app/runtime/progress_line.h) ending at
# 100%. A map done sooner (one hour, here) says nothing.
cp "$here/environments/studio_small_01_256.exr" "$out/"  # beside the scene: a scene reads files from its folder
printf '{"format": "glint-scene", "version": 1, "environment": {"type": "file", "file": "%s"},\n "materials": [{"name": "m", "model": "lambert"}], "objects": [{"shape": "sphere", "material": "m"}]}\n' \
  studio_small_01_256.exr >"$out/exr_map.json"
sed 's/"type": "file", "file": "[^"]*"/"type": "white"/' "$out/exr_map.json" >"$out/white_map.json"
GLINT_PROGRESS_AFTER_SECONDS=0 "$glint" render "$out/exr_map.json" -o "$out/exr_map.png" --size 32x32 2>"$out/exr_map.txt"
GLINT_PROGRESS_AFTER_SECONDS=3600 "$glint" render "$out/white_map.json" -o "$out/white_map.png" --size 32x32 2>"$out/white_map.txt"
if ! progress_lines "precomputing studio_small_01_256.exr" "$out/exr_map.txt" || grep -q precomputing "$out/white_map.txt"; then
  fail "precompute progress on stderr: slow map said '$(cat "$out/exr_map.txt")', fast map '$(cat "$out/white_map.txt")'"
else
  pass "a slow map's precompute is reported on stderr, a fast one's not"
fi
# A CI log of a 200x200 reference render holds at most 25 progress lines (issue 41 met 84
# carriage-return fragments on one line).
if ! "$glint" render "$here/scenes/environment_studio.json" --reference --samples 2 --size 200x200 -o "$out/progress.png" \
     2>"$out/progress.txt" || ! progress_lines "glint render: reference" "$out/progress.txt"; then
  fail "reference progress off a terminal: '$(cat -A "$out/progress.txt" | head -c 600)'"
else
  pass "reference progress off a terminal: $(grep -c "glint render: reference" "$out/progress.txt") lines"
fi
# glint spectral reports after each wavelength, the same way.
if ! "$glint" spectral "$here/../examples/spectral/sodium_lamp.json" -o "$out/spectral.png" --size 24x18 --wavelengths 4 \
     >/dev/null 2>"$out/spectral.txt" || ! progress_lines "glint spectral: wavelengths" "$out/spectral.txt"; then
  fail "spectral progress off a terminal: '$(cat -A "$out/spectral.txt" | head -c 600)'"
else
  pass "spectral progress off a terminal: $(grep -c "glint spectral" "$out/spectral.txt") lines"
fi
# Limits stated, not met by surprise: a texture larger than 16384 texels a side (OpenGL 4.1's least
# GL_MAX_TEXTURE_SIZE) is refused naming its size and the limit; a PLY header declaring 10^12
# vertices is refused before anything is allocated; 257 lights name the limit of 256.
{ printf 'P5\n16385 1\n255\n'; head -c 16385 /dev/zero; } >"$out/wide.pgm"
printf '{"format": "glint-scene", "version": 1,\n "materials": [{"name": "m", "model": "lambert",\n   "textures": {"albedo": {"type": "image", "file": "wide.pgm"}}}],\n "objects": [{"shape": "sphere", "material": "m"}]}\n' >"$out/wide_texture.json"
expect_error wide_texture "wide\.pgm: texture image is 16385×1 texels, larger than Glint's limit of 16384 a side .*refused: scale the image down" -- render "$out/wide_texture.json" -o "$out/x.png"
printf 'ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n3 0 0 0\n' >"$out/huge.ply"
expect_error huge_ply "huge\.ply:3:1: cannot load mesh: the PLY header declares 1000000000000 vertex elements; Glint loads at most 50000000 .*simplify the mesh" -- render "$out/huge.ply" -o "$out/x.png"
{ printf '{"format": "glint-scene", "version": 1, "lights": [\n'; for i in $(seq 256); do printf '{"type": "directional"},\n'; done
  printf '{"type": "directional"}],\n "materials": [{"name": "m", "model": "lambert"}], "objects": [{"shape": "sphere", "material": "m"}]}\n'; } >"$out/lights_257.json"
expect_error too_many_lights "lights_257\.json:[0-9]+:[0-9]+: .*257 lights: Glint supports at most 256 lights per scene \(the GPU's light block: 64 bytes a light, in the 16 KiB that OpenGL 4\.1 guarantees\); merge lights" -- render "$out/lights_257.json" -o "$out/x.png"
expect_error unknown_preset "unknown preset 'unobtainium'" -- presets unobtainium -o "$out/x.json"
printf '{"format": "glint-scene", "version": 1,\n "materials": [{"name": "m", "model": "lambert",\n   "textures": {"albedo": {"type": "image", "file": "maps/missing.png"}}}],\n "objects": [{"shape": "sphere", "material": "m"}]}\n' >"$out/missing_texture.json"
expect_error missing_texture "missing_texture\.json:3:[0-9]+: .*texture 'maps/missing\.png' for 'albedo': .*maps/missing\.png: texture image file not found" -- render "$out/missing_texture.json" -o "$out/x.png"

# Good input: both outputs, the requested size, exit code 0.
if "$glint" render "$here/scenes/lambert_sun.json" -o "$out/sun.png" --size 100x60 &&
   "$glint" render "$here/scenes/lambert_sun.json" -o "$out/sun.exr" &&
   [[ $(od -An -tu1 -j16 -N8 "$out/sun.png" | tr -s ' ') == " 0 0 0 100 0 0 0 60" ]] &&
   [[ $(head -c 4 "$out/sun.exr" | od -An -tx1 | tr -d ' ') == "762f3101" ]]; then
  pass "render: PNG 100x60 and EXR written"
else
  fail "render: good input did not produce the images"
fi
# Presets: the list names sources; a preset written to a file is a material file.
if "$glint" presets >"$out/presets.stdout" && grep -q "^gold .*cook_torrance.*McPeak" "$out/presets.stdout" &&
   "$glint" presets copper -o "$out/copper.json" >/dev/null && grep -q '"format": "glint-material"' "$out/copper.json"; then
  pass "presets: listed $(($(wc -l <"$out/presets.stdout") - 1)), copper written"
else
  fail "presets: no list or no material file"
fi
# Classroom: display lessons and compare views (docs/classroom.md, "Classroom: compare and display chain").
sun="$here/scenes/lambert_sun.json"
expect_error bad_levels "--levels needs a whole number in \[2, 256\]" -- render "$sun" -o "$out/x.png" --levels 1
expect_error bad_dither "--dither needs none, bayer2, bayer4 or halftone" -- render "$sun" -o "$out/x.png" --dither floyd
expect_error compare_one_pane "--compare needs 2 to 4" -- render "$sun" -o "$out/x.png" --compare only.json
expect_error compare_missing_material "/no/such/material\.json" -- render "$sun" -o "$out/x.png" --compare /no/such/material.json,preset:gold
expect_error compare_reference "compare views are drawn by the OpenGL renderer" -- render "$sun" -o "$out/x.png" --compare preset:gold,preset:copper --reference
if "$glint" render "$sun" -o "$out/compare.png" --size 96x64 --compare preset:gold,preset:copper --levels 8 --dither bayer2 &&
   "$glint" render "$sun" -o "$out/shading.png" --size 96x48 --compare-interpolation --tessellation 8x4 &&
   [[ -s "$out/compare.png" && -s "$out/shading.png" ]]; then
  pass "classroom: split compare with 8 dithered levels, interpolation row"
else
  fail "classroom: no compare image"
fi
# Every sample count --msaa accepts renders: above what this OpenGL offers (llvmpipe: 4) with a note, never a failed check.
msaa_failed=0
for samples in 1 2 4 8 16; do
  DISPLAY= "$glint" render "$sun" -o "$out/msaa$samples.png" --size 48x32 --msaa "$samples" 2>"$out/msaa$samples.stderr" &&
    [[ -s "$out/msaa$samples.png" ]] || { echo "FAIL msaa $samples:"; cat "$out/msaa$samples.stderr"; msaa_failed=1; }
done
if [[ $msaa_failed -eq 0 ]] && grep -q "note: MSAA 16 asked; this OpenGL offers at most [0-9]* samples" "$out/msaa16.stderr"; then
  pass "msaa: 1 to 16 render; $(head -n 1 "$out/msaa16.stderr")"
else
  fail "msaa: a sample count failed or 16 gave no note"
fi
# No display: plain `glint` renders the default scene headless and says where it went.
if (cd "$out" && DISPLAY= "$glint" >"$out/nodisplay.stdout") && grep -q "glint-default.png" "$out/nodisplay.stdout" &&
   [[ -s "$out/glint-default.png" ]]; then
  pass "no display: $(tail -n 1 "$out/nodisplay.stdout")"
else
  fail "no display: no headless image"
fi

summary
