#!/usr/bin/env bash
# Benchmark (not a test): 100 material thumbnails at 256×256 rendered by one `glint thumbnails`
# process (--jobs 1 and --jobs 2) and by 100 separate `glint render` processes; prints the
# median of RUNS repetitions and the ratios. usage: thumbnails_bench.sh GLINT [RUNS=3] [WORKDIR]
set -eu
glint=$(realpath "$1")
runs=${2:-3}
work=${3:-$(mktemp -d)}
export DISPLAY=
mkdir -p "$work/materials"

# 100 materials: Lambert and the four Blinn-Phong forms, colours and exponents spread out.
forms=(lecture max_cosine half_vector normalized)
for i in $(seq 0 99); do
  r=$(printf '0.%02d' $(((i * 37) % 90 + 5))) g=$(printf '0.%02d' $(((i * 53) % 90 + 5))) b=$(printf '0.%02d' $(((i * 71) % 90 + 5)))
  if ((i % 5 == 0)); then
    echo "{ \"format\": \"glint-material\", \"version\": 1, \"model\": \"lambert\", \"albedo\": [$r, $g, $b] }"
  else
    echo "{ \"format\": \"glint-material\", \"version\": 1, \"model\": \"blinn_phong\", \"diffuse_albedo\": [$r, $g, $b]," \
         "\"specular\": 0.1, \"exponent\": $((4 + i * 3)), \"form\": \"${forms[i % 4]}\" }"
  fi >"$work/materials/material_$(printf %03d "$i").json"
done

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
TIMEFORMAT='%R %U %S'  # bash's `time`: wall, user and system seconds (children included)

run_thumbnails() {  # run_thumbnails JOBS → "wall user system"
  { time "$glint" thumbnails "$work/materials" -o "$work/thumbs_$1" --jobs "$1" >/dev/null; } 2>&1
}
run_processes() {  # 100 × glint render → "wall user system"
  mkdir -p "$work/processes"
  { time for material in "$work"/materials/*.json; do
      "$glint" render "$material" -o "$work/processes/$(basename "$material" .json).png"
    done; } 2>&1
}

one=() two=() many=()
for _ in $(seq "$runs"); do
  one+=("$(run_thumbnails 1)")
  two+=("$(run_thumbnails 2)")
  many+=("$(run_processes)")
done
wall() { printf '%s\n' "$@" | cut -d' ' -f1 | median; }
cpu() { printf '%s\n' "$@" | awk '{ print $2 + $3 }' | median; }
echo "runs: $runs (medians); machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
report() {  # report LABEL TIMES...
  local label=$1; shift
  local w c; w=$(wall "$@"); c=$(cpu "$@")
  printf '%-27s %6.2f s wall = %5.1f thumbnails/s; %6.2f s CPU = %5.1f ms CPU per thumbnail   (wall: %s)\n' \
    "$label" "$w" "$(echo "100 / $w" | bc -l)" "$c" "$(echo "10 * $c" | bc -l)" "$(printf '%s\n' "$@" | cut -d' ' -f1 | tr '\n' ' ')"
}
report "glint thumbnails --jobs 1:" "${one[@]}"
report "glint thumbnails --jobs 2:" "${two[@]}"
report "100 x glint render:" "${many[@]}"
printf 'one process (--jobs 1) is %.1fx faster (wall) and uses %.1fx less CPU than a process per image\n' \
  "$(echo "$(wall "${many[@]}") / $(wall "${one[@]}")" | bc -l)" "$(echo "$(cpu "${many[@]}") / $(cpu "${one[@]}")" | bc -l)"
