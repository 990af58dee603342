"""Scenes as items of a Scene: a loaded scene beside numpy Meshes, placed by a transform on top of
its own instance transforms, its materials and textures kept, its instances numbered in item
order."""

import gc

import numpy as np
import pytest

import zraster
from conftest import bits
from model_files import plane_grid, write_obj

W, H = 128, 96
OUTPUTS = ("rgba", "depth", "instance_id", "primitive_id", "normal")


def frame(scene, camera, **options):
    return zraster.Renderer(W, H).render(scene, camera, outputs=OUTPUTS, **options)


def assert_same_frames(a, b):
    for name in OUTPUTS:
        np.testing.assert_array_equal(bits(a[name]), bits(b[name]), err_msg=name)


def translation(x, y, z):
    t = np.eye(4)
    t[:3, 3] = (x, y, z)
    return t


def textured_obj(folder):
    """An OBJ + MTL + PNG of two planes, one of them textured, as zraster.load() reads it."""
    positions, faces, normals, uvs = plane_grid()
    texture = np.random.default_rng(3).integers(0, 256, (8, 8, 3), dtype=np.uint8)
    return zraster.load(write_obj(folder, "planes", [
        {"positions": positions, "faces": faces, "normals": normals, "uvs": uvs,
         "kd": (1, 1, 1), "texture": texture},
        {"positions": positions + np.float32([0.25, 0.25, -0.5]), "faces": faces,
         "normals": normals, "kd": (0.2, 0.6, 0.3)},
    ]), isolation="in-process")


@pytest.mark.parametrize("spec, instances", [("builtin:default", 7), ("city:12", 1)])
def test_a_loaded_scene_as_an_item_draws_as_itself(spec, instances):
    loaded = zraster.load(spec)
    combined = zraster.Scene([loaded])
    assert len(combined) == len(loaded) == instances
    assert combined.triangle_count == loaded.triangle_count
    np.testing.assert_array_equal(combined.bounds, loaded.bounds)
    camera = zraster.Camera.fit(loaded, W, H)
    assert_same_frames(frame(combined, camera), frame(loaded, camera))
    # Its materials whole, after the combined scene's own default.
    assert [m.name for m in combined.materials] == ["default"] + [m.name for m in
                                                                  loaded.materials]


def test_a_loaded_scene_keeps_its_textures(tmp_path):
    loaded = textured_obj(tmp_path)
    assert any(m.has_texture for m in loaded.materials)
    combined = zraster.Scene([loaded])
    camera = zraster.Camera.look_at((0.4, -0.6, 1.6), (0, 0, 0), fovy=45.0)
    assert_same_frames(frame(combined, camera), frame(loaded, camera))
    # The texture shows (the comparison above would hold for untextured frames too).
    untextured = frame(combined, camera, no_textures=True)
    assert not np.array_equal(untextured["rgba"], frame(combined, camera)["rgba"])


def test_a_scene_item_keeps_the_loaded_scene_alive(tmp_path):
    loaded = textured_obj(tmp_path)
    camera = zraster.Camera.look_at((0.4, -0.6, 1.6), (0, 0, 0), fovy=45.0)
    expected = frame(loaded, camera)
    combined = zraster.Scene([loaded])
    del loaded
    gc.collect()
    assert_same_frames(frame(combined, camera), expected)


def test_an_item_transform_applies_after_the_scene_s_own():
    # Exact in float32: the combined transform is the same bits as numpy's product.
    a = np.array([[0, -1, 0, 0.5], [1, 0, 0, 0], [0, 0, 1, -0.25], [0, 0, 0, 1]], np.float64)
    b = np.array([[2, 0, 0, 0], [0, 1, 0, 0.75], [0, 0, 0.5, 0], [0, 0, 0, 1]], np.float64)
    mesh = zraster.Mesh.box((0.5, 0.25, 0.125), color=(0.9, 0.5, 0.2))
    nested = zraster.Scene([(zraster.Scene([(mesh, a)]), b)])
    camera = zraster.Camera.look_at((1.5, 2.0, 4.0), (0, 0.5, 0), fovy=50.0)
    assert_same_frames(frame(nested, camera), frame(zraster.Scene([(mesh, b @ a)]), camera))
    # The other order is another picture: the test tells them apart.
    swapped = frame(zraster.Scene([(mesh, a @ b)]), camera)
    assert not np.array_equal(swapped["rgba"], frame(nested, camera)["rgba"])


def test_an_item_transform_moves_a_loaded_scene():
    loaded = zraster.load("builtin:default")
    moved = zraster.Scene([(loaded, translation(4, -2, 8))])
    lo, hi = loaded.bounds
    moved_lo, moved_hi = moved.bounds
    np.testing.assert_allclose(moved_lo, lo + (4, -2, 8), rtol=0, atol=1e-5)
    np.testing.assert_allclose(moved_hi, hi + (4, -2, 8), rtol=0, atol=1e-5)


