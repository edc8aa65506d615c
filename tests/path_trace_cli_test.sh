#!/usr/bin/env bash
# `glint render --path-trace`: what it refuses (exit code 2 and a message), its progress off a
# terminal, and that a seed gives the same picture again. usage: path_trace_cli_test.sh GLINT OUTPUT_DIR
source "$(dirname "$0")/cli_checks.sh" "$@"
box="$here/scenes/cornell_box.json"

expect_error both_renderers "give --reference or --path-trace, not both" -- render "$box" -o "$out/x.png" --path-trace --reference
expect_error samples_alone "--samples needs --reference .* or --path-trace" -- render "$box" -o "$out/x.png" --samples 4
expect_error seed_alone "--seed needs --path-trace" -- render "$box" -o "$out/x.png" --seed 3
expect_error bounces_alone "--bounces needs --path-trace" -- render "$box" -o "$out/x.png" --bounces 2 --reference
expect_error no_bounces "--bounces needs a whole number from 1 to 1000" -- render "$box" -o "$out/x.png" --path-trace --bounces 0
expect_error wide_seed "--seed needs a whole number from 0 to 4294967295" -- render "$box" -o "$out/x.png" --path-trace --seed 4294967296
expect_error wireframe "not with --path-trace" -- render "$box" -o "$out/x.png" --path-trace --wireframe

# Progress on stderr, one line per 5% at most; the same seed, the same picture, another seed
# another (PNGs: an EXR's header holds the time it was written; path_tracer_test.cpp compares
# the radiance itself to the bit).
for run in first:9 second:9 other:10; do
  "$glint" render "$box" --path-trace --samples 4 --seed "${run#*:}" --size 24x24 -o "$out/${run%:*}.png" 2>"$out/${run%:*}.txt"
done
if progress_lines "glint render: path trace" "$out/first.txt"; then
  pass "path-trace progress off a terminal: $(grep -c "glint render: path trace" "$out/first.txt") lines"
else
  fail "path-trace progress off a terminal: '$(cat -A "$out/first.txt" | head -c 600)'"
fi
if [[ -s "$out/first.png" ]] && cmp -s "$out/first.png" "$out/second.png" && ! cmp -s "$out/first.png" "$out/other.png"; then
  pass "the same seed writes the same picture, another seed another"
else
  fail "seeds 9, 9 and 10 wrote: $(cksum "$out"/first.png "$out"/second.png "$out"/other.png 2>&1 | tr '\n' ' ')"
fi

summary
