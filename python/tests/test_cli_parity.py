"""The module's arrays equal the command's files bit for bit, for the same scene and flags."""

import numpy as np
import pytest

import zraster
from conftest import bits, read_png, run_cli, shared_mesh

W, H = 128, 96

# (scene, keywords): each keyword is passed to the command as its flag.
CASES = [
    ("builtin:default", {}),
    ("builtin:cube", {"eye": (2.5, 1.5, 3.0), "target": (0, 0.2, 0), "up": (0, 1, 0),
                      "fovy": 50.0, "near": 0.5, "far": 20.0}),
    ("sphere:3000", {"orbit": (30, 20, 3), "shading": "flat", "reversed_z": True}),
    ("sphere:3000", {"depth_format": "d24", "depth_compare": "lequal", "shading": "gouraud",
                     "reflection": "phong", "infinite_viewer": True}),
    ("city:300", {"light_dir": [(-1, 2, 1), (0.5, 1, -1)], "point_light": (0, 30, 0),
                  "clip_plane": (0, -1, 0, 20), "background": (10, 20, 30), "cull": "none"}),
    ("city:300", {"occlusion_cull": True, "front_to_back": True, "shading_strategy": "forward",
                  "front_face": "cw", "no_cull": True}),
    ("builtin:default", {"interpolation": "linear", "texture_filter": "nearest",
                         "infinite_far": True}),
    ("builtin:default", {"no_textures": True, "shading": "unlit"}),
    ("builtin:sphere", {"ortho": True, "wireframe": True, "edge_color": (255, 128, 0)}),
    ("builtin:cube", {"hidden_line": True, "edge_color": "0,255,0"}),
    ("sphere:800", {"visibility": "painter"}),
    ("sphere:800", {"visibility": "bsp"}),
    ("builtin:cube", {"aa": 2}),
    ("builtin:cube", {"aa": 4, "msaa": True}),
    ("builtin:cube", {"visibility": "abuffer"}),
]


def flags(keywords):
    """The command's flags for the module's keywords."""
    args = []
    for name, value in keywords.items():
        flag = "--" + name.replace("_", "-")
        # FLAG=VALUE: values such as -1,2,1 must not read as flags.
        if value is True:
            args.append(flag)
        elif isinstance(value, list):
            args += [f"{flag}={','.join(map(repr, item))}" for item in value]
        elif isinstance(value, tuple):
            args.append(f"{flag}={','.join(map(repr, value))}")
        else:
            args.append(f"{flag}={value}")
    return args


def command_outputs(tmp_path, scene, keywords, ids=True, normals=True):
    color, depth = tmp_path / "c.png", tmp_path / "d.npy"
    args = ["render", scene, "-o", color, "--size", f"{W}x{H}", "--depth-out", depth]
    if ids:
        args += ["--id-out", tmp_path / "i.npy"]
    if normals:
        args += ["--normal-out", tmp_path / "n.png"]
    run_cli(*args, *flags(keywords))
    out = {"color": read_png(color), "depth": np.load(depth)}
    if ids:
        out["ids"] = np.load(tmp_path / "i.npy")
    if normals:
        out["normal"] = read_png(tmp_path / "n.png")
    return out


def normal_png(normal):
    """The module's normals encoded as --normal-out encodes them (n * 0.5 + 0.5, 0 if empty)."""
    v = np.clip(normal * np.float32(0.5) + np.float32(0.5), 0, 1) * np.float32(255)
    rgb = np.floor(v.astype(np.float64) + 0.5).astype(np.uint8)
    rgb[np.all(normal == 0, axis=2)] = 0
    return rgb


