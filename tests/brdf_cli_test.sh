#!/usr/bin/env bash
# `glint render` on BRDF Explorer files: a .brdf renders on the preview stage, a material JSON
# that references one renders too; the reference renderer, parse errors, GLSL errors and an
# endless loop each end with exit code 2 and a located message (the loop within its timeout).
# usage: brdf_cli_test.sh GLINT OUTPUT_DIR EXAMPLES_DIR
examples=$3
source "$(dirname "$0")/cli_checks.sh" "$@"
# A loaded CI machine may need more than the default 8 s to prove a good shader; the endless-loop
# case sets its own 2 s.
export GLINT_BRDF_TIMEOUT_S=60

expect_image() {  # expect_image NAME IMAGE -- ARGS...
  local name=$1 image=$2
  shift 3
  if "$glint" "$@" >"$out/$name.stdout" 2>"$out/$name.stderr" && [[ -s $image ]]; then
    pass "$name"
  else
    fail "$name:"; cat "$out/$name.stderr"
  fi
}

for example in "$examples"/*.brdf; do
  name=$(basename "$example" .brdf)
  expect_image "example_$name" "$out/$name.png" -- render "$example" -o "$out/$name.png" --size 64x64
done

cp "$examples/ggx_smith.brdf" "$out/ggx.brdf"
cat >"$out/ggx_material.json" <<'JSON'
{
  "format": "glint-material", "version": 1,
  "name": "rough plastic", "model": "brdf_file", "brdf_file": "ggx.brdf",
  "roughness": 0.5, "diffuse": [0.3, 0.1, 0.05], "specularOn": true
}
JSON
expect_image material_json "$out/material.png" -- render "$out/ggx_material.json" -o "$out/material.png" --size 64x64
sed 's/"roughness": 0.5/"roughness": 5/' "$out/ggx_material.json" >"$out/out_of_range.json"
expect_error material_out_of_range "out_of_range.json:4:.*roughness" -- render "$out/out_of_range.json" -o "$out/x.png"
sed 's/"ggx.brdf"/"missing.brdf"/' "$out/ggx_material.json" >"$out/missing.json"
expect_error material_missing_brdf "missing.json:3:.*brdf_file.*missing.brdf" -- render "$out/missing.json" -o "$out/x.png"

expect_error reference_refused "custom .brdf shaders run only on the GPU preview" -- \
  render --reference "$examples/lambert.brdf" -o "$out/x.png"

printf 'analytic\n::begin parameters\nfloat a 0 1 0.5x\n::end parameters\n' >"$out/bad_number.brdf"
expect_error parse_error "bad_number.brdf:3:13: a default: '0.5x' is not a number" -- render "$out/bad_number.brdf" -o "$out/x.png"

cp "$here/brdf_files/glsl_error.brdf" "$here/brdf_files/endless.brdf" "$out/"
expect_error glsl_error "glsl_error.brdf:7:[0-9]+: error" -- render "$out/glsl_error.brdf" -o "$out/x.png"

start=$(date +%s)
GLINT_BRDF_TIMEOUT_S=2 expect_error endless_loop "endless.brdf:2:1: the shader did not finish in 2 s" -- \
  render "$out/endless.brdf" -o "$out/x.png"
elapsed=$(($(date +%s) - start))
if [[ $elapsed -gt 15 ]]; then fail "endless_loop took ${elapsed} s"; fi
[[ -e "$out/x.png" ]] && fail "an image was written for a failed render"

summary
