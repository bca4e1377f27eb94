#!/usr/bin/env bash
# Shows that a change leaves every image bit for bit as it was: builds the apps of commit BEFORE
# (in a temporary worktree) and of the working tree, renders scripts/image_hashes.sh's images with
# each, and compares their SHA-256 sums. Exit 0 when all are equal, 1 with the differing files.
# Usage: same_images.sh BEFORE   (a commit, e.g. HEAD~1 or origin/main)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
before=$(git -C "$root" rev-parse --verify "$1^{commit}")
scratch=$(mktemp -d /tmp/same_images.XXXXXX)
trap 'git -C "$root" worktree remove --force "$scratch/source" >/dev/null 2>&1 || true; rm -rf "$scratch"' EXIT

build_apps() {  # SOURCE BUILD: the two apps, their output shown only when the build fails
  if ! { cmake -S "$1" -B "$2" -G Ninja -DCMAKE_BUILD_TYPE=Release -DMATPREDICT_BUILD_TESTS=OFF \
           -DMATPREDICT_BUILD_BENCH=OFF &&
         cmake --build "$2" --target render_object make_dataset -j "$(nproc)"; } >"$2.log" 2>&1; then
    tail -n 30 "$2.log" >&2
    echo "same_images: the build of $1 failed" >&2
    exit 1
  fi
}

git -C "$root" worktree add --detach "$scratch/source" "$before" >/dev/null 2>&1
build_apps "$scratch/source" "$scratch/build-before"
build_apps "$root" "$scratch/build-after"
bash "$root/scripts/image_hashes.sh" "$scratch/build-before" "$scratch/images-before" > "$scratch/before.txt"
bash "$root/scripts/image_hashes.sh" "$scratch/build-after" "$scratch/images-after" > "$scratch/after.txt"
count=$(wc -l < "$scratch/before.txt")
if diff "$scratch/before.txt" "$scratch/after.txt"; then
  echo "same_images: all $count images are bit for bit those of $1"
else
  echo "same_images: the images above differ from those of $1" >&2
  exit 1
fi
