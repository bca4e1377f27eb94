"""Cameras from Python: one built scene seen from many cameras, their pose and OpenCV intrinsics."""
import json
import math

import numpy as np
import pytest

import matpredict
from conftest import write_scene


def scene_dict(path):
    with open(path) as f:
        return json.load(f)


def test_a_camera_renders_as_the_scene_file_with_that_camera(tmp_path):
    description = scene_dict(write_scene(str(tmp_path), spp=2))
    grid_camera = {"grid": {"cell": [3, 7], "n_phi": 8, "n_theta": 16, "radius": 0.8}, "width": 40, "height": 30}
    scene = matpredict.load_scene(description)
    from_dict = matpredict.render(scene, camera=grid_camera, aovs="all", threads=2)
    from_camera = matpredict.render(scene, camera=scene.make_camera(grid_camera), aovs="all", threads=2)
    description["camera"] = grid_camera
    from_file = matpredict.render(matpredict.load_scene(description), aovs="all", threads=1)
    assert from_dict["color"].shape == (30, 40, 3)
    for name in from_file:
        assert np.array_equal(from_dict[name], from_file[name]), name
        assert np.array_equal(from_camera[name], from_file[name]), name
    assert from_dict["alpha"].mean() > 0.05  # the vase is in view
    # The scene's own camera is still the file's.
    assert (scene.camera.width, scene.camera.height) == (48, 36)
    assert matpredict.render(scene, spp=1)["color"].shape == (36, 48, 3)


def grid_positions(center, radius, n_phi, n_theta, phi_range_deg=(0, 90), theta_range_deg=(-90, 90)):
    """docs/scene_format.md, "Grid camera": cell centres on the sphere, row by row."""
    phi0, phi1 = np.radians(phi_range_deg)
    theta0, theta1 = np.radians(theta_range_deg)
    positions = []
    for i in range(n_phi):
        phi = phi0 + (i + 0.5) * (phi1 - phi0) / n_phi
        for j in range(n_theta):
            theta = theta0 + (j + 0.5) * (theta1 - theta0) / n_theta
            positions.append(np.asarray(center) + radius * np.array(
                [math.sin(phi) * math.cos(theta), math.sin(phi) * math.sin(theta), math.cos(phi)]))
    return positions


def test_grid_cameras_are_the_cells_of_the_grid(small_scene):
    scene = matpredict.load_scene(small_scene)
    grid = {"n_phi": 3, "n_theta": 5, "radius": 2.5, "center": [0.1, -0.2, 0.3], "phi_range_deg": [10, 80],
            "theta_range_deg": [0, 360]}
    cameras = scene.grid_cameras(grid)
    assert list(cameras) == [f"view_{i:03d}_{j:03d}" for i in range(3) for j in range(5)]
    expected = grid_positions(grid["center"], 2.5, 3, 5, (10, 80), (0, 360))
    for (name, camera), position in zip(cameras.items(), expected):
        np.testing.assert_allclose(camera.position, position, atol=1e-12, err_msg=name)
        pose = camera.camera_to_world
        np.testing.assert_allclose(pose[:3, :3].T @ pose[:3, :3], np.eye(3), atol=1e-12)
        # It looks at the centre (down its -Z), upright (its +X horizontal).
        toward_center = np.asarray(grid["center"]) - position
        np.testing.assert_allclose(-pose[:3, 2], toward_center / np.linalg.norm(toward_center), atol=1e-12)
        assert abs(pose[2, 0]) < 1e-12 and pose[2, 1] > 0
        assert (camera.width, camera.height, camera.fov_deg) == (48, 36, scene.camera.fov_deg)
        i, j = int(name[5:8]), int(name[9:12])
        one = scene.make_camera({"grid": grid | {"cell": [i, j]}, "width": 48, "height": 36,
                                 "fov_deg": scene.camera.fov_deg})
        assert np.array_equal(one.camera_to_world, pose), name
    # None is the paper's grid: 16 x 32 cells at 1 m around the objects' centroid.
    paper = scene.grid_cameras()
    assert len(paper) == 512 and list(paper)[-1] == "view_015_031"
    centroid = paper["view_000_000"].position - grid_positions([0, 0, 0], 1.0, 16, 32)[0]
    for camera, position in zip(paper.values(), grid_positions(centroid, 1.0, 16, 32)):
        np.testing.assert_allclose(camera.position, position, atol=1e-9)


