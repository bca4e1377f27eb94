"""Datasets from Python: the reader's samples against the files decoded by Pillow, a torch
DataLoader with workers, and verify_dataset finding a damaged file."""
import os
import shutil

import numpy as np
import pytest
from PIL import Image

import matpredict

FRAMES = ["vase/var000/000", "vase/var000/001", "vase/var001/000", "vase/var001/001"]


def png(root, sample_id, folder):
    obj, variant, stem = sample_id.split("/")
    return np.asarray(Image.open(os.path.join(root, obj, variant, folder, stem + ".png")))


def test_the_reader_lists_every_frame_in_order(tiny_dataset):
    reader = matpredict.DatasetReader(tiny_dataset, size=32)
    assert len(reader) == 4 and reader.ids == FRAMES
    assert [reader[k]["id"] for k in range(-4, 0)] == FRAMES
    with pytest.raises(IndexError):
        reader[4]


def test_a_sample_at_its_own_size_is_the_files_as_pillow_decodes_them(tiny_dataset):
    reader = matpredict.DatasetReader(tiny_dataset, size=32)
    for k, sample_id in enumerate(FRAMES):
        sample = reader[k]
        label = png(tiny_dataset, sample_id, "label").astype(np.int32)
        orm = png(tiny_dataset, sample_id, "ORM").astype(np.float32) / 255
        np.testing.assert_allclose(sample["input"], png(tiny_dataset, sample_id, "images")[:, :, :3] / 255, atol=1e-6)
        np.testing.assert_allclose(sample["albedo"], png(tiny_dataset, sample_id, "albedo")[:, :, :3] / 255, atol=1e-6)
        np.testing.assert_allclose(sample["roughness"][:, :, 0], orm[:, :, 1], atol=1e-6)
        np.testing.assert_allclose(sample["metallic"][:, :, 0], orm[:, :, 2], atol=1e-6)
        np.testing.assert_array_equal(sample["material_id"], label)
        np.testing.assert_array_equal(sample["mask"], label > 0)
        assert sample["input"].dtype == np.float32 and sample["mask"].dtype == bool
        assert sample["roughness"].shape == (32, 32, 1) and sample["material_id"].shape == (32, 32)
        assert 0 < sample["mask"].sum() < 32 * 32  # the vase is in the frame, not all of it


def test_samples_are_resized_and_split_as_the_trainer_reads_them(tiny_dataset):
    reader = matpredict.DatasetReader(tiny_dataset, size=16, linear_albedo=True, read_normal=True,
                                      split_file=os.path.join(tiny_dataset, "config", "paper_random_v1.yaml"), split="test")
    assert reader.ids == ["vase/var000/000"]
    sample = reader[0]
    assert sample["input"].shape == (16, 16, 3) and sample["normal"].shape == (16, 16, 3)
    stored = matpredict.DatasetReader(tiny_dataset, size=16)[0]["albedo"]
    on = sample["mask"]
    assert np.all(sample["albedo"][on] <= stored[on] + 1e-6)  # sRGB decoded: darker, never brighter


def test_a_torch_dataloader_with_workers_gives_the_readers_samples(tiny_dataset):
    torch = pytest.importorskip("torch")
    from matpredict.torch_data import MaterialDataset

    dataset = MaterialDataset(tiny_dataset, size=32)
    loader = torch.utils.data.DataLoader(dataset, batch_size=2, num_workers=2, shuffle=False)
    batches = list(loader)
    assert len(batches) == 2
    first = batches[0]
    assert first["input"].shape == (2, 3, 32, 32) and first["input"].dtype == torch.float32
    assert first["roughness"].shape == (2, 1, 32, 32) and first["mask"].shape == (2, 1, 32, 32)
    assert first["material_id"].dtype == torch.int64 and first["id"] == FRAMES[:2]
    reader = matpredict.DatasetReader(tiny_dataset, size=32)
    np.testing.assert_array_equal(first["input"][1].permute(1, 2, 0).numpy(), reader[1]["input"])
    np.testing.assert_array_equal(first["mask"][0, 0].numpy(), reader[0]["mask"].astype(np.float32))


def test_verify_finds_a_damaged_file_and_the_reader_names_it(tiny_dataset, tmp_path):
    assert matpredict.verify_dataset(tiny_dataset) == {"variants": 2, "frames": 4, "problems": []}
    damaged = str(tmp_path / "damaged")
    shutil.copytree(tiny_dataset, damaged)
    orm = os.path.join(damaged, "vase", "var001", "ORM", "000.png")
    with open(orm, "r+b") as f:
        f.truncate(100)
    report = matpredict.verify_dataset(damaged)
    assert report["problems"] and any("var001/ORM/000.png" in p for p in report["problems"])
    with pytest.raises(matpredict.DatasetError, match="var001/ORM/000.png"):
        matpredict.DatasetReader(damaged, size=32)[2]


def test_bad_arguments_raise_clear_errors(tiny_dataset, tmp_path):
    with pytest.raises(matpredict.InputError, match="no_such"):
        matpredict.DatasetReader(str(tmp_path / "no_such"))
    with pytest.raises(ValueError, match="size"):
        matpredict.DatasetReader(tiny_dataset, size=0)
    with pytest.raises(ValueError, match="split"):
        matpredict.DatasetReader(tiny_dataset, split="training")
    with pytest.raises(TypeError):
        matpredict.DatasetReader(tiny_dataset, size="big")
