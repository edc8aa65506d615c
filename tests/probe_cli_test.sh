#!/usr/bin/env bash
# `glint render --probe X,Y --overlay probe`: the printed chain at the lambert_sun centre (E = π,
# f_r = 0.5/π, L = 0.5, 8-bit 188), the overlay drawn over the PNG, and bad probe arguments
# refused with exit code 2. usage: probe_cli_test.sh GLINT OUTPUT_DIR
source "$(dirname "$0")/cli_checks.sh" "$@"
sun="$here/scenes/lambert_sun.json"

# The worked example: the centre of a 255x255 image is the sphere's apex.
if "$glint" render "$sun" -o "$out/probe.png" --size 255x255 --reference --probe 127,127 --overlay probe >"$out/probe.stdout" &&
   grep -q "E = E⊥·cos θ = 3.142 W/m² × 1.000 = 3.142 W/m²" "$out/probe.stdout" &&
   grep -q "L = f_r·E = 0.159 1/sr × 3.142 W/m² = 0.500 W/(sr·m²)" "$out/probe.stdout" &&
   grep -q "→ 8-bit 188" "$out/probe.stdout" && [[ -s "$out/probe.png" ]]; then
  pass "probe: $(grep 'L = f_r' "$out/probe.stdout" | head -n 1 | sed 's/^ *//')"
else
  fail "probe: the printed chain or the PNG is wrong"; cat "$out/probe.stdout"
fi
# A miss says so.
if "$glint" render "$sun" -o "$out/miss.png" --size 64x64 --probe 0,0 >"$out/miss.stdout" &&
   grep -q "no surface" "$out/miss.stdout"; then
  pass "probe miss: no surface"
else
  fail "probe miss: no 'no surface' line"
fi

# probe_error NAME PATTERN ARGS...: rendering the sun scene with ARGS exits with code 2, stderr matching the pattern.
probe_error() {
  local name=$1 pattern=$2
  shift 2
  expect_error "$name" "$pattern" render "$sun" -o "$out/x.png" --size 64x64 "$@"
}
probe_error probe_outside "--probe 64,3 lies outside the 64x64 image" --probe 64,3
probe_error probe_syntax "--probe needs a pixel X,Y" --probe 3
probe_error overlay_unknown "unknown overlay 'sparkles'" --overlay sparkles
probe_error overlay_needs_probe "--overlay probe needs --probe X,Y" --overlay probe
probe_error overlay_exr "write a PNG" --probe 3,3 --overlay probe -o "$out/x.exr"

summary
