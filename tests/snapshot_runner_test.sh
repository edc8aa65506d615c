#!/usr/bin/env bash
# `glint snapshot` from the outside: a passing case, a failure of known size (figures checked),
# missing / corrupt / other-size goldens, a broken scene, --update and --update-case, shards,
# JUnit XML, exit codes, determinism (LP_NUM_THREADS, --jobs) and the CMake function used by
# another project. usage: snapshot_runner_test.sh GLINT OUTPUT_DIR GLINT_SNAPSHOT_CMAKE
set -u
glint=$(realpath "$1")
out=$2
cmake_module=$(realpath "$3")
here=$(cd "$(dirname "$0")" && pwd)
tools="/usr/bin/python3 $here/snapshot_test_tools.py"
export DISPLAY=
rm -rf "$out" && mkdir -p "$out"
passes=0 failures=0

pass() { echo "ok   $1"; passes=$((passes + 1)); }
fail() { echo "FAIL $1"; failures=$((failures + 1)); }
# expect NAME COMMAND...: the command must succeed.
expect() { local name=$1; shift; if "$@"; then pass "$name"; else fail "$name"; fi; }
# snapshot NAME ARGS...: runs glint snapshot, keeping stdout, stderr and the exit code.
snapshot() {
  local name=$1; shift
  "$glint" snapshot "$@" >"$out/$name.stdout" 2>"$out/$name.stderr"
  echo $? >"$out/$name.code"
}
code() { cat "$out/$1.code"; }

uniform_scene() {  # uniform_scene FILE: a 64×64 scene with nothing in it, a black background
  cat >"$1" <<'JSON'
{ "format": "glint-scene", "version": 1, "output": { "width": 64, "height": 64 }, "background": [0, 0, 0] }
JSON
}
material() {  # material FILE ALBEDO
  echo "{ \"format\": \"glint-material\", \"version\": 1, \"model\": \"lambert\", \"albedo\": $2 }" >"$1"
}

# --- a suite with one case of each kind ------------------------------------------------------
mixed=$out/mixed
mkdir -p "$mixed/goldens"
sed 's/"width": 256, "height": 256/"width": 64, "height": 64/' "$here/scenes/lambert_sun.json" >"$mixed/ball.json"
uniform_scene "$mixed/known_diff.json"
$tools uniform "$mixed/goldens/known_diff.png" 64 64 0 5 7 10 10 12   # 100 pixels off by 12/255
material "$mixed/missing.json" 0.5
material "$mixed/corrupt.json" 0.3
echo "this is not a PNG" >"$mixed/goldens/corrupt.png"
uniform_scene "$mixed/other_size.json"
$tools uniform "$mixed/goldens/other_size.png" 8 8 0
printf '{ "format": "glint-scene", "version": 1,\n  "lights": [ { "type": "point", "watts": 5 } ] }\n' >"$mixed/broken.json"

snapshot update_ball "$mixed" --out "$out/report_update_ball" --update-case ball
expect "--update-case writes only the named golden" \
  grep -qx "wrote golden $mixed/goldens/ball.png" "$out/update_ball.stdout"
expect "--update-case leaves the other goldens alone" test "$(grep -c '^wrote golden' "$out/update_ball.stdout")" -eq 1
cp "$mixed/goldens/ball.png" "$out/ball_golden_before.png"

snapshot mixed "$mixed" --out "$out/report_mixed"
expect "a failing suite exits with 1" test "$(code mixed)" -eq 1
expect "summary line" grep -qx "1 passed, 4 failed, 1 error" "$out/mixed.stdout"
expect "known difference: the figures" \
  grep -q "FAIL  known_diff: 100 of 4096 pixels (2.441%) differ by more than 5/255; at most 0.1% may (max difference 12/255)" "$out/mixed.stderr"
expect "known difference: actual, expected and diff images" \
  test -s "$out/report_mixed/images/known_diff.actual.png" -a -s "$out/report_mixed/images/known_diff.expected.png" \
       -a -s "$out/report_mixed/images/known_diff.diff.png"
