"""matpredict.render: the CLI's images bit for bit, arrays as documented, Python free to run."""
import base64
import gc
import json
import os
import signal
import subprocess
import threading
import time

import numpy as np
import pytest

import matpredict
from conftest import EXAMPLES, RENDER_OBJECT, read_exr, write_scene


INT_AOVS = {"label", "part_id", "object_id", "sample_count"}


def test_render_equals_the_cli_bit_for_bit(tmp_path, small_scene):
    out = tmp_path / "cli"
    subprocess.run([RENDER_OBJECT, "--scene", small_scene, "--aovs", "all", "--output", str(out), "--threads", "2"],
                   check=True, stdout=subprocess.DEVNULL)
    frame = matpredict.render(matpredict.load_scene(small_scene), aovs="all", threads=1)
    assert set(frame) == {"color"} | set(matpredict.aov_names())
    compared = 0
    for name, array in frame.items():
        exr = out / f"view_{name}.exr"
        if name == "alpha":  # written as a PNG only
            continue
        reference = read_exr(str(exr))
        if name == "color":
            np.testing.assert_array_equal(reference[:, :, 3], 1.0)  # opaque background
            reference = reference[:, :, :3]
        expected = array.astype(np.float32) if name in INT_AOVS else array
        assert reference.shape == expected.shape, name
        assert np.array_equal(reference, expected), name
        compared += 1
    assert compared == len(frame) - 1
    # The display image is the PNG's bytes.
    from PIL import Image

    png = np.asarray(Image.open(out / "view_color.png"))
    assert png.shape == (36, 48, 3)
    assert np.array_equal(matpredict.display_image(frame["color"], exposure_stops=matpredict.load_scene(small_scene).exposure_stops), png)
    assert not np.array_equal(matpredict.display_image(frame["color"], exposure_stops=1.0), png)


def test_arrays_have_the_documented_shapes_dtypes_and_owner(small_scene):
    scene = matpredict.load_scene(small_scene)
    assert (scene.width, scene.height, scene.spp) == (48, 36, 4)
    frame = matpredict.render(scene, aovs="all")
    channels = {"color": 3, "base_color": 3, "normal_world": 3, "normal_camera": 3, "normal_tangent": 3,
                "roughness": 1, "metallic": 1, "depth": 1, "alpha": 1, "label": 1, "part_id": 1}
    for name, c in channels.items():
        assert frame[name].shape == (36, 48, c), name
    for name, array in frame.items():
        assert array.dtype == (np.int32 if name in INT_AOVS else np.float32), name
        assert array.flags.c_contiguous and array.flags.aligned, name
        assert np.all(np.isfinite(array)), name
    # The arrays view one frame's buffers, which outlive the scene and the dict.
    depth = frame["depth"]
    assert depth.base is not None and not depth.flags.owndata
    expected = depth.copy()
    del scene, frame
    gc.collect()
    np.testing.assert_array_equal(depth, expected)
    # Hits have a depth and unit normals; misses are 0 and part -1.
    hit = depth[:, :, 0] > 0
    assert 0 < hit.sum() < hit.size


def test_the_image_is_the_same_whatever_the_threads(small_scene):
    scene = matpredict.load_scene(small_scene)
    one = matpredict.render(scene, threads=1, seed=7)
    two = matpredict.render(scene, threads=2, seed=7)
    for name in one:
        assert np.array_equal(one[name], two[name]), name
    other_seed = matpredict.render(scene, threads=2, seed=8)
    assert not np.array_equal(one["color"], other_seed["color"])


def test_progress_is_reported_on_the_calling_thread(small_scene):
    fractions, threads = [], set()

    def progress(fraction):
        fractions.append(fraction)
        threads.add(threading.get_ident())

    matpredict.render(matpredict.load_scene(small_scene), spp=64, progress=progress)
    assert fractions and fractions[-1] == 1.0
    assert fractions == sorted(fractions)
    assert threads == {threading.get_ident()}


def test_the_gil_is_released_while_rendering(tmp_path):
    scene = matpredict.load_scene(write_scene(str(tmp_path), width=96, height=96, spp=1024))
    counted, stop = [0], threading.Event()

    def count():
        while not stop.is_set():
            counted[0] += 1

    counter = threading.Thread(target=count)
    counter.start()
    started = time.monotonic()
    matpredict.render(scene, threads=1)
    seconds = time.monotonic() - started
    stop.set()
    counter.join()
    # Holding the GIL, the render would leave the counter a 5 ms switch interval now and then; a
    # released GIL lets it count all along (millions a second).
    assert seconds > 0.2
    assert counted[0] > 100_000 * seconds, f"{counted[0]} counts in {seconds:.2f} s"


