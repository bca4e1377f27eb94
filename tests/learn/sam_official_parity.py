#!/usr/bin/env python3
"""Our Segment Anything against the official code, stage by stage, with the same weights.

    /usr/bin/python3 sam_official_parity.py --segment-anything DIR --mobile-sam DIR \\
        --dump build/tests/learn/sam_prediction_dump --convert scripts/convert_segment_anything.py

DIR are checkouts of facebookresearch/segment-anything (holding the package segment_anything)
and ChaoningZhang/MobileSAM (holding mobile_sam), which are not Debian packages; nothing is
downloaded. For SAM ViT-B and MobileSAM, the official model is built with every parameter and
buffer randomised (so that no weight sits at a value that hides a swapped or missing term),
saved as a released checkpoint is, converted by our script and run by our code on
scikit-image's coffee photograph with three prompts: a box, one point (ambiguous: multi-mask)
and a box with points. Each stage is compared with the official one fed the same tensors:

  image encoder      the same normalised input: the embeddings
  prompt + decoder   the same embedding and prompt: the four masks' logits and predicted IoUs
  mask at photo size the same low-resolution logits: Sam.postprocess_masks
  preprocessing      our float resize against the predictor's 8-bit Pillow resize (at most a code)
  end to end         SamPredictor.predict's mask against ours (IoU)

Exits 1 when a stage differs by more than float32 arithmetic in another order explains.
"""
import argparse
import os
import subprocess
import sys
import tempfile

import numpy as np
import torch

# Relative to the largest magnitude of the official output: float32 sums in another order.
NETWORK_TOLERANCE = 2e-4
# Our input is resized in float, the official predictor's in 8 bits: a code, over the smallest std.
INPUT_TOLERANCE = 1.0 / 57.12 + 1e-5
# End to end, the masks differ only where the logit is within the input's rounding of zero.
END_TO_END_IOU = 0.98

# timm, which MobileSAM's TinyViT imports for three helpers, is not a Debian package: the
# smallest stand-in (no parameter, no buffer; DropPath is the identity in eval mode).
TIMM_STAND_IN = '''
import collections.abc
import torch.nn as nn
def to_2tuple(x):
    return tuple(x) if isinstance(x, collections.abc.Iterable) and not isinstance(x, str) else (x, x)
def trunc_normal_(tensor, mean=0.0, std=1.0, a=-2.0, b=2.0):
    return nn.init.trunc_normal_(tensor, mean=mean, std=std, a=a, b=b)
class DropPath(nn.Identity):
    def __init__(self, drop_prob=None):
        super().__init__()
'''

PROMPTS = {
    "box": {"box": (40, 10, 560, 390), "points": []},
    "one point": {"box": None, "points": [(300, 220, 1)]},
    "box and points": {"box": (40, 10, 560, 390), "points": [(300, 220, 1), (30, 380, 0)]},
}


def install_timm_stand_in(folder):
    try:
        import timm  # noqa: F401
    except ImportError:
        os.makedirs(os.path.join(folder, "timm", "models"))
        for name, text in (("timm/__init__.py", ""), ("timm/models/__init__.py", ""),
                           ("timm/models/layers.py", TIMM_STAND_IN),
                           ("timm/models/registry.py", "def register_model(f):\n    return f\n")):
            with open(os.path.join(folder, name), "w") as f:
                f.write(text)
        sys.path.insert(0, folder)


def randomised(model, seed):
    """Every floating tensor of the state dict (what a released checkpoint holds) moved off its
    initial value, zeros and ones included; the normalisation's mean and std are constants."""
    generator = torch.Generator().manual_seed(seed)
    with torch.no_grad():
        for name, tensor in model.state_dict().items():  # views of the model's own tensors
            if not tensor.is_floating_point():
                continue
            spread = float(tensor.std()) if tensor.numel() > 1 and float(tensor.std()) > 0 else 0.05
            noise = torch.randn(tensor.shape, generator=generator) * 0.2 * spread
            tensor.add_(noise)
            if name.endswith("running_var"):
                tensor.abs_().add_(0.5)
    return model.eval()


def relative_difference(ours, official):
    ours, official = torch.as_tensor(ours, dtype=torch.float32), torch.as_tensor(official, dtype=torch.float32)
    assert ours.shape == official.shape, f"shapes {tuple(ours.shape)} and {tuple(official.shape)}"
    return float((ours - official).abs().max() / official.abs().max().clamp_min(1e-12))


def official_prompt(prompt, transform, original_size):
    points = labels = boxes = None
    if prompt["points"]:
        coordinates = np.array([p[:2] for p in prompt["points"]], dtype=np.float32)
        points = torch.as_tensor(transform.apply_coords(coordinates, original_size))[None]
        labels = torch.as_tensor([p[2] for p in prompt["points"]])[None]
    if prompt["box"] is not None:
        boxes = torch.as_tensor(transform.apply_boxes(np.array(prompt["box"], dtype=np.float32), original_size))
    return points, labels, boxes


