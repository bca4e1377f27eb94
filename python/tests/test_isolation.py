"""Isolating an object before a network sees it: GrabCut on rendered frames whose label is the
truth, the crop against Pillow's resize, the whole flow from a photograph, and refused prompts."""
import os
import subprocess

import numpy as np
import pytest
from PIL import Image

import matpredict
from conftest import EVALUATE, write_exr

# bench/isolation_bench.py over the 18 built-in objects x 14 classes on cluttered backgrounds at
# 256 px: GrabCut's IoU has a 10th percentile of 0.603 (README, "Isolating an object"), so a
# typical frame (a saturated mug on a pale floor here) clears 0.60.
IOU_DECILE = 0.60


def blotches(path):
    """An environment of coloured blotches, the bench's kind of clutter."""
    rng = np.random.default_rng(3)
    v, u = np.mgrid[0:64, 0:128] / np.array([64, 128])[:, None, None]
    image = np.stack([0.5 + 0.3 * (1 - v), 0.45 + 0.2 * (1 - v), 0.4 + 0.1 * v], axis=-1)
    for _ in range(25):
        cu, cv, radius = rng.random(), rng.random(), 0.05 + 0.1 * rng.random()
        image += np.exp(-(((u - cu) / radius) ** 2 + ((v - cv) / radius) ** 2))[:, :, None] * (rng.random(3) - 0.3)
    return write_exr(path, np.clip(image, 0.02, None).astype(np.float32))


def cluttered_frame(tmp_path, name, material_class):
    """The object in a library material on a concrete floor under blotches and a sun, 128 px."""
    floor = matpredict.Mesh(np.array([[-9, -9, 0], [9, -9, 0], [9, 9, 0], [-9, 9, 0]], dtype=float),
                            np.array([[0, 1, 2], [0, 2, 3]]),
                            uvs=np.array([[0, 0], [9, 0], [9, 9], [0, 9]], dtype=float))
    scene = matpredict.load_scene({
        "camera": {"grid": {"cell": [6, 3], "n_phi": 16, "n_theta": 16, "radius": 0.35, "theta_range_deg": [0, 360]},
                   "width": 128, "height": 128},
        "lights": [{"type": "sun", "position": [2, -1, 2], "look_at": [0, 0, 0], "strength": 3}],
        "background": {"environment": str(blotches(tmp_path / "blotches.exr"))},
        "materials": {"object": {"class": material_class, "resolution": 128},
                      "floor": {"class": "concrete", "resolution": 128}},
        "objects": [{"builtin": name, "material": "object"}, {"mesh": floor, "material": "floor"}],
        "render": {"spp": 8, "seed": 2},
    })
    frame = matpredict.render(scene, aovs=["label"])
    truth = frame["label"][:, :, 0] == matpredict.material_classes()[material_class]
    return exposed(frame["color"]), truth


def exposed(color):
    """The bench's exposure: the frame's 98th percentile luminance at 0.9, as a camera meters."""
    bright = np.percentile(color @ np.array([0.2126, 0.7152, 0.0722], dtype=np.float32), 98)
    return matpredict.display_image(color, exposure_stops=float(np.log2(0.9 / bright)))


def iou(a, b):
    return np.logical_and(a, b).sum() / np.logical_or(a, b).sum()


def test_grabcut_isolates_a_rendered_object_on_a_cluttered_background(tmp_path):
    image, truth = cluttered_frame(tmp_path, "mug", "plastic")
    assert 0.05 < truth.mean() < 0.6
    isolated = matpredict.isolate(image, box=matpredict.mask_box(truth, grow=0.05))
    assert iou(isolated["mask"], truth) > IOU_DECILE
    # The same prompt, the same mask.
    assert np.array_equal(matpredict.isolate(image, box=matpredict.mask_box(truth, grow=0.05))["mask"], isolated["mask"])


def test_mask_box_is_the_grown_box_around_the_mask():
    mask = np.zeros((30, 52), dtype=bool)
    mask[4:24, 10:50] = True  # columns 10-49 (40 wide: 5 % is 2), rows 4-23 (20 tall: 5 % is 1)
    assert matpredict.mask_box(mask) == (10, 4, 49, 23)
    assert matpredict.mask_box(mask, grow=0.05) == (8, 3, 51, 24)
    mask[4:24, 0:50] = True  # clipped at column 0 and at the last column, 51
    assert matpredict.mask_box(mask, grow=0.1) == (0, 2, 51, 25)
    wide = np.zeros((30, 60), dtype=bool)
    wide[4:24, 5:55] = True  # 50 wide: 5 % is 2.5, rounded away from zero to 3
    assert matpredict.mask_box(wide, grow=0.05)[::2] == (2, 57)
    assert matpredict.mask_box(np.zeros((3, 3))) is None
    with pytest.raises(ValueError, match="mask: expected shape"):
        matpredict.mask_box(np.zeros(3))
    with pytest.raises(ValueError, match="grow: expected a fraction"):
        matpredict.mask_box(mask, grow=-0.1)


