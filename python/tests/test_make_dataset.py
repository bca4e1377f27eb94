"""make_dataset from a configuration dict: the command line's bytes, progress, resuming, refusals."""
import filecmp
import json
import os
import subprocess

import pytest

import matpredict
from conftest import MAKE_DATASET

CONFIGURATION = {
    "objects": [{"name": "vase", "builtin": "vase", "seed": 0}],
    "materials": {"all": ["wood/raw:1", "ceramic:2"]},
    "camera": {"grid": [1, 2]},
    "render": {"resolution": [32, 24], "samples": 2, "material_resolution": 64},
}


def all_files(root):
    return sorted(os.path.relpath(os.path.join(folder, name), root) for folder, _, names in os.walk(root) for name in names)


def test_a_dict_makes_the_command_lines_dataset_byte_for_byte(tmp_path):
    config_file = tmp_path / "config.json"
    config_file.write_text(json.dumps(CONFIGURATION))
    cli = tmp_path / "cli"
    subprocess.run([MAKE_DATASET, "--config", str(config_file), "--output", str(cli)], check=True,
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    seen = []
    summary = matpredict.make_dataset(CONFIGURATION, output=str(tmp_path / "python"), threads=1,
                                      progress=lambda done, total: seen.append((done, total)))
    assert summary["frames"] == 4 and summary["rendered"] == 4 and summary["skipped"] == 0
    assert summary["output"] == str(tmp_path / "python")
    assert set(summary["splits"]) == {"object_disjoint_v1", "variance_disjoint_v1", "material_disjoint_v1",
                                      "paper_random_v1", "lighting_disjoint_v1"}
    assert seen[-1] == (4, 4) and [d for d, _ in seen] == sorted(d for d, _ in seen)
    files = all_files(cli)
    assert files == all_files(tmp_path / "python") and len(files) > 20
    _, mismatch, errors = filecmp.cmpfiles(cli, tmp_path / "python", files, shallow=False)
    assert mismatch == [] and errors == []
    # Made again (the output as a pathlib.Path this time), every frame is found complete.
    again = matpredict.make_dataset(CONFIGURATION, output=tmp_path / "python")
    assert again["rendered"] == 0 and again["skipped"] == 4
    assert matpredict.verify_dataset(tmp_path / "python")["problems"] == []


def test_a_bad_configuration_is_refused_by_key(tmp_path):
    bad = dict(CONFIGURATION, render={"sampels": 4})
    with pytest.raises(matpredict.InputError, match=r"the configuration: render\.sampels: unknown key"):
        matpredict.make_dataset(bad, output=str(tmp_path / "out"))
    quoted = dict(CONFIGURATION, render={"samples": "4"})
    with pytest.raises(matpredict.InputError, match=r'render\.samples: expected a whole number from 1 to 65,535, got "4"'):
        matpredict.make_dataset(quoted, output=str(tmp_path / "out"))
    not_a_number = dict(CONFIGURATION, render={"samples": 4, "exposure": float("nan")})
    with pytest.raises(matpredict.InputError, match=r"the configuration: render\.exposure: expected a finite number, got nan"):
        matpredict.make_dataset(not_a_number, output=str(tmp_path / "out"))
    assert not (tmp_path / "out").exists()
    with pytest.raises(ValueError, match="shard"):
        matpredict.make_dataset(CONFIGURATION, output=str(tmp_path / "out"), shard="2/2")
    with pytest.raises(TypeError, match="progress"):
        matpredict.make_dataset(CONFIGURATION, output=str(tmp_path / "out"), progress="bar")
