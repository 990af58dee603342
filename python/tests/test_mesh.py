"""Meshes reference the caller's arrays where dtype and layout fit, copy them otherwise, and keep
them alive."""

import gc
import sys

import numpy as np
import pytest

import zraster

W, H = 96, 72


def grid(n=8):
    """A bumpy n x n grid in the xy plane: positions (float32) and triangles (uint32)."""
    y, x = np.mgrid[0:n, 0:n].astype(np.float32) / (n - 1)
    z = 0.1 * np.sin(6 * x) * np.cos(5 * y)
    positions = np.stack([x - 0.5, y - 0.5, z], axis=-1).reshape(-1, 3)
    quads = np.array([[i * n + j, i * n + j + 1, (i + 1) * n + j + 1, (i + 1) * n + j]
                      for i in range(n - 1) for j in range(n - 1)], dtype=np.uint32)
    faces = np.concatenate([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    return np.ascontiguousarray(positions, np.float32), np.ascontiguousarray(faces)


CAMERA = zraster.Camera.look_at((0.3, -0.4, 1.5), (0, 0, 0), fovy=50.0)


def image(mesh):
    return zraster.Renderer(W, H).render(zraster.Scene([mesh]), CAMERA,
                                         outputs=("color", "depth"))


def test_float32_and_32_bit_indices_are_referenced():
    positions, faces = grid()
    count = sys.getrefcount(positions)
    mesh = zraster.Mesh(positions, faces)
    assert mesh.positions is positions and mesh.indices is faces
    assert sys.getrefcount(positions) == count + 1
    assert mesh.copied == {"positions": False, "indices": False, "normals": False, "uvs": False,
                           "colors": False}
    assert mesh.computed_normals  # none given: computed into an array the Mesh owns
    int32 = zraster.Mesh(positions, faces.astype(np.int32))
    assert not int32.copied["indices"]
    uint16 = zraster.Mesh(positions, faces.astype(np.uint16).reshape(-1))
    assert not uint16.copied["indices"]
    np.testing.assert_array_equal(image(int32)["color"], image(mesh)["color"])
    np.testing.assert_array_equal(image(uint16)["color"], image(mesh)["color"])


def test_interleaved_columns_are_referenced():
    positions, faces = grid()
    normals = zraster.Mesh(positions, faces).normals
    interleaved = np.concatenate([positions, normals, np.zeros((len(positions), 2), np.float32)],
                                 axis=1)
    mesh = zraster.Mesh(interleaved[:, 0:3], faces, normals=interleaved[:, 3:6],
                        uvs=interleaved[:, 6:8])
    assert not any(mesh.copied.values())
    assert np.shares_memory(mesh.positions, interleaved)
    assert np.shares_memory(mesh.normals, interleaved)
    packed = zraster.Mesh(positions, faces, normals=normals)
    np.testing.assert_array_equal(image(mesh)["color"], image(packed)["color"])
    np.testing.assert_array_equal(image(mesh)["depth"], image(packed)["depth"])


@pytest.mark.parametrize("convert", [
    lambda p: p.astype(np.float64),
    lambda p: np.asfortranarray(p),
    lambda p: p[::-1][::-1].copy()[::1].astype(">f4"),
    lambda p: p.tolist(),
    lambda p: np.repeat(p, 2, axis=0)[::2],
])
def test_other_layouts_are_copied_once_and_render_the_same(convert):
    positions, faces = grid()
    reference = image(zraster.Mesh(positions, faces))
    given = convert(positions)
    mesh = zraster.Mesh(given, faces.astype(np.int64))
    if isinstance(given, np.ndarray) and given.dtype == np.float32 and given.strides[1] == 4:
        assert not mesh.copied["positions"]  # a row stride of 24 bytes still fits
    else:
        assert mesh.copied["positions"]
        assert mesh.positions.dtype == np.float32 and mesh.positions.flags.c_contiguous
        if isinstance(given, np.ndarray):
            assert not np.shares_memory(mesh.positions, given)
    assert mesh.copied["indices"] and mesh.indices.dtype == np.uint32
    np.testing.assert_array_equal(image(mesh)["color"], reference["color"])


def test_referenced_arrays_stay_alive_and_changes_show():
    def make():
        positions, faces = grid()
        return zraster.Scene([zraster.Mesh(positions, faces)])

    scene = make()  # the only references to the arrays are the Mesh's, inside the Scene
    gc.collect()
    garbage = [np.full((len(grid()[0]), 3), 1e6, np.float32) for _ in range(20)]
    positions, faces = grid()
    expected = image(zraster.Mesh(positions, faces))
    out = zraster.Renderer(W, H).render(scene, CAMERA, outputs=("color", "depth"))
    np.testing.assert_array_equal(out["color"], expected["color"])
    del garbage

    mesh = zraster.Mesh(positions, faces)
    before = image(mesh)["depth"]
    positions[:, 2] += 0.05  # the Mesh sees the caller's array
    after = image(mesh)["depth"]
    assert not np.array_equal(before, after)


def test_instances_and_colors():
    positions, faces = grid()
    red = zraster.Mesh(positions, faces, color=(1, 0, 0))
    shifted = np.eye(4)
    shifted[0, 3] = 0.6
    scene = zraster.Scene([red, (red, shifted)])
    assert len(scene) == 2 and scene.triangle_count == 2 * len(faces)
    lo, hi = scene.bounds
    np.testing.assert_allclose(lo[:2], (-0.5, -0.5))
    np.testing.assert_allclose(hi[:2], (1.1, 0.5), rtol=1e-6)
    out = zraster.Renderer(W, H).render(scene, CAMERA, outputs=("rgba", "instance_id"))
    assert set(np.unique(out["instance_id"])) == {-1, 0, 1}
    drawn = out["rgba"][out["instance_id"] >= 0]
    assert np.all(drawn[:, 0] >= drawn[:, 1]) and np.all(drawn[:, 3] == 255)
    assert red.color == (1.0, 0.0, 0.0, 1.0)


def test_outputs_layout():
    scene = zraster.load("builtin:cube")
    out = zraster.Renderer(W, H).render(scene, outputs=("color", "rgba", "depth", "normal",
                                                        "instance_id", "primitive_id"))
    assert out["color"].shape == (H, W, 3) and out["color"].dtype == np.uint8
    assert out["rgba"].shape == (H, W, 4) and out["rgba"].dtype == np.uint8
    assert np.shares_memory(out["color"], out["rgba"])  # a view: nothing copied
    assert out["depth"].dtype == np.float32 and out["normal"].dtype == np.float32
    assert out["instance_id"].dtype == np.int32 and out["primitive_id"].dtype == np.int32
    empty = out["instance_id"] < 0
    assert empty.any() and (~empty).any()
    assert np.all(out["depth"][empty] == 1.0) and np.all(out["normal"][empty] == 0)
    assert np.all(out["primitive_id"][empty] == -1)
    lengths = np.linalg.norm(out["normal"][~empty], axis=1)
    np.testing.assert_allclose(lengths, 1.0, atol=1e-3)
