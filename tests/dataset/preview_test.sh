#!/usr/bin/env bash
# make_dataset --preview on a tiny dataset, opened in a real browser (Debian's headless
# chromium): the page's own check finds every contact sheet loaded; with one sheet removed it
# names the broken one. A damaged map is drawn as a broken tile and named; a variant that cannot
# be read leaves the preview as it was.
# Usage: preview_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER
set -u
binary=$1
config=$2
output=$3
rm -rf "$output"
status=0
"$binary" --config "$config" --output "$output" >/dev/null 2>&1 || { echo "make_dataset failed"; exit 1; }
"$binary" --preview "$output" > "$output.log" 2>&1 || { echo "--preview failed:"; cat "$output.log"; exit 1; }
grep -q "wrote 5 contact sheets" "$output.log" || { echo "expected 5 contact sheets:"; cat "$output.log"; status=1; }
page="$output/preview/index.html"
# check: what the page says of its images once loaded.
check() {
  chromium --headless --no-sandbox --disable-gpu --disable-dev-shm-usage --virtual-time-budget=10000 \
    --dump-dom "file://$(realpath "$page")" 2>/dev/null | grep -o '<p id="image-check"[^<]*'
}
seen=$(check)
echo "$seen" | grep -q 'class="ok">images: 5 of 5 loaded' || { echo "in chromium: ${seen:-no image check}"; status=1; }
mv "$output/preview/stool__var000.png" "$output/stool.png"
seen=$(check)
echo "$seen" | grep -q 'class="broken">images: 4 of 5 loaded; broken: stool__var000.png' \
  || { echo "a missing sheet went unnoticed: ${seen:-no image check}"; status=1; }
mv "$output/stool.png" "$output/preview/stool__var000.png"

# A damaged map is drawn as a broken tile and named, on the console and the page; exit 1.
orm=$(find "$output/vase" -path '*/ORM/*.png' | sort | head -1)
truncate -s 200 "$orm"
"$binary" --preview "$output" > "$output.log" 2>&1
code=$?
[ "$code" -eq 1 ] || { echo "a damaged map: exit code $code, expected 1"; status=1; }
grep -qF "$orm" "$output.log" || { echo "the damaged map is not named:"; cat "$output.log"; status=1; }
grep -q "1 maps could not be read" "$output.log" || { echo "no count of damaged maps:"; cat "$output.log"; status=1; }
grep -qF "damaged maps, drawn as red and black stripes:<br>$orm" "$page" || { echo "the page does not name it"; status=1; }
seen=$(check)
echo "$seen" | grep -q 'class="ok">images: 5 of 5 loaded' || { echo "with a broken tile: ${seen:-no image check}"; status=1; }

# A variant whose records cannot be read: an error naming the file, and the preview as it was,
# with no half-made folder beside it.
before=$(cd "$output/preview" && sha256sum ./* | sort)
echo '{"w": 32, "h": 32}' > "$output/stool/var000/transforms.json"
"$binary" --preview "$output" > "$output.log" 2>&1
code=$?
[ "$code" -eq 1 ] || { echo "unreadable records: exit code $code, expected 1"; status=1; }
grep -q "stool/var000/transforms.json: no frames list" "$output.log" || { echo "not named:"; cat "$output.log"; status=1; }
after=$(cd "$output/preview" && sha256sum ./* | sort)
[ "$before" == "$after" ] || { echo "the preview changed after an error"; status=1; }
[ -z "$(find "$output" -maxdepth 1 -name '.preview*')" ] || { echo "a staging folder was left behind"; status=1; }
rm -f "$output.log"
exit $status
