#!/usr/bin/env bash
# Shards 0/3, 1/3 and 2/3 written into one folder are the unsharded run, file for file, byte for
# byte (lighting drawn per frame included); each shard alone renders only its third.
# Usage: shards_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER
set -u
binary=$1
config=$2
output=$3
rm -rf "$output"
status=0
"$binary" --config "$config" --output "$output/whole" --threads 2 >/dev/null 2>&1 || { echo "unsharded run failed"; exit 1; }
for k in 0 1 2; do
  "$binary" --config "$config" --output "$output/sharded" --shard "$k/3" --threads 1 > "$output/shard_$k.log" 2>&1 \
    || { echo "shard $k/3 failed:"; cat "$output/shard_$k.log"; exit 1; }
  grep -q "rendered [0-9]* frames and found 0 complete, of [0-9]* in this shard" "$output/shard_$k.log" \
    || { echo "shard $k/3 did not render its own frames:"; cat "$output/shard_$k.log"; status=1; }
done
rm "$output"/shard_*.log
frames=$(find "$output/sharded" -path '*/images/*.png' | wc -l)
whole=$(find "$output/whole" -path '*/images/*.png' | wc -l)
[ "$frames" -eq "$whole" ] || { echo "the shards wrote $frames frames, the unsharded run $whole"; status=1; }
diff -r "$output/whole" "$output/sharded" || { echo "the shards' union differs from the unsharded run"; status=1; }
exit $status
