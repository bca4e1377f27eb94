#!/usr/bin/env bash
# make_dataset --preview on a tiny dataset, opened in a real browser (Debian's headless
# chromium): the page's own check finds every contact sheet loaded; with one sheet removed it
# names the broken one.
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
rm -f "$output.log"
exit $status
