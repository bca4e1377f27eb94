"""The example scripts run as a user runs them, at small sizes, and write what they say."""
import os
import subprocess
import sys

import numpy as np
from PIL import Image

import matpredict

EXAMPLES = os.path.join(os.path.dirname(__file__), "..", "..", "examples", "python")


def run(script, *args, cwd):
    # The package this test imports, wherever it runs from.
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(os.path.abspath(matpredict.__file__))))
    result = subprocess.run([sys.executable, os.path.join(EXAMPLES, script), *args], cwd=cwd, env=env,
                            capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_three_materials_saves_three_renders_side_by_side(tmp_path):
    out = run("three_materials.py", "--size", "48", "--spp", "8", "--out", "panel.png", cwd=tmp_path)
    assert "wrote panel.png" in out
    panel = np.asarray(Image.open(tmp_path / "panel.png"))
    assert panel.shape == (48, 144, 3)
    thirds = [panel[:, k * 48:(k + 1) * 48].astype(float) for k in range(3)]
    # Three different materials, each exposed: neither black nor clipped.
    assert all(5 < third.mean() < 250 for third in thirds)
    assert not np.array_equal(thirds[0], thirds[1]) and not np.array_equal(thirds[1], thirds[2])


def test_tiny_training_makes_a_dataset_and_trains_one_epoch(tmp_path):
    out = run("tiny_training.py", "--out", "run", "--size", "32", cwd=tmp_path)
    assert "8 frames in" in out and "trained one epoch" in out
    losses = [float(line.rsplit(" ", 1)[1]) for line in out.splitlines() if line.startswith("batch of")]
    assert len(losses) == 2 and all(0 < loss < 1 for loss in losses)
