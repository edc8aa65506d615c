#!/usr/bin/env bash
# `glint render --overlay polar|lobe|albedo|fresnel`: each plot is written as a PNG, also of a
# .brdf material (sampled on the GPU) and a MERL table, and beside the probe overlay on one
# canvas; bad plot options exit with code 2 and a message. usage: plots_cli_test.sh GLINT OUTPUT_DIR TESTS_DIR
set -u
glint=$1
out=$2
tests=$3
rm -rf "$out" && mkdir -p "$out"
failures=0
passes=0

expect_png() {  # expect_png NAME ARGS...: exit code 0 and a non-empty PNG at $out/NAME.png
  local name=$1
  shift
  if "$glint" render "$@" -o "$out/$name.png" --size 200x160 >"$out/$name.stdout" 2>"$out/$name.stderr" && [[ -s "$out/$name.png" ]]; then
    echo "ok   $name"; passes=$((passes + 1))
  else
    echo "FAIL $name:"; cat "$out/$name.stderr"; failures=$((failures + 1))
  fi
}

expect_error() {  # expect_error NAME REGEX ARGS...: exit code 2 and stderr matching REGEX
  local name=$1 pattern=$2
  shift 2
  "$glint" render "$@" >/dev/null 2>"$out/$name.stderr"
  local code=$?
  if [[ $code -eq 2 ]] && grep -Eq -- "$pattern" "$out/$name.stderr"; then
    echo "ok   $name: $(head -n 1 "$out/$name.stderr")"; passes=$((passes + 1))
  else
    echo "FAIL $name: exit code $code"; cat "$out/$name.stderr"; failures=$((failures + 1))
  fi
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
expect_error two_plots "one plot per image" "$blinn" -o "$out/x.png" --overlay polar --overlay lobe
expect_error fresnel_merl "grey\" is a measured table" "$out/grey.binary" -o "$out/x.png" --overlay fresnel
expect_error bad_incidence "--incidence needs an angle in degrees from 0 to 90 \(got 95\)" "$blinn" -o "$out/x.png" --overlay polar --incidence 95
expect_error nan_incidence "--incidence needs an angle" "$blinn" -o "$out/x.png" --overlay polar --incidence nan
expect_error unknown_plot "(unknown option --overlay|bogus)" "$blinn" -o "$out/x.png" --overlay bogus
expect_error plot_reference "not with --reference" "$blinn" -o "$out/x.png" --overlay albedo --reference
expect_error plot_exr "drawn on the PNG" "$blinn" -o "$out/x.exr" --overlay albedo
expect_error incidence_alone "--incidence needs --overlay" "$blinn" -o "$out/x.png" --incidence 30
expect_error fresnel_without_index "no material in the scene has an index of refraction" "$blinn" -o "$out/x.png" --overlay fresnel

echo "$passes passed, $failures failed"
[[ $failures -eq 0 ]]