def test_the_crop_is_the_square_around_the_mask_resized_as_pillow_resizes():
    rng = np.random.default_rng(5)
    image = rng.integers(0, 256, size=(60, 80, 3), dtype=np.uint8)
    mask = np.zeros((60, 80), dtype=bool)
    mask[10:40, 30:50] = True  # 20 wide, 30 tall: 4 % of 30 is 1.2, so 2 px each side: a 34 px square
    isolated = matpredict.isolate(image, mask=mask, size=24, background="white")
    assert isolated["crop"] == (23, 8, 34)
    assert np.array_equal(isolated["mask"], mask)
    expected_square = np.ones((34, 34, 3), dtype=np.float32)
    inside = mask[8:42, 23:57]
    expected_square[inside] = image[8:42, 23:57][inside] / np.float32(255)
    for c in range(3):
        resized = Image.fromarray(expected_square[:, :, c], mode="F").resize((24, 24), Image.BILINEAR)
        np.testing.assert_allclose(isolated["input"][:, :, c], np.asarray(resized), atol=2e-6)
    assert isolated["input"].dtype == np.float32 and isolated["input_mask"].shape == (24, 24)
    # An RGBA image's transparent pixels are off the object.
    rgba = np.dstack([image, np.where(mask, 255, 0).astype(np.uint8)])
    assert np.array_equal(matpredict.isolate(rgba, size=24, background="white")["input"], isolated["input"])


def test_a_photograph_gives_maps_with_one_command(tmp_path, checkpoint):
    """skimage's coffee (Debian's python3-skimage): a cup on a saucer, no mask, GrabCut's default."""
    import skimage.data

    photo = tmp_path / "coffee.png"
    Image.fromarray(skimage.data.coffee()).save(photo)
    run = subprocess.run([EVALUATE, "--checkpoint", checkpoint, "--image", str(photo), "--box", "40,10,560,390",
                          "--output-dir", str(tmp_path / "out")], capture_output=True, text=True, check=True)
    assert "object: grabcut in the box (40,10)-(560,390)" in run.stdout
    for name in ("mask.png", "input.png", "panel.png", "base_color.png", "roughness.png"):
        assert (tmp_path / "out" / name).is_file(), name
    mask = np.asarray(Image.open(tmp_path / "out" / "mask.png")) > 0
    assert mask.shape == (400, 600) and 0.3 < mask.mean() < 0.7
    isolated = matpredict.isolate(skimage.data.coffee(), box=(40, 10, 560, 390), size=32)
    assert np.array_equal(isolated["mask"], mask)


def test_bad_prompts_and_images_are_refused_clearly():
    image = np.zeros((40, 50, 3), dtype=np.uint8)
    with pytest.raises(matpredict.InputError, match=r"the image: the box \(10,10\)-\(50,20\) reaches outside the 50 x 40 image"):
        matpredict.isolate(image, box=(10, 10, 50, 20))
    with pytest.raises(matpredict.InputError, match=r"the box \(30,10\)-\(20,20\) is empty"):
        matpredict.isolate(image, box=(30, 10, 20, 20))
    with pytest.raises(matpredict.InputError, match=r"the point \(3,40\) lies outside"):
        matpredict.isolate(image, points=[(3, 40)])
    with pytest.raises(ValueError, match=r"points: expected \(x, y\)"):
        matpredict.isolate(image, points=[(3, 4, 7)])
    with pytest.raises(matpredict.InputError, match="the mask marks no pixel"):
        matpredict.isolate(image, mask=np.zeros((40, 50)))
    with pytest.raises(ValueError, match=r"mask: expected shape \(40, 50\)"):
        matpredict.isolate(image, mask=np.ones((40, 49)))
    with pytest.raises(TypeError, match="image: expected uint8, uint16 or float values"):
        matpredict.isolate(image.astype(np.int32))
    with pytest.raises(ValueError, match=r"image: expected values in \[0, 1\]"):
        matpredict.isolate(image.astype(np.float32) + 2)
    with pytest.raises(ValueError, match="segmenter"):
        matpredict.isolate(image, segmenter="magic")
    with pytest.raises(matpredict.InputError, match="this box covers the whole image"):
        matpredict.isolate(image, box=(0, 0, 49, 39))


def test_segment_anything_isolates_from_a_converted_checkpoint(tmp_path):
    """A MobileSAM checkpoint in the released layout (random weights, written by Debian's torch),
    converted by the script a user runs: isolate(segmenter="sam:...") loads it through _learn."""
    import sys

    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    released, converted = tmp_path / "mobile_sam.pt", tmp_path / "converted.pt"
    subprocess.run([sys.executable, os.path.join(root, "tests", "learn", "official_sam_checkpoint.py"),
                    os.path.join(root, "tests", "learn", "data", "segment_anything", "vit_t_state_dict.tsv"), str(released)],
                   check=True)
    run = subprocess.run([sys.executable, os.path.join(root, "scripts", "convert_segment_anything.py"), str(released),
                          str(converted)], check=True, capture_output=True, text=True)
    assert "MobileSAM, 439 tensors, 10,130,092 parameters" in run.stdout
    image = np.full((90, 120, 3), 128, dtype=np.uint8)
    image[30:60, 40:80] = (200, 40, 30)
    try:
        isolated = matpredict.isolate(image, box=(35, 25, 84, 64), segmenter=f"sam:{converted}", size=32)
    except matpredict.InputError as error:  # random weights may find nothing; the message says so
        assert "found no object" in str(error)
    else:
        assert isolated["mask"].shape == (90, 120) and isolated["input"].shape == (32, 32, 3)
    with pytest.raises(matpredict.InputError, match="no_such.pt"):
        matpredict.isolate(image, segmenter=f"sam:{tmp_path / 'no_such.pt'}")
    with pytest.raises(ValueError, match="segmenter: expected grabcut or sam:CHECKPOINT"):
        matpredict.isolate(image, segmenter="sam:")
