#!/usr/bin/env bash
# The three.js peer benchmark (not part of the test command; docs/performance.md): the scenes of
# tests/bench/scenes/peer_{ggx,lambert,empty}.json in three.js (npm) in headless Chromium (Debian's
# `chromium`) on the same Mesa llvmpipe, and in Glint, interleaved; prints both and the ratio.
# Installs what it lacks: Debian's chromium (apt-get, as root) and three into a cache folder.
# usage: tests/bench/threejs_peer.sh build/app/glint [peer.py options: --rounds N --frames N --size WxH]
set -euo pipefail
glint=$(realpath "$1"); shift
here=$(dirname "$(realpath "$0")")
tool=threejs_peer
source "$here/threejs_peer/install.sh"
exec /usr/bin/python3 "$here/threejs_peer/peer.py" "$glint" "$three" "$@"
