#!/usr/bin/env python3
"""Converts torchvision ImageNet weights into the state dict of a libmatlearn encoder.

Usage: convert_torchvision_weights.py MODEL IN.pth OUT.pt
  MODEL   resnet50, swin_t or convnext_tiny
  IN.pth  the weights as torchvision distributes them (a state dict, e.g.
          resnet50-11ad3fa6.pth, swin_t-704ceda3.pth, convnext_tiny-983f1562.pth);
          nothing is downloaded
  OUT.pt  the encoder's tensors, classifier dropped, for matlearn::load_state_dict

Run it with Debian's Python (/usr/bin/python3, package python3-torch); the encoders' module
trees equal torchvision's, so no tensor is renamed.
"""
import os
import sys

import torch

CLASSIFIER_PREFIXES = {"resnet50": ("fc.",), "swin_t": ("head.",), "convnext_tiny": ("classifier.",)}


def main() -> int:
    if len(sys.argv) != 4 or sys.argv[1] not in CLASSIFIER_PREFIXES:
        print(__doc__, file=sys.stderr)
        return 2
    model, source, target = sys.argv[1:]
    state = torch.load(source, map_location="cpu")
    if not isinstance(state, dict) or not all(isinstance(v, torch.Tensor) for v in state.values()):
        print(f"{source}: not a state dict of tensors", file=sys.stderr)
        return 1
    encoder = {name: tensor.float().contiguous() if tensor.is_floating_point() else tensor
               for name, tensor in state.items() if not name.startswith(CLASSIFIER_PREFIXES[model])}
    partial = target + ".partial"
    torch.save(encoder, partial)
    os.replace(partial, target)
    print(f"{target}: {len(encoder)} tensors of {model}'s encoder ({len(state) - len(encoder)} classifier tensors dropped)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