def test_ctrl_c_stops_a_render_within_a_second(tmp_path):
    scene = matpredict.load_scene(write_scene(str(tmp_path), spp=65535))
    timer = threading.Timer(0.5, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    started = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        matpredict.render(scene, threads=1)
    assert time.monotonic() - started < 1.5  # 0.5 s before the signal, then at most a second
    timer.join()


def test_an_exception_in_the_progress_callback_stops_the_render(small_scene):
    def progress(fraction):
        raise RuntimeError("enough")

    with pytest.raises(RuntimeError, match="enough"):
        matpredict.render(matpredict.load_scene(small_scene), spp=4096, progress=progress)


def test_bad_input_raises_clear_exceptions(tmp_path, small_scene):
    with pytest.raises(matpredict.InputError, match="no_such.json"):
        matpredict.load_scene(str(tmp_path / "no_such.json"))
    broken = tmp_path / "broken.json"
    broken.write_text(open(small_scene).read().replace('"spp": 4', '"spp": "4"'))
    with pytest.raises(matpredict.InputError, match=r"broken\.json: /render/spp: expected a whole number"):
        matpredict.load_scene(str(broken))
    assert issubclass(matpredict.InputError, ValueError)
    scene = matpredict.load_scene(small_scene)
    with pytest.raises(ValueError, match='unknown AOV "roughnes"'):
        matpredict.render(scene, aovs=["roughnes"])
    with pytest.raises(ValueError, match="spp"):
        matpredict.render(scene, spp=0)
    with pytest.raises(TypeError):
        matpredict.render(scene, spp="many")
    with pytest.raises(TypeError, match="progress"):
        matpredict.render(scene, progress=5)
    with pytest.raises(TypeError):
        matpredict.render("scene.json")


def test_an_example_scene_loads_as_the_cli_reads_it():
    scene = matpredict.load_scene(os.path.join(EXAMPLES, "vase_in_the_sun.json"))
    assert (scene.width, scene.height, scene.spp) == (256, 256, 64)
    assert repr(scene) == "<matpredict.Scene 256x256>"


def test_a_dict_with_the_scene_files_keys_is_the_same_scene(small_scene):
    import json

    with open(small_scene) as f:
        description = json.load(f)
    from_dict = matpredict.render(matpredict.load_scene(description), aovs="all")
    from_file = matpredict.render(matpredict.load_scene(small_scene), aovs="all")
    assert all(np.array_equal(from_dict[name], from_file[name]) for name in from_file)
    description["objects"][0]["builtin"] = "sofa2"
    with pytest.raises(matpredict.InputError, match='the scene: /objects/0/builtin: expected one of "basket"'):
        matpredict.load_scene(description)
    with pytest.raises(TypeError):
        matpredict.load_scene(42)


def cube(side=0.3):
    """A box on the ground: 8 corners, 12 triangles counter-clockwise from outside."""
    half = side / 2
    positions = np.array([[x, y, z] for z in (0.0, side) for y in (-half, half) for x in (-half, half)])
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    triangles = np.array([t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))])
    return positions, triangles


def cube_scene(mesh):
    return {
        "camera": {"position": [0.8, -0.9, 0.6], "look_at": [0, 0, 0.15], "width": 40, "height": 30},
        "lights": {"rig": {}},
        "materials": {"paint": {"base_color": [0.8, 0.2, 0.1], "roughness": 0.4}},
        "objects": [{"mesh": mesh, "material": "paint"}],
        "render": {"spp": 4},
    }


def test_a_numpy_mesh_renders_as_the_same_mesh_from_a_file(tmp_path, monkeypatch):
    positions, triangles = cube()
    mesh = matpredict.Mesh(positions, triangles)
    assert (mesh.vertex_count, mesh.triangle_count, mesh.part_names) == (8, 12, ["part0"])
    # PLY, which keeps its axes (OBJ and glTF are +Y up and turned on import).
    with open(tmp_path / "cube.ply", "w") as f:
        f.write("ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 12\nproperty list uchar int vertex_indices\nend_header\n")
        f.writelines(f"{x!r} {y!r} {z!r}\n" for x, y, z in positions.astype(np.float32).astype(float))
        f.writelines(f"3 {a} {b} {c}\n" for a, b, c in triangles)
    monkeypatch.chdir(tmp_path)
    from_arrays = matpredict.render(matpredict.load_scene(cube_scene(mesh)), aovs="all")
    from_file = matpredict.render(matpredict.load_scene(cube_scene("cube.ply")), aovs="all")
    for name in ("color", "depth", "normal_world", "base_color", "roughness", "alpha"):
        assert np.array_equal(from_arrays[name], from_file[name]), name
    assert 0 < (from_arrays["depth"] > 0).mean() < 1


