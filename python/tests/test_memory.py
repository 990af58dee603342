"""1,000 frames in a loop do not grow the process (the outputs and scenes are freed)."""

import gc

import numpy as np

import zraster

# The allowance: a few MB for the allocators' caches and numpy's small-object pools. A leaked
# output would be 160 * 120 * 8 bytes = 150 KB per frame, 150 MB over the loop.
ALLOWANCE_KB = 8 * 1024


def rss_kb():
    with open("/proc/self/status") as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    raise AssertionError("no VmRSS in /proc/self/status")


def test_renders_in_a_loop_do_not_leak():
    scene = zraster.load("sphere:5000")
    r = zraster.Renderer(160, 120, threads=1)
    outputs = ("color", "rgba", "depth", "normal", "instance_id", "primitive_id")
    for _ in range(50):  # warm up: the renderer's working memory, numpy's pools
        r.render(scene, outputs=outputs)
    gc.collect()
    before = rss_kb()
    for i in range(1000):
        out = r.render(scene, outputs=outputs, shading=("phong", "flat")[i % 2])
        assert out["depth"].shape == (120, 160)
    del out
    gc.collect()
    grown = rss_kb() - before
    assert grown < ALLOWANCE_KB, f"RSS grew by {grown} KB over 1,000 frames"


def test_meshes_and_scenes_in_a_loop_do_not_leak():
    positions = np.random.default_rng(1).random((3000, 3), dtype=np.float32)
    indices = np.arange(3000, dtype=np.int64).reshape(-1, 3)  # copied: int64
    camera = zraster.Camera.look_at((0.5, 0.5, 3), (0.5, 0.5, 0.5))
    r = zraster.Renderer(64, 48, threads=1)
    for _ in range(50):
        r.render(zraster.Scene([zraster.Mesh(positions, indices)]), camera)
    gc.collect()
    before = rss_kb()
    for i in range(1000):
        mesh = zraster.Mesh(positions.astype(np.float64), indices, color=(1, 0, 0))
        # Every 100th frame supersampled: the owning copy of the scene, and the copied images.
        r.render(zraster.Scene([mesh, (mesh, np.eye(4))]), camera, aa=2 if i % 100 == 0 else 1)
    del mesh
    gc.collect()
    grown = rss_kb() - before
    assert grown < ALLOWANCE_KB, f"RSS grew by {grown} KB over 1,000 meshes"


def address(array):
    return array.__array_interface__["data"][0]


def test_freed_outputs_are_recycled_and_kept_outputs_never_overwritten():
    scene = zraster.load("sphere:5000")
    r = zraster.Renderer(160, 120, threads=1)
    first = r.render(scene, outputs=("rgba", "depth"))
    kept_rgba, kept_depth = first["rgba"].copy(), first["depth"].copy()
    used = {address(first["rgba"]), address(first["depth"])}
    # Frames drawn while `first` lives never write into its memory, whatever they draw.
    for shading in ("flat", "gouraud", "phong"):
        other = r.render(scene, outputs=("rgba", "depth"), shading=shading, orbit=(40, 20, 3))
        assert address(other["rgba"]) not in used and address(other["depth"]) not in used
        assert not np.array_equal(other["rgba"], kept_rgba)
    np.testing.assert_array_equal(first["rgba"], kept_rgba)
    np.testing.assert_array_equal(first["depth"], kept_depth)
    # Once freed (with the views of it: `color` is one), its memory serves a later frame, and
    # that frame is exactly the frame drawn into fresh memory.
    view, rgba_block = first["rgba"][..., :3], address(first["rgba"])
    del first, other
    held = r.render(scene, outputs=("rgba",))
    assert address(held["rgba"]) != rgba_block  # `view` still holds that block
    del view, held
    gc.collect()
    again = r.render(scene, outputs=("rgba", "depth"))
    assert {address(again["rgba"]), address(again["depth"])} & used
    np.testing.assert_array_equal(again["rgba"], kept_rgba)
    np.testing.assert_array_equal(again["depth"], kept_depth)


def test_outputs_outlive_their_renderer():
    scene = zraster.load("sphere:5000")
    r = zraster.Renderer(96, 64, threads=1)
    out = r.render(scene, outputs=("color", "depth", "normal"))
    expected = {k: v.copy() for k, v in out.items()}
    del r
    gc.collect()
    for _ in range(3):  # other allocations that would reuse freed memory
        zraster.Renderer(96, 64, threads=1).render(scene, outputs=("color", "depth", "normal"),
                                                   shading="flat")
    for name, array in out.items():
        np.testing.assert_array_equal(array, expected[name], err_msg=name)
