"""Materials' alpha from Python: loaded materials as zraster.Material, and numpy Meshes with
alpha_mode / alpha_cutoff / an RGBA color drawn as the equivalent file is."""

import numpy as np
import pytest

import zraster
from conftest import bits
from model_files import plane_grid, write_gltf, write_obj

W, H = 160, 120
OUTPUTS = ("rgba", "depth", "instance_id", "primitive_id", "normal")
CAMERA = zraster.Camera.look_at((0.4, -0.6, 1.5), (0, 0, 0.1), fovy=50.0)


def frame(scene, **options):
    return zraster.Renderer(W, H).render(scene, CAMERA, outputs=OUTPUTS, **options)


def assert_same_frame(a, b):
    for name in OUTPUTS:
        np.testing.assert_array_equal(bits(a[name]), bits(b[name]), err_msg=name)


def planes():
    """Two planes: one at z = 0 and a smaller one in front of it at z = 0.25."""
    positions, faces, normals, uvs = plane_grid()
    front = positions * np.float32([0.5, 0.5, 1]) + np.float32([0.125, 0.0625, 0.25])
    return (positions, faces, normals, uvs), (front, faces, normals, uvs)


def alpha_fields(m):
    return (m.base_color, m.opacity, m.alpha_mode, m.alpha_cutoff, m.has_texture, m.specular,
            m.shininess, m.ambient, m.diffuse)


def test_loaded_materials_report_their_alpha(tmp_path):
    (back, faces, normals, uvs), (front, *_) = planes()
    cutout = np.full((4, 4, 4), 255, np.uint8)
    cutout[:2, :, 3] = 0
    obj = zraster.load(write_obj(tmp_path, "alpha", [
        {"positions": back, "faces": faces, "normals": normals, "kd": (1, 0, 0)},
        {"positions": front, "faces": faces, "normals": normals, "uvs": uvs,
         "kd": (0, 0, 1), "d": 0.5, "opacity_texture": np.full((2, 2, 3), 128, np.uint8)},
    ]))
    materials = obj.materials
    assert [type(m) for m in materials] == [zraster.Material] * 3
    assert materials[0].name == "default"
    assert (materials[1].name, materials[1].alpha_mode, materials[1].opacity) == ("m0", "blend",
                                                                                  1.0)
    assert materials[1].base_color == (1.0, 0.0, 0.0) and not materials[1].has_opacity_texture
    assert (materials[2].alpha_mode, materials[2].opacity) == ("blend", 0.5)
    assert materials[2].has_opacity_texture and not materials[2].has_texture
    gltf = zraster.load(write_gltf(tmp_path, "alpha", [
        {"positions": back, "faces": faces, "normals": normals, "color": (1, 1, 1, 0.5)},
        {"positions": front, "faces": faces, "normals": normals, "uvs": uvs,
         "color": (1, 1, 1, 0.75), "alpha_mode": "MASK", "alpha_cutoff": 0.25,
         "texture": cutout},
        {"positions": front, "faces": faces, "normals": normals, "color": (1, 1, 1, 0.5),
         "alpha_mode": "BLEND"},
    ]))
    modes = [(m.alpha_mode, m.opacity, m.alpha_cutoff) for m in gltf.materials[1:]]
    assert modes == [("opaque", 1.0, 0.5), ("mask", 0.75, 0.25), ("blend", 0.5, 0.5)]
    assert gltf.materials[2].has_texture and gltf.materials[2].translucent_texture
    assert "mask" in repr(gltf.materials[2]) and "cutoff 0.25" in repr(gltf.materials[2])


def test_a_blended_mesh_over_an_opaque_one_draws_as_the_obj_file(tmp_path):
    (back, faces, normals, _), (front, *_) = planes()
    loaded = zraster.load(write_obj(tmp_path, "blend", [
        {"positions": back, "faces": faces, "normals": normals, "kd": (1, 0.5, 0)},
        {"positions": front, "faces": faces, "normals": normals, "kd": (0, 0.25, 1),
         "d": 0.5},
    ]))
    opaque = zraster.Mesh(back, faces, normals, color=(1, 0.5, 0))
    blended = zraster.Mesh(front, faces, normals, color=(0, 0.25, 1, 0.5), alpha_mode="blend")
    assert alpha_fields(opaque.material) == alpha_fields(loaded.materials[1])
    assert alpha_fields(blended.material) == alpha_fields(loaded.materials[2])
    scene = zraster.Scene([opaque, blended])
    got = frame(scene)
    assert_same_frame(got, frame(loaded))
    # Blended: the front plane wrote no depth and let the back one show through.
    alone = frame(zraster.Scene([opaque]))
    np.testing.assert_array_equal(got["depth"], alone["depth"])
    assert not np.array_equal(got["rgba"], alone["rgba"])
    # The default alpha mode is blend: the same picture without saying so.
    implicit = zraster.Mesh(front, faces, normals, color=(0, 0.25, 1, 0.5))
    assert_same_frame(frame(zraster.Scene([opaque, implicit])), got)
    # So do the frames drawn through an owning copy of the scene.
    for options in ({"aa": 2}, {"visibility": "abuffer"}):
        assert_same_frame(frame(scene, **options), frame(loaded, **options))