def test_scene_notes_say_what_a_mesh_file_holds_that_is_not_applied(tmp_path, monkeypatch):
    positions, triangles = cube()
    buffer = positions.astype("<f4").tobytes() + triangles.astype("<u2").tobytes()
    gltf = {
        "asset": {"version": "2.0"},
        "extensionsUsed": ["KHR_materials_volume"],
        "scenes": [{"nodes": [0]}], "scene": 0, "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
        "buffers": [{"byteLength": len(buffer),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(buffer).decode()}],
        "bufferViews": [{"buffer": 0, "byteLength": 96}, {"buffer": 0, "byteOffset": 96, "byteLength": 72}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3"},
                      {"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}],
    }
    (tmp_path / "cube.gltf").write_text(json.dumps(gltf))
    monkeypatch.chdir(tmp_path)
    scene = matpredict.load_scene(cube_scene("cube.gltf"))
    assert len(scene.notes) == 1
    assert scene.notes[0].endswith('cube.gltf: the glTF extension "KHR_materials_volume" is not applied')
    assert matpredict.load_scene(cube_scene(matpredict.Mesh(positions, triangles))).notes == []


def test_bad_mesh_arrays_raise_clear_errors():
    positions, triangles = cube()
    with pytest.raises(ValueError, match=r"positions: expected shape \(N, 3\)"):
        matpredict.Mesh(positions[:, :2], triangles)
    with pytest.raises(ValueError, match="triangles: triangle 0 names vertex 8"):
        matpredict.Mesh(positions, np.array([[8, 1, 2]]))
    with pytest.raises(TypeError, match="triangles: expected an array of integers"):
        matpredict.Mesh(positions, triangles.astype(float))
    bad = positions.copy()
    bad[3, 1] = np.nan
    with pytest.raises(ValueError, match="mesh"):
        matpredict.Mesh(bad, triangles)
    with pytest.raises(ValueError, match="part_names: expected 2 names"):
        matpredict.Mesh(positions, triangles, parts=np.arange(12) % 2, part_names=["a"])
    scene = cube_scene(matpredict.Mesh(positions, triangles))
    scene["objects"][0]["seed"] = 3
    with pytest.raises(matpredict.InputError, match="the scene: /objects/0/seed: unknown key"):
        matpredict.load_scene(scene)
    # Every key of a mesh object is read by the scene reader itself; a mesh from arrays has its normals.
    scene = cube_scene(matpredict.Mesh(positions, triangles))
    scene["objects"][0]["auto_smooth_deg"] = 30
    with pytest.raises(matpredict.InputError, match="the scene: /objects/0/auto_smooth_deg: only a mesh file's faces"):
        matpredict.load_scene(scene)


def test_the_names_a_scene_dict_can_use_load():
    assert "vase" in matpredict.builtin_objects() and len(matpredict.builtin_objects()) == 18
    classes = matpredict.material_classes()
    assert classes["wood"] == 7 and "background" not in classes
    scene = matpredict.load_scene({
        "camera": {"position": [1.2, -1.2, 0.9], "look_at": [0, 0, 0.3], "width": 16, "height": 16},
        "lights": {"rig": {}},
        "materials": {name: {"class": name, "resolution": 8} for name in classes},
        "objects": [{"builtin": name, "material": list(classes)[k % len(classes)], "transform": {"translate": [k, 0, 0]}}
                    for k, name in enumerate(matpredict.builtin_objects())],
        "render": {"spp": 1},
    })
    assert scene.bounds[1] > 8  # eighteen objects a metre apart


def test_aov_info_describes_every_array_render_returns(small_scene):
    scene = matpredict.load_scene(small_scene)
    info = matpredict.aov_info()
    every = matpredict.render(scene, spp=1, aovs="all")
    assert list(every) == list(info) == ["color"] + matpredict.aov_names()
    for name, array in every.items():
        assert (str(array.dtype), array.shape[2]) == (info[name]["dtype"], info[name]["channels"]), name
        assert len(info[name]["description"]) > 20, name
        assert info[name]["description"] in matpredict.render.__doc__, name
    defaults = matpredict.render(scene, spp=1, aovs="default")
    assert list(defaults) == [name for name, entry in info.items() if entry["default"]]
    assert "linear RGB" in info["base_color"]["description"] and "+Z toward the viewer" in info["normal_camera"]["description"]
