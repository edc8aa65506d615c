#!/usr/bin/env bash
# `glint lessons` and `glint spectral` from outside: the shipped lessons all load (--check) and
# all render headless (--render, 64 px wide, one PNG each); a broken list or bad spectral
# settings exit 2 with a message. usage: classroom_cli_test.sh GLINT OUTPUT_DIR SOURCE_DIR
source=$3
source "$(dirname "$0")/cli_checks.sh" "$@"

"$glint" lessons --check >"$out/check.stdout" 2>"$out/check.stderr" || fail "lessons --check exited $? ($(cat "$out/check.stderr"))"
grep -q "18 lessons, 18 load, 0 failed" "$out/check.stdout" || fail "lessons --check summary: $(tail -n 1 "$out/check.stdout")"
grep -q "White-out" "$out/check.stdout" || fail "lessons list does not name the white-out lesson"

"$glint" lessons --render "$out/rendered" --width 64 >"$out/render.stdout" 2>"$out/render.stderr" || fail "lessons --render exited $?"
count=$(ls "$out/rendered"/*.png 2>/dev/null | wc -l)
[[ $count -eq 18 ]] || fail "lessons --render wrote $count PNGs, expected 18"
[[ -s "$out/rendered/08_08_white_out.png" ]] || fail "no white-out render"
[[ -s "$out/rendered/17_17_dispersion.png" ]] || fail "no dispersion render"

printf '{"format": "glint-lessons", "version": 1,\n "lessons": [{"title": "A", "scene": "missing.json"}]}\n' >"$out/missing.json"
"$glint" lessons "$out/missing.json" --check >/dev/null 2>"$out/missing.stderr"
[[ $? -eq 1 ]] || fail "a lesson with a missing scene should exit 1"
grep -q "missing.json" "$out/missing.stderr" || fail "missing scene not named: $(cat "$out/missing.stderr")"
printf '{"format": "glint-lessons", "version": 1,\n "lessons": [{"title": "A", "scene": "a.json", "slide": 1}]}\n' >"$out/bad.json"
"$glint" lessons "$out/bad.json" >/dev/null 2>"$out/bad.stderr"
[[ $? -eq 2 ]] || fail "an unknown key in the list should exit 2"
grep -Eq "bad.json:2:[0-9]+: .*slide" "$out/bad.stderr" || fail "unknown key not located: $(cat "$out/bad.stderr")"

"$glint" spectral "$source/examples/spectral/sodium_lamp.json" -o "$out/sodium.png" --size 48x36 --band 589,2 --wavelengths 4 \
  >"$out/spectral.stdout" 2>"$out/spectral.stderr" || fail "spectral exited $? ($(cat "$out/spectral.stderr"))"
[[ -s "$out/sodium.png" ]] || fail "spectral wrote no image"
"$glint" spectral "$source/examples/spectral/sodium_lamp.json" -o "$out/bad.png" --band 900,2 >/dev/null 2>"$out/band.stderr"
[[ $? -eq 2 ]] || fail "a band outside 380-780 nm should exit 2"
grep -q "outside the visible range" "$out/band.stderr" || fail "band message: $(cat "$out/band.stderr")"
"$glint" spectral "$source/examples/spectral/dispersion.json" -o "$out/bad.png" --cauchy-b nan >/dev/null 2>"$out/nan.stderr"
[[ $? -eq 2 ]] || fail "--cauchy-b nan should exit 2"

"$glint" cmf -o "$out/cmf.png" --size 320x200 >/dev/null 2>"$out/cmf.stderr" || fail "cmf exited $? ($(cat "$out/cmf.stderr"))"
[[ -s "$out/cmf.png" ]] || fail "cmf wrote no image"
"$glint" cmf -o "$out/cmf_bad.png" --size 10x10 >/dev/null 2>&1
[[ $? -eq 2 ]] || fail "cmf --size 10x10 should exit 2"

[[ $failures -eq 0 ]] && echo "classroom CLI: all passed"
exit $((failures > 0))
