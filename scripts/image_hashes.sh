#!/usr/bin/env bash
# Renders the images a refactoring must leave bit for bit as they were, with the apps of one build
# folder, and prints a SHA-256 line per image file: the default render, the three example scenes,
# one of them with --cycles-parity, all built-in objects, every material class on the vase and the
# embedded default dataset. scripts/same_images.sh compares two commits with it.
# Usage: image_hashes.sh BUILD_DIR WORK_DIR   (WORK_DIR is emptied and filled with the images)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$(cd "$1" && pwd)
work=$2
render="$build/apps/render_object/render_object"
make_dataset="$build/apps/make_dataset/make_dataset"
small=(--resolution 64x64 --spp 16 --threads 2)

rm -rf "$work" && mkdir -p "$work" && cd "$work"
log="$PWD/log.txt"
run() {  # a command, its output kept in the log and shown when it fails
  "$@" >>"$log" 2>&1 || { tail -n 20 "$log" >&2; echo "image_hashes: failed: $*" >&2; exit 1; }
}
run "$render" --threads 2 --output default
for scene in "$root"/apps/render_object/examples/*.json; do
  name=$(basename "$scene" .json)
  run "$render" --scene "$scene" "${small[@]}" --aovs all --output "examples/$name"
done
run "$render" --scene "$root/apps/render_object/examples/vase_in_library_materials.json" "${small[@]}" \
  --cycles-parity --output cycles_parity
for object in $("$render" --list-objects); do
  run "$render" --object "$object" "${small[@]}" --output "objects/$object"
done
for class in $("$render" --list-materials | awk -F'`' '/^\| [0-9]+ \|/ && $2 != "background" {print $2}'); do
  run "$render" --object vase --material "$class" --material-resolution 256 "${small[@]}" \
    --output "materials/$class"
done
run "$make_dataset" --threads 2 --output dataset
find . -type f \( -name '*.png' -o -name '*.exr' \) -print0 | sort -z | xargs -0 sha256sum
