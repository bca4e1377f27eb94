#!/usr/bin/env bash
# A disk that fills up: train_regressor and evaluate exit 1 naming the file, and leave no half of
# their outputs (no checkpoint, no temporary, no tables without panels, no empty folder).
# A small tmpfs where the machine lets us mount one, else a file-size limit (ulimit -f, SIGXFSZ
# ignored, so writes fail with EFBIG).
# Usage: full_disk_test.sh TRAIN_REGRESSOR EVALUATE SCRATCH (example_test_setup.sh)
source "$(dirname "$0")/example_test_setup.sh" "$@"

# run_full KB COMMAND...: runs COMMAND with at most KB kilobytes of room for its outputs, which it
# writes under $scratch/small; sets $code.
run_full() {
  local kb=$1
  shift
  mkdir -p "$scratch/small"
  if mount -t tmpfs -o "size=${kb}k" tmpfs "$scratch/small" 2>/dev/null; then
    "$@" >/dev/null 2>"$log"
    code=$?
    umount "$scratch/small"
  else
    (trap '' XFSZ; ulimit -f "$kb"; exec "$@") >/dev/null 2>"$log"
    code=$?
  fi
}

# The evaluation's tables fit, its panel does not: neither may appear.
run_full 20 "$evaluate" --dataset-root "$dataset" --output-dir "$scratch/small/evaluation"
[ "$code" -eq 1 ] || fail "evaluate: exit code $code, expected 1"
grep -q "cannot write .*panels/[a-z]*\.png: " "$log" || fail "evaluate: the error names no file"
[ ! -e "$scratch/small/evaluation" ] || fail "evaluate: left $scratch/small/evaluation"

# One epoch's checkpoint (about 10 MB) does not fit in 2 MB.
run_full 2048 "$train" --dataset-root "$dataset" --epochs 1 --image-size 64 --output-dir "$scratch/small/training"
[ "$code" -eq 1 ] || fail "train_regressor: exit code $code, expected 1 (134 was an uncaught c10::Error)"
grep -q "checkpoints/last.pt: cannot write: " "$log" || fail "train_regressor: the error names no checkpoint"
if [ -d "$scratch/small/training/checkpoints" ]; then
  left=$(ls -A "$scratch/small/training/checkpoints")
  [ -z "$left" ] || fail "train_regressor: left $left in checkpoints/"
fi

exit "$status"