def compare(kind, build, predictor_class, transform_class, photo, photo_path, args, folder):
    model = randomised(build(checkpoint=None), seed=11)
    released = os.path.join(folder, f"{kind}_released.pth")
    converted = os.path.join(folder, f"{kind}_converted.pt")
    torch.save(model.state_dict(), released)
    subprocess.run([sys.executable, args.convert, released, converted], check=True, stdout=subprocess.DEVNULL)
    predictor = predictor_class(model)
    predictor.set_image(photo)
    transform = transform_class(1024)
    original_size = photo.shape[:2]
    failures = []
    rows = []

    def check(stage, value, limit, compare_above=False):
        failed = value < limit if compare_above else value > limit
        rows.append(f"  {stage:<58} {value:.3g} ({'>' if compare_above else '<'}= {limit:.3g}){'  FAILED' if failed else ''}")
        if failed:
            failures.append(f"{kind}: {stage}")

    for label, prompt in PROMPTS.items():
        dump = os.path.join(folder, f"{kind}_{label.replace(' ', '_')}.pt")
        command = [args.dump, converted, photo_path, dump]
        if prompt["box"] is not None:
            command += ["--box", ",".join(map(str, prompt["box"]))]
        for point in prompt["points"]:
            command += ["--point", ",".join(map(str, point))]
        subprocess.run(command, check=True)
        ours = torch.load(dump)
        with torch.no_grad():
            if label == "box":
                official_input = predictor.model.preprocess(
                    torch.as_tensor(transform.apply_image(photo)).permute(2, 0, 1)[None].float())
                check("preprocessing: largest input difference", float((ours["input"] - official_input).abs().max()),
                      INPUT_TOLERANCE)
                embedding = model.image_encoder(ours["input"])
                check("image encoder, same input: embedding", relative_difference(ours["embedding"], embedding),
                      NETWORK_TOLERANCE)
            points, labels, boxes = official_prompt(prompt, transform, original_size)
            sparse, dense = model.prompt_encoder(points=(points, labels) if points is not None else None, boxes=boxes,
                                                 masks=None)
            logits, iou = model.mask_decoder.predict_masks(ours["embedding"], model.prompt_encoder.get_dense_pe(),
                                                           sparse, dense)
            check(f"{label}: decoder, same embedding: four masks' logits",
                  relative_difference(ours["mask_logits"], logits), NETWORK_TOLERANCE)
            check(f"{label}: decoder, same embedding: predicted IoUs", relative_difference(ours["iou"], iou),
                  NETWORK_TOLERANCE)
            chosen = int(ours["chosen"])
            at_photo = model.postprocess_masks(ours["mask_logits"][:, chosen:chosen + 1], transform.get_preprocess_shape(
                *original_size, 1024), original_size)[0, 0]
            check(f"{label}: mask {chosen} at the photograph's size", relative_difference(ours["logits"], at_photo),
                  NETWORK_TOLERANCE)
            multimask = prompt["box"] is None and len(prompt["points"]) <= 1
            masks, scores, _ = predictor.predict(
                point_coords=np.array([p[:2] for p in prompt["points"]], dtype=np.float32) if prompt["points"] else None,
                point_labels=np.array([p[2] for p in prompt["points"]]) if prompt["points"] else None,
                box=np.array(prompt["box"], dtype=np.float32) if prompt["box"] is not None else None,
                multimask_output=multimask)
            official_mask = masks[int(np.argmax(scores))] if multimask else masks[0]
            our_mask = (ours["logits"] > 0).numpy()
            union = np.logical_or(our_mask, official_mask).sum()
            check(f"{label}: end to end, SamPredictor's mask: IoU",
                  float(np.logical_and(our_mask, official_mask).sum() / union) if union else 1.0, END_TO_END_IOU,
                  compare_above=True)
    print(f"{kind}:")
    print("\n".join(rows))
    return failures


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--segment-anything", required=True, help="folder holding the package segment_anything")
    parser.add_argument("--mobile-sam", required=True, help="folder holding the package mobile_sam")
    parser.add_argument("--dump", required=True, help="the sam_prediction_dump executable")
    parser.add_argument("--convert", required=True, help="scripts/convert_segment_anything.py")
    args = parser.parse_args()

    import skimage.data
    from PIL import Image

    torch.manual_seed(0)
    torch.set_num_threads(2)
    photo = skimage.data.coffee()
    failures = []
    with tempfile.TemporaryDirectory() as folder:
        install_timm_stand_in(os.path.join(folder, "stand_in"))
        photo_path = os.path.join(folder, "coffee.png")
        Image.fromarray(photo).save(photo_path)
        sys.path.insert(0, args.segment_anything)
        from segment_anything import SamPredictor, sam_model_registry
        from segment_anything.utils.transforms import ResizeLongestSide
        failures += compare("SAM ViT-B", sam_model_registry["vit_b"], SamPredictor, ResizeLongestSide, photo, photo_path,
                            args, folder)
        sys.path.insert(0, args.mobile_sam)
        from mobile_sam import SamPredictor as MobileSamPredictor
        from mobile_sam import sam_model_registry as mobile_sam_registry
        from mobile_sam.utils.transforms import ResizeLongestSide as MobileSamResize
        failures += compare("MobileSAM", mobile_sam_registry["vit_t"], MobileSamPredictor, MobileSamResize, photo,
                            photo_path, args, folder)
    if failures:
        print("differs from the official model: " + "; ".join(failures), file=sys.stderr)
        return 1
    print("every stage agrees with the official model")
    return 0


if __name__ == "__main__":
    sys.exit(main())
