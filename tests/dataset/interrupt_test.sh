#!/usr/bin/env bash
# SIGTERM and SIGINT while a library material is generated (8192 texels a side: tens of seconds
# on 2 cores) are acted on within seconds, with the signal's exit code and the resume hint, and
# leave no frame or variant record behind.
# Usage: interrupt_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER
set -u
binary=$1
output=$3
rm -rf "$output"
mkdir -p "$output"
status=0

# interrupt SIGNAL EXPECTED_CODE
interrupt() {
  local signal=$1 expected=$2 folder=$output/$1
  "$binary" --objects vase --materials wood/raw:1 --grid 1x1 --resolution 16 --spp 1 --material-resolution 8192 \
    --output "$folder" >"$output/$signal.log" 2>&1 &
  local pid=$!
  # The split files are written just before the first variant's materials are made.
  for _ in $(seq 600); do
    [ -f "$folder/config/paper_random_v1.yaml" ] && break
    sleep 0.02
  done
  sleep 0.5
  local start=$(date +%s%N)
  kill "-$signal" "$pid"
  wait "$pid"
  local code=$? seconds=$(( ($(date +%s%N) - start) / 1000000000 ))
  [ "$code" -eq "$expected" ] || { echo "$signal: exit code $code, expected $expected"; cat "$output/$signal.log"; status=1; }
  # Generation stops within a row; the bound leaves room for a busy machine.
  [ "$seconds" -le 5 ] || { echo "$signal: the run took $seconds s to stop"; status=1; }
  grep -q "run the same command again to resume" "$output/$signal.log" || { echo "$signal: no resume hint"; status=1; }
  [ ! -e "$folder/vase/var000/metadata.json" ] || { echo "$signal: a variant record was written"; status=1; }
}

interrupt TERM 143
interrupt INT 130
exit $status
