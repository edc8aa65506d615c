#!/usr/bin/env bash
# `glint export` and `glint render` on interchange files: a material goes to .mtl and .gltf and
# back, both render on the preview stage, and malformed files exit with code 2 and a message
# naming file:line; a MERL .binary and a .glb render too, and `glint FILE` with no display renders
# them headless as the editor would open them; images inside glTF files render and `glint info`
# lists them, and a required extension Glint lacks is refused. usage: interchange_cli_test.sh GLINT OUTPUT_DIR
source "$(dirname "$0")/cli_checks.sh" "$@"
export GLINT_BRDF_TIMEOUT_S=60  # the .brdf safety probe, on a loaded machine or under the sanitizers
check() {  # check NAME COMMAND...: the command must succeed
  local name=$1
  shift
  if "$@" >"$out/$name.log" 2>&1; then
    pass "$name"
  else
    fail "$name:"; cat "$out/$name.log"
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
# Wavefront readers skip what they do not know: a located warning, and the file is read.
check unknown_statement bash -c "'$glint' export '$out/unknown.mtl' -o '$out/x.gltf' 2>&1 | grep -q \"unknown.mtl:2: warning: unknown statement 'frobnicate'\""
printf '{"asset": {"version": "2.0"},\n "materials": [{"pbrMetallicRoughness": {"roughnessFactor": 2}}]}\n' >"$out/bad.gltf"
expect_error bad_gltf "bad.gltf:2:[0-9]+: .*'roughnessFactor'" render "$out/bad.gltf" -o "$out/x.png"
printf '{"asset": {"version": "2.0"}, "materials": [{}]' >"$out/truncated.gltf"
expect_error truncated_gltf "truncated.gltf:1:" render "$out/truncated.gltf" -o "$out/x.png"
expect_error export_extension "must end in .mtl, .gltf or .mtlx" export "$out/plastic.json" -o "$out/x.obj"

# A MERL measured BRDF (a constant table, made here) renders on the GPU and on the CPU reference,
# and exports as its Lambert stand-in with a warning; a .glb carries the .gltf's JSON chunk and its
# buffer as the BIN chunk.
/usr/bin/python3 - "$out" <<'PY'
import base64, json, struct, sys
out = sys.argv[1]
with open(out + "/grey.binary", "wb") as f:
    f.write(struct.pack("<3i", 90, 90, 180))
    for scale in (1500.0, 1500.0 / 1.15, 1500.0 / 1.66):
        f.write(struct.pack("<d", 0.5 / 3.141592653589793 * scale) * (90 * 90 * 180))
with open(out + "/short.binary", "wb") as f:
    f.write(struct.pack("<3i", 90, 90, 180) + b"\0" * 64)
gltf = json.load(open(out + "/varnish.gltf"))
body = base64.b64decode(gltf["buffers"][0].pop("uri").split(",", 1)[1])  # the sphere's buffer into the BIN chunk
body += b"\0" * (-len(body) % 4)
text = json.dumps(gltf).encode()
text += b" " * (-len(text) % 4)
chunks = struct.pack("<2I", len(text), 0x4E4F534A) + text + struct.pack("<2I", len(body), 0x004E4942) + body
open(out + "/varnish.glb", "wb").write(struct.pack("<3I", 0x46546C67, 2, 12 + len(chunks)) + chunks)
open(out + "/lying.glb", "wb").write(struct.pack("<3I", 0x46546C67, 2, 4000) + chunks)
PY
check render_merl "$glint" render "$out/grey.binary" -o "$out/grey.png" --size 48x48
check render_merl_reference "$glint" render "$out/grey.binary" -o "$out/grey_reference.png" --size 48x48 --reference
check export_merl_mtl "$glint" export "$out/grey.binary" -o "$out/grey.mtl"
check merl_export_warns grep -q "has no MTL form" "$out/export_merl_mtl.log"
expect_error short_merl "short.binary: .*truncated" render "$out/short.binary" -o "$out/x.png"
check render_glb "$glint" render "$out/varnish.glb" -o "$out/varnish_glb.png" --size 64x64
check same_glb_image cmp "$out/varnish_gltf.png" "$out/varnish_glb.png"
expect_error lying_glb "lying.glb: byte offset 8: the header says the file is 4000 bytes" render "$out/lying.glb" -o "$out/x.png"

# `glint FILE` (the editor's argument) with no display: the file rendered headless, as it opens.
glint_path=$(realpath "$glint")  # run from $out, where glint-NAME.png is written
for file in grey.binary varnish.glb varnish.gltf plastic.mtl; do
  check "no_display_${file/./_}" bash -c "cd '$out' && DISPLAY= '$glint_path' '$file' | grep -q 'glint-${file%.*}.png' && [[ -s 'glint-${file%.*}.png' ]]"
done
(cd "$out" && DISPLAY= "$glint_path" short.binary >/dev/null 2>"$out/no_display_short.stderr")
code=$?
if [[ $code -eq 2 ]] && grep -q "short.binary: .*truncated" "$out/no_display_short.stderr"; then
  pass "no_display_short: $(head -n 1 "$out/no_display_short.stderr")"
else
  fail "no_display_short: exit code $code"; cat "$out/no_display_short.stderr"
fi

# Files from the wild (tests/files/README.md): what `glint render`, `glint FILE` and `glint info` say.
files=$(dirname "$(realpath "$0")")/files
expect_output() {  # expect_output NAME PATTERN ARGS...: exit code 0 and stdout+stderr matching PATTERN
  local name=$1 pattern=$2
  shift 2
  "$glint" "$@" >"$out/$name.log" 2>&1
  local code=$?
  if [[ $code -eq 0 ]] && grep -Eq -- "$pattern" "$out/$name.log"; then
    pass "$name"
  else
    fail "$name: exit code $code, output:"; cat "$out/$name.log"
  fi
}
expect_output render_mesh "cube.obj: 24 vertices, 12 triangles; dropped 1 faces of one or two corners" \
  render "$files/obj/cube.obj" -o "$out/cube.png"
expect_output render_zup_mesh "zup_column.obj: 24 vertices" render "$files/obj/zup_column.obj" --up z -o "$out/column.png"
expect_error render_cut_obj "cut_mid_face.obj:15:1: cannot load mesh: a face with 2 corner" render "$files/obj/cut_mid_face.obj" -o "$out/x.png"
expect_output render_tristrips "tristrips_binary.ply: 6 vertices, 4 triangles" render "$files/ply/tristrips_binary.ply" -o "$out/strips.png"
# A .bparam renders its .brdf with its values: not the picture of the .brdf's defaults.
check render_bparam bash -c "'$glint' render '$files/brdf/explorer_disney.bparam' -o '$out/bparam.png' && '$glint' render '$files/brdf/disney.brdf' -o '$out/brdf.png' && ! cmp -s '$out/bparam.png' '$out/brdf.png'"
expect_output render_gltf_lights "its 1 light\\(s\\) added" render "$files/gltf/DirectionalLight.gltf" --material 0 -o "$out/lights.png"
# An asset: every part with its own material on the stage. DirectionalLight.gltf's geometry (its
# .bin) is left out of the repository: an error, and how to see one of its materials instead.
expect_output render_asset_gltf "parts.gltf: 72 vertices, 36 triangles from 4 meshes; 4 parts, 3 materials" \
  render "$files/assets/parts.gltf" -o "$out/parts.png"
expect_output render_asset_obj "blender_two_materials.mtl:4: warning: 'Base': 'Ns 0'" \
  render "$files/assets/blender_two_materials.obj" -o "$out/blender.png"
expect_error render_asset_without_geometry "DirectionalLight.gltf.*--material NAME\\|INDEX renders one of the file's materials" \
  render "$files/gltf/DirectionalLight.gltf" -o "$out/x.png"
# Warnings are for the material used: ClearCoatTest's Partial_Coating blends alpha, the others do not.
expect_output render_gltf_warned "/materials/5: alpha" render "$files/gltf/khronos/ClearCoatTest.gltf" --material Partial_Coating -o "$out/m5.png"
check render_gltf_quiet bash -c "! '$glint' render '$files/gltf/khronos/ClearCoatTest.gltf' --material 1 -o '$out/m1.png' 2>&1 | grep -Eq 'warning|note'"
check render_gltf_chosen bash -c "'$glint' render '$files/gltf/DirectionalLight.gltf' --material mat_1.001 -o '$out/m1.png' 2>&1 | grep -q \"'mat_1.001' (1) on the stage\" && ! '$glint' render '$files/gltf/DirectionalLight.gltf' --material 1 -o '$out/m1.png' 2>&1 | grep -q warning"
expect_error render_gltf_unknown_material "no material 'nope' in the file; it holds 0 'mat_0.001', 1 'mat_1.001', 2 'mat_2.001'" \
  render "$files/gltf/DirectionalLight.gltf" --material nope -o "$out/x.png"
expect_error render_lfs_pointer "lfs_pointer.binary:1:1: not a MERL BRDF but a Git LFS pointer" render "$files/merl/lfs_pointer.binary" -o "$out/x.png"
check export_chosen bash -c "'$glint' export '$files/gltf/DirectionalLight.gltf' -o '$out/chosen.mtl' --material 2 && grep -q 'newmtl mat_2.001' '$out/chosen.mtl' && ! grep -q 'newmtl mat_0.001' '$out/chosen.mtl'"
expect_output info_gltf "1 'mat_1.001' \\(openpbr\\)" info "$files/gltf/DirectionalLight.gltf"
expect_output info_gltf_lights "0 'Sun' \\(directional\\)" info "$files/gltf/DirectionalLight.gltf"
expect_output info_gltf_meshes "2 'Sphere.100'" info "$files/gltf/DirectionalLight.gltf"
expect_output info_mesh "asset: 24 vertices, 12 triangles" info "$files/obj/cube.obj"
# An asset's parts as the editor opens them: an OBJ's usemtl groups, a glTF's primitives.
expect_output info_obj_parts "1 'Base': material 'Base', 12 triangles" info "$files/assets/blender_two_materials.obj"
expect_output info_gltf_parts "2 'Cube-1': material 'Gold', 4 triangles" info "$files/assets/parts.gltf"
expect_output info_bparam "values for d_ggx.brdf \\(found: " info "$files/brdf/explorer_isfunc.bparam"
expect_output info_mtl "0 'Matériau_01'" info "$files/mtl/max_latin1_km.mtl"
# Images inside a .glb and a .gltf are rendered textures (the same picture from both), and info
# says so; MaterialX images are rendered, none called "not rendered".
expect_output info_glb_image "0 renders texture base_color: image 0 inside .*BoxTextured.glb" info "$files/gltf/khronos/BoxTextured.glb"
check render_glb_image "$glint" render "$files/gltf/khronos/BoxTextured.glb" -o "$out/box_glb.png" --size 64x64
check render_data_uri_image "$glint" render "$files/gltf/khronos/BoxTextured_embedded.gltf" -o "$out/box_gltf.png" --size 64x64
check same_embedded_image cmp "$out/box_glb.png" "$out/box_gltf.png"
expect_output info_mtlx_rendered "0 renders texture emission_color: .*BoomBox_emissive.png" info "$files/materialx/gltf_pbr_boombox.mtlx"
check info_mtlx_honest bash -c "! '$glint' info '$files/materialx/gltf_pbr_boombox.mtlx' 2>&1 | grep -q 'not rendered'"
# A required extension Glint lacks is refused by name, whether read for its materials or its mesh.
printf '{"asset": {"version": "2.0"}, "extensionsRequired": ["KHR_draco_mesh_compression"], "materials": [{}]}\n' >"$out/draco.gltf"
expect_error render_required_extension "draco.gltf:1:[0-9]+: the file requires the extension \"KHR_draco_mesh_compression\"" \
  render "$out/draco.gltf" -o "$out/x.png"
expect_error info_required_extension "requires the extension \"KHR_draco_mesh_compression\"" info "$out/draco.gltf"
for file in obj/cube.obj brdf/explorer_disney.bparam; do
  name=$(basename "${file%.*}")
  check "no_display_$name" bash -c "cd '$out' && DISPLAY= '$glint_path' '$files/$file' | grep -q 'glint-$name.png' && [[ -s 'glint-$name.png' ]]"
done

summary
