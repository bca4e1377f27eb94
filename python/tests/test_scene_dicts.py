"""Scene dicts hold what Python code computes: numpy values and paths are read as their values;
what JSON cannot say is refused at its place."""

import numpy as np
import pytest

import matpredict


@pytest.fixture
def environment(tmp_path):
    """A small sky-to-ground gradient as an equirectangular EXR, written by OpenImageIO."""
    import OpenImageIO as oiio

    rows = np.linspace(1.0, 0.1, 8, dtype=np.float32)[:, None, None]
    pixels = np.broadcast_to(rows * np.array([0.6, 0.7, 1.0], dtype=np.float32), (8, 16, 3)).copy()
    path = tmp_path / "sky.exr"
    output = oiio.ImageOutput.create(str(path))
    assert output.open(str(path), oiio.ImageSpec(16, 8, 3, "float"))
    assert output.write_image(pixels)
    output.close()
    return path


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