expect "missing golden is reported" grep -q "FAIL  missing: no golden at $mixed/goldens/missing.png (run with --update" "$out/mixed.stderr"
expect "corrupt golden is reported" grep -q "FAIL  corrupt: golden unreadable: .*corrupt.png" "$out/mixed.stderr"
expect "golden of another size is reported" grep -q "FAIL  other_size: golden is 8x8, the render is 64x64" "$out/mixed.stderr"
expect "a broken scene is an error with its location" grep -q "ERROR broken: $mixed/broken.json:2:.*'watts': unknown key" "$out/mixed.stderr"
$tools junit "$out/report_mixed/junit.xml" >"$out/mixed.junit" 2>&1
expect "JUnit XML parses and counts" grep -qx "tests=6 failures=4 errors=1" "$out/mixed.junit"
expect "JUnit XML outcomes per case" diff <(sort "$out/mixed.junit" | grep -v tests=) <(printf '%s\n' "ball passed" "broken error" \
  "corrupt failure" "known_diff failure" "missing failure" "other_size failure")
expect "HTML report: failures first, figures, hover swap" \
  /usr/bin/python3 -c "
import re, sys
html = open('$out/report_mixed/index.html').read()
order = re.findall(r'<div class=\"case (\w+)\"', html)
assert order == ['failed'] * 4 + ['error', 'passed'], order
assert '100 of 4096 (2.441%)' in html and '12/255' in html
assert 'src=\"images/known_diff.actual.png\"' in html and '.swap:hover .expected' in html
"

# --- --update rewrites only the failing goldens -----------------------------------------------
snapshot update "$mixed" --out "$out/report_update" --update
expect "--update says which goldens it wrote" diff <(sort "$out/update.stdout" | grep '^wrote') \
  <(printf 'wrote golden %s\n' "$mixed/goldens/corrupt.png" "$mixed/goldens/known_diff.png" "$mixed/goldens/missing.png" "$mixed/goldens/other_size.png")
expect "--update leaves a passing golden untouched" cmp -s "$mixed/goldens/ball.png" "$out/ball_golden_before.png"
snapshot after_update "$mixed" --out "$out/report_after_update"
expect "after --update only the broken scene remains" grep -qx "5 passed, 0 failed, 1 error" "$out/after_update.stdout"
expect "an errored case still exits with 1" test "$(code after_update)" -eq 1

# --- shards ---------------------------------------------------------------------------------
snapshot shard0 "$mixed" --out "$out/report_shard0" --shard 0/2
snapshot shard1 "$mixed" --out "$out/report_shard1" --shard 1/2
$tools junit "$out/report_shard0/junit.xml" | grep -v tests= | cut -d' ' -f1 >"$out/shard0.names"
$tools junit "$out/report_shard1/junit.xml" | grep -v tests= | cut -d' ' -f1 >"$out/shard1.names"
expect "shard 0/2 takes cases 0, 2, 4 of the sorted list" diff "$out/shard0.names" <(printf '%s\n' ball corrupt missing)
expect "two shards cover the suite exactly once" \
  diff <(sort "$out/shard0.names" "$out/shard1.names") <(printf '%s\n' ball broken corrupt known_diff missing other_size)

# --- exit codes and suites that cannot run ----------------------------------------------------
passing=$out/passing
mkdir -p "$passing/goldens"
cp "$mixed/ball.json" "$passing/" && cp "$mixed/goldens/ball.png" "$passing/goldens/"
snapshot passing "$passing" --out "$out/report_passing"
expect "an all-passing suite exits with 0" test "$(code passing)" -eq 0
expect "an all-passing summary" grep -qx "1 passed, 0 failed, 0 errors" "$out/passing.stdout"
snapshot no_suite "$out/no/such/suite" --out "$out/report_no_suite"
expect "a missing suite exits with 2" test "$(code no_suite)" -eq 2
expect "a missing suite still leaves a JUnit report" grep -q "<error message=\".*no such suite" "$out/report_no_suite/junit.xml"
mkdir -p "$out/bad_manifest" && cp "$mixed/ball.json" "$out/bad_manifest/"
printf '{\n  "format": "glint-snapshot-suite", "version": 1,\n  "tolerance": { "channel": 5, "percent": 1 }\n}\n' >"$out/bad_manifest/snapshot.json"
snapshot bad_manifest "$out/bad_manifest" --out "$out/report_bad_manifest"
expect "an unknown manifest key exits with 2" test "$(code bad_manifest)" -eq 2
expect "an unknown manifest key is located" grep -q "snapshot.json:3:32: tolerance 'percent': unknown key" "$out/bad_manifest.stderr"
snapshot bad_shard "$passing" --shard 2/2
expect "a bad --shard exits with 2" test "$(code bad_shard)" -eq 2
snapshot bad_option "$passing" --frobnicate
expect "an unknown option exits with 2 and names it" grep -q "unknown option --frobnicate" "$out/bad_option.stderr"
snapshot two_suites "$passing" "$mixed"
expect "two suites exit with 2" grep -q "one suite at a time" "$out/two_suites.stderr"
snapshot bad_jobs "$passing" --jobs 0
expect "--jobs 0 exits with 2" test "$(code bad_jobs)" -eq 2
snapshot bad_update "$passing" --out "$out/report_bad_update" --update-case nobody
expect "--update-case of an unknown case exits with 2" test "$(code bad_update)" -eq 2
# A goldens "directory" that is a file, and a case file that is a directory: failed / errored cases, the run goes on.
odd=$out/odd
mkdir -p "$odd/folder.json" && cp "$mixed/ball.json" "$odd/" && echo "not a directory" >"$odd/goldens"
printf '{ "format": "glint-snapshot-suite", "version": 1, "cases": [ { "file": "ball.json" }, { "file": "folder.json" } ] }\n' >"$odd/snapshot.json"
snapshot odd "$odd" --out "$out/report_odd"
expect "unreadable goldens and a directory as a case: the run goes on" grep -qx "0 passed, 1 failed, 1 error" "$out/odd.stdout"
expect "a directory as a case says so" grep -q "ERROR folder: .*folder.json: is a directory" "$out/odd.stderr"

