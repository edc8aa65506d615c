#!/usr/bin/env bash
# `glint thumbnails` from the outside: one PNG per material at the asked size, a labelled contact
# sheet, a bad file reported while the rest are rendered, same bytes with --jobs 2, the same
# pixels as the snapshot runner's render, bad arguments.
# usage: thumbnails_test.sh GLINT OUTPUT_DIR
set -u
glint=$(realpath "$1")
out=$2
here=$(cd "$(dirname "$0")" && pwd)
tools="/usr/bin/python3 $here/snapshot_test_tools.py"
export DISPLAY=
rm -rf "$out" && mkdir -p "$out/materials"
passes=0 failures=0
expect() { local name=$1; shift; if "$@"; then echo "ok   $name"; passes=$((passes + 1)); else echo "FAIL $name"; failures=$((failures + 1)); fi; }

cp "$here"/snapshots/*.json "$out/materials/"
rm "$out/materials/snapshot.json"
printf '{ "format": "glint-material", "version": 1,\n  "model": "velvet" }\n' >"$out/materials/unknown_model.json"

"$glint" thumbnails "$out/materials" -o "$out/thumbs" --size 96 >"$out/thumbs.stdout" 2>"$out/thumbs.stderr"
expect "a bad file gives exit code 1" test $? -eq 1
expect "the bad file is named with its location" grep -q "unknown_model.json:2:.*unknown model 'velvet'" "$out/thumbs.stderr"
expect "one thumbnail per good material" test "$(ls "$out/thumbs" | grep -vc contact_sheet)" -eq 3
expect "thumbnails have the asked size" test "$($tools size "$out/thumbs/clay.png")" = "96x96"
expect "the contact sheet is written" test -s "$out/thumbs/contact_sheet.png"
expect "the contact sheet holds a 2x2 grid with label rows" test "$($tools size "$out/thumbs/contact_sheet.png")" = "216x246"
expect "the summary says what happened" grep -q "^3 thumbnails (96x96) and contact_sheet.png written" "$out/thumbs.stdout"

# `glint render MATERIAL`, `glint thumbnails` and `glint snapshot` give the same pixels (PNG bytes
# differ: thumbnails use faster compression): a suite whose two goldens are the render and the
# thumbnail, compared with zero tolerance.
"$glint" render "$out/materials/clay.json" -o "$out/clay_render.png" --size 96x96
mkdir -p "$out/same/goldens" && cp "$out/materials/clay.json" "$out/same/"
cp "$out/clay_render.png" "$out/same/goldens/via_render.png" && cp "$out/thumbs/clay.png" "$out/same/goldens/via_thumbnails.png"
cat >"$out/same/snapshot.json" <<'JSON'
{ "format": "glint-snapshot-suite", "version": 1, "width": 96, "height": 96, "tolerance": { "channel": 0, "failing_percent": 0 },
  "cases": [ { "file": "clay.json", "name": "via_render" }, { "file": "clay.json", "name": "via_thumbnails" } ] }
JSON
"$glint" snapshot "$out/same" --out "$out/same_report" >"$out/same.stdout" 2>&1
expect "a material: glint render, thumbnails and snapshot give the same pixels" grep -qx "2 passed, 0 failed, 0 errors" "$out/same.stdout"

rm "$out/materials/unknown_model.json"
"$glint" thumbnails "$out/materials" -o "$out/thumbs_jobs2" --size 96 --jobs 2 >/dev/null 2>&1
expect "all good: exit code 0" test $? -eq 0
"$glint" thumbnails "$out/materials" -o "$out/thumbs_jobs1" --size 96 >/dev/null 2>&1
expect "--jobs 2 gives the same bytes" diff -r "$out/thumbs_jobs1" "$out/thumbs_jobs2"

"$glint" thumbnails "$out/no_such_dir" -o "$out/x" >/dev/null 2>"$out/missing.stderr"
expect "a missing directory gives exit code 2" test $? -eq 2
"$glint" thumbnails "$out/materials" >/dev/null 2>&1
expect "no -o gives exit code 2" test $? -eq 2
"$glint" thumbnails "$out/materials" -o "$out/x" --size 3 >/dev/null 2>&1
expect "a bad --size gives exit code 2" test $? -eq 2

echo "$passes passed, $failures failed"
[[ $failures -eq 0 ]]
