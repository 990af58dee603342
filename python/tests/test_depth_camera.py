"""The depth camera: metric z, range, point clouds and the Kinect-style sensor model, against
the geometry they measure and against the command's outputs."""

import warnings

import numpy as np
import pytest

import zraster
from conftest import bits, run_cli

W, H = 160, 120


def wall(distance, half=50.0):
    """A square facing +z at z = -distance (the camera at the origin looks down -z)."""
    positions = np.array([[-half, -half, -distance], [half, -half, -distance],
                          [half, half, -distance], [-half, half, -distance]], np.float32)
    return zraster.Mesh(positions, np.array([[0, 1, 2], [0, 2, 3]], np.uint32))


def pinhole(fx=120.0, fy=120.0, cx=79.5, cy=59.5, near=0.1, far=100.0):
    """An OpenCV camera at the origin looking down -z (its +z axis is the world's -z)."""
    pose = np.diag([1.0, -1.0, -1.0, 1.0])
    return zraster.Camera.from_intrinsics(fx, fy, cx, cy, W, H, near, far, pose=pose)


def test_z_of_a_plane_is_its_distance():
    for distance in (0.7, 3.0, 42.0):
        for keywords in ({}, {"reversed_z": True}, {"depth_format": "d24"}):
            out = zraster.Renderer(W, H).render(wall(distance), pinhole(), ("z", "depth"),
                                                **keywords)
            z = out["z"]
            assert z.shape == (H, W) and z.dtype == np.float32
            # The stored depth's rounding, turned into z: a few float steps of the window
            # depth (or D24 steps), times dz/dw = z^2 (far - near) / (far near) there.
            step = 2.0 ** -24 if keywords.get("depth_format") != "d24" else 1.0 / (2 ** 24 - 1)
            tolerance = 4 * step * distance ** 2 * (100.0 - 0.1) / (100.0 * 0.1) + 1e-6 * distance
            np.testing.assert_allclose(z, distance, rtol=0, atol=tolerance, err_msg=str(keywords))


def test_range_is_z_times_the_pixel_ray_length():
    camera = pinhole()
    out = zraster.Renderer(W, H).render(wall(3.0), camera, ("z", "range"))
    z, rng = out["z"].astype(np.float64), out["range"].astype(np.float64)
    v, u = np.mgrid[0:H, 0:W]
    ray = np.sqrt(1 + ((u - 79.5) / 120.0) ** 2 + ((v - 59.5) / 120.0) ** 2)
    np.testing.assert_allclose(rng, z * ray, rtol=1e-6)
    for corner in ((0, 0), (0, W - 1), (H - 1, 0), (H - 1, W - 1)):
        assert rng[corner] > z[corner] * 1.25  # the corners' rays are long


def test_empty_pixels_are_zero():
    out = zraster.Renderer(W, H).render(wall(3.0, half=0.5), pinhole(), ("z", "range", "depth"))
    empty = out["depth"] == 1.0
    assert 0 < empty.sum() < W * H
    assert (out["z"][empty] == 0).all() and (out["range"][empty] == 0).all()
    assert (out["z"][~empty] > 0).all()


def test_unprojected_points_lie_on_the_surface():
    sphere = zraster.Mesh.uv_sphere(1.0, 48, 96)
    camera = zraster.Camera.look_at((0.5, 1.0, 4.0), (0, 0, 0), fovy=45.0, near=1.0, far=10.0)
    z = zraster.Renderer(W, H).render(sphere, camera, "z")["z"]
    points = zraster.unproject(z, camera)
    assert points.dtype == np.float32 and points.shape == (int((z > 0).sum()), 3)
    radius = np.linalg.norm(points.astype(np.float64), axis=1)
    # On the facets: between the inscribed radius cos(pi/48) and 1, plus the depth's rounding.
    assert radius.max() < 1.0 + 1e-4
    assert radius.min() > np.cos(np.pi / 48) - 1e-4
    # Row-major: the first point is the first drawn pixel.
    v, u = np.argwhere(z > 0)[0]
    assert points.shape[0] > 1000 and (v, u) == tuple(np.argwhere(z > 0)[0])


def test_a_sphere_on_the_optical_axis_is_centred_at_cx_cy():
    # (Principal point between pixel centres: the drawn disc is then symmetric about it.)
    camera = pinhole(cx=70.5, cy=52.5)
    sphere = zraster.Scene([(zraster.Mesh.uv_sphere(1.0, 32, 64),
                             np.array([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, -6.0], [0, 0, 0, 1]]))])
    z = zraster.Renderer(W, H).render(sphere, camera, "z")["z"]
    rows, cols = np.nonzero(z)
    assert len(rows) > 500
    assert abs(cols.mean() - 70.5) < 0.01 and abs(rows.mean() - 52.5) < 0.01


# The default scene spans z = 5 to 70 scene units: sensors here measure up to 100 of them.
FAR = ["--sensor-max-range", "100"]