# --- determinism: LP_NUM_THREADS and --jobs give the same bytes --------------------------------
det=$out/det
mkdir -p "$det"
cp "$mixed/ball.json" "$here/scenes/blinn_point.json" "$det/"
material "$det/grey.json" 0.18
echo '{ "format": "glint-material", "version": 1, "model": "blinn_phong", "specular": 0.5, "exponent": 200 }' >"$det/shiny.json"
LP_NUM_THREADS=1 "$glint" snapshot "$det" --out "$out/det_threads1" >"$out/det_threads1.stdout" 2>/dev/null
LP_NUM_THREADS=4 "$glint" snapshot "$det" --out "$out/det_threads4" >"$out/det_threads4.stdout" 2>/dev/null
LP_NUM_THREADS=4 "$glint" snapshot "$det" --out "$out/det_jobs2" --jobs 2 >"$out/det_jobs2.stdout" 2>/dev/null
expect "determinism: every case wrote its actual image" test "$(ls "$out/det_threads1/images" | grep -c actual)" -eq 4
expect "determinism: LP_NUM_THREADS=1 and 4 give the same bytes" diff -r "$out/det_threads1" "$out/det_threads4"
expect "determinism: --jobs 2 gives the same bytes as --jobs 1" diff -r "$out/det_threads1" "$out/det_jobs2"
expect "determinism: same summary" diff "$out/det_threads1.stdout" "$out/det_jobs2.stdout"

# --- the CMake function in another project ---------------------------------------------------
project=$out/user_project
mkdir -p "$project"
cp -r "$passing" "$project/looks" && cp -r "$mixed" "$project/broken_looks"
cat >"$project/CMakeLists.txt" <<CMAKE
cmake_minimum_required(VERSION 3.20)
project(user_materials NONE)
enable_testing()
include("$cmake_module")
glint_add_snapshot_test(looks looks JOBS 2)
glint_add_snapshot_test(broken_looks broken_looks SHARD 1/2)
CMAKE
if cmake -S "$project" -B "$project/build" -DGLINT_EXECUTABLE="$glint" >"$out/user_project.configure" 2>&1; then
  (cd "$project/build" && ctest -R '^looks$' >"$out/user_project.looks" 2>&1)
  expect "CMake function: a passing suite passes in ctest" test $? -eq 0
  expect "CMake function: the report lands in the build tree" test -s "$project/build/snapshot-report/looks/junit.xml"
  (cd "$project/build" && ctest -R '^broken_looks$' >"$out/user_project.broken" 2>&1)
  expect "CMake function: a failing suite fails in ctest" test $? -ne 0
  expect "CMake function: SHARD is passed on" grep -q "shard 1/2" "$project/build/snapshot-report/broken_looks/junit.xml"
else
  fail "CMake function: the user project does not configure"; cat "$out/user_project.configure"
fi

echo "$passes passed, $failures failed"
[[ $failures -eq 0 ]]
