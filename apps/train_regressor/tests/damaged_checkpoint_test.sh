#!/usr/bin/env bash
# Damaged checkpoints and checkpoints of another layout are refused (exit 2, naming the file) by
# evaluate and by train_regressor --pretrained-model alike, and nothing is written.
# Usage: damaged_checkpoint_test.sh TRAIN_REGRESSOR EVALUATE SCRATCH (example_test_setup.sh)
source "$(dirname "$0")/example_test_setup.sh" "$@"

# expect_refusal WHAT MESSAGE OUTPUT COMMAND...: COMMAND exits 2 with MESSAGE and leaves no OUTPUT.
expect_refusal() {
  local what=$1 message=$2 output=$3
  shift 3
  "$@" >/dev/null 2>"$log"
  local code=$?
  [ "$code" -eq 2 ] || fail "$what: exit code $code, expected 2"
  grep -q -- "$message" "$log" || fail "$what: no \"$message\" on stderr"
  [ ! -e "$output" ] || fail "$what: wrote $output"
}

# 200 bytes flipped in the middle half of the file, where the weights are (torch itself loads it).
flipped="$scratch/flipped.pt"
/usr/bin/python3 - train_output/checkpoints/last.pt "$flipped" <<'PY'
import random, sys
data = bytearray(open(sys.argv[1], "rb").read())
rng = random.Random(7)
for _ in range(200):
    data[rng.randrange(len(data) // 4, 3 * len(data) // 4)] ^= 0xFF
open(sys.argv[2], "wb").write(data)
PY
expect_refusal "evaluate, flipped bytes" "flipped.pt is damaged" "$scratch/evaluation" \
  "$evaluate" --checkpoint "$flipped" --dataset-root "$dataset" --output-dir "$scratch/evaluation"
expect_refusal "evaluate --image, flipped bytes" "flipped.pt is damaged" "$scratch/prediction" \
  "$evaluate" --checkpoint "$flipped" --image "$dataset/chair/var002/images/003.png" --output-dir "$scratch/prediction"
expect_refusal "--pretrained-model, flipped bytes" "flipped.pt is damaged" "$scratch/tuned" \
  "$train" --dataset-root "$dataset" --width-divisor 4 --image-size 64 --epochs 41 --pretrained-model "$flipped" \
  --output-dir "$scratch/tuned"

# Cut short, as by a copy that stopped half-way.
cut="$scratch/cut.pt"
head -c "$(($(stat -c %s train_output/checkpoints/last.pt) / 2))" train_output/checkpoints/last.pt >"$cut"
expect_refusal "evaluate, cut short" "cut.pt is not a checkpoint" "$scratch/evaluation" \
  "$evaluate" --checkpoint "$cut" --dataset-root "$dataset" --output-dir "$scratch/evaluation"

# base_color,normal has the 6 channels of the default base_color,roughness:3, but not their meaning.
"$train" --dataset-root "$dataset" --outputs base_color,normal --width-divisor 4 --image-size 64 --epochs 1 \
  --output-dir "$scratch/normal" >/dev/null 2>"$log" || fail "training base_color,normal failed"
expect_refusal "--pretrained-model, another layout" \
  "normal/checkpoints/last.pt was trained to predict base_color,normal, not the configured base_color,roughness:3" \
  "$scratch/tuned" \
  "$train" --dataset-root "$dataset" --width-divisor 4 --image-size 64 --epochs 2 \
  --pretrained-model "$scratch/normal/checkpoints/last.pt" --output-dir "$scratch/tuned"

exit "$status"
