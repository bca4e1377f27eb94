#!/usr/bin/env python3
"""Writes a checkpoint in a released Segment Anything layout, random weights: the test's stand-in
for a file the user downloads. Usage: official_sam_checkpoint.py LAYOUT.tsv OUT.pth [--without-counters]
[--wrong NAME]; --wrong gives NAME one more row than the official shape."""
import sys

import torch

layout, out = sys.argv[1], sys.argv[2]
without_counters = "--without-counters" in sys.argv
wrong = sys.argv[sys.argv.index("--wrong") + 1] if "--wrong" in sys.argv else None
generator = torch.Generator().manual_seed(5)
state = {}
with open(layout) as f:
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        name, shape_text = line.rstrip("\n").split("\t")
        shape = [int(s) for s in shape_text.strip("()").split(",") if s.strip()]
        if name.endswith("num_batches_tracked"):
            if not without_counters:
                state[name] = torch.tensor(7, dtype=torch.int64)
            continue
        if name == wrong:
            shape[0] += 1
        tensor = torch.randn(shape, generator=generator) * 0.05
        if name.endswith("running_var"):
            tensor = tensor.abs() + 1.0
        state[name] = tensor
torch.save(state, out)
