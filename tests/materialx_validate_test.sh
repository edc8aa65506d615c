#!/usr/bin/env bash
# What `glint export` writes as MaterialX, checked by the MaterialX library itself: every model
# (converted to open_pbr_surface), image textures with channels and ranges, a normal map, and the
# MaterialX examples read and written back. tests/tools/materialx_validate.mjs runs MaterialX 1.39
# (WebAssembly, npm package @needle-tools/materialx) on each file: validate() and a GLSL shader.
# The package is fetched once into a cache folder (npm pack); the test is skipped (exit 77) only
# when it is not cached and the npm registry cannot be reached.
# usage: tests/materialx_validate_test.sh build/app/glint OUTPUT_DIR
set -euo pipefail
glint=$(realpath "$1")
out=$2
here=$(dirname "$(realpath "$0")")
version=1.4.6  # MaterialX 1.39.4
cache=${GLINT_MATERIALX_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/glint-materialx}/needle-materialx-$version
bin=$cache/package/bin
rm -rf "$out" && mkdir -p "$out"

if [[ ! -f $bin/JsMaterialXGenShader.wasm ]]; then
  command -v npm >/dev/null || { echo "materialx_validate: npm (Debian's npm) is needed to fetch MaterialX" >&2; exit 1; }
  mkdir -p "$cache"
  echo "materialx_validate: fetching @needle-tools/materialx@$version from the npm registry into $cache" >&2
  if ! tarball=$(cd "$cache" && timeout 120 npm pack --silent "@needle-tools/materialx@$version" 2>"$out/npm.log"); then
    if grep -qE 'ENOTFOUND|EAI_AGAIN|ETIMEDOUT|ECONNREFUSED|ECONNRESET|ENETUNREACH|network' "$out/npm.log" || [[ ! -s $out/npm.log ]]; then
      echo "SKIPPED: the npm registry cannot be reached and MaterialX is not cached in $cache:" >&2
      cat "$out/npm.log" >&2
      exit 77
    fi
    cat "$out/npm.log" >&2
    exit 1
  fi
  tar -xzf "$cache/$tarball" -C "$cache" && rm "$cache/$tarball"
fi

# A material of every model (the scene's objects' materials are exported), and textures: an image on a colour, one channel of an image on a scalar with a
# range, a normal map.
cp "$here/goldens/blinn_point.png" "$out/texture.png"
cat > "$out/models.json" <<'JSON'
{ "format": "glint-scene", "version": 1,
  "materials": [
    { "name": "lambert", "model": "lambert", "albedo": [0.7, 0.2, 0.1],
      "textures": { "albedo": { "type": "image", "file": "texture.png", "tiling": [2, 3] },
                    "normal": { "type": "image", "file": "texture.png", "color_space": "linear" } } },
    { "name": "blinn phong", "model": "blinn_phong" }, { "name": "oren-nayar", "model": "oren_nayar" },
    { "name": "phong", "model": "phong", "form": "lecture" },
    { "name": "cook torrance", "model": "cook_torrance", "roughness": 0.3,
      "textures": { "roughness": { "type": "image", "file": "texture.png", "channel": "g", "min": 0.1, "max": 0.6 } } },
    { "name": "ggx", "model": "ggx_anisotropic" }, { "name": "ward", "model": "ward" },
    { "name": "moon", "model": "retroreflective" }, { "name": "mirror", "model": "mirror" },
    { "name": "glass", "model": "glass", "absorption": [1, 0.2, 0.5] },
    { "name": "openpbr", "model": "openpbr", "coat_weight": 1, "fuzz_weight": 0.5, "geometry_thin_walled": true,
      "textures": { "specular_roughness": { "type": "image", "file": "texture.png", "channel": "g", "min": 0.1, "max": 0.6 } } }
  ],
  "objects": [
    { "name": "lambert", "shape": "sphere", "material": "lambert" },
    { "name": "blinn phong", "shape": "sphere", "material": "blinn phong" },
    { "name": "oren-nayar", "shape": "sphere", "material": "oren-nayar" },
    { "name": "phong", "shape": "sphere", "material": "phong" },
    { "name": "cook torrance", "shape": "sphere", "material": "cook torrance" },
    { "name": "ggx", "shape": "sphere", "material": "ggx" },
    { "name": "ward", "shape": "sphere", "material": "ward" },
    { "name": "moon", "shape": "sphere", "material": "moon" },
    { "name": "mirror", "shape": "sphere", "material": "mirror" },
    { "name": "glass", "shape": "sphere", "material": "glass" },
    { "name": "openpbr", "shape": "sphere", "material": "openpbr" } ] }
JSON
written=("$out/models.mtlx")
"$glint" export "$out/models.json" -o "$out/models.mtlx" 2>"$out/models.warnings"
grep -q "material 'phong' converted from Phong to OpenPBR: kept .*; dropped form" "$out/models.warnings"
grep -q '<tiledimage name="specular_roughness_image" type="color4">' "$out/models.mtlx"
grep -q '<remap name="specular_roughness_range" type="float">' "$out/models.mtlx"
# The MaterialX examples (tests/files/materialx), read by Glint and written back.
for example in "$here"/files/materialx/*.mtlx; do
  name=$(basename "$example")
  "$glint" export "$example" -o "$out/$name" 2>/dev/null
  written+=("$out/$name")
done
# Glint renders what it reads (File ▸ Open and glint render share the loader).
"$glint" render "$here/files/materialx/standard_surface_carpaint.mtlx" -o "$out/carpaint.png" >/dev/null
[[ -s $out/carpaint.png ]]
# A document MaterialX must refuse (an input open_pbr_surface does not have): the check can fail.
sed 's/name="coat_weight"/name="coat_wieght"/' "$out/open_pbr_carpaint.mtlx" > "$out/misspelt.mtlx"
start=$(date +%s%N)
node "$here/tools/materialx_validate.mjs" "$bin" "${written[@]}" "!$out/misspelt.mtlx"
echo "materialx_validate: ${#written[@]} files valid in $(( ($(date +%s%N) - start) / 1000000 )) ms (MaterialX loaded and run)"
