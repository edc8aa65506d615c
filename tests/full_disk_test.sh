#!/usr/bin/env bash
# Saves on a full file system never leave a half-written file: `glint render` (an image through
# OpenImageIO) and `glint presets -o` (a JSON file) fail with the path and the system's reason, the
# file they would have replaced is unchanged and no temporary is left beside it.
# The full file system is a 64 KiB tmpfs filled to the last byte (mounting needs root). Where
# mounting is not permitted, a file-size limit of zero (ulimit -f 0) makes every write fail with
# EFBIG instead: no root needed, but it tests the same error path less faithfully (the writes fail
# at once, not part-way). Where neither works the test is skipped (exit 77) and says why.
# usage: full_disk_test.sh GLINT OUTPUT_DIR
source "$(dirname "$0")/cli_checks.sh" "$@"

disk="$out/disk"
mkdir -p "$disk"
# The files a failed save must leave as they were, written while there is room.
"$glint" render "$here/scenes/lambert_sun.json" -o "$disk/sun.png" --size 32x32 >/dev/null &&
  "$glint" presets copper -o "$disk/copper.json" >/dev/null || { echo "cannot write the files to replace"; exit 1; }
cp "$disk/sun.png" "$disk/copper.json" "$out/"

# run_full ARGS...: glint ARGS with the disk full, stderr to $out/full.stderr, its exit code returned.
if mount -t tmpfs -o size=64k tmpfs "$disk" 2>"$out/mount.stderr"; then
  trap 'umount "$disk"' EXIT
  cp "$out/sun.png" "$out/copper.json" "$disk/"
  dd if=/dev/zero of="$disk/filler" bs=4k 2>/dev/null  # fills the file system: "No space left on device"
  method="a full 64 KiB tmpfs"
  reason="No space left on device"
  run_full() { "$glint" "$@" >/dev/null 2>"$out/full.stderr"; }
elif (ulimit -f 0 && true) 2>/dev/null; then
  method="ulimit -f 0 (mounting a tmpfs was refused: $(head -n1 "$out/mount.stderr"))"
  reason="File too large"
  # stderr through a pipe: the limit would stop glint writing it to a file too.
  run_full() {
    (ulimit -f 0 && exec "$glint" "$@") 2>&1 >/dev/null | cat >"$out/full.stderr"
    return "${PIPESTATUS[0]}"
  }
else
  echo "SKIP: neither a tmpfs mount ($(head -n1 "$out/mount.stderr")) nor a file-size limit (ulimit -f) is available"
  exit 77
fi
echo "full disk: $method"

# expect_refused NAME FILE ARGS...: glint ARGS (writing FILE) fails naming FILE and the reason; FILE is
# unchanged and no temporary is left.
expect_refused() {
  local name=$1 file=$2
  shift 2
  run_full "$@"
  local code=$?
  if ((code == 0)) || ! grep -qF "$disk/$file" "$out/full.stderr" || ! grep -qF "$reason" "$out/full.stderr"; then
    fail "$name: exit code $code, stderr: $(cat "$out/full.stderr")"
  elif ! cmp -s "$disk/$file" "$out/$file"; then
    fail "$name: $file changed by a failed save"
  elif ls -A "$disk" | grep -q partial; then
    fail "$name: a temporary was left: $(ls -A "$disk")"
  else
    pass "$name: refused with '$(head -n1 "$out/full.stderr")'"
  fi
}
expect_refused render_png sun.png render "$here/scenes/lambert_sun.json" -o "$disk/sun.png" --size 64x64
expect_refused preset_json copper.json presets gold -o "$disk/copper.json"
summary
