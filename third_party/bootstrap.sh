#!/usr/bin/env bash
# The README's two commands: installs what is missing (Debian packages), configures and builds
# Glint, then either runs the editor (`run`, with any arguments passed on to glint) or the
# whole test suite (`test`). Idempotent and quick when everything is already there.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="${GLINT_BUILD_DIR:-$root/build}"
mode=${1:-}
[[ $mode == run || $mode == test ]] || { echo "usage: $0 run [glint arguments…] | test" >&2; exit 2; }
shift

"$root/third_party/install-deps.sh"
if [[ ! -f "$build/build.ninja" ]]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo
fi
cmake --build "$build"

case $mode in
  run) exec "$build/app/glint" "$@" ;;
  test) cd "$build" && exec ctest --output-on-failure --timeout 300 ;;
esac
