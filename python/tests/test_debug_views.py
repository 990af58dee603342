"""The view keyword: a debug view replaces the color only; a bad name is an InputError."""

import numpy as np
import pytest

import zraster

W, H = 96, 72


def test_view_replaces_color_only():
    scene = zraster.load("sphere:2000")
    plain = zraster.render(scene, W, H, outputs=("color", "depth"))
    view = zraster.render(scene, W, H, outputs=("color", "depth"), view="overdraw")
    assert not np.array_equal(plain["color"], view["color"])
    np.testing.assert_array_equal(plain["depth"], view["depth"])


def test_lod_is_mip():
    scene = zraster.load("sphere:2000")
    mip = zraster.render(scene, W, H, view="mip")["color"]
    lod = zraster.render(scene, W, H, view="lod")["color"]
    np.testing.assert_array_equal(mip, lod)


def test_bad_view_name():
    scene = zraster.load("sphere:200")
    with pytest.raises(zraster.InputError) as info:
        zraster.render(scene, W, H, view="heat")
    assert "'heat'" in str(info.value)
    assert "overdraw" in str(info.value)
    assert isinstance(info.value, ValueError)
