#!/usr/bin/env python3
"""Makes a tiny dataset and trains a small network on it for one epoch, all from Python.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/tiny_training.py [--out tiny_training]

make_dataset renders the vase in two library materials from four views at 64 px; the samples come
through matpredict.torch_data.MaterialDataset and a DataLoader; a three-layer convolutional
network predicts base colour and roughness with an L1 loss on the object's pixels.
"""
import argparse
import os

import torch
import torch.nn as nn

import matpredict
from matpredict.torch_data import MaterialDataset


def configuration(size):
    return {
        "objects": [{"name": "vase", "builtin": "vase", "seed": 0}],
        "materials": {"all": ["wood/raw:1", "ceramic:2"]},
        "camera": {"grid": [2, 2]},
        "render": {"resolution": [size, size], "samples": 4, "material_resolution": 128},
    }


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="tiny_training", help="folder of the dataset")
    parser.add_argument("--size", type=int, default=64, help="pixels per side")
    args = parser.parse_args()
    torch.manual_seed(0)

    summary = matpredict.make_dataset(configuration(args.size), output=os.path.join(args.out, "dataset"),
                                      progress=lambda done, total: print(f"\rframes {done}/{total}", end=""))
    print(f"\n{summary['frames']} frames in {summary['output']}")

    loader = torch.utils.data.DataLoader(MaterialDataset(summary["output"], size=args.size), batch_size=4,
                                         shuffle=True, num_workers=2)
    network = nn.Sequential(nn.Conv2d(3, 16, 3, padding=1), nn.ReLU(), nn.Conv2d(16, 16, 3, padding=1), nn.ReLU(),
                            nn.Conv2d(16, 4, 3, padding=1), nn.Sigmoid())
    optimizer = torch.optim.Adam(network.parameters(), lr=1e-3)
    for batch in loader:
        target = torch.cat([batch["albedo"], batch["roughness"]], dim=1)
        mask = batch["mask"]
        loss = ((network(batch["input"]) - target).abs() * mask).sum() / (mask.sum() * target.shape[1]).clamp(min=1)
        optimizer.zero_grad()
        loss.backward()
        optimizer.step()
        print(f"batch of {len(batch['id'])}: L1 on the object {loss.item():.4f}")
    print("trained one epoch")


if __name__ == "__main__":
    main()
