#!/usr/bin/env bash
# Writes that fail leave nothing behind: render_object exits 1 naming the file, and none of the
# view's files (nor the output folder it made) remains.
#   - a disk that fills up halfway through the view: a 60 KB tmpfs where the machine lets us mount
#     one, else a 40 KB file-size limit (ulimit -f, with SIGXFSZ ignored so writes fail with EFBIG);
#   - a directory in the way of one of the files.
# Usage: full_disk_test.sh RENDER_OBJECT SCRATCH_FOLDER
set -u
binary=$1
scratch=$2
rm -rf "$scratch"
mkdir -p "$scratch"
log="$scratch/stderr.txt"
status=0
fail() { echo "$1"; echo "--- stderr ---"; cat "$log"; status=1; }

small="$scratch/small"
mkdir -p "$small"
if mount -t tmpfs -o size=60k tmpfs "$small" 2>/dev/null; then
  how="a 60 KB tmpfs"
  "$binary" --spp 4 --output "$small/out" >/dev/null 2>"$log"
  code=$?
  umount_later=1
else
  how="a 40 KB file-size limit"
  (trap '' XFSZ; ulimit -f 40; exec "$binary" --spp 4 --output "$small/out") >/dev/null 2>"$log"
  code=$?
  umount_later=0
fi
[ "$code" -eq 1 ] || fail "$how: exit code $code, expected 1"
grep -q "render_object: .*: cannot write $small/out/view_005_016_[a-z_]*\.\(exr\|png\): " "$log" ||
  fail "$how: the error names no file"
[ ! -e "$small/out" ] || fail "$how: $(ls -a "$small/out" | tr '\n' ' ') left in $small/out"
[ "$umount_later" -eq 0 ] || umount "$small"

way="$scratch/in_the_way"
mkdir -p "$way/view_005_016_depth.png"
"$binary" --spp 1 --resolution 16x16 --output "$way" >/dev/null 2>"$log"
code=$?
[ "$code" -eq 1 ] || fail "directory in the way: exit code $code, expected 1"
grep -q "view_005_016_depth.png: a directory of that name is in the way" "$log" || fail "directory in the way: no such message"
left=$(ls -A "$way")
[ "$left" = "view_005_016_depth.png" ] || fail "directory in the way: left $left"

exit "$status"
