"""Textures on numpy Meshes: the image becomes the same C++ Texture, mip levels and all, as the
same image loaded through an OBJ + MTL + PNG, so the frames are the same bits."""

import numpy as np
import pytest

import zraster
from conftest import bits
from model_files import plane_grid, write_obj

W, H = 160, 120
OUTPUTS = ("rgba", "depth", "instance_id", "primitive_id", "normal")
# Near: texels magnified; far and grazing: the smaller mip levels, trilinear between them.
CAMERAS = [zraster.Camera.look_at((0.3, -0.5, 1.2), (0, 0, 0), fovy=50.0),
           zraster.Camera.look_at((0.5, -6.0, 1.5), (0, 0, 0), fovy=20.0)]


def frames(scene, **options):
    renderer = zraster.Renderer(W, H)
    return [renderer.render(scene, camera, outputs=OUTPUTS, **options) for camera in CAMERAS]


def assert_same_frames(a, b):
    for frame_a, frame_b in zip(a, b):
        for name in OUTPUTS:
            np.testing.assert_array_equal(bits(frame_a[name]), bits(frame_b[name]),
                                          err_msg=name)


def image(height, width, channels, seed=1, opaque=False):
    img = np.random.default_rng(seed).integers(0, 256, (height, width, channels), np.uint8)
    if channels == 4 and opaque:
        img[..., 3] = 255
    elif channels == 4:
        img[..., 3] = np.where(img[..., 3] < 64, 255, img[..., 3])  # some opaque texels
    return img


def material_fields(m):
    return (m.base_color, m.opacity, m.alpha_mode, m.alpha_cutoff, m.has_texture,
            m.has_opacity_texture, m.texture_size, m.translucent_texture, m.ambient, m.diffuse,
            m.specular, m.shininess)


@pytest.mark.parametrize("height, width, channels", [(16, 16, 3), (13, 7, 3), (32, 8, 4),
                                                     (5, 9, 4)])
def test_a_textured_mesh_draws_as_the_same_obj_mtl_png(tmp_path, height, width, channels):
    positions, faces, normals, uvs = plane_grid(uv_repeat=3.0)
    texture = image(height, width, channels)
    loaded = zraster.load(write_obj(tmp_path, "textured", [
        {"positions": positions, "faces": faces, "normals": normals, "uvs": uvs,
         "kd": (1, 1, 1), "texture": texture}]))
    mesh = zraster.Mesh(positions, faces, normals, uvs, texture=texture)
    # The same material: white base color times the texture, the same Phong terms.
    assert loaded.materials[1].has_texture
    assert material_fields(mesh.material) == material_fields(loaded.materials[1])
    assert mesh.material.texture_size == (width, height)
    assert_same_frames(frames(zraster.Scene([mesh])), frames(loaded))
    # The texture is what makes these frames: without it they differ.
    plain = frames(zraster.Scene([mesh]), no_textures=True)
    assert not np.array_equal(plain[0]["rgba"], frames(loaded)[0]["rgba"])


def test_a_texture_with_a_base_color_and_filters(tmp_path):
    positions, faces, normals, uvs = plane_grid(uv_repeat=2.0)
    texture = image(16, 16, 3, seed=4)
    loaded = zraster.load(write_obj(tmp_path, "tinted", [
        {"positions": positions, "faces": faces, "normals": normals, "uvs": uvs,
         "kd": (0.5, 0.75, 1), "texture": texture}]))
    mesh = zraster.Mesh(positions, faces, normals, uvs, color=(0.5, 0.75, 1), texture=texture)
    for texture_filter in ("nearest", "bilinear", "trilinear"):
        assert_same_frames(frames(zraster.Scene([mesh]), texture_filter=texture_filter),
                           frames(loaded, texture_filter=texture_filter))
    # Frames drawn through an owning copy of the scene (antialiasing, the A-buffer).
    for options in ({"aa": 2}, {"visibility": "abuffer"}):
        assert_same_frames(frames(zraster.Scene([mesh]), **options), frames(loaded, **options))


def test_float_texels_are_scaled_to_bytes():
    positions, faces, normals, uvs = plane_grid()
    texture = image(8, 8, 4)
    as_bytes = zraster.Mesh(positions, faces, normals, uvs, texture=texture)
    as_floats = zraster.Mesh(positions, faces, normals, uvs,
                             texture=texture.astype(np.float32) / 255)
    np.testing.assert_array_equal(as_floats.texture, texture)
    assert_same_frames(frames(zraster.Scene([as_floats])), frames(zraster.Scene([as_bytes])))


def test_the_texture_is_a_copy_with_alpha():
    positions, faces, normals, uvs = plane_grid()
    texture = image(4, 6, 3)
    mesh = zraster.Mesh(positions, faces, normals, uvs, texture=texture)
    kept = mesh.texture
    assert kept.shape == (4, 6, 4) and kept.dtype == np.uint8
    np.testing.assert_array_equal(kept[..., :3], texture)
    assert (kept[..., 3] == 255).all()
    texture[:] = 0  # the Mesh copied it
    np.testing.assert_array_equal(mesh.texture, kept)
    assert mesh.material.base_color == (1.0, 1.0, 1.0)
    assert zraster.Mesh(positions, faces).texture is None


def test_an_rgba_texture_with_translucent_texels_is_blended():
    positions, faces, normals, uvs = plane_grid()
    opaque = zraster.Mesh(positions, faces, normals, uvs, texture=image(8, 8, 4, opaque=True))
    translucent = zraster.Mesh(positions, faces, normals, uvs, texture=image(8, 8, 4))
    assert not opaque.material.translucent_texture and translucent.material.translucent_texture
    # Blended fragments write no depth: where the plane is, the translucent one leaves depth 1.
    drawn = frames(zraster.Scene([opaque]))[0]["depth"] < 1
    assert drawn.any()
    assert (frames(zraster.Scene([translucent]))[0]["depth"][drawn] == 1).all()


def test_bad_textures_name_the_argument():
    positions, faces, normals, uvs = plane_grid()
    good = image(4, 4, 3)
    with pytest.raises(zraster.InputError) as info:
        zraster.Mesh(positions, faces, normals, texture=good)
    assert info.value.source == "texture" and "uvs" in info.value.cause
    bad_shapes = [np.zeros((4, 4), np.uint8), np.zeros((4, 4, 2), np.uint8),
                  np.zeros((0, 4, 3), np.uint8), np.zeros((2, 4, 4, 3), np.uint8)]
    for bad in bad_shapes:
        with pytest.raises(zraster.InputError) as info:
            zraster.Mesh(positions, faces, normals, uvs, texture=bad)
        assert info.value.source == "texture", bad.shape
    for bad in (np.zeros((4, 4, 3), np.int32), np.zeros((4, 4, 3), np.uint16),
                np.zeros((4, 4, 3), bool), "texture.png"):
        with pytest.raises(TypeError, match=r"^texture: "):
            zraster.Mesh(positions, faces, normals, uvs, texture=bad)
    for value in (1.5, -0.25, np.nan):
        bad = np.full((4, 4, 3), value, np.float32)
        with pytest.raises(zraster.InputError) as info:
            zraster.Mesh(positions, faces, normals, uvs, texture=bad)
        assert info.value.source == "texture" and "[0, 1]" in info.value.cause
