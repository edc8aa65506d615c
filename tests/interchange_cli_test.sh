#!/usr/bin/env bash
# `glint export` and `glint render` on interchange files: a material goes to .mtl and .gltf and
# back, both render on the preview stage, and malformed files exit with code 2 and a message
# naming file:line. usage: interchange_cli_test.sh GLINT OUTPUT_DIR
set -u
glint=$1
out=$2
rm -rf "$out" && mkdir -p "$out"
failures=0
passed=0
check() {  # check NAME COMMAND...: the command must succeed
  local name=$1
  shift
  if "$@" >"$out/$name.log" 2>&1; then
    echo "ok   $name"; passed=$((passed + 1))
  else
    echo "FAIL $name:"; cat "$out/$name.log"; failures=$((failures + 1))
  fi
}
expect_error() {  # expect_error NAME PATTERN ARGS...: exit code 2 and stderr matching PATTERN
  local name=$1 pattern=$2
  shift 2
  "$glint" "$@" >"$out/$name.stdout" 2>"$out/$name.stderr"
  local code=$?
  if [[ $code -eq 2 ]] && grep -Eq -- "$pattern" "$out/$name.stderr"; then
    echo "ok   $name: $(head -n 1 "$out/$name.stderr")"; passed=$((passed + 1))
  else
    echo "FAIL $name: exit code $code, stderr:"; cat "$out/$name.stderr"; failures=$((failures + 1))
  fi
}

cat >"$out/plastic.json" <<'JSON'
{ "format": "glint-material", "version": 1, "name": "red plastic", "model": "blinn_phong",
  "diffuse_albedo": [0.5, 0.1, 0.1], "specular": 0.2, "exponent": 64, "form": "lecture" }
JSON
cat >"$out/varnish.json" <<'JSON'
{ "format": "glint-material", "version": 1, "name": "varnish", "model": "cook_torrance",
  "diffuse_albedo": [0.3, 0.2, 0.1], "ior": 1.6, "roughness": 0.09, "fresnel": "schlick" }
JSON
check export_mtl "$glint" export "$out/plastic.json" -o "$out/plastic.mtl"
check mtl_has_illum2 grep -q "^illum 2" "$out/plastic.mtl"
check render_mtl "$glint" render "$out/plastic.mtl" -o "$out/plastic_mtl.png" --size 64x64
check export_gltf "$glint" export "$out/varnish.json" -o "$out/varnish.gltf"
check gltf_embedded grep -q '"uri": "data:application/octet-stream;base64,' "$out/varnish.gltf"
check render_gltf "$glint" render "$out/varnish.gltf" -o "$out/varnish_gltf.png" --size 64x64
check gltf_to_mtl "$glint" export "$out/varnish.gltf" -o "$out/varnish.mtl"
# The same material renders the same from its JSON and from its .mtl (lecture Blinn-Phong survives).
check render_json "$glint" render "$out/plastic.json" -o "$out/plastic_json.png" --size 64x64
check same_image cmp "$out/plastic_json.png" "$out/plastic_mtl.png"

printf 'newmtl a\nKd 0.5 0.5\n' >"$out/bad.mtl"
expect_error bad_mtl "bad.mtl:2: 'Kd' takes one" render "$out/bad.mtl" -o "$out/x.png"
printf 'newmtl a\nfrobnicate 1\n' >"$out/unknown.mtl"
expect_error unknown_statement "unknown.mtl:2: unknown statement 'frobnicate'" export "$out/unknown.mtl" -o "$out/x.gltf"
printf '{"asset": {"version": "2.0"},\n "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 2}}]}\n' >"$out/bad.gltf"
expect_error bad_gltf "bad.gltf:2:[0-9]+: .*'roughnessFactor'" render "$out/bad.gltf" -o "$out/x.png"
printf '{"asset": {"version": "2.0"}, "materials": [{}]' >"$out/truncated.gltf"
expect_error truncated_gltf "truncated.gltf:1:" render "$out/truncated.gltf" -o "$out/x.png"
expect_error export_extension "must end in .mtl or .gltf" export "$out/plastic.json" -o "$out/x.obj"

echo "$passed passed, $failures failed"
[[ $failures -eq 0 ]]
