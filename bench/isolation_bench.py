#!/usr/bin/env python3
"""How well each segmenter isolates an object, measured on rendered frames whose label is the truth.

    PYTHONPATH=build/python /usr/bin/python3 bench/isolation_bench.py [--objects all] [--classes all]
        [--segmenters grabcut] [--prompts box,none] [--size 256] [--spp 16] [--output isolation_bench.json]

Every built-in object in a material of every library class is rendered from one view of a grid
around it (a cell drawn from the seed), three times: on the black background under the paper's
light rig; cluttered, standing on a textured floor of another class under an environment map of
coloured blotches and a sun, so that the background is no flat colour; and in a room, on the floor
of a box room (floors of wood, stone, concrete, marble or ceramic, walls of plaster, concrete,
paper or wood) with two or three other built-in objects standing around it in materials of other
classes (which may hide part of it), under the paper's rig. The object's pixels are those whose
nearest hit is on it (the object_id AOV). The prompt is their bounding box grown by 5 % on each side
(matpredict.isolate's `box`), as a user draws a box around an object, or none (the most central
object: the frame is centred on it, as a photograph of one object is). Each segmenter's mask is
scored by its intersection over union with the truth, and timed (the isolate call alone, on
the frame as an 8-bit display image). Prints the IoU distribution per segmenter and background,
and per material class, as markdown tables; writes every frame's figures to --output.

With --checkpoint (a network train_regressor wrote), each frame is also predicted twice, isolated
with its true mask and with each segmenter's, exposed as make_dataset exposes its images (a grey
card at the object's centre, metered under the frame's lights, shows half its albedo; the
segmenters see the camera's exposure above), and the predicted base colour is scored (RMSE, in
the stored sRGB encoding) against the rendered base colour cropped and resized the same way, on
the true object's pixels of the crop: what a segmenter's mistakes cost the prediction.
"""
import argparse
import json
import math
import os
import random
import statistics
import tempfile
import time

import numpy as np

import matpredict

# The floor's class, unless the object has it: then the second.
FLOOR_CLASSES = ("concrete", "wood")
# What stands behind the object: nothing, a floor under blotches and a sun, a room with distractors.
BACKGROUNDS = ("black", "cluttered", "room")
# A room's floor and walls are drawn from what rooms are made of (configs/paper_in_room.yaml's),
# leaving out the object's own class.
ROOM_FLOOR_CLASSES = ("wood", "stone", "concrete", "marble", "ceramic")
ROOM_WALL_CLASSES = ("plaster", "concrete", "paper", "wood")


def write_environment(path, seed):
    """An equirectangular EXR of soft coloured blotches over a sky-to-floor gradient (the clutter
    of a room's walls, seen blurred), written by OpenImageIO."""
    import OpenImageIO as oiio

    rng = np.random.default_rng(seed)
    height, width = 128, 256
    v, u = np.mgrid[0:height, 0:width] / np.array([height, width])[:, None, None]
    image = np.stack([0.5 + 0.3 * (1 - v), 0.45 + 0.2 * (1 - v), 0.4 + 0.1 * v], axis=-1)
    for _ in range(40):
        cu, cv, radius = rng.random(), rng.random(), 0.03 + 0.1 * rng.random()
        du = np.minimum(np.abs(u - cu), 1 - np.abs(u - cu))
        weight = np.exp(-((du / radius) ** 2 + ((v - cv) / radius) ** 2))
        image += weight[:, :, None] * (rng.random(3) * 1.5 - 0.3)
    image = np.clip(image, 0.02, None).astype(np.float32)
    output = oiio.ImageOutput.create(path)
    assert output.open(path, oiio.ImageSpec(width, height, 3, "float"))
    assert output.write_image(image)
    output.close()


def floor_mesh(half_side):
    positions = np.array([[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]], dtype=float) * half_side
    uvs = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float) * half_side  # one texture per metre
    return matpredict.Mesh(positions, np.array([[0, 1, 2], [0, 2, 3]]), uvs=uvs)


def object_scene(name, material_class, seed, camera, size, spp, cluttered, environment):
    scene = {
        "camera": dict(camera, width=size, height=size),
        "materials": {"object": {"class": material_class, "seed": seed, "resolution": 512}},
        "objects": [{"builtin": name, "material": "object"}],
        "render": {"spp": spp, "seed": seed},
    }
    if not cluttered:
        scene["lights"] = {"rig": {}}
        return scene
    floor = next(c for c in FLOOR_CLASSES if c != material_class)
    scene["materials"]["floor"] = {"class": floor, "seed": seed + 1, "resolution": 512}
    scene["objects"].append({"mesh": floor_mesh(20.0), "material": "floor"})
    scene["background"] = {"environment": environment, "strength": 1.0, "rotation_z_deg": (37 * seed) % 360}
    scene["lights"] = [{"type": "sun", "position": [2, -1, 2], "look_at": [0, 0, 0], "strength": 3, "angle_deg": 5}]
    return scene


