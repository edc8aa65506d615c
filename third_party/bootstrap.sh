#!/usr/bin/env bash
# The README's two commands: installs what is missing (Debian packages), configures and builds
# Glint, then either runs the editor (`run`, with any arguments passed on to glint) or the
# whole test suite (`test`): the normal build, then one clang build that runs the headless suite
# again under AddressSanitizer + UndefinedBehaviorSanitizer and the fuzz targets on their corpus.
# Idempotent; quick when everything is already there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${GLINT_BUILD_DIR:-$root/build}"
mode=${1:-}
[[ $mode == run || $mode == test ]] || { echo "usage: $0 run [glint arguments…] | test" >&2; exit 2; }
shift

# configure_and_build DIR [CMAKE ARGS…]: configures (under a second when nothing changed, and an
# older folder gets any option added since), then builds incrementally.
configure_and_build() {
  local dir=$1
  shift
  cmake -S "$root" -B "$dir" -G Ninja "$@"
  cmake --build "$dir"
}

"$root/third_party/install-deps.sh"
# Optimised; line tables only (-g1): stack traces keep file and line. Unity batches (see
# CMakeLists.txt) and -g1 keep the test command's two builds inside CI's time budget.
configure_and_build "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
  -DGLINT_UNITY_BUILD=ON -DGLINT_SHARD_GTESTS=ON
[[ $mode == run ]] && exec "$build/app/glint" "$@"

# test: each suite's ctest summary is collected, then one closing line for all of them.
logs=$(mktemp -d)
trap 'rm -rf "$logs"' EXIT
suite_failed=0
run_suite() {  # run_suite NAME DIR [CTEST ARGS…]
  local name=$1 dir=$2
  shift 2
  echo "=== $name ==="
  (cd "$dir" && ctest --output-on-failure --timeout 300 "$@") 2>&1 | tee "$logs/$name.log" || suite_failed=1
}
# Two at a time (most tests spend their time compiling shaders on one core), but the GUI tests
# alone afterwards: they drive a real X server and wait for frames.
run_suite tests "$build" -j2 -LE "gui|heavy"
run_suite gui "$build" -L gui

# One clang-14 build runs the headless suite under AddressSanitizer + UndefinedBehaviorSanitizer and
# holds the libFuzzer targets (core instrumented for them), which run on their corpus in the same
# ctest, and the test that compiles each source of its unity batches on its own (`includes`). -O1,
# as AddressSanitizer's own documentation advises: the numerical property tests run several times
# faster than at -O0, and every report keeps its file and line. A folder configured
# by an older test command with another compiler is configured afresh.
sanitize="$root/build-sanitize"
if [[ -f "$sanitize/CMakeCache.txt" ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$' "$sanitize/CMakeCache.txt"; then
  rm -rf "$sanitize"
fi
CC=clang-14 CXX=clang++-14 configure_and_build "$sanitize" -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" \
  -DGLINT_SANITIZE=ON -DGLINT_FUZZ=ON -DGLINT_UNITY_BUILD=ON -DGLINT_CHECK_INCLUDES=ON
# GUI tests need a window manager's timing, and the benchmark's timings mean nothing under ASan
# (its code paths are the renderer's, which the GPU tests cover there); the tests labelled
# `pictures` spend their time in llvmpipe, on host code the other tests run (tests/CMakeLists.txt).
ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS="suppressions=$root/tests/sanitizer/lsan.supp" \
UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 run_suite sanitizers "$sanitize" -j2 -LE "gui|bench|heavy|pictures"

total_passed=0 total_failed=0
for log in "$logs"/*.log; do
  summary=$(grep -E '^[0-9]+% tests passed, [0-9]+ tests? failed out of [0-9]+' "$log" | tail -n 1) || true
  if [[ -z $summary ]]; then suite_failed=1; echo "glint: $(basename "$log" .log) printed no summary"; continue; fi
  failed=$(sed -E 's/.* ([0-9]+) tests? failed out of ([0-9]+).*/\1/' <<<"$summary")
  total=$(sed -E 's/.* failed out of ([0-9]+).*/\1/' <<<"$summary")
  total_passed=$((total_passed + total - failed))
  total_failed=$((total_failed + failed))
done
echo "tests: $total_passed passed, $total_failed failed"
[[ $suite_failed -eq 0 && $total_failed -eq 0 ]]