def assert_same(module, command, single_instance):
    assert module["color"].shape == (H, W, 3) and module["color"].dtype == np.uint8
    assert module["depth"].shape == (H, W) and module["depth"].dtype == np.float32
    np.testing.assert_array_equal(module["color"], command["color"])
    np.testing.assert_array_equal(bits(module["depth"]), bits(command["depth"]))
    if "normal" in command:
        np.testing.assert_array_equal(normal_png(module["normal"]), command["normal"])
    if "ids" in command:
        drawn = module["instance_id"] >= 0
        np.testing.assert_array_equal(drawn, command["ids"] >= 0)
        np.testing.assert_array_equal(module["primitive_id"] < 0, ~drawn)
        if single_instance:
            np.testing.assert_array_equal(module["primitive_id"], command["ids"])


@pytest.mark.parametrize("scene,keywords", CASES, ids=[f"{s} {k}" for s, k in CASES])
def test_render_matches_command(tmp_path, scene, keywords):
    pipeline = keywords.get("visibility", "zbuffer") == "zbuffer" and "aa" not in keywords
    outputs = ["color", "depth"] + (["normal", "instance_id", "primitive_id"] if pipeline else [])
    command = command_outputs(tmp_path, scene, keywords, ids=pipeline, normals=pipeline)
    module = zraster.render(scene, W, H, outputs=outputs, **keywords)
    assert list(module) == outputs
    assert_same(module, command, single_instance=scene.startswith("sphere:"))


def test_camera_fit_is_the_command_default(tmp_path):
    scene = zraster.load("sphere:2000")
    command = command_outputs(tmp_path, "sphere:2000", {}, normals=False)
    camera = zraster.Camera.fit(scene, W, H)
    module = zraster.Renderer(W, H).render(scene, camera,
                                            outputs=("color", "depth", "instance_id",
                                                     "primitive_id"))
    assert_same(module, command, single_instance=True)


def test_camera_orbit_is_the_command_orbit(tmp_path):
    scene = zraster.load("builtin:cube")
    command = command_outputs(tmp_path, "builtin:cube", {"orbit": (-40.0, 25.0, 2.5)},
                              normals=False, ids=False)
    camera = zraster.Camera.orbit(scene, -40.0, 25.0, W, H, distance=2.5)
    module = zraster.Renderer(W, H).render(scene, camera)
    assert_same(module, command, single_instance=False)


def write_obj(path, positions, normals, indices):
    with open(path, "w") as f:
        for p in positions:
            f.write("v %r %r %r\n" % tuple(float(x) for x in p))
        for n in normals:
            f.write("vn %r %r %r\n" % tuple(float(x) for x in n))
        for t in indices + 1:
            f.write("f %d//%d %d//%d %d//%d\n" % (t[0], t[0], t[1], t[1], t[2], t[2]))


def test_numpy_mesh_matches_the_command_on_the_same_obj(tmp_path):
    rng = np.random.default_rng(7)
    sphere = zraster.Mesh.uv_sphere(1.0, 12, 24)
    positions = sphere.positions + rng.normal(0, 0.02, sphere.positions.shape).astype(np.float32)
    normals = sphere.normals
    indices = sphere.indices.astype(np.int64)
    write_obj(tmp_path / "m.obj", positions, normals, indices)
    command = command_outputs(tmp_path, tmp_path / "m.obj", {"shading": "phong"})
    mesh = zraster.Mesh(positions, indices, normals=normals)
    module = zraster.Renderer(W, H).render(
        zraster.Scene([mesh]), outputs=("color", "depth", "normal", "instance_id",
                                         "primitive_id"), shading="phong")
    assert_same(module, command, single_instance=True)


def test_shared_bunny_matches_the_command(tmp_path):
    bunny = shared_mesh("obj/bunny.obj")
    command = command_outputs(tmp_path, bunny, {})
    module = zraster.render(bunny, W, H, outputs=("color", "depth", "normal", "instance_id",
                                                  "primitive_id"))
    assert_same(module, command, single_instance=True)


def test_in_process_loading_gives_the_same_scene(tmp_path):
    bunny = shared_mesh("obj/bunny-small.obj")
    a = zraster.render(bunny, W, H, isolation="worker")
    b = zraster.render(bunny, W, H, isolation="in-process")
    np.testing.assert_array_equal(a["color"], b["color"])
