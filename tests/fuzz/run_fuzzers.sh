#!/usr/bin/env bash
# Runs every fuzz target for a while (default 300 s each) on a copy of its corpus, and copies
# any crashing input into the checked-in corpus as a regression file.
# usage: tests/fuzz/run_fuzzers.sh [SECONDS_PER_TARGET]
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
seconds=${1:-300}
build="$root/build-fuzz"
if [[ ! -f "$build/build.ninja" ]]; then
  CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$build" -G Ninja -DGLINT_FUZZ=ON -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build"
# Libraries' own leaks (OpenImageIO's error text, reached through glTF's embedded images) are
# suppressed as in the test command's sanitizer build.
export LSAN_OPTIONS="suppressions=$root/tests/sanitizer/lsan.supp"
status=0
for corpus in "$root"/tests/fuzz/corpus/*/; do
  target=$(basename "$corpus")
  work=$(mktemp -d)
  cp "$corpus"* "$work"/
  echo "fuzz_$target: ${seconds} s"
  extra=()  # assimp 5.2.5 leaks inside its STL reader on malformed input (see tests/fuzz/CMakeLists.txt)
  [[ $target == mesh_import ]] && extra=(-detect_leaks=0)
  if ! (cd "$work" && "$build/tests/fuzz/fuzz_$target" -max_total_time="$seconds" -max_len=4096 -timeout=10 \
          -rss_limit_mb=2048 "${extra[@]}" "$work" >"$work/log" 2>&1); then
    status=1
    for crash in "$work"/crash-* "$work"/timeout-* "$work"/leak-*; do
      [[ -e $crash ]] && cp "$crash" "$corpus/regression-$(basename "$crash")" && echo "  kept $(basename "$crash") in the corpus"
    done
    tail -n 30 "$work/log"
  fi
  rm -rf "$work"
done
exit $status
