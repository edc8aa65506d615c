# Sourced by tests/bench/threejs_peer.sh and threejs_compare.sh with $tool set: installs what they
# lack (Debian's chromium with apt-get, as root; three from the npm registry into a cache folder)
# and sets $three to the three package's folder.
three_version=0.187.0
cache=${GLINT_PEER_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/glint-threejs-peer}
if ! command -v chromium >/dev/null; then
  echo "$tool: installing Debian's chromium" >&2
  apt-get install -y chromium >&2
fi
three=$cache/three-$three_version/node_modules/three
if [[ ! -f $three/build/three.module.js ]]; then
  echo "$tool: installing three@$three_version from the npm registry into $cache" >&2
  npm install --prefix "$cache/three-$three_version" --no-audit --no-fund --no-save "three@$three_version" >&2
fi
