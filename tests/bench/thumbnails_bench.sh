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

seconds() { date +%s.%N; }
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

run_thumbnails() {  # run_thumbnails JOBS → seconds
  local start; start=$(seconds)
  "$glint" thumbnails "$work/materials" -o "$work/thumbs_$1" --jobs "$1" >/dev/null
  echo "$(seconds) - $start" | bc -l
}
run_processes() {  # 100 × glint render → seconds
  local start; start=$(seconds)
  mkdir -p "$work/processes"
  for material in "$work"/materials/*.json; do
    "$glint" render "$material" -o "$work/processes/$(basename "$material" .json).png"
  done
  echo "$(seconds) - $start" | bc -l
}

one=() two=() many=()
for _ in $(seq "$runs"); do
  one+=("$(run_thumbnails 1)")
  two+=("$(run_thumbnails 2)")
  many+=("$(run_processes)")
done
t1=$(printf '%s\n' "${one[@]}" | median)
t2=$(printf '%s\n' "${two[@]}" | median)
tp=$(printf '%s\n' "${many[@]}" | median)
echo "runs: $runs (median); machine: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg)"
printf 'glint thumbnails --jobs 1: %6.2f s  %6.1f thumbnails/s   (runs: %s)\n' "$t1" "$(echo "100 / $t1" | bc -l)" "${one[*]}"
printf 'glint thumbnails --jobs 2: %6.2f s  %6.1f thumbnails/s   (runs: %s)\n' "$t2" "$(echo "100 / $t2" | bc -l)" "${two[*]}"
printf '100 x glint render:        %6.2f s  %6.1f thumbnails/s   (runs: %s)\n' "$tp" "$(echo "100 / $tp" | bc -l)" "${many[*]}"
printf 'one process (--jobs 1) is %.1fx faster than a process per image\n' "$(echo "$tp / $t1" | bc -l)"
