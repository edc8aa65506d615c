#!/usr/bin/env bash
# The README's two commands: installs what is missing (Debian packages), configures and builds
# Glint, then either runs the editor (`run`, with any arguments passed on to glint) or the
# whole test suite (`test`), each test once: the normal, optimised build runs what users see
# (the GPU tests and other pictures, the GUI, the benchmark, the soak), and one clang build runs
# the unit, editor and command-line tests under AddressSanitizer + UndefinedBehaviorSanitizer, and
# the fuzz targets on their corpus. Idempotent; quick when everything is already there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${GLINT_BUILD_DIR:-$root/build}"
mode=${1:-}
[[ $mode == run || $mode == test ]] || { echo "usage: $0 run [glint arguments…] | test" >&2; exit 2; }
shift

# configure_and_build DIR [CMAKE ARGS…]: configures (under a second when nothing changed, and an
# older folder gets any option added since), then builds incrementally.
configure_and_build() {
  cmake -S "$root" -B "$1" -G Ninja "${@:2}"
  cmake --build "$1"
}

"$root/third_party/install-deps.sh"
# Commit messages are checked by the repository's hook (docs/contributing.md).
if git -C "$root" rev-parse --git-dir >/dev/null 2>&1; then git -C "$root" config core.hooksPath .githooks; fi
# Optimised; line tables only (-g1): stack traces keep file and line. Unity batches (see
# CMakeLists.txt) and -g1 keep the test command's two builds inside CI's time budget.
# The unit tests are left out here: the sanitizer build below runs them.
configure_and_build "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O2 -g1 -DNDEBUG" \
  -DGLINT_UNITY_BUILD=ON -DGLINT_UNIT_TESTS=OFF -DGLINT_SHARD_GTESTS=ON
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
# One clang-14 build runs the unit, editor and command-line tests under AddressSanitizer +
# UndefinedBehaviorSanitizer and holds the libFuzzer targets (core instrumented for them), which run
# on their corpus in the same ctest, and the test that compiles each source of its unity batches on
# its own (`includes`). The program at -O1, as AddressSanitizer's own documentation advises: the
# numerical property tests run several times faster than at -O0, and every report keeps its file
# and line (the tests' own code is compiled at -O0, uninstrumented: tests/CMakeLists.txt).
# A folder configured by an older test command with another compiler is configured afresh.
sanitize="$root/build-sanitize"
if [[ -f "$sanitize/CMakeCache.txt" ]] && ! grep -q '^CMAKE_CXX_COMPILER:[A-Z]*=.*clang++-14$' "$sanitize/CMakeCache.txt"; then
  rm -rf "$sanitize"
fi
CC=clang-14 CXX=clang++-14 cmake -S "$root" -B "$sanitize" -G Ninja -DCMAKE_BUILD_TYPE=Debug "-DCMAKE_CXX_FLAGS_DEBUG=-O1 -g1" \
  -DGLINT_SANITIZE=ON -DGLINT_FUZZ=ON -DGLINT_UNITY_BUILD=ON -DGLINT_CHECK_INCLUDES=ON

# The optimised build's tests two at a time (most spend their time compiling shaders on one core),
# then the GUI tests one at a time: they drive a real X server and wait for frames, which leaves
# about half of the two cores idle, so the sanitizer build compiles meanwhile at the lowest priority.
run_suite tests "$build" -j2 -LE "gui|heavy"
nice -n 19 cmake --build "$sanitize" >"$logs/sanitizer-build.txt" 2>&1 &
sanitizer_build=$!
run_suite gui "$build" -L gui
# The GUI tests are done, so the build need no longer yield to them: beside other busy processes
# a build left at nice 19 barely runs (it got about 2% of a core beside two busy loops). Raising
# a priority again needs root, as CI has; elsewhere the build stays at 19.
raise_priority() {  # raise_priority PID: PID and everything it started, back to nice 0
  local child
  for child in $(cat /proc/"$1"/task/*/children 2>/dev/null); do raise_priority "$child"; done
  renice -n 0 -p "$1" >/dev/null 2>&1 || true
}
raise_priority "$sanitizer_build"
echo "=== sanitizer build ==="
wait "$sanitizer_build" || { cat "$logs/sanitizer-build.txt"; echo "glint: the sanitizer build failed"; exit 1; }
tail -n 3 "$logs/sanitizer-build.txt"

# GUI tests and the benchmark are the optimised build's; the tests labelled `pictures` spend their
# time in llvmpipe, on host code the unit tests run (tests/CMakeLists.txt).
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
