#!/usr/bin/env bash
# Ctrl-C during a render: render_object stops, says so, exits with 130 and writes nothing.
# Usage: interrupt_test.sh RENDER_OBJECT OUTPUT_FOLDER
set -u
binary=$1
output=$2
rm -rf "$output"
log=$(mktemp)
trap 'rm -f "$log"' EXIT

# Far more work than the test waits for, so the interrupt always lands mid-render.
"$binary" --object vase --resolution 512x512 --spp 1024 --output "$output" >/dev/null 2>"$log" &
pid=$!
# The first progress line means the scene is built and tiles are being rendered.
for _ in $(seq 200); do
  grep -q "render" "$log" && break
  sleep 0.05
done
kill -INT "$pid"
wait "$pid"
code=$?

status=0
[ "$code" -eq 130 ] || { echo "exit code $code, expected 130"; status=1; }
grep -q "interrupted; nothing written" "$log" || { echo "no interruption message"; status=1; }
[ ! -e "$output" ] || { echo "$output was written"; status=1; }
[ "$status" -eq 0 ] || { echo "--- stderr ---"; cat "$log"; }
exit "$status"
