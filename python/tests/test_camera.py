"""Cameras: intrinsics against the equivalent look-at camera, the principal point, the factories."""

import math

import numpy as np
import pytest

import zraster

W, H = 160, 120


def sphere_scene(center, radius=1.0):
    mesh = zraster.Mesh.uv_sphere(radius, 64, 128)
    transform = np.eye(4)
    transform[:3, 3] = center
    return zraster.Scene([(mesh, transform)])


def test_intrinsics_equal_the_look_at_camera():
    # A centred principal point and fx = fy make a pinhole camera that a look-at camera with the
    # matching field of view reproduces: OpenCV's camera looks down +z with y down.
    f = 140.0
    intrinsics = zraster.Camera.from_intrinsics(f, f, (W - 1) / 2, (H - 1) / 2, W, H, 0.5, 20.0)
    fovy = math.degrees(2 * math.atan(H / 2 / f))
    look_at = zraster.Camera.look_at((0, 0, 0), (0, 0, 1), up=(0, -1, 0), fovy=fovy,
                                     near=0.5, far=20.0)
    scene = zraster.Scene([
        (zraster.Mesh.box((0.5, 0.4, 0.3)), np.array([[1, 0, 0, 0.4], [0, 1, 0, -0.2],
                                                      [0, 0, 1, 4.0], [0, 0, 0, 1]])),
        (zraster.Mesh.uv_sphere(0.6, 24, 48), np.array([[1, 0, 0, -0.8], [0, 1, 0, 0.5],
                                                        [0, 0, 1, 6.0], [0, 0, 0, 1]])),
    ])
    r = zraster.Renderer(W, H)
    a = r.render(scene, intrinsics, outputs=("color", "depth", "instance_id"))
    b = r.render(scene, look_at, outputs=("color", "depth", "instance_id"))
    # The two projection matrices are computed differently (focal length against tan(fovy/2)):
    # equal up to float rounding, which may move a pixel's coverage on an edge.
    differing = np.count_nonzero(a["instance_id"] != b["instance_id"])
    assert differing <= 0.001 * W * H, differing
    assert np.count_nonzero(np.any(a["color"] != b["color"], axis=2)) <= 0.002 * W * H
    both = (a["instance_id"] >= 0) & (b["instance_id"] >= 0)
    np.testing.assert_allclose(a["depth"][both], b["depth"][both], rtol=0, atol=1e-5)
    k = intrinsics.intrinsics(W, H)
    assert (k["fx"], k["fy"], k["cx"], k["cy"]) == (f, f, (W - 1) / 2, (H - 1) / 2)


@pytest.mark.parametrize("cx,cy", [(70.0, 50.0), (101.5, 64.25)])
def test_sphere_on_the_optical_axis_is_centred_at_the_principal_point(cx, cy):
    camera = zraster.Camera.from_intrinsics(150.0, 150.0, cx, cy, W, H, 0.1, 50.0)
    out = zraster.Renderer(W, H).render(sphere_scene((0, 0, 8.0)), camera,
                                        outputs=("instance_id",))
    ys, xs = np.nonzero(out["instance_id"] >= 0)
    # The disc's centroid, in OpenCV pixel coordinates (pixel centers at integers).
    assert len(xs) > 500
    assert abs(xs.mean() - cx) < 0.05 and abs(ys.mean() - cy) < 0.05, (xs.mean(), ys.mean())


def test_pose_moves_the_camera():
    # The same view from a camera moved by +10 in x, and the scene moved with it.
    pose = np.eye(4)
    pose[0, 3] = 10.0
    a = zraster.Camera.from_intrinsics(150.0, 150.0, 80.0, 60.0, W, H, 0.1, 50.0)
    b = zraster.Camera.from_intrinsics(150.0, 150.0, 80.0, 60.0, W, H, 0.1, 50.0, pose=pose)
    r = zraster.Renderer(W, H)
    ia = r.render(sphere_scene((0, 0, 8.0)), a, outputs="instance_id")["instance_id"]
    ib = r.render(sphere_scene((10.0, 0, 8.0)), b, outputs="instance_id")["instance_id"]
    assert np.count_nonzero(ia != ib) <= 4
    np.testing.assert_allclose(b.eye, (10, 0, 0))
    np.testing.assert_allclose(b.camera_to_world(), pose, atol=1e-12)


def test_look_at_fields_and_matrices():
    c = zraster.Camera.look_at((0, 0, 5), (0, 0, 0), fovy=45.0, near=1.0, far=10.0)
    np.testing.assert_allclose(c.eye, (0, 0, 5))
    np.testing.assert_allclose(c.view_direction, (0, 0, -1))
    assert (c.fovy, c.near, c.far, c.orthographic) == (45.0, 1.0, 10.0, False)
    np.testing.assert_allclose(c.view_matrix() @ np.array([0, 0, 0, 1.0]), (0, 0, -5, 1))
    p = c.projection_matrix(W, H)
    assert p.shape == (4, 4) and p[3, 2] == -1.0
    o = zraster.Camera.look_at((0, 0, 5), (0, 0, 0), ortho_height=3.0)
    assert o.orthographic and o.ortho_height == 3.0
    m = zraster.Camera.from_matrices(c.view_matrix(), p)
    r = zraster.Renderer(W, H)
    scene = sphere_scene((0.3, 0.1, 0.0))
    np.testing.assert_array_equal(r.render(scene, c)["color"], r.render(scene, m)["color"])


def test_camera_keywords_apply_to_a_given_camera():
    scene = sphere_scene((0, 0, 0))
    camera = zraster.Camera.look_at((0, 0, 5), (0, 0, 0), near=1.0, far=10.0)
    r = zraster.Renderer(W, H)
    depth = r.render(scene, camera, outputs="depth", reversed_z=True)["depth"]
    standard = r.render(scene, camera, outputs="depth")["depth"]
    # Reversed: empty pixels hold the clear value 0, and nearer is larger.
    assert depth[0, 0] == 0.0 and standard[0, 0] == 1.0
    assert 0.0 < depth[H // 2, W // 2] < 1.0
    assert depth[H // 2, W // 2] > depth[H // 2 + 20, W // 2]
    near = r.render(scene, camera, outputs="depth", near=3.9)["depth"]
    assert near[H // 2, W // 2] < r.render(scene, camera, outputs="depth")["depth"][H // 2, W // 2]
