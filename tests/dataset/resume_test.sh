#!/usr/bin/env bash
# A run killed part way, by SIGTERM (a scheduler's preemption: exit 143, finished frames kept)
# and by SIGKILL (no chance to clean up), then resumed with the same command, ends with the files
# of an uninterrupted run, byte for byte; a frame damaged since it was written is rendered again.
# Usage: resume_test.sh MAKE_DATASET CONFIG OUTPUT_FOLDER
set -u
binary=$1
config=$2
output=$3
rm -rf "$output"
mkdir -p "$output"
status=0
# Frames slow enough (about 0.1 s each on one thread) for a signal to land mid-run.
settings=(--resolution 64 --spp 16)
"$binary" --config "$config" --output "$output/whole" "${settings[@]}" >/dev/null 2>&1 \
  || { echo "uninterrupted run failed"; exit 1; }

# interrupt SIGNAL FOLDER: starts a run on one thread, waits for a few finished frames, signals it.
interrupt() {
  local signal=$1 folder=$2
  "$binary" --config "$config" --output "$folder" --threads 1 "${settings[@]}" >"$output/run.log" 2>&1 &
  local pid=$!
  for _ in $(seq 600); do
    [ "$(find "$folder" -path '*/images/*.png' 2>/dev/null | wc -l)" -ge 4 ] && break
    sleep 0.02
  done
  kill "-$signal" "$pid"
  wait "$pid"
  echo $?
}

code=$(interrupt TERM "$output/terminated")
[ "$code" -eq 143 ] || { echo "SIGTERM: exit code $code, expected 143"; cat "$output/run.log"; status=1; }
grep -q "run the same command again to resume" "$output/run.log" || { echo "SIGTERM: no resume hint"; status=1; }
done_before=$(find "$output/terminated" -path '*/images/*.png' | wc -l)
[ "$done_before" -lt 30 ] || { echo "SIGTERM came after the run had finished"; status=1; }
"$binary" --config "$config" --output "$output/terminated" --threads 1 "${settings[@]}" >"$output/run.log" 2>&1 \
  || { echo "resume after SIGTERM failed"; cat "$output/run.log"; status=1; }
grep -q "found $done_before complete" "$output/run.log" \
  || { echo "the resumed run did not skip the $done_before finished frames:"; cat "$output/run.log"; status=1; }
diff -r "$output/whole" "$output/terminated" || { echo "SIGTERM then resume differs from the uninterrupted run"; status=1; }

code=$(interrupt KILL "$output/killed")
[ "$code" -eq 137 ] || { echo "SIGKILL: exit code $code, expected 137"; status=1; }
[ "$(find "$output/killed" -path '*/images/*.png' | wc -l)" -lt 30 ] || { echo "SIGKILL came after the run had finished"; status=1; }
# A finished map damaged afterwards (a full disk, a copy cut short): found and rendered again.
damaged=$(find "$output/killed" -path '*/ORM/*.png' | sort | head -1)
[ -n "$damaged" ] && truncate -s 100 "$damaged"
"$binary" --config "$config" --output "$output/killed" --threads 1 "${settings[@]}" >"$output/run.log" 2>&1 \
  || { echo "resume after SIGKILL failed"; cat "$output/run.log"; status=1; }
diff -r "$output/whole" "$output/killed" || { echo "SIGKILL then resume differs from the uninterrupted run"; status=1; }
# No temporary of the killed run is left.
left=$(find "$output/killed" -name '.*' | wc -l)
[ "$left" -eq 0 ] || { echo "temporaries left: $(find "$output/killed" -name '.*')"; status=1; }
exit $status
