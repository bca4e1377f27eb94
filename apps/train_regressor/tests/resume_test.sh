#!/usr/bin/env bash
# Ctrl-C during training, then the command the message prints, run as printed from another
# folder: it continues to the end. Run again, it has nothing to do (exit 0); asked for fewer epochs than the checkpoint
# holds, it says so (exit 2) instead of claiming it wrote files. Interrupted before the first
# epoch, it says no checkpoint was written.
# Usage: resume_test.sh TRAIN_REGRESSOR EVALUATE SCRATCH (example_test_setup.sh)
source "$(dirname "$0")/example_test_setup.sh" "$@"

# interrupt_after REGEX ARGS...: starts a training, sends SIGINT once stdout shows REGEX, and
# waits for the exit; sets $code.
interrupt_after() {
  local wait_for=$1
  shift
  "$train" "$@" >"$out" 2>"$log" &
  local pid=$!
  for _ in $(seq 1200); do
    grep -Eq "$wait_for" "$out" && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.05
  done
  kill -INT "$pid" 2>/dev/null
  wait "$pid"
  code=$?
}

run=(--dataset-root "$dataset" --width-divisor 4 --image-size 64 --epochs 4 --output-dir "$scratch/run")
interrupt_after "^epoch 1/4" "${run[@]}"
[ "$code" -eq 130 ] || fail "interrupted: exit code $code, expected 130"
command=$(sed -n 's/.*continue with: train_regressor //p' "$log")
[ -n "$command" ] || fail "interrupted: the message names no command"
# As printed: word-split the way a shell would the line the user copies, and run from another
# folder (the dataset root was given relative to this one).
read -r -a words <<<"$command"
(cd / && "$train" "${words[@]}") >"$out" 2>"$log"
code=$?
[ "$code" -eq 0 ] || fail "the printed command, run from /: exit code $code, expected 0"
grep -q "^resuming after epoch [12] from" "$out" || fail "the printed command did not resume"
grep -q "^epoch 4/4" "$out" || fail "the printed command did not train to epoch 4"
[ "$(wc -l <"$scratch/run/log.csv")" -eq 5 ] || fail "log.csv does not hold 4 epochs"

"$train" "${words[@]}" >"$out" 2>"$log"
code=$?
[ "$code" -eq 0 ] || fail "resuming a finished run: exit code $code, expected 0"
grep -q "already holds all 4 epochs; nothing to train" "$out" || fail "resuming a finished run: no message"

before=$(stat -c %Y "$scratch/run/config.yaml")
"$train" "${words[@]}" --epochs 2 >"$out" 2>"$log"
code=$?
[ "$code" -eq 2 ] || fail "resuming with fewer epochs: exit code $code, expected 2"
grep -q "last.pt already holds epoch 4, beyond the 2 epochs asked for; nothing was trained" "$log" ||
  fail "resuming with fewer epochs: no message"
grep -q "^wrote" "$out" && fail "resuming with fewer epochs claims it wrote files"
[ "$(stat -c %Y "$scratch/run/config.yaml")" -eq "$before" ] || fail "resuming with fewer epochs rewrote config.yaml"

interrupt_after "^training " --dataset-root "$dataset" --width-divisor 4 --image-size 64 --epochs 40 \
  --output-dir "$scratch/early"
[ "$code" -eq 130 ] || fail "interrupted early: exit code $code, expected 130"
grep -q "interrupted before the first epoch finished; no checkpoint was written" "$log" ||
  fail "interrupted early: no message"

exit "$status"
