#!/usr/bin/env python3
"""Renders one built-in object in three library materials and saves them side by side.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/three_materials.py [--object vase] [--out three_materials.png]

The scene is a dict with the scene file's keys (docs/scene_format.md): the paper's light rig, a
camera of the paper's grid looking at the object, one material of the procedural library per
render. The images are scene-linear; for the PNG all three are exposed alike, the objects' mean
luminance to 18 % grey, and sRGB-encoded.
"""
import argparse

import numpy as np
from PIL import Image

import matpredict

MATERIALS = [{"class": "wood", "style": "lacquered", "seed": 1},
             {"class": "metal", "seed": 2},
             {"class": "fabric", "seed": 3}]


def scene(object_name, material, size, spp):
    return {
        "camera": {"grid": {"cell": [5, 12], "radius": 0.55}, "width": size, "height": size},
        "lights": {"rig": {"target_illuminance_lux": 1000}},
        # A grey world for the metal to reflect: against black it would show only the lamps.
        "background": [0.3, 0.3, 0.3],
        "objects": [{"builtin": object_name, "material": dict(material, resolution=256)}],
        "render": {"spp": spp, "seed": 0},
    }


def srgb(linear):
    linear = np.clip(linear, 0.0, 1.0)
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * np.power(linear, 1 / 2.4) - 0.055)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--object", default="vase", help="a built-in object (render_object --list-objects)")
    parser.add_argument("--size", type=int, default=256, help="pixels per side of each render")
    parser.add_argument("--spp", type=int, default=64, help="samples per pixel")
    parser.add_argument("--out", default="three_materials.png", help="the PNG to write")
    args = parser.parse_args()

    frames = []
    for material in MATERIALS:
        frames.append(matpredict.render(matpredict.load_scene(scene(args.object, material, args.size, args.spp)),
                                        aovs=["alpha"]))
        print(f"{material['class']}: rendered {args.size}x{args.size} at {args.spp} spp")
    luminance = np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)
    on_objects = np.concatenate([(f["color"] @ luminance)[f["alpha"][:, :, 0] > 0.5] for f in frames])
    exposure = 0.18 / max(float(on_objects.mean()), 1e-6) if on_objects.size else 1.0
    panels = [(srgb(f["color"] * exposure) * 255 + 0.5).astype(np.uint8) for f in frames]
    Image.fromarray(np.concatenate(panels, axis=1)).save(args.out)
    print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
