#!/usr/bin/env bash
# Shows that a change leaves every image bit for bit as it was: builds the apps of commit BEFORE
# (in a temporary worktree) and of commit AFTER (another one; without AFTER, the working tree),
# renders scripts/image_hashes.sh's images with each, and compares their SHA-256 sums. Exit 0 when
# all are equal, 1 with the differing files. Give AFTER to go on editing while it runs.
# Usage: same_images.sh BEFORE [AFTER]   (commits, e.g. HEAD~1 or origin/main)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
before=$(git -C "$root" rev-parse --verify "$1^{commit}")
after=${2:+$(git -C "$root" rev-parse --verify "$2^{commit}")}
scratch=$(mktemp -d /tmp/same_images.XXXXXX)
trap 'for tree in source after-source; do git -C "$root" worktree remove --force "$scratch/$tree" >/dev/null 2>&1 || true; done; rm -rf "$scratch"' EXIT

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
after_source=$root
if [ -n "$after" ]; then
  git -C "$root" worktree add --detach "$scratch/after-source" "$after" >/dev/null 2>&1
  after_source=$scratch/after-source
fi
build_apps "$after_source" "$scratch/build-after"
bash "$root/scripts/image_hashes.sh" "$scratch/build-before" "$scratch/images-before" > "$scratch/before.txt"
bash "$root/scripts/image_hashes.sh" "$scratch/build-after" "$scratch/images-after" > "$scratch/after.txt"
count=$(wc -l < "$scratch/before.txt")
if diff "$scratch/before.txt" "$scratch/after.txt"; then
  echo "same_images: all $count images${2:+ of $2} are bit for bit those of $1"
else
  echo "same_images: the images above differ from those of $1" >&2
  exit 1
fi