def plane_scene(camera):
    """A 40 m square floor at z = 0 and nothing else."""
    positions = np.array([[-20, -20, 0], [20, -20, 0], [20, 20, 0], [-20, 20, 0]], dtype=float)
    floor = matpredict.Mesh(positions, np.array([[0, 1, 2], [0, 2, 3]]))
    return {"camera": camera, "lights": [], "background": [1, 1, 1], "objects": [{"mesh": floor}],
            "render": {"spp": 256, "seed": 3}}


def test_intrinsics_and_pose_give_the_rendered_depth():
    # Rolled (up is not +Z) and wider than tall, so that both focal terms and both centres count.
    view = {"position": [1.2, -0.9, 1.0], "look_at": [0.1, 0.2, 0.0], "up": [1.0, 0.4, 1.0], "fov_deg": 50,
            "width": 64, "height": 48}
    scene = matpredict.load_scene(plane_scene(view))
    camera = scene.camera
    k = camera.intrinsics
    f = 24 / math.tan(math.radians(25))
    np.testing.assert_allclose(k, [[f, 0, 31.5], [0, f, 23.5], [0, 0, 1]], rtol=1e-12)
    depth = matpredict.render(scene, aovs=["depth", "alpha"], threads=2)
    covered = depth["alpha"][:, :, 0] == 1
    assert covered.mean() > 0.9

    # The floor's depth at each pixel centre, from the pose and K alone: the ray K^-1 (u, v, 1) in
    # OpenCV's camera frame, turned into the world, meets z = 0 at distance t along the axis.
    v, u = np.mgrid[0:48, 0:64].astype(float)
    rays_cv = np.stack([u, v, np.ones_like(u)], axis=-1) @ np.linalg.inv(k).T
    opencv_to_blender = np.diag([1.0, -1.0, -1.0])
    rays_world = rays_cv @ (camera.camera_to_world[:3, :3] @ opencv_to_blender).T
    expected = -camera.position[2] / rays_world[:, :, 2]
    # The depth AOV is the sample nearest the pixel centre (of 256): within a tenth of a pixel, so
    # allow a fifth of the depth's change per pixel. Half a pixel off in cx or cy would not pass.
    gy, gx = np.gradient(expected)
    tolerance = 0.2 * np.hypot(gx, gy) + 1e-6 * expected
    error = np.abs(depth["depth"][:, :, 0] - expected)
    assert np.all(error[covered] <= tolerance[covered]), float(np.max((error - tolerance)[covered]))
    shifted = -camera.position[2] / (rays_cv + [0.5 / f, 0, 0]) @ (camera.camera_to_world[:3, :3] @ opencv_to_blender).T
    assert np.mean(np.abs(depth["depth"][:, :, 0] - (-camera.position[2] / shifted[:, :, 2]))[covered] >
                   tolerance[covered]) > 0.5


def test_bad_cameras_raise_clear_errors(small_scene):
    scene = matpredict.load_scene(small_scene)
    with pytest.raises(matpredict.InputError, match=r"the camera: /grid/cell/0: expected a whole number from 0 to 1, got 5"):
        matpredict.render(scene, camera={"grid": {"cell": [5, 0], "n_phi": 2}})
    with pytest.raises(matpredict.InputError, match="the camera: expected exactly one of"):
        scene.make_camera({"fov_deg": 30})
    with pytest.raises(matpredict.InputError, match=r"the camera: /width: expected a whole number from 1"):
        scene.make_camera({"position": [1, 0, 0], "look_at": [0, 0, 0], "width": 0})
    with pytest.raises(matpredict.InputError, match="the camera grid: /grid/cell: not taken here"):
        scene.grid_cameras({"cell": [0, 0]})
    with pytest.raises(matpredict.InputError, match=r"the camera grid: /grid/radius: expected a number greater than 0"):
        scene.grid_cameras({"radius": -1})
    with pytest.raises(TypeError, match="camera: expected None"):
        matpredict.render(scene, camera="view_000_000")
    with pytest.raises(matpredict.InputError, match="beyond 65536 m"):
        scene.make_camera({"position": [1e6, 0, 0], "look_at": [0, 0, 0]})
