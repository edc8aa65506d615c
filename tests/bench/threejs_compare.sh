#!/usr/bin/env bash
# Side by side with three.js (not part of the test command; docs/openpbr-vs-threejs.md): OpenPBR
# materials (car paint, velvet, gold, glass, iridescence) drawn by three.js's
# MeshPhysicalMaterial (npm, headless Chromium on Mesa llvmpipe) and by `glint render`, one PNG
# per scene. Installs what it lacks as tests/bench/threejs_peer.sh does (the same cache).
# usage: tests/bench/threejs_compare.sh build/app/glint OUTPUT_DIR [compare.py options: --size WxH --scenes a,b]
set -euo pipefail
glint=$(realpath "$1"); output=$2; shift 2
here=$(dirname "$(realpath "$0")")
three_version=0.187.0
cache=${GLINT_PEER_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/glint-threejs-peer}
if ! command -v chromium >/dev/null; then
  echo "threejs_compare: installing Debian's chromium" >&2
  apt-get install -y chromium >&2
fi
three=$cache/three-$three_version/node_modules/three
if [[ ! -f $three/build/three.module.js ]]; then
  echo "threejs_compare: installing three@$three_version from the npm registry into $cache" >&2
  npm install --prefix "$cache/three-$three_version" --no-audit --no-fund --no-save "three@$three_version" >&2
fi
exec /usr/bin/python3 "$here/threejs_peer/compare.py" "$glint" "$three" "$output" "$@"
