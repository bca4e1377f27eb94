"""Scene dicts: everything a scene file says, and what Python code computes (numpy values, paths)
read as their values; what JSON cannot say is refused at its place."""
import json
import os
import subprocess

import numpy as np
import pytest

import matpredict
from conftest import RENDER_OBJECT, read_exr, write_exr


@pytest.fixture
def environment(tmp_path):
    """A small sky-to-ground gradient as an equirectangular EXR."""
    rows = np.linspace(1.0, 0.1, 8, dtype=np.float32)[:, None, None]
    return write_exr(tmp_path / "sky.exr", np.broadcast_to(rows * np.array([0.6, 0.7, 1.0], dtype=np.float32), (8, 16, 3)).copy())


def vase_scene(position, roughness, color, environment):
    return {
        "camera": {"position": position, "look_at": [0, 0, 0.15], "width": 40, "height": 30, "fov_deg": 35},
        "lights": [{"type": "sun", "position": [2, -1, 1], "look_at": [0, 0, 0], "strength": 3}],
        "background": {"environment": environment, "strength": 0.5},
        "materials": {"glaze": {"base_color": color, "roughness": roughness}},
        "objects": [{"builtin": "vase", "material": "glaze"}],
        "render": {"spp": 2},
    }


def test_numpy_values_and_paths_read_as_their_values(environment):
    plain = vase_scene([0.9, -0.9, 0.45], 0.3, [0.8, 0.3, 0.2], str(environment))
    computed = vase_scene(np.array([0.9, -0.9, 0.45]), np.float64(0.3), (np.float64(0.8), np.float64(0.3), 0.2),
                          environment)
    computed["render"] = {"spp": np.int64(2), "mipmaps": np.bool_(True)}
    from_plain = matpredict.render(matpredict.load_scene(plain), aovs="all", threads=2)
    from_computed = matpredict.render(matpredict.load_scene(computed), aovs="all", threads=2)
    for name in from_plain:
        assert np.array_equal(from_plain[name], from_computed[name]), name


def test_values_json_cannot_say_are_refused_at_their_place(environment):
    scene = vase_scene([0.9, -0.9, 0.45], float("nan"), [0.8, 0.3, 0.2], environment)
    with pytest.raises(matpredict.InputError, match=r"the scene: /materials/glaze/roughness: expected a finite number, got nan"):
        matpredict.load_scene(scene)
    scene = vase_scene([0.9, -0.9, np.inf], 0.3, [0.8, 0.3, 0.2], environment)
    with pytest.raises(matpredict.InputError, match=r"the scene: /camera/position/2: expected a finite number, got inf"):
        matpredict.load_scene(scene)
    scene = vase_scene([0.9, -0.9, 0.45], 0.3, {0.8, 0.3}, environment)
    with pytest.raises(TypeError, match=r"the scene: /materials/glaze/base_color: expected a number, text.*got a value of type set"):
        matpredict.load_scene(scene)
    scene = vase_scene([0.9, -0.9, 0.45], 0.3, [0.8, 0.3, 0.2], environment)
    scene["materials"][3] = {}
    with pytest.raises(TypeError, match=r"the scene: /materials: expected text keys, got the key 3"):
        matpredict.load_scene(scene)
    looped = vase_scene([0.9, -0.9, 0.45], 0.3, [0.8, 0.3, 0.2], environment)
    looped["render"]["again"] = looped
    with pytest.raises(matpredict.InputError, match="nest deeper than 256 levels"):
        matpredict.load_scene(looped)


