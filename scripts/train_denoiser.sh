#!/usr/bin/env bash
# Trains the learned denoiser as the committed weights were trained (docs/denoising.md,
# "Training"), or continues a stopped run where it stopped: every step resumes.
#   1. make_dataset renders configs/denoiser_training.yaml and configs/denoiser_test.yaml (the
#      held-out frames) at 1024 samples, the references, and at 1, 2, 4, ..., 64 samples with
#      another render.seed each, the noisy inputs: the same frames with independent noise. A
#      finished frame is not rendered again.
#   2. train_denoiser trains on the training pairs from the checkpoint beside the weights, if
#      there is one, and writes the weights.
# Usage: scripts/train_denoiser.sh BUILD_DIR DATA_DIR WEIGHTS [train_denoiser options...]
set -euo pipefail
if [ $# -lt 3 ]; then
  sed -n '2,11p' "$0" | sed 's/^# \{0,1\}//'
  exit 2
fi
build=$1 data=$2 weights=$3
shift 3
here=$(cd "$(dirname "$0")/.." && pwd)
make_dataset=$build/apps/make_dataset/make_dataset
noisy_counts="1 2 4 8 16 32 64"

for split in training test; do
  config=$here/configs/denoiser_$split.yaml
  "$make_dataset" --config "$config" --output "$data/$split/reference" --set render.seed=1
  for spp in $noisy_counts; do
    "$make_dataset" --config "$config" --output "$data/$split/spp_$spp" --spp "$spp" --set "render.seed=$((100 + spp))"
  done
done

noisy=()
for spp in $noisy_counts; do noisy+=("$data/training/spp_$spp"); done
"$build/apps/train_denoiser/train_denoiser" --reference "$data/training/reference" --noisy "${noisy[@]}" \
  --output "$weights" "$@"