def nearest_of(parts, offsets):
    """The frame that drawing every part's instances together must give: per pixel the nearest
    part's outputs (ids shifted by the part's first instance id); pixels where two parts are at
    the same depth are left out (`mask` False)."""
    depth = np.stack([p["depth"] for p in parts])
    nearest = np.argmin(depth, axis=0)
    ordered = np.sort(depth, axis=0)
    mask = (ordered[0] < ordered[1]) | (ordered[0] == 1.0)
    expected = {}
    for name in OUTPUTS:
        stack = np.stack([p[name] for p in parts])
        picked = np.take_along_axis(
            stack, nearest.reshape((1,) + nearest.shape + (1,) * (stack.ndim - 3)), 0)[0]
        if name == "instance_id":
            shifted = picked + np.asarray(offsets)[nearest]
            picked = np.where(picked < 0, -1, shifted).astype(np.int32)
        expected[name] = picked
    return expected, mask


def test_instance_ids_follow_the_items_order(tmp_path):
    loaded = textured_obj(tmp_path)
    sphere = zraster.Mesh.uv_sphere(0.3, color=(0.9, 0.2, 0.2))
    box = zraster.Mesh.box((0.2, 0.2, 0.2), color=(0.2, 0.2, 0.9))
    items = [(sphere, translation(-0.4, 0.1, 0.2)), (loaded, translation(0.5, 0.4, 0.05)),
             (box, translation(0.35, -0.2, 0.3)), loaded]
    combined = zraster.Scene(items)
    assert len(combined) == 1 + len(loaded) + 1 + len(loaded)
    camera = zraster.Camera.look_at((0.3, -0.5, 2.2), (0, 0, 0), fovy=50.0)
    parts = [frame(zraster.Scene([item]), camera) for item in items]
    offsets = [0, 1, 1 + len(loaded), 2 + len(loaded)]
    expected, mask = nearest_of(parts, offsets)
    got = frame(combined, camera)
    assert mask.mean() > 0.9
    for name in OUTPUTS:
        np.testing.assert_array_equal(bits(got[name])[mask], bits(expected[name])[mask],
                                      err_msg=name)
    # Every item shows, under its own ids.
    ids = set(np.unique(got["instance_id"]))
    assert {0, 1 + len(loaded)} <= ids
    assert ids & set(range(1, 1 + len(loaded))) and ids & set(range(2 + len(loaded),
                                                                      2 + 2 * len(loaded)))


def test_a_scene_given_twice_shares_its_meshes_and_materials(tmp_path):
    loaded = textured_obj(tmp_path)
    twice = zraster.Scene([loaded, (loaded, translation(2, 0, 0))])
    assert len(twice) == 2 * len(loaded)
    assert len(twice.materials) == 1 + len(loaded.materials)
    assert twice.triangle_count == 2 * loaded.triangle_count


def test_scenes_of_meshes_nest():
    mesh = zraster.Mesh.uv_sphere(0.5, stacks=8, slices=16)
    inner = zraster.Scene([mesh, (mesh, translation(1, 0, 0))])
    outer = zraster.Scene([(inner, translation(0, 1, 0)), mesh])
    flat = zraster.Scene([(mesh, translation(0, 1, 0)), (mesh, translation(1, 1, 0)), mesh])
    camera = zraster.Camera.fit(flat, W, H)
    assert_same_frames(frame(outer, camera), frame(flat, camera))


def test_bad_items_name_their_index():
    mesh = zraster.Mesh.box()
    loaded = zraster.load("builtin:cube")
    with pytest.raises(TypeError, match=r"items\[2\].*Scene.*got str"):
        zraster.Scene([mesh, loaded, "room.glb"])
    with pytest.raises(TypeError, match=r"items\[1\].*got int"):
        zraster.Scene([loaded, (3, np.eye(4))])
    with pytest.raises(TypeError, match=r"items\[0\]"):
        zraster.Scene([(loaded, np.eye(4), np.eye(4))])


@pytest.mark.parametrize("transform, cause", [
    (np.eye(3), "(3, 3)"),
    (np.full((4, 4), np.inf), "not finite"),
    (np.diag([1.0, 0.0, 1.0, 1.0]), "singular"),
    (np.zeros((4, 4)), "singular"),
])
def test_bad_item_transforms_name_the_item(transform, cause):
    for item in (zraster.load("builtin:cube"), zraster.Mesh.box()):
        with pytest.raises(zraster.InputError) as info:
            zraster.Scene([item, (item, transform)])
        assert info.value.source == "items[1] transform"
        assert cause in str(info.value)
