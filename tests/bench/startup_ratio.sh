#!/usr/bin/env bash
# Whole-process time of `glint render lambert_sun.json` at 512×512 against the bare OSMesa
# program (context, clear, read back, PNG), interleaved run by run; prints the medians and the ratio.
# usage: tests/bench/startup_ratio.sh [BUILD_DIR] [RUNS]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:-$here/../../build}
runs=${2:-21}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export DISPLAY=
now() { date +%s%N; }
glint_times=() bare_times=()
for ((i = 0; i < runs; ++i)); do
  start=$(now); "$build/app/glint" render "$here/../scenes/lambert_sun.json" -o "$out/glint.png" --size 512x512; glint_times+=($(( $(now) - start )))
  start=$(now); "$build/tests/bench/bare_osmesa_png" "$out/bare.png" 512 512; bare_times+=($(( $(now) - start )))
done
median() { printf '%s\n' "$@" | sort -n | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
glint_ms=$(( $(median "${glint_times[@]}") / 1000000 ))
bare_ms=$(( $(median "${bare_times[@]}") / 1000000 ))
echo "glint render lambert_sun.json 512x512: median ${glint_ms} ms over $runs runs"
echo "bare OSMesa context+clear+readback+PNG:  median ${bare_ms} ms over $runs runs"
awk -v g="$glint_ms" -v b="$bare_ms" 'BEGIN { printf "ratio: %.2f\n", g / b }'
