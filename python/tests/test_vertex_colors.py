"""Vertex colors from Python: Mesh(colors=...) as RGBA or RGB floats or uint8, drawn as the glTF
file with the same COLOR_0 is (color times the base color, alpha times the material's), and
refused by name when malformed; Mesh(double_sided=...) as glTF's doubleSided."""

import numpy as np
import pytest

import zraster
from conftest import bits
from model_files import plane_grid, write_gltf

W, H = 160, 120
OUTPUTS = ("rgba", "depth", "instance_id", "primitive_id", "normal")
CAMERA = zraster.Camera.look_at((0.4, -0.6, 1.5), (0, 0, 0.1), fovy=50.0)


def frame(scene, camera=CAMERA, **options):
    return zraster.Renderer(W, H).render(scene, camera, outputs=OUTPUTS, **options)


def assert_same_frame(a, b):
    for name in OUTPUTS:
        np.testing.assert_array_equal(bits(a[name]), bits(b[name]), err_msg=name)


def gradient(positions, alpha=True):
    """Colors that vary over the plane: red to green in x, alpha 0.2 to 1 in y."""
    x = (positions[:, 0] - positions[:, 0].min()) / np.ptp(positions[:, 0])
    y = (positions[:, 1] - positions[:, 1].min()) / np.ptp(positions[:, 1])
    rgba = np.stack([1 - x, x, np.full_like(x, 0.5), 0.2 + 0.8 * y], axis=1).astype(np.float32)
    return rgba if alpha else rgba[:, :3].copy()


def test_vertex_colors_draw_as_the_gltf_file(tmp_path):
    positions, faces, normals, _ = plane_grid()
    front = positions * np.float32([0.5, 0.5, 1]) + np.float32([0.125, 0.0625, 0.25])
    colors = gradient(front)
    loaded = zraster.load(write_gltf(tmp_path, "colors", [
        {"positions": positions, "faces": faces, "normals": normals, "color": (0.5, 0.5, 0.5, 1)},
        {"positions": front, "faces": faces, "normals": normals, "colors": colors,
         "color": (1, 0.75, 1, 1), "alpha_mode": "BLEND"},
    ]))
    back = zraster.Mesh(positions, faces, normals, color=(0.5, 0.5, 0.5), alpha_mode="opaque")
    blended = zraster.Mesh(front, faces, normals, color=(1, 0.75, 1), alpha_mode="blend",
                           colors=colors)
    assert blended.colors is not None and blended.colors.shape == (len(front), 4)
    assert not blended.copied["colors"]  # float32 RGBA rows are referenced
    got = frame(zraster.Scene([back, blended]))
    assert_same_frame(got, frame(loaded))
    # Blended where the plane is: the back plane's depth shows through, the colors vary.
    alone = frame(zraster.Scene([back]))
    np.testing.assert_array_equal(got["depth"], alone["depth"])
    changed = np.any(got["rgba"] != alone["rgba"], axis=2)
    assert changed.sum() > 500
    assert len(np.unique(got["rgba"][changed].reshape(-1, 4), axis=0)) > 100


def test_rgb_and_byte_colors_equal_their_float_rgba():
    positions, faces, normals, _ = plane_grid()
    rgba = gradient(positions)
    as_bytes = np.round(rgba * 255).astype(np.uint8)
    from_bytes = zraster.Mesh(positions, faces, normals, colors=as_bytes)
    assert from_bytes.copied["colors"]
    np.testing.assert_array_equal(from_bytes.colors, as_bytes.astype(np.float32) / np.float32(255))
    rgb = zraster.Mesh(positions, faces, normals, colors=rgba[:, :3])
    np.testing.assert_array_equal(rgb.colors[:, 3], 1)
    opaque = rgba.copy()
    opaque[:, 3] = 1
    assert_same_frame(frame(zraster.Scene([rgb])),
                      frame(zraster.Scene([zraster.Mesh(positions, faces, normals,
                                                        colors=opaque)])))
    # Vertex alpha makes the default (blend) material transparent; without colors it is opaque.
    blended = frame(zraster.Scene([zraster.Mesh(positions, faces, normals, colors=rgba)]))
    plain = frame(zraster.Scene([zraster.Mesh(positions, faces, normals)]))
    assert (blended["instance_id"] >= 0).sum() == 0  # blended fragments write no ids
    assert (plain["instance_id"] >= 0).sum() > 1000


def test_bad_colors_name_the_argument():
    positions, faces, _, _ = plane_grid()
    n = len(positions)
    for bad, words in ((np.zeros((n, 2), np.float32), "shape"),
                       (np.zeros((n - 1, 4), np.float32), "per position"),
                       (np.full((n, 4), 1.5, np.float32), "outside 0..1"),
                       (np.full((n, 4), np.nan, np.float32), "non-finite")):
        with pytest.raises(zraster.InputError) as info:
            zraster.Mesh(positions, faces, colors=bad)
        assert info.value.source == "colors" and words in str(info.value), str(info.value)
    with pytest.raises(TypeError, match=r"^double_sided: "):
        zraster.Mesh(positions, faces, double_sided="yes")


def test_double_sided_mesh_is_drawn_from_behind_as_the_gltf_file(tmp_path):
    positions, faces, normals, _ = plane_grid()
    behind = zraster.Camera.look_at((0.2, -0.1, -1.5), (0, 0, 0), fovy=50.0)
    loaded = zraster.load(write_gltf(tmp_path, "double", [
        {"positions": positions, "faces": faces, "normals": normals,
         "color": (1, 0.5, 0.25, 1), "double_sided": True}]))
    double = zraster.Mesh(positions, faces, normals, color=(1, 0.5, 0.25), alpha_mode="opaque",
                          double_sided=True)
    assert double.material.double_sided
    assert_same_frame(frame(zraster.Scene([double]), behind), frame(loaded, behind))
    single = zraster.Mesh(positions, faces, normals, color=(1, 0.5, 0.25), double_sided=False)
    assert (frame(zraster.Scene([single]), behind)["instance_id"] >= 0).sum() == 0
