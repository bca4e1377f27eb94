"""A trained checkpoint from Python: the maps evaluate --image writes, and refusals naming the file."""
import os
import subprocess
import sys

import numpy as np
import pytest
from PIL import Image

import matpredict
from conftest import EVALUATE


def test_importing_matpredict_does_not_load_libtorch():
    code = "import sys, matpredict; sys.exit('matpredict._learn' in sys.modules)"
    assert subprocess.run([sys.executable, "-c", code]).returncode == 0


def test_a_build_without_the_learning_extension_says_how_to_make_it(tmp_path):
    package = os.path.dirname(matpredict.__file__)
    copy = tmp_path / "matpredict"
    copy.mkdir()
    for name in os.listdir(package):
        if not name.startswith("_learn") and os.path.isfile(os.path.join(package, name)):
            os.symlink(os.path.join(package, name), copy / name)
    code = "import matpredict; matpredict.load_model('x.pt')"
    # From tmp_path: `python -c` looks in its working folder first, where ctest's holds the package.
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=tmp_path,
                         env=dict(os.environ, PYTHONPATH=str(tmp_path)))
    assert run.returncode == 1
    assert "ImportError: matpredict.load_model needs the extension matpredict._learn" in run.stderr, run.stderr
    assert "--target matpredict_python_learn" in run.stderr


def test_a_checkpoint_predicts_the_maps_evaluate_writes(checkpoint, tiny_dataset, tmp_path):
    model = matpredict.load_model(checkpoint)
    assert (model.network, model.image_size, model.epochs_done) == ("unet_no_skip", 32, 1)
    assert model.outputs == ["base_color", "roughness"]
    frame = os.path.join(tiny_dataset, "vase", "var001")
    image, mask = os.path.join(frame, "images", "001.png"), os.path.join(frame, "label", "001.png")
    subprocess.run([EVALUATE, "--checkpoint", checkpoint, "--image", image, "--mask", mask, "--output-dir",
                    str(tmp_path)], check=True, stdout=subprocess.DEVNULL)
    # evaluate isolates the object as matpredict.isolate does, then predicts its crop.
    on_image = np.asarray(Image.open(mask)) > 0
    isolated = matpredict.isolate(np.asarray(Image.open(image).convert("RGB")), mask=on_image, size=32)
    assert np.array_equal(np.asarray(Image.open(tmp_path / "mask.png")) > 0, on_image)
    written_input = np.asarray(Image.open(tmp_path / "input.png"), dtype=np.float32) / 255
    assert np.abs(written_input - isolated["input"]).max() <= 0.5 / 255 + 1e-6
    rgb = isolated["input"]
    maps = model.predict(rgb)
    assert list(maps) == model.outputs
    # The default layout predicts roughness in three channels, as the repository's networks do.
    assert maps["base_color"].shape == (32, 32, 3) and maps["roughness"].shape == (32, 32, 3)
    on = isolated["input_mask"]
    assert 0.2 < on.mean() < 1
    for name, predicted in maps.items():
        assert predicted.dtype == np.float32 and np.all((0 <= predicted) & (predicted <= 1))
        written = np.asarray(Image.open(tmp_path / f"{name}.png").convert("RGB"), dtype=np.float32) / 255
        expected = np.broadcast_to(predicted, written.shape) if predicted.shape[2] == 1 else predicted
        # evaluate's PNG holds each value rounded to 8 bits, black off the object.
        assert np.abs(written[on] - expected[on]).max() <= 0.5 / 255 + 1e-6, name
        assert np.all(written[~on] == 0), name
    # The same image again gives the same maps: inference is deterministic.
    again = model.predict(rgb)
    assert all(np.array_equal(maps[name], again[name]) for name in maps)


def test_bad_checkpoints_and_images_raise_clear_errors(checkpoint, tmp_path):
    with pytest.raises(matpredict.InputError, match="no_such.pt"):
        matpredict.load_model(str(tmp_path / "no_such.pt"))
    damaged = tmp_path / "damaged.pt"
    data = bytearray(open(checkpoint, "rb").read())
    data[len(data) // 2] ^= 0xFF
    damaged.write_bytes(bytes(data))
    with pytest.raises(matpredict.InputError, match="damaged.pt"):
        matpredict.load_model(str(damaged))
    model = matpredict.load_model(checkpoint)
    with pytest.raises(ValueError, match=r"image: expected \(32, 32, 3\)"):
        model.predict(np.zeros((64, 64, 3), dtype=np.float32))
    with pytest.raises(TypeError):
        model.predict(np.full((32, 32, 3), "x"))
