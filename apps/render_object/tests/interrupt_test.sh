#!/usr/bin/env bash
# Ctrl-C or SIGTERM during a render: render_object stops, says so, exits with 128 + the signal
# (130, 143) and writes nothing; at 16,777,216 spp it shows progress within a pixel and stops
# within seconds of the signal, as it does while a library material is generated.
# Usage: interrupt_test.sh RENDER_OBJECT OUTPUT_FOLDER
set -u
binary=$1
output=$2
# Beside the output folder, in the build tree: nothing else a test run does touches it there.
log="$output.stderr"
trap 'rm -f "$log"' EXIT
status=0

# interrupt SIGNAL EXPECTED_CODE WAIT_FOR ARGS...: starts a render, waits until stderr shows
# WAIT_FOR (a regex; empty: three seconds, time enough on a loaded machine for the program to
# have started and installed its handlers, which a second was not), sends SIGNAL and checks the
# outcome.
interrupt() {
  local signal=$1 expected=$2 wait_for=$3
  shift 3
  rm -rf "$output"
  "$binary" "$@" --output "$output" >/dev/null 2>"$log" &
  local pid=$!
  local seen=0
  if [ -z "$wait_for" ]; then
    sleep 3
    seen=1
  fi
  for _ in $(seq 400); do
    [ "$seen" -eq 1 ] && break
    grep -Eq "$wait_for" "$log" && { seen=1; break; }
    sleep 0.05
  done
  [ "$seen" -eq 1 ] || { echo "$signal case: never printed '$wait_for'"; status=1; }
  kill "-$signal" "$pid"
  # A render that ignored the signal would run for hours: give it 10 s.
  local code=""
  for _ in $(seq 200); do
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  if kill -0 "$pid" 2>/dev/null; then
    echo "$signal case: still running 10 s after the signal"
    kill -KILL "$pid"
    status=1
  fi
  wait "$pid"
  code=$?
  [ "$code" -eq "$expected" ] || { echo "$signal case: exit code $code, expected $expected"; status=1; }
  grep -q "interrupted; nothing written" "$log" || { echo "$signal case: no interruption message"; status=1; }
  [ ! -e "$output" ] || { echo "$signal case: $output was written"; status=1; }
  [ "$status" -eq 0 ] || { echo "--- stderr ---"; cat "$log"; }
}

# Far more work than the test waits for, so the signal always lands mid-render. The first
# progress line means the scene is built and samples are being taken.
interrupt INT 130 "render" --object vase --resolution 512x512 --spp 1024
interrupt TERM 143 "render" --object vase --resolution 512x512 --spp 1024
# One pixel's samples take minutes here: progress must come from within the pixel.
interrupt INT 130 "render +0%" --object vase --resolution 8x8 --spp 16777216
# While a library material's 8192 x 8192 maps are made (tens of seconds), before any progress
# line: the signal is sent three seconds after the start.
interrupt TERM 143 "" --object vase --material wood --material-resolution 8192 --resolution 8x8 --spp 1
exit "$status"