def test_a_masked_textured_mesh_draws_as_the_gltf_file(tmp_path):
    (back, faces, normals, uvs), (front, *_) = planes()
    cutout = np.random.default_rng(5).integers(0, 256, (8, 8, 4), dtype=np.uint8)
    loaded = zraster.load(write_gltf(tmp_path, "mask", [
        {"positions": back, "faces": faces, "normals": normals, "color": (0.5, 0.5, 0.5, 1)},
        {"positions": front, "faces": faces, "normals": normals, "uvs": uvs,
         "color": (1, 0.75, 0.5, 0.75), "alpha_mode": "MASK", "alpha_cutoff": 0.375,
         "texture": cutout},
    ]))
    back_mesh = zraster.Mesh(back, faces, normals, color=(0.5, 0.5, 0.5), alpha_mode="opaque")
    masked = zraster.Mesh(front, faces, normals, uvs, color=(1, 0.75, 0.5, 0.75),
                          texture=cutout, alpha_mode="mask", alpha_cutoff=0.375)
    assert alpha_fields(back_mesh.material) == alpha_fields(loaded.materials[1])
    assert alpha_fields(masked.material) == alpha_fields(loaded.materials[2])
    got = frame(zraster.Scene([back_mesh, masked]))
    assert_same_frame(got, frame(loaded))
    # Masked: some of the front plane's fragments were discarded, the rest wrote depth.
    front_only = frame(zraster.Scene([masked]))["depth"]
    solid = frame(zraster.Scene([zraster.Mesh(front, faces, normals)]))["depth"] < 1
    assert (front_only[solid] < 1).any() and (front_only[solid] == 1).any()


def test_an_opaque_mesh_ignores_its_alpha():
    (back, faces, normals, uvs), _ = planes()
    translucent = np.full((4, 4, 4), 40, np.uint8)
    ignored = zraster.Mesh(back, faces, normals, uvs, color=(0.2, 0.4, 0.6, 0.25),
                           texture=translucent, alpha_mode="opaque")
    assert ignored.material.opacity == 1.0 and ignored.material.alpha_mode == "opaque"
    solid = zraster.Mesh(back, faces, normals, uvs, color=(0.2, 0.4, 0.6),
                         texture=np.full((4, 4, 3), 40, np.uint8))
    assert_same_frame(frame(zraster.Scene([ignored])), frame(zraster.Scene([solid])))
    assert ignored.color == (pytest.approx(0.2), pytest.approx(0.4), pytest.approx(0.6), 1.0)


def test_a_mesh_without_material_keywords_has_no_material():
    (back, faces, normals, _), _ = planes()
    assert zraster.Mesh(back, faces).material is None
    only_cutoff = zraster.Mesh(back, faces, alpha_cutoff=0.125).material
    assert (only_cutoff.alpha_mode, only_cutoff.alpha_cutoff) == ("blend", 0.125)
    assert only_cutoff.base_color == zraster.Scene([zraster.Mesh(back, faces)]).materials[
        0].base_color


def test_bad_alpha_keywords_name_the_argument():
    (back, faces, _, _), _ = planes()
    with pytest.raises(zraster.InputError) as info:
        zraster.Mesh(back, faces, alpha_mode="transparent")
    assert info.value.source == "alpha_mode" and "'opaque', 'mask' or 'blend'" in str(info.value)
    with pytest.raises(TypeError, match=r"^alpha_mode: "):
        zraster.Mesh(back, faces, alpha_mode=1)
    for cutoff in (-0.5, 1.5):
        with pytest.raises(zraster.InputError) as info:
            zraster.Mesh(back, faces, alpha_cutoff=cutoff)
        assert info.value.source == "alpha_cutoff" and "0..1" in str(info.value)
    with pytest.raises(zraster.InputError) as info:
        zraster.Mesh(back, faces, alpha_cutoff=float("nan"))
    assert info.value.source == "alpha_cutoff"
    with pytest.raises(TypeError, match=r"^alpha_cutoff: "):
        zraster.Mesh(back, faces, alpha_cutoff="half")
    with pytest.raises(zraster.InputError) as info:
        zraster.Mesh(back, faces, color=(1, 1, 1, 1.5))
    assert info.value.source == "color"