def room_scene(scene, material_class, seed, center, radius, sizes):
    """`scene` moved into a box room: a floor and walls six radii out, in room classes other than
    the object's, and two or three other built-in objects on the floor around the object in any
    other class, scaled to 0.4 to 0.9 of its bounding radius, their bounding spheres apart from its
    and from each other's, lit by the rig."""
    rng = random.Random(seed)
    others = [c for c in matpredict.material_classes() if c != material_class]
    floor = rng.choice([c for c in ROOM_FLOOR_CLASSES if c != material_class])
    walls = rng.choice([c for c in ROOM_WALL_CLASSES if c not in (material_class, floor)])
    scene["materials"]["floor"] = {"class": floor, "seed": seed + 1, "resolution": 512}
    scene["materials"]["walls"] = {"class": walls, "seed": seed + 2, "resolution": 512}
    scene["objects"].append({"room": {"floor_center": [center[0], center[1], 0.0], "half_width": 6 * radius,
                                      "height": 6 * radius, "walls": "box", "metres_per_uv": radius},
                             "materials": {"floor": "floor", "walls": "walls"}})
    count = rng.choice((2, 3))
    first = rng.uniform(0, 360)
    for k, name in enumerate(rng.sample([n for n in sizes if n != scene["objects"][0]["builtin"]], count)):
        size = rng.uniform(0.4, 0.9) * radius
        # Bearings 360 / count apart (at least 120 degrees), at a distance that keeps the spheres
        # a fifth of a radius apart from the object's.
        bearing = math.radians(first + 360 * k / count + rng.uniform(-15, 15))
        distance = radius + size + rng.uniform(0.2, 1.2) * radius
        scale = size / sizes[name]
        scene["materials"][f"distractor{k}"] = {"class": rng.choice(others), "seed": seed + 3 + k, "resolution": 512}
        scene["objects"].append({"builtin": name, "material": f"distractor{k}", "surroundings": True,
                                 "transform": {"translate": [center[0] + distance * math.cos(bearing),
                                                             center[1] + distance * math.sin(bearing), 0.0],
                                               "rotate_deg": [0, 0, rng.uniform(0, 360)], "scale": scale}})
    scene["lights"] = {"rig": {}}
    return scene


def display(color):
    """The frame as a camera would expose it: its 98th percentile luminance at 0.9, sRGB 8-bit."""
    luminance = color @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32)
    bright = float(np.percentile(luminance, 98))
    stops = math.log2(0.9 / bright) if bright > 0 else 0.0
    return matpredict.display_image(color, exposure_stops=max(-20.0, min(20.0, stops)))