def test_a_dict_renders_as_render_object_renders_the_same_file(tmp_path, monkeypatch, environment):
    """Everything a scene file says, said from Python: the paper's rig, a grid camera, an environment
    map, a library material, a textured one; the CLI reads the dict written as JSON."""
    from PIL import Image

    checker = (np.indices((16, 16)).sum(axis=0) % 2 * 180 + 40).astype(np.uint8)
    Image.fromarray(np.stack([checker, checker // 2, 255 - checker], axis=-1)).save(tmp_path / "checker.png")
    scene = {
        "camera": {"grid": {"cell": [4, 9], "n_phi": 8, "n_theta": 16, "radius": 1.4}, "width": 40, "height": 32},
        "lights": {"rig": {"target_illuminance_lux": 800}},
        "background": {"environment": "sky.exr", "strength": 0.3, "rotation_z_deg": 40},
        "materials": {
            "lacquer": {"class": "wood", "style": "lacquered", "seed": 2, "resolution": 64},
            "checked": {"base_color": {"texture": "checker.png"}, "roughness": 0.4},
        },
        "objects": [
            {"builtin": "chair", "materials": {"seat": "checked", "frame": "lacquer", "back": "lacquer"}},
        ],
        "render": {"spp": 3, "seed": 11},
    }
    path = tmp_path / "scene.json"
    path.write_text(json.dumps(scene))
    out = tmp_path / "cli"
    subprocess.run([RENDER_OBJECT, "--scene", str(path), "--aovs", "base_color,roughness,depth", "--output", str(out)],
                   check=True, stdout=subprocess.DEVNULL)
    monkeypatch.chdir(tmp_path)  # the dict's relative paths are from the current folder
    frame = matpredict.render(matpredict.load_scene(scene), aovs=["base_color", "roughness", "depth"])
    for name in ("color", "base_color", "roughness", "depth"):
        reference = read_exr(out / f"view_004_009_{name}.exr")[:, :, : frame[name].shape[2]]
        assert np.array_equal(reference, frame[name]), name
    assert len(np.unique(frame["base_color"].reshape(-1, 3), axis=0)) > 20  # the chair, textured, is in view
    assert 0.02 < frame["color"].mean() < 1  # lit by the rig and the sky


def test_lamps_of_a_temperature_under_a_built_in_environment():
    """A dict's lamp takes {"blackbody": K} and its environment a built-in name, as a scene file's."""
    def scene(color, environment):
        description = vase_scene([0.9, -0.9, 0.45], 0.5, [0.7, 0.7, 0.7], environment)
        description["lights"][0]["color"] = color
        description["render"] = {"spp": 4}
        return description
    warm = matpredict.render(matpredict.load_scene(scene({"blackbody": 2700}, "night")), threads=2)["color"]
    cool = matpredict.render(matpredict.load_scene(scene({"blackbody": 9000}, "night")), threads=2)["color"]
    # The warm sun reddens the lit vase, the cool one blues it; same seed, same paths otherwise.
    assert (warm[..., 0] - warm[..., 2]).mean() > (cool[..., 0] - cool[..., 2]).mean() + 0.01
    with pytest.raises(matpredict.InputError, match=r"/lights/0/color/blackbody: expected a number from 800 to 12000, got 100"):
        matpredict.load_scene(scene({"blackbody": 100}, "night"))


def test_a_daylight_sky_from_a_dict():
    """A dict's background takes a sky as a scene file's: a sun near the horizon lights the vase
    redder than a high one; a sun below the horizon is refused at its place."""
    def scene(elevation):
        description = vase_scene([0.9, -0.9, 0.45], 0.5, [0.7, 0.7, 0.7], "night")
        description["lights"] = []
        description["background"] = {"sky": {"sun_elevation_deg": elevation, "sun_rotation_deg": 135}, "strength": 0.02}
        description["render"] = {"spp": 8}
        return description
    high = matpredict.render(matpredict.load_scene(scene(60)), threads=2)["color"]
    low = matpredict.render(matpredict.load_scene(scene(3)), threads=2)["color"]
    assert np.isfinite(high).all() and np.isfinite(low).all()
    lit = high.sum(axis=-1) > 0
    redness = lambda image: image[lit][:, 0].sum() / image[lit][:, 2].sum()
    assert redness(low) > 1.2 * redness(high)
    with pytest.raises(matpredict.InputError, match=r"/background/sky/sun_elevation_deg: sun_elevation_deg -2 is not in \[0, 90\]"):
        matpredict.load_scene(scene(-2))
