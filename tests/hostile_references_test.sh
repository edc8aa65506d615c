#!/usr/bin/env bash
# Files that name files outside their own folder (core/util/reference_confinement.h), one of each
# format that names files (tests/files/hostile/): an .obj's mtllib, an .mtl's map_Kd, a glTF's
# image and buffer, a MaterialX image, a scene's mesh, texture and environment, a material's
# .brdf, a lesson's scene, a .bparam's .brdf. Each names a target outside as an absolute path,
# through ../ and through a symlink; the targets hold a marker line. Refused by default (by name,
# located), read with --allow-outside-references, and no message ever holds the marker.
# usage: hostile_references_test.sh GLINT OUTPUT_DIR
source "$(dirname "$0")/cli_checks.sh" "$@"
fixtures="$(dirname "$0")/files/hostile"
marker=GLINT_HOSTILE_MARKER_5e1f

mkdir -p "$out/outside"
for extension in mtl png bin obj hdr brdf json; do
  printf '%s:x:102:109:Avahi mDNS daemon\n%s 1 2 3\n' "$marker" "$marker" >"$out/outside/secret.$extension"
done

# run NAME FILE EXIT LOCATION ARGS...: `glint ARGS` exits with EXIT, says "refused" located at
# LOCATION (a regex) by default and nothing refused with the flag; the marker is never printed.
run() {
  local name=$1 file=$2 expected=$3 location=$4
  shift 4
  local log="$out/$name.log"
  "$glint" "$@" >"$log" 2>&1
  local code=$?
  if [[ $code -ne $expected ]]; then fail "$name: exit code $code (expected $expected):"; cat "$log"; return; fi
  if grep -q "$marker" "$log"; then fail "$name: a message quotes the file outside:"; cat "$log"; return; fi
  if [[ $location == - ]]; then
    if grep -q "refused" "$log"; then fail "$name: refused with --allow-outside-references:"; cat "$log"; return; fi
  elif ! grep -Eq "$file:$location.*refused '.*secret\..*outside the folder.*--allow-outside-references" "$log"; then
    fail "$name: no located refusal at $file:$location:"; cat "$log"; return
  fi
  pass "$name"
}

for variant in absolute dotdot symlink; do
  asset="$out/$variant"
  mkdir -p "$asset"
  case $variant in
    absolute) outside="$out/outside" ;;
    dotdot) outside="../outside" ;;
    symlink) ln -s ../outside "$asset/linked" && outside="linked" ;;
  esac
  for fixture in "$fixtures"/*; do sed "s|@OUTSIDE@|$outside|g" "$fixture" >"$asset/$(basename "$fixture")"; done
  # A material library, a texture map, images: the file loads without them, with a warning.
  run "obj_mtllib_$variant" mtllib.obj 0 "2: material library not used: " info "$asset/mtllib.obj"
  run "mtl_map_kd_$variant" map_kd.mtl 0 "4: warning: " info "$asset/map_kd.mtl"
  run "gltf_image_$variant" image.gltf 0 "[0-9]+:[0-9]+: warning: /materials/0/pbrMetallicRoughness/baseColorTexture: " info "$asset/image.gltf"
  run "materialx_image_$variant" image.mtlx 0 "[0-9]+:[0-9]+: warning: " info "$asset/image.mtlx"
  for file in mtllib.obj map_kd.mtl image.gltf image.mtlx; do
    run "${file/./_}_${variant}_allowed" "$file" 0 - info --allow-outside-references "$asset/$file"
  done
  # What a scene, a material or a lesson list cannot do without: the file is refused, at its key.
  run "scene_mesh_$variant" scene_mesh.json 2 "4:[0-9]+: .*'path': " info "$asset/scene_mesh.json"
  run "scene_texture_$variant" scene_texture.json 2 "3:[0-9]+: .*'file': " info "$asset/scene_texture.json"
  run "scene_environment_$variant" scene_environment.json 2 "3:[0-9]+: .*'file': " info "$asset/scene_environment.json"
  run "gltf_buffer_$variant" buffer.gltf 2 "6:[0-9]+: cannot load mesh: /buffers/0/uri: " info "$asset/scene_gltf_buffer.json"
  run "material_brdf_$variant" material_brdf.json 2 "1:[0-9]+: .*'brdf_file': " info "$asset/material_brdf.json"
  run "lessons_$variant" lessons.json 2 "3:[0-9]+: .*'scene': " lessons "$asset/lessons.json"
  run "bparam_brdf_$variant" brdf_explorer.bparam 2 "1:1: " render "$asset/brdf_explorer.bparam" -o "$out/x.png"
  # Allowed, each target is read and found invalid: said without its bytes.
  for scene in scene_mesh scene_texture scene_environment scene_gltf_buffer material_brdf; do
    run "${scene}_${variant}_allowed" "$scene.json" 2 - info --allow-outside-references "$asset/$scene.json"
  done
  run "lessons_${variant}_allowed" lessons.json 0 - lessons --allow-outside-references "$asset/lessons.json"
  run "bparam_brdf_${variant}_allowed" brdf_explorer.bparam 2 - render --allow-outside-references "$asset/brdf_explorer.bparam" -o "$out/x.png"
done
summary
