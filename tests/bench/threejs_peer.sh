#!/usr/bin/env bash
# The three.js peer benchmark (not part of the test command; docs/performance.md): the scenes of
# tests/bench/scenes/peer_{ggx,lambert,empty}.json in three.js (npm) in headless Chromium (Debian's
# `chromium`) on the same Mesa llvmpipe, and in Glint, interleaved; prints both and the ratio.
# Installs what it lacks: Debian's chromium (apt-get, as root) and three into a cache folder.
# usage: tests/bench/threejs_peer.sh build/app/glint [peer.py options: --rounds N --frames N --size WxH]
set -euo pipefail
glint=$(realpath "$1"); shift
here=$(dirname "$(realpath "$0")")
three_version=0.187.0
cache=${GLINT_PEER_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/glint-threejs-peer}
if ! command -v chromium >/dev/null; then
  echo "threejs_peer: installing Debian's chromium" >&2
  apt-get install -y chromium >&2
fi
three=$cache/three-$three_version/node_modules/three
if [[ ! -f $three/build/three.module.js ]]; then
  echo "threejs_peer: installing three@$three_version from the npm registry into $cache" >&2
  npm install --prefix "$cache/three-$three_version" --no-audit --no-fund --no-save "three@$three_version" >&2
fi
exec /usr/bin/python3 "$here/threejs_peer/peer.py" "$glint" "$three" "$@"
