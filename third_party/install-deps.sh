#!/usr/bin/env bash
# Installs the Debian 12 packages listed in packages.txt, and nothing else.
# Idempotent: when every package is already present it touches neither apt nor the network.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
mapfile -t wanted < <(sed 's/#.*//; s/[[:space:]]//g; /^$/d' "$here/packages.txt")
missing=()
for package in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$package" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$package")
done
if ((${#missing[@]} == 0)); then
  echo "glint: all ${#wanted[@]} Debian packages present"
  exit 0
fi
if [[ $(id -u) -ne 0 ]]; then
  echo "glint: missing packages: ${missing[*]}" >&2
  echo "glint: run this script as root (or: sudo apt-get install ${missing[*]})" >&2
  exit 2
fi
echo "glint: installing ${#missing[@]} Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
