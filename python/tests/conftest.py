"""Fixtures of the Python package's tests: small scene files, written where each test runs."""
import json
import os
import subprocess

import pytest

# The render_object binary and the example scenes, from the CMake build (python/CMakeLists.txt).
RENDER_OBJECT = os.environ.get("MATPREDICT_RENDER_OBJECT", "")
MAKE_DATASET = os.environ.get("MATPREDICT_MAKE_DATASET", "")
TRAIN_REGRESSOR = os.environ.get("MATPREDICT_TRAIN_REGRESSOR", "")
EVALUATE = os.environ.get("MATPREDICT_EVALUATE", "")
EXAMPLES = os.environ.get("MATPREDICT_EXAMPLES", "")


def read_exr(path):
    """An EXR as OpenImageIO reads it, (height, width, channels) float32: the reference reader."""
    import OpenImageIO as oiio

    image = oiio.ImageInput.open(str(path))
    assert image is not None, oiio.geterror()
    pixels = image.read_image(format="float")
    image.close()
    return pixels


def write_exr(path, pixels):
    """(height, width, channels) float32 pixels as an EXR, by OpenImageIO."""
    import OpenImageIO as oiio

    height, width, channels = pixels.shape
    output = oiio.ImageOutput.create(str(path))
    assert output.open(str(path), oiio.ImageSpec(width, height, channels, "float"))
    assert output.write_image(pixels)
    output.close()
    return path


def write_scene(folder, width=48, height=36, spp=4, **render):
    """The built-in vase under the sun and a soft lamp, small enough to render in a blink."""
    scene = {
        "camera": {"position": [0.9, -0.9, 0.45], "look_at": [0, 0, 0.15], "width": width, "height": height},
        "background": [0.05, 0.06, 0.08],
        "lights": [
            {"type": "sun", "position": [2, -1, 1], "look_at": [0, 0, 0], "strength": 4, "angle_deg": 3},
            {"type": "point", "position": [-0.6, -0.8, 0.5], "power": 8, "radius": 0.2},
        ],
        "objects": [{"builtin": "vase"}],
        "render": {"spp": spp, **render},
    }
    path = os.path.join(folder, "scene.json")
    with open(path, "w") as f:
        json.dump(scene, f)
    return path


@pytest.fixture
def small_scene(tmp_path):
    return write_scene(str(tmp_path))


@pytest.fixture(scope="session")
def tiny_dataset(tmp_path_factory):
    """Two variants of the vase (two library materials) from two views at 32 px, by make_dataset."""
    root = tmp_path_factory.mktemp("dataset") / "out"
    subprocess.run([MAKE_DATASET, "--objects", "vase", "--materials", "wood/raw:1,metal/brushed:2", "--grid", "1x2",
                    "--resolution", "32x32", "--spp", "2", "--output", str(root), "--threads", "2"],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return str(root)


@pytest.fixture(scope="session")
def checkpoint(tiny_dataset, tmp_path_factory):
    """One epoch of the quarter-width UNet on the tiny dataset at its own 32 px."""
    out = tmp_path_factory.mktemp("training")
    subprocess.run([TRAIN_REGRESSOR, "--dataset-root", tiny_dataset, "--width-divisor", "4", "--image-size", "32",
                    "--epochs", "1", "--threads", "2", "--output-dir", str(out)],
                   check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    return str(out / "checkpoints" / "last.pt")
