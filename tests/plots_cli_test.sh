#!/usr/bin/env bash
# `glint render --overlay polar|lobe|albedo|fresnel`: each plot is written as a PNG, also of a
# .brdf material (sampled on the GPU) and a MERL table, and beside the probe overlay on one
# canvas; bad plot options exit with code 2 and a message. usage: plots_cli_test.sh GLINT OUTPUT_DIR TESTS_DIR
tests=$3
source "$(dirname "$0")/cli_checks.sh" "$@"

expect_png() {  # expect_png NAME ARGS...: exit code 0 and a non-empty PNG at $out/NAME.png
  local name=$1
  shift
  if "$glint" render "$@" -o "$out/$name.png" --size 200x160 >"$out/$name.stdout" 2>"$out/$name.stderr" && [[ -s "$out/$name.png" ]]; then
    pass "$name"
  else
    fail "$name:"; cat "$out/$name.stderr"
  fi
}

render_error() {  # render_error NAME REGEX ARGS...: `glint render ARGS` exits with code 2, stderr matching REGEX
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "$pattern" render "$@"
}

blinn="$tests/scenes/blinn_point.json"
glass="$tests/scenes/glass_sphere.json"
expect_png polar "$blinn" --overlay polar --incidence 30
expect_png lobe "$glass" --overlay lobe --incidence 60
expect_png albedo "$blinn" --overlay albedo
expect_png fresnel "$glass" --overlay fresnel --from-inside
export GLINT_BRDF_TIMEOUT_S=60  # the .brdf safety probe, on a loaded machine
expect_png polar_brdf "$tests/../examples/brdf/lambert.brdf" --overlay polar --incidence 20
/usr/bin/python3 -c '
import struct, sys
with open(sys.argv[1], "wb") as f:
    f.write(struct.pack("<3i", 90, 90, 180))
    for scale in (1500.0, 1500.0 / 1.15, 1500.0 / 1.66):
        f.write(struct.pack("<d", 0.5 / 3.141592653589793 * scale) * (90 * 90 * 180))' "$out/grey.binary"
expect_png albedo_merl "$out/grey.binary" --overlay albedo
expect_png plot_and_probe "$blinn" --overlay polar --overlay probe --probe 100,80
render_error two_plots "one plot per image" "$blinn" -o "$out/x.png" --overlay polar --overlay lobe
render_error fresnel_merl "grey\" is a measured table" "$out/grey.binary" -o "$out/x.png" --overlay fresnel
render_error bad_incidence "--incidence needs an angle in degrees from 0 to 90 \(got 95\)" "$blinn" -o "$out/x.png" --overlay polar --incidence 95
render_error nan_incidence "--incidence needs an angle" "$blinn" -o "$out/x.png" --overlay polar --incidence nan
render_error unknown_plot "(unknown option --overlay|bogus)" "$blinn" -o "$out/x.png" --overlay bogus
render_error plot_reference "not with --reference" "$blinn" -o "$out/x.png" --overlay albedo --reference
render_error plot_exr "drawn on the PNG" "$blinn" -o "$out/x.exr" --overlay albedo
render_error incidence_alone "--incidence needs --overlay" "$blinn" -o "$out/x.png" --incidence 30
render_error fresnel_without_index "no material in the scene has an index of refraction" "$blinn" -o "$out/x.png" --overlay fresnel

summary
