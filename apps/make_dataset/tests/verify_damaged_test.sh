#!/usr/bin/env bash
# make_dataset --verify on a dataset damaged in five ways: a map cut short, a map missing, a label
# id of a class the variant does not use, sample counts of 0 and beyond the render's samples, a
# split file listing a frame that is not there (so its counts contradict its lists). Each is
# reported with its file, and the exit code is 1.
# Usage: verify_damaged_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER
set -u
binary=$1
config=$2
output=$3
rm -rf "$output"
"$binary" --config "$config" --output "$output" >/dev/null 2>&1 || { echo "make_dataset failed"; exit 1; }
variant=$output/box_without_uvs/var000
truncate -s 200 "$variant/ORM/000.png"
rm "$variant/depth/001.exr"
# Label 3 (leather) everywhere the object is, in a variant of wood and metal.
/usr/bin/python3 - "$output/box_without_uvs/var001/label/000.png" <<'PY'
import sys
from PIL import Image
path = sys.argv[1]
image = Image.open(path)
image.point(lambda v: 3 if v > 0 else 0).save(path)
PY
# A pixel that took no sample and one that took more than the render's samples.
/usr/bin/python3 - "$output/box_without_uvs/var001/sample_count/001.png" <<'PY'
import sys
from PIL import Image
path = sys.argv[1]
image = Image.open(path)
image.putpixel((0, 0), 0)
image.putpixel((1, 0), 999)
image.save(path)
PY
echo "  - box_without_uvs/var009/000" >> "$output/config/paper_random_v1.yaml"
"$binary" --verify "$output" > "$output.log" 2>&1
code=$?
status=0
[ "$code" -eq 1 ] || { echo "exit code $code, expected 1"; status=1; }
for expected in "cannot decode $variant/ORM/000.png" "var000/depth/001.exr: missing" \
    "var001/label/000.png: label 3 (leather) is not among the variant's used_materials" \
    "var001/sample_count/001.png: 1 pixels took no sample" \
    "var001/sample_count/001.png: 1 pixels took more than the 2 samples metadata.json states" \
    "paper_random_v1.yaml: lists box_without_uvs/var009/000, no frame of the dataset" \
    "paper_random_v1.yaml: counts.test is 1, but its test lists 2 frames" \
    "paper_random_v1.yaml: counts.total is 4, but its three lists 5 frames" "8 problems"; do
  grep -qF "$expected" "$output.log" || { echo "not reported: $expected"; status=1; }
done
[ "$status" -eq 0 ] || cat "$output.log"
rm -f "$output.log"
exit $status