def test_z_and_range_equal_the_commands(tmp_path):
    scene = zraster.load("builtin:default")
    for sensor_flags, sensor in (([], None),
                                 (["--sensor", "kinect", *FAR],
                                  zraster.StructuredLightSensor(max_range=100)),
                                 (["--sensor", "kinect", *FAR, "--sensor-baseline", "1.5",
                                   "--sensor-noise", "0.3", "--sensor-seed", "5"],
                                  zraster.StructuredLightSensor(baseline=1.5, max_range=100,
                                                                noise=0.3, seed=5))):
        run_cli("render", "builtin:default", "--size", f"{W}x{H}", "-o", tmp_path / "c.png",
                "--z-out", tmp_path / "z.npy", "--range-out", tmp_path / "r.npy", *sensor_flags)
        out = zraster.Renderer(W, H).render(scene, None, ("z", "range"), sensor=sensor)
        np.testing.assert_array_equal(bits(out["z"]), bits(np.load(tmp_path / "z.npy")))
        np.testing.assert_array_equal(bits(out["range"]), bits(np.load(tmp_path / "r.npy")))


def test_the_sensor_loses_pixels_and_quantizes_depth():
    scene = zraster.load("builtin:default")
    renderer = zraster.Renderer(W, H, threads=2)
    sensor = zraster.StructuredLightSensor(baseline=2.0, max_range=100)
    ideal = renderer.render(scene, None, "z")["z"]
    measured = renderer.render(scene, None, "z", sensor=sensor)["z"]
    assert ((measured > 0) <= (ideal > 0)).all()          # nothing appears
    assert (measured > 0).sum() > 0.25 * (ideal > 0).sum()
    assert (measured > 0).sum() < (ideal > 0).sum()       # shadows and grazing angles
    camera_fx = zraster.Camera.fit(scene, W, H).intrinsics(W, H)["fx"]
    fb = camera_fx * 2.0
    seen = measured[measured > 0].astype(np.float64)
    steps = fb / (seen * 0.125)  # whole numbers of 1/8-pixel disparity steps
    np.testing.assert_allclose(steps, np.round(steps), atol=1e-3)
    assert len(np.unique(np.round(steps))) > 20


def test_a_sensor_that_measures_nothing_warns():
    scene = zraster.load("builtin:default")
    renderer = zraster.Renderer(W, H)
    nothing = zraster.StructuredLightSensor(baseline=1e-300)
    with pytest.warns(UserWarning, match=r"^builtin:default: the sensor measured none of the \d+ "
                                         r"pixels that see the scene \("):
        z = renderer.render(scene, None, "z", sensor=nothing)["z"]
    assert not z.any()
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert renderer.render(scene, None, "z", sensor=zraster.StructuredLightSensor(
            max_range=100))["z"].any()


def test_the_same_seed_gives_the_same_image():
    scene = zraster.load("builtin:default")
    noisy = zraster.StructuredLightSensor(max_range=100, noise=0.5, seed=9)
    a = zraster.Renderer(W, H, threads=1).render(scene, None, "z", sensor=noisy)["z"]
    b = zraster.Renderer(W, H, threads=2).render(scene, None, "z", sensor=noisy)["z"]
    c = zraster.Renderer(W, H).render(scene, None, "z",
                                      sensor=zraster.StructuredLightSensor(max_range=100, noise=0.5,
                                                                           seed=10))["z"]
    np.testing.assert_array_equal(bits(a), bits(b))
    assert (a > 0).sum() > 1000 and (a != c).any()


def test_bad_depth_camera_arguments():
    renderer = zraster.Renderer(W, H)
    mesh = wall(3.0)
    with pytest.raises(zraster.InputError, match="unknown sensor 'lidar'"):
        renderer.render(mesh, pinhole(), "z", sensor="lidar")
    with pytest.raises(TypeError, match="sensor"):
        renderer.render(mesh, pinhole(), "z", sensor=3)
    with pytest.raises(zraster.InputError, match="sensor: measures the 'z' and 'range' outputs"):
        renderer.render(mesh, pinhole(), "color", sensor="kinect")
    with pytest.raises(zraster.InputError, match="baseline: must be finite and > 0"):
        zraster.StructuredLightSensor(baseline=-0.1)
    with pytest.raises(zraster.InputError, match="max_range: must be greater than min_range"):
        zraster.StructuredLightSensor(min_range=2.0, max_range=1.0)
    with pytest.raises(zraster.InputError, match="max_incidence"):
        zraster.StructuredLightSensor(max_incidence=95)
    with pytest.raises(zraster.InputError, match="seed"):
        zraster.StructuredLightSensor(seed=-1)
    with pytest.raises(zraster.InputError, match="z: must be a"):
        zraster.unproject(np.zeros((4, 4, 4), np.float32), pinhole())
    with pytest.raises(TypeError, match="camera"):
        zraster.unproject(np.zeros((H, W), np.float32), "camera")
