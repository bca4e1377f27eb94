#!/usr/bin/env python3
"""Converts a released Segment Anything checkpoint into the tensors libmatlearn's model loads.

Usage: convert_segment_anything.py IN OUT.pt
  IN      sam_vit_b_01ec64.pth (SAM ViT-B, facebookresearch/segment-anything) or mobile_sam.pt
          (MobileSAM, ChaoningZhang/MobileSAM), as their authors distribute them, downloaded by
          you: nothing is downloaded here
  OUT.pt  the same tensors as float32, for evaluate --segmenter sam:OUT.pt and
          matpredict.isolate(segmenter="sam:OUT.pt")

Run it with Debian's Python (/usr/bin/python3, package python3-torch). libmatlearn's modules are
laid out as the official ones (docs/segment_anything.md), so no tensor is renamed; MobileSAM's
BatchNorm counters, which inference does not use and some files lack, are added as zeros.
"""
import os
import sys

import torch

# A tensor only each size's image encoder has, and the sizes this build does not have.
SIZES = {"SAM ViT-B": "image_encoder.blocks.0.attn.qkv.weight",
         "MobileSAM": "image_encoder.layers.0.blocks.0.conv1.c.weight"}
VIT_WIDTHS = {768: "SAM ViT-B", 1024: "SAM ViT-L", 1280: "SAM ViT-H"}


def size_of(state, source):
    found = [name for name, mark in SIZES.items() if mark in state]
    qkv = state.get(SIZES["SAM ViT-B"])
    if qkv is not None and qkv.dim() == 2 and VIT_WIDTHS.get(qkv.shape[1]) != "SAM ViT-B":
        raise ValueError(f"{source}: {VIT_WIDTHS.get(qkv.shape[1], 'a ViT of width ' + str(qkv.shape[1]))} is not a size "
                         "this build has (SAM ViT-B or MobileSAM)")
    if len(found) != 1:
        raise ValueError(f"{source}: not a Segment Anything checkpoint (no {SIZES['SAM ViT-B']} nor "
                         f"{SIZES['MobileSAM']})")
    return found[0]


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    source, target = sys.argv[1:]
    try:
        state = torch.load(source, map_location="cpu")
    except Exception as error:  # torch raises many kinds for a file that is not its own
        print(f"{source}: cannot be read by torch.load: {error}", file=sys.stderr)
        return 1
    if not isinstance(state, dict) or not state or not all(isinstance(v, torch.Tensor) for v in state.values()):
        print(f"{source}: not a state dict of tensors", file=sys.stderr)
        return 1
    try:
        size = size_of(state, source)
    except ValueError as error:
        print(error, file=sys.stderr)
        return 1
    converted = {name: tensor.float().contiguous() if tensor.is_floating_point() else tensor.contiguous()
                 for name, tensor in state.items()}
    added = 0
    for name in list(converted):
        if name.endswith(".running_mean"):
            counter = name[: -len("running_mean")] + "num_batches_tracked"
            if counter not in converted:
                converted[counter] = torch.tensor(0, dtype=torch.int64)
                added += 1
    partial = target + ".partial"
    torch.save(converted, partial)
    os.replace(partial, target)
    # The model's parameters: every float tensor but the buffers (BatchNorm statistics, the
    # positional encoding's Gaussian), comparable with the count docs/segment_anything.md states.
    buffers = ("running_mean", "running_var", "positional_encoding_gaussian_matrix")
    parameters = sum(t.numel() for n, t in converted.items() if t.is_floating_point() and not n.endswith(buffers))
    print(f"{target}: {size}, {len(converted)} tensors, {parameters:,} parameters"
          + (f" ({added} BatchNorm counters added)" if added else ""))
    return 0


if __name__ == "__main__":
    sys.exit(main())
