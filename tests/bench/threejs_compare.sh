#!/usr/bin/env bash
# Side by side with three.js (not part of the test command; docs/openpbr-vs-threejs.md): OpenPBR
# materials (car paint, velvet, gold, glass, iridescence) drawn by three.js's
# MeshPhysicalMaterial (npm, headless Chromium on Mesa llvmpipe) and by `glint render`, one PNG
# per scene. Installs what it lacks as tests/bench/threejs_peer.sh does (the same cache).
# usage: tests/bench/threejs_compare.sh build/app/glint OUTPUT_DIR [compare.py options: --size WxH --scenes a,b]
set -euo pipefail
glint=$(realpath "$1"); output=$2; shift 2
here=$(dirname "$(realpath "$0")")
tool=threejs_compare
source "$here/threejs_peer/install.sh"
exec /usr/bin/python3 "$here/threejs_peer/compare.py" "$glint" "$three" "$output" "$@"