def grey_card_stops(scene, center, radius, camera_position):
    """The exposure make_dataset's images have (docs/make_dataset.md, "Exposure"), measured as a
    photographer meters incident light: a grey Lambertian card at the object's centre, turned to
    the camera, rendered under the scene's lights with the object made transparent (so that its
    rig stays where it was and it casts no shadow), is shown at half its albedo."""
    albedo = 0.18
    normal = np.asarray(camera_position, dtype=float) - center
    normal /= np.linalg.norm(normal)
    side = np.cross(normal, [0.0, 0.0, 1.0])
    side = side / np.linalg.norm(side) if np.linalg.norm(side) > 1e-6 else np.array([1.0, 0.0, 0.0])
    up = np.cross(side, normal)
    half = 0.25 * radius
    corners = [center + half * (a * side + b * up) for a, b in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    metering = dict(scene, camera=dict(scene["camera"], width=64, height=64),
                    render={"spp": 64, "seed": scene["render"]["seed"]})
    metering["materials"] = dict(scene["materials"], object={"opacity": 0.0},
                                 card={"base_color": [albedo] * 3, "roughness": 0.5, "specular": 0.0})
    metering["objects"] = scene["objects"] + [{"mesh": matpredict.Mesh(np.array(corners), np.array([[0, 1, 2], [0, 2, 3]])),
                                               "material": "card"}]
    color = matpredict.render(matpredict.load_scene(metering))["color"]
    luminance = float(np.mean(color[30:34, 30:34] @ np.array([0.2126, 0.7152, 0.0722])))
    return math.log2(albedo / (2 * luminance))


def intersection_over_union(a, b):
    union = np.logical_or(a, b).sum()
    return float(np.logical_and(a, b).sum() / union) if union else 1.0


def crop_like(values, crop, size, resample):
    """(H, W, C) values cut to isolate's square `crop` (zero past the image) and resized as isolate
    resizes (Pillow's filter per channel)."""
    from PIL import Image

    left, top, side = crop
    height, width, channels = values.shape
    square = np.zeros((side, side, channels), dtype=np.float32)
    y0, x0, y1, x1 = max(0, top), max(0, left), min(height, top + side), min(width, left + side)
    square[y0 - top:y1 - top, x0 - left:x1 - left] = values[y0:y1, x0:x1]
    return np.stack([np.asarray(Image.fromarray(square[:, :, c], mode="F").resize((size, size), resample))
                     for c in range(channels)], axis=-1)


def srgb(linear):
    linear = np.clip(linear, 0, 1)
    return np.where(linear <= 0.0031308, 12.92 * linear, 1.055 * np.power(linear, 1 / 2.4) - 0.055).astype(np.float32)


def base_color_error(model, isolated, albedo, truth):
    """RMSE of the predicted base colour of an isolated object on its true pixels in the crop."""
    from PIL import Image

    size = model.image_size
    predicted = model.predict(isolated["input"])["base_color"]
    expected = crop_like(albedo, isolated["crop"], size, Image.BILINEAR)
    on_object = crop_like(truth[:, :, None].astype(np.float32), isolated["crop"], size, Image.NEAREST)[:, :, 0] > 0.5
    return float(np.sqrt(np.mean((predicted - expected)[on_object] ** 2))) if on_object.any() else None


def summary_row(label, ious, seconds):
    ious = sorted(ious)
    decile = ious[max(0, len(ious) // 10 - 1)] if len(ious) >= 10 else ious[0]
    return (f"| {label} | {len(ious)} | {statistics.mean(ious):.3f} | {decile:.3f} | {statistics.median(ious):.3f} | "
            f"{ious[0]:.3f} | {statistics.median(seconds) * 1000:.0f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--objects", default="all", help="comma-separated built-in objects, or all")
    parser.add_argument("--classes", default="all", help="comma-separated material classes, or all")
    parser.add_argument("--size", type=int, default=256)
    parser.add_argument("--spp", type=int, default=16)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--segmenters", default="grabcut", help="comma-separated: grabcut, sam:CHECKPOINT")
    parser.add_argument("--prompts", default="box,none", help="comma-separated: box (the label's, grown by 5 %%), none")
    parser.add_argument("--checkpoint", help="also score a trained network's base colour on the isolated objects")
    parser.add_argument("--output", default="isolation_bench.json")
    args = parser.parse_args()

    objects = matpredict.builtin_objects() if args.objects == "all" else args.objects.split(",")
    classes = matpredict.material_classes()
    chosen = list(classes) if args.classes == "all" else args.classes.split(",")
    segmenters = args.segmenters.split(",")
    prompts = args.prompts.split(",")
    if not set(prompts) <= {"box", "none"}:
        parser.error(f"--prompts: expected box and/or none, got {args.prompts}")
    methods = [(segmenter, prompt) for segmenter in segmenters for prompt in prompts]
    model = matpredict.load_model(args.checkpoint) if args.checkpoint else None
    rng = random.Random(args.seed)
    # Each built-in object's bounding radius, which the room's distractors are scaled by.
    sizes = {name: matpredict.load_scene(object_scene(name, "wood", 0, {"position": [1, 1, 1], "look_at": [0, 0, 0]},
                                                      8, 1, False, None)).bounds[1]
             for name in matpredict.builtin_objects()}
    records = []
    skipped = 0
    with tempfile.TemporaryDirectory() as folder:
        environment = os.path.join(folder, "blotches.exr")
        write_environment(environment, args.seed)
        for name in objects:
            # A view that frames the object: a grid cell above the horizon, at 3.4 times its
            # bounding sphere's radius (Blender's 50 mm lens, 39.6 degrees across, fits the sphere
            # from 2.95 radii).
            (cx, cy, cz), radius = matpredict.load_scene(
                object_scene(name, "wood", 0, {"position": [1, 1, 1], "look_at": [0, 0, 0]}, 8, 1, False, None)).bounds
            for k, material_class in enumerate(chosen):
                cell = [rng.randrange(5, 12), rng.randrange(0, 16)]
                camera = {"grid": {"cell": cell, "n_phi": 16, "n_theta": 16, "radius": 3.4 * radius,
                                   "theta_range_deg": [0, 360], "center": [cx, cy, cz]}}
                for background in BACKGROUNDS:
                    described = object_scene(name, material_class, 1 + k, camera, args.size, args.spp,
                                             background == "cluttered", environment)
                    if background == "room":
                        described = room_scene(described, material_class, 1 + k, (cx, cy, cz), radius, sizes)
                    scene = matpredict.load_scene(described)
                    frame = matpredict.render(scene, aovs=["base_color", "object_id"])
                    truth = frame["object_id"][:, :, 0] == 0
                    edges = np.concatenate([truth[0], truth[-1], truth[:, 0], truth[:, -1]])
                    if truth.sum() < 16 or edges.any():
                        skipped += 1  # not wholly in view: no box lies around it
                        continue
                    image = display(frame["color"])
                    box = matpredict.mask_box(truth, grow=0.05)
                    albedo = srgb(frame["base_color"])
                    true_error = None
                    if model:
                        # The segmenters see the frame as a camera exposes it; the network sees it
                        # exposed as its training images were.
                        metered = matpredict.display_image(frame["color"], exposure_stops=grey_card_stops(
                            described, np.array([cx, cy, cz]), radius, scene.camera.position))
                        true_error = base_color_error(model, matpredict.isolate(metered, mask=truth, size=model.image_size),
                                                      albedo, truth)
                    for segmenter, prompt in methods:
                        start = time.perf_counter()
                        error = None
                        try:
                            isolated = matpredict.isolate(image, box=box if prompt == "box" else None,
                                                          segmenter=segmenter, size=model.image_size if model else 224)
                            seconds = time.perf_counter() - start
                            iou = intersection_over_union(isolated["mask"], truth)
                            refusal = None
                            if model:
                                error = base_color_error(model, matpredict.isolate(metered, mask=isolated["mask"],
                                                                                   size=model.image_size), albedo, truth)
                        except matpredict.InputError as refused:  # counted as no overlap
                            seconds = time.perf_counter() - start
                            iou, refusal = 0.0, str(refused)
                        room = ([described["materials"][part]["class"] for part in ("floor", "walls")]
                                if background == "room" else None)
                        records.append({"object": name, "class": material_class, "background": background,
                                        "room": room,
                                        "segmenter": segmenter, "prompt": prompt, "cell": cell, "box": list(box), "iou": iou,
                                        "refusal": refusal, "seconds": seconds, "object_pixels": int(truth.sum()),
                                        "base_color_rmse": error, "base_color_rmse_true_mask": true_error})
            print(f"{name}: {len(records)} frames so far", flush=True)
    with open(args.output, "w") as f:
        json.dump({"size": args.size, "spp": args.spp, "seed": args.seed, "skipped": skipped, "frames": records}, f, indent=1)

    def label(segmenter, prompt, background):
        return f"{segmenter}, {'box' if prompt == 'box' else 'no prompt'}, {background}"

    def chosen_records(segmenter, prompt, background):
        return [r for r in records if (r["segmenter"], r["prompt"], r["background"]) == (segmenter, prompt, background)]

    print(f"\nIoU with the true mask, {args.size} x {args.size} frames ({skipped} frames skipped: the object not "
          "wholly in view); box: the label's box grown by 5 %:\n")
    print("| segmenter, prompt, background | frames | mean | 10th percentile | median | worst | ms per image |")
    print("|---|---|---|---|---|---|---|")
    groups = [(segmenter, prompt, background) for segmenter, prompt in methods for background in BACKGROUNDS]
    for group in groups:
        found = chosen_records(*group)
        if found:
            print(summary_row(label(*group), [r["iou"] for r in found], [r["seconds"] for r in found]))
    if model:
        print(f"\nBase colour RMSE of {args.checkpoint} ({model.network}, {model.image_size} px), on the true object's "
              "pixels of each crop:\n")
        print("| segmenter, prompt, background | frames | isolated with the true mask | isolated by the segmenter |")
        print("|---|---|---|---|")
        for group in groups:
            scored = [r for r in chosen_records(*group)
                      if r["base_color_rmse"] is not None and r["base_color_rmse_true_mask"] is not None]
            if scored:
                print(f"| {label(*group)} | {len(scored)} | "
                      f"{statistics.mean(r['base_color_rmse_true_mask'] for r in scored):.4f} | "
                      f"{statistics.mean(r['base_color_rmse'] for r in scored):.4f} |")
    print("\nMean IoU per material class (cluttered | room):\n")
    print("| class | " + " | ".join(f"{segmenter}, {prompt}" for segmenter, prompt in methods) + " |")
    print("|---|" + "---|" * len(methods))
    for material_class in chosen:
        cells = []
        for segmenter, prompt in methods:
            means = []
            for background in ("cluttered", "room"):
                ious = [r["iou"] for r in chosen_records(segmenter, prompt, background) if r["class"] == material_class]
                means.append(f"{statistics.mean(ious):.3f}" if ious else "-")
            cells.append(" / ".join(means))
        print(f"| {material_class} | " + " | ".join(cells) + " |")
    print(f"\nwrote {args.output}")


if __name__ == "__main__":
    main()
