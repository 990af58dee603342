"""Bad input raises InputError (a ValueError) or TypeError naming the argument and the cause."""

import warnings

import numpy as np
import pytest

import zraster

TRIANGLE = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0]], dtype=np.float32)
FACES = np.array([[0, 1, 2]], dtype=np.uint32)


def raises(kind, *fragments):
    """pytest.raises, checking that the message holds every fragment."""

    class Check:
        def __enter__(self):
            self.context = pytest.raises(kind)
            self.info = self.context.__enter__()
            return self.info

        def __exit__(self, *exc):
            suppressed = self.context.__exit__(*exc)
            message = str(self.info.value)
            for fragment in fragments:
                assert fragment in message, f"{fragment!r} not in {message!r}"
            return suppressed

    return Check()


def test_input_error_is_a_value_error_with_its_parts():
    assert issubclass(zraster.InputError, ValueError)
    with raises(zraster.InputError) as info:
        zraster.Mesh(TRIANGLE, [[0, 1, 5]])
    assert info.value.source == "indices"
    assert "out of range" in info.value.cause


@pytest.mark.parametrize("positions,kind,fragments", [
    (np.zeros((3, 2), np.float32), zraster.InputError, ("positions", "shape (N, 3)", "(3, 2)")),
    (np.zeros(9, np.float32), zraster.InputError, ("positions", "shape", "(9,)")),
    (np.zeros((3, 3), np.complex64), TypeError, ("positions", "complex64")),
    (np.zeros((3, 3), bool), TypeError, ("positions", "bool")),
    ("not an array", TypeError, ("positions", "str")),
    (None, TypeError, ("positions", "NoneType")),
    ([[0, 0, 0], [1, 0]], zraster.InputError, ("positions",)),
    (np.array([[0, 0, 0], [1, np.nan, 0], [0, 1, 0]]), zraster.InputError,
     ("positions", "row 1", "non-finite")),
    (np.array([[0, 0, 0], [1, 0, 0], [0, np.inf, 0]], np.float32), zraster.InputError,
     ("positions", "row 2", "non-finite")),
])
def test_bad_positions(positions, kind, fragments):
    with raises(kind, *fragments):
        zraster.Mesh(positions, FACES)


@pytest.mark.parametrize("indices,kind,fragments", [
    ([[0, 1, 3]], zraster.InputError, ("indices", "index 3", "out of range for 3 positions")),
    (np.array([[0, -1, 2]], np.int32), zraster.InputError, ("indices", "index -1", "element 1")),
    (np.array([0, 1], np.uint32), zraster.InputError, ("indices", "(3M,)", "(2,)")),
    (np.zeros((1, 4), np.uint32), zraster.InputError, ("indices", "(M, 3)", "(1, 4)")),
    (np.array([[0.0, 1.0, 2.0]]), TypeError, ("indices", "integer", "float64")),
    (2.5, TypeError, ("indices",)),
])
def test_bad_indices(indices, kind, fragments):
    with raises(kind, *fragments):
        zraster.Mesh(TRIANGLE, indices)


def test_bad_attributes_and_color():
    with raises(zraster.InputError, "normals", "2 rows for 3 positions"):
        zraster.Mesh(TRIANGLE, FACES, normals=np.zeros((2, 3)))
    with raises(zraster.InputError, "uvs", "shape (N, 2)"):
        zraster.Mesh(TRIANGLE, FACES, uvs=np.zeros((3, 3)))
    with raises(zraster.InputError, "normals", "non-finite"):
        zraster.Mesh(TRIANGLE, FACES, normals=np.full((3, 3), np.nan))
    with raises(zraster.InputError, "color", "0..1"):
        zraster.Mesh(TRIANGLE, FACES, color=(1.5, 0, 0))
    with raises(TypeError, "color", "3 or 4 numbers"):
        zraster.Mesh(TRIANGLE, FACES, color=(1, 0))


def test_bad_scene_items():
    mesh = zraster.Mesh(TRIANGLE, FACES)
    with raises(TypeError, "items[1]", "Mesh", "int"):
        zraster.Scene([mesh, 3])
    with raises(zraster.InputError, "items[0] transform", "4x4", "(3, 3)"):
        zraster.Scene([(mesh, np.eye(3))])
    with raises(zraster.InputError, "items[0] transform", "not finite"):
        zraster.Scene([(mesh, np.full((4, 4), np.nan))])
    with raises(TypeError, "scene", "Scene or zraster.Mesh", "str"):
        zraster.Renderer(8, 8).render("builtin:cube")


@pytest.mark.parametrize("width,height,fragment", [(0, 10, "width"), (10, -3, "height"),
                                                   (100000, 10, "width")])
def test_bad_sizes(width, height, fragment):
    with raises(zraster.InputError, fragment, "must be in 1..16384"):
        zraster.Renderer(width, height)
    with raises(zraster.InputError, fragment):
        zraster.Camera.from_intrinsics(100, 100, 5, 5, width, height, 0.1, 10)


def test_bad_renderer_arguments():
    with raises(TypeError, "width", "integer", "float"):
        zraster.Renderer(10.5, 10)
    with raises(zraster.InputError, "threads", "must be in 0.."):
        zraster.Renderer(10, 10, threads=-1)
    with raises(zraster.InputError, "more than max_pixels 50"):
        zraster.Renderer(10, 10, max_pixels=50)
    # Integers past any C++ type are range errors naming the argument, not failed conversions.
    with raises(zraster.InputError, "width", "must be in 1..16384", str(2**64)):
        zraster.Renderer(2**64, 1)
    with raises(zraster.InputError, "max_pixels", str(-2**70)):
        zraster.Renderer(10, 10, max_pixels=-2**70)


def test_bad_load_budgets():
    for name, value in (("max_instances", -1), ("max_instances", 2**70), ("max_triangles", 0),
                        ("max_texture_side", 2**63), ("max_texture_bytes", -5),
                        ("max_geometry_bytes", 0), ("max_triangulation_work", 2**41),
                        ("max_materials", 0), ("max_materials", 2**40)):
        with raises(zraster.InputError, name, "must be in", str(value)):
            zraster.load("builtin:cube", **{name: value})
    with raises(TypeError, "max_texture_side", "integer", "float"):
        zraster.load("builtin:cube", max_texture_side=float("nan"))


@pytest.mark.parametrize("arguments,fragments", [
    ((np.nan, 100, 5, 5), ("fx", "finite")),
    ((100, 0, 5, 5), ("fy",)),
    ((100, 100, np.nan, 5), ("cx", "finite")),
    ((100, 100, 5, np.inf), ("cy", "finite")),
])
def test_bad_intrinsics(arguments, fragments):
    with raises(zraster.InputError, *fragments):
        zraster.Camera.from_intrinsics(*arguments, 10, 10, 0.1, 10)


def test_bad_cameras():
    with raises(zraster.InputError, "near", "far"):
        zraster.Camera.from_intrinsics(100, 100, 5, 5, 10, 10, 1.0, 0.5)
    with raises(zraster.InputError, "pose"):
        zraster.Camera.from_intrinsics(100, 100, 5, 5, 10, 10, 0.1, 10, pose=np.zeros((4, 4)))
    with raises(zraster.InputError, "convention", "'opencv' or 'opengl'"):
        zraster.Camera.from_intrinsics(100, 100, 5, 5, 10, 10, 0.1, 10, convention="ros")
    with raises(TypeError, "fx", "number", "str"):
        zraster.Camera.from_intrinsics("100", 100, 5, 5, 10, 10, 0.1, 10)
    with raises(zraster.InputError, "eye", "not finite"):
        zraster.Camera.look_at((np.nan, 0, 0), (0, 0, 0))
    with raises(zraster.InputError, "eye and target coincide"):
        zraster.Camera.look_at((1, 0, 0), (1, 0, 0))
    with raises(zraster.InputError, "fovy"):
        zraster.Camera.look_at((0, 0, 5), (0, 0, 0), fovy=0)
    with raises(zraster.InputError, "distance", "positive"):
        zraster.Camera.orbit(zraster.load("builtin:cube"), 0, 0, 10, 10, distance=0)
    with raises(zraster.InputError, "intrinsics", "160x120"):
        camera = zraster.Camera.from_intrinsics(100, 100, 5, 5, 160, 120, 0.1, 10)
        zraster.Renderer(80, 60).render(zraster.load("builtin:cube"), camera)


def test_bad_files():
    with raises(zraster.InputError, "/no/such/file.obj") as info:
        zraster.load("/no/such/file.obj")
    assert info.value.source == "/no/such/file.obj"
    with raises(zraster.InputError, "isolation", "'worker' or 'in-process'"):
        zraster.load("builtin:cube", isolation="thread")
    with raises(zraster.InputError, "sphere:x"):
        zraster.load("sphere:x")
    with raises(TypeError, "path", "int"):
        zraster.load(42)
    # A name that is not UTF-8 is a path like any other (os.fsencode's bytes), not a conversion
    # error.
    with raises(zraster.InputError, "file not found") as info:
        zraster.load("/no/such/\udcff.obj")
    assert info.value.source == "/no/such/\udcff.obj"


def test_huge_broadcast_arrays_are_refused_before_any_copy():
    # A few bytes each as numpy views; copied, 36 GB and 11 GiB.
    indices = np.broadcast_to(np.uint32(0), (3 * 10**9,))
    with raises(zraster.LimitExceeded, "indices", "1000000000 triangles, more than") as info:
        zraster.Mesh(TRIANGLE, indices)
    assert info.value.limit == "max_triangles"
    positions = np.broadcast_to(np.float32(0), (10**9, 3))
    with raises(zraster.LimitExceeded, "positions", "1000000000 rows, more than") as info:
        zraster.Mesh(positions, FACES)
    assert info.value.limit == "max_vertices"


# Ten levels of two children each above a node placing one triangle: 1024 placements.
SHARED_NODES_GLTF = (
    '{"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[10]}],'
    '"meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],'
    '"accessors":[{"bufferView":0,"componentType":5126,"count":3,"type":"VEC3",'
    '"min":[0,0,0],"max":[1,1,0]}],"bufferViews":[{"buffer":0,"byteLength":36}],'
    '"buffers":[{"uri":"data:application/octet-stream;base64,'
    'AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36}],"nodes":['
    + '{"mesh":0},'
    + ",".join('{"children":[%d,%d]}' % (k, k) for k in range(10))
    + "]}"
)


@pytest.mark.parametrize("isolation", ["worker", "in-process"])
def test_load_budgets_raise_limit_exceeded(tmp_path, isolation):
    assert issubclass(zraster.LimitExceeded, zraster.InputError)
    path = tmp_path / "shared.gltf"
    path.write_text(SHARED_NODES_GLTF)
    with raises(zraster.LimitExceeded, "shared.gltf", "more than 1000 meshes") as info:
        zraster.load(path, isolation=isolation, max_instances=1000)
    assert info.value.limit == "max_instances"
    assert info.value.source == str(path)
    obj = tmp_path / "two.obj"
    obj.write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n")
    with raises(zraster.LimitExceeded, "too many triangles (2, limit 1)") as info:
        zraster.load(obj, isolation=isolation, max_triangles=1)
    assert info.value.limit == "max_triangles"
    ply = tmp_path / "two.ply"
    ply.write_text("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\n"
                   "property float y\nproperty float z\nelement face 2\n"
                   "property list uchar int vertex_indices\nend_header\n"
                   "0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n")
    with raises(zraster.LimitExceeded, "too many triangles (2, limit 1)") as info:
        zraster.load(ply, isolation=isolation, max_triangles=1)
    assert info.value.limit == "max_triangles"
    pentagon = tmp_path / "pentagon.obj"
    pentagon.write_text("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0 0\nf 1 2 3 4 5\n")
    with raises(zraster.LimitExceeded, "line 6: a polygon of 5 corners") as info:
        zraster.load(pentagon, isolation=isolation, max_triangulation_work=24)
    assert info.value.limit == "max_triangulation_work"
    (tmp_path / "m.mtl").write_text("newmtl a\nKd 1 0 0\nnewmtl b\nKd 0 1 0\n")
    materials = tmp_path / "materials.obj"
    materials.write_text("mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n")
    assert len(zraster.load(materials, isolation=isolation, max_materials=2).materials) >= 2
    with raises(zraster.LimitExceeded, "define 2 materials, more than max_materials (1)") as info:
        zraster.load(materials, isolation=isolation, max_materials=1)
    assert info.value.limit == "max_materials"
    with raises(zraster.LimitExceeded, "more than max_geometry_bytes (100 bytes)") as info:
        zraster.load(path, isolation=isolation, max_geometry_bytes=100)
    assert info.value.limit == "max_geometry_bytes"
    # A size as the command writes it, as Renderer's max_frame_bytes takes it.
    with raises(zraster.LimitExceeded, "more than max_geometry_bytes (1024 bytes)") as info:
        zraster.load(path, isolation=isolation, max_geometry_bytes="1K")
    assert zraster.load(path, isolation=isolation, max_geometry_bytes="1G").triangle_count == 1024
    with raises(zraster.InputError, "max_geometry_bytes", "expected a size in bytes like 4G"):
        zraster.load(path, isolation=isolation, max_geometry_bytes="lots")


@pytest.fixture(scope="module")
def cube():
    return zraster.load("builtin:cube")


@pytest.mark.parametrize("keywords, limit, fragment", [
    (dict(visibility="bsp", max_bsp_polygons=3), "max_bsp_polygons",
     "BSP tree: 12 input triangles, more than the budget of 3 polygons"),
    (dict(visibility="painter", max_painter_comparisons=3), "max_painter_comparisons",
     "more than 3 polygon comparisons"),
    (dict(visibility="abuffer", max_abuffer_fragments=10), "max_abuffer_fragments", "A-buffer"),
    (dict(max_frame_bytes=10), "max_frame_bytes", "more than"),
])
def test_render_budgets_raise_limit_exceeded(cube, keywords, limit, fragment):
    with raises(zraster.LimitExceeded, "builtin:cube", fragment) as info:
        zraster.Renderer(64, 64).render(cube, **keywords)
    assert info.value.limit == limit


def test_bad_outputs(cube):
    r = zraster.Renderer(16, 16)
    with raises(zraster.InputError, "outputs", "unknown output 'colour'", "expected color"):
        r.render(cube, outputs=("colour",))
    with raises(zraster.InputError, "outputs", "no output"):
        r.render(cube, outputs=())
    with raises(TypeError, "outputs", "int"):
        r.render(cube, outputs=3)
    with raises(zraster.InputError, "outputs", "'color' given twice: give it once"):
        r.render(cube, outputs=("color", "depth", "color"))


@pytest.mark.parametrize("keywords,kind,fragments", [
    ({"shadnig": "flat"}, TypeError, ("unexpected keyword argument 'shadnig'",)),
    ({"size": "8x8"}, TypeError, ("'size'", "Renderer(width, height")),
    ({"help": True}, TypeError, ("'help'",)),
    ({"output": "x.png"}, TypeError, ("'output'",)),
    ({"shading": "phon"}, zraster.InputError, ("shading", "phon")),
    ({"cull": 3}, zraster.InputError, ("cull",)),
    ({"light_dir": (0, 0, 0)}, zraster.InputError, ("light_dir", "non-zero")),
    ({"light_dir": (1, 2)}, zraster.InputError, ("light_dir", "X,Y,Z")),
    ({"eye": (np.nan, 0, 0)}, zraster.InputError, ("eye", "finite")),
    ({"orbit": (0, 0, -1)}, zraster.InputError, ("orbit", "distance must be in (0, 1e6]")),
    ({"orbit": (0, 0, 2), "eye": (1, 1, 1)}, zraster.InputError, ("orbit", "eye")),
    ({"background": (0, 0, 300)}, zraster.InputError, ("background", "0..255")),
    ({"clip_plane": (0, 0, 0, 1)}, zraster.InputError, ("clip_plane", "zero")),
    ({"aa": 32}, zraster.InputError, ("aa", "1..16")),
    ({"msaa": True, "aa": 3}, zraster.InputError, ("aa", "1, 2, 4 or 8")),
    ({"wireframe": True, "hidden_line": True}, zraster.InputError, ("wireframe", "not both")),
    ({"visibility": "raytrace"}, zraster.InputError, ("visibility", "raytrace")),
    ({"reversed_z": "yes"}, TypeError, ("reversed_z", "True or False", "str")),
    ({"fovy": None}, TypeError, ("fovy",)),
    ({"fovy": (30, 40)}, zraster.InputError, ("fovy",)),
    ({"eye": [[1, 2], 3]}, TypeError, ("eye", "nested")),
    # Keywords that would change nothing in the frame the others ask for.
    ({"visibility": "bsp", "depth_compare": "less"}, zraster.InputError,
     ("depth_compare: sets the z-buffer's depth test, which visibility bsp does not use",)),
    ({"edge_color": (255, 0, 0)}, zraster.InputError, ("edge_color", "wireframe or hidden_line")),
    ({"shading": "unlit", "point_light": (0, 1, 0)}, zraster.InputError,
     ("point_light: lights nothing with shading unlit",)),
])
def test_bad_render_options(cube, keywords, kind, fragments):
    with raises(kind, *fragments):
        zraster.Renderer(16, 16).render(cube, **keywords)


def test_a_compare_that_passes_nothing_warns(cube):
    with pytest.warns(UserWarning, match="depth_compare greater passes nothing nearer than the "
                                         "cleared depth buffer"):
        out = zraster.Renderer(16, 16).render(cube, outputs=("color",), depth_compare="greater")
    assert (out["color"] == out["color"][0, 0]).all()  # the background only


def test_settings_that_change_nothing_in_the_scene_warn():
    renderer = zraster.Renderer(8, 8)
    cube = zraster.load("builtin:cube")
    with pytest.warns(UserWarning, match="^texture_filter: builtin:cube has no textured surface"):
        renderer.render(cube, texture_filter="nearest")
    with pytest.warns(UserWarning, match="^alpha_mode opaque: every surface of builtin:cube is "
                                         "opaque already"):
        renderer.render(cube, alpha_mode="opaque")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        renderer.render(zraster.load("builtin:default"), texture_filter="nearest")


def test_a_scene_of_triangles_without_area_is_refused():
    flat = zraster.Mesh(np.array([[0, 0, 0], [1, 1, 1], [2, 2, 2]], np.float32),
                        np.array([[0, 1, 2]], np.uint32))
    cause = ("scene: every one of its 2 triangles has zero area as placed (repeated or collinear "
             "corners, or a transform that flattens them): nothing to draw")
    with raises(zraster.InputError, cause):
        zraster.Renderer(8, 8).render(zraster.Scene([flat, flat]))
    empty = zraster.Mesh(np.zeros((0, 3), np.float32), np.zeros((0, 3), np.uint32))
    with raises(zraster.InputError, "scene: no triangles: nothing to draw"):
        zraster.Renderer(8, 8).render(empty)
    with raises(zraster.InputError, "scene: no triangles: nothing to draw"):
        zraster.Renderer(8, 8).render(zraster.Scene([]))
    with raises(zraster.InputError, "path: contains a NUL character"):
        zraster.load("builtin:cube\x00junk")
    # One triangle with area is enough to draw.
    out = zraster.Renderer(8, 8).render(zraster.Scene([flat, zraster.Mesh.box()]))
    assert out["color"].shape == (8, 8, 3)


@pytest.mark.parametrize("call,message", [
    (lambda: zraster.Camera.look_at((0, 0, 5), (0, 0, 0), width=8),
     "look_at() got an unexpected keyword argument 'width' (it takes eye, target, up, fovy, near, "
     "far, reversed_z, infinite_far, ortho_height)"),
    (lambda: zraster.Camera.look_at((0, 0, 5), (0, 0, 0), reversed_z="yes"),
     "look_at(): reversed_z must be bool, not str"),
    (lambda: zraster.Mesh(np.zeros((3, 3), np.float32), np.array([[0, 1, 2]]), colour=1),
     "Mesh() got an unexpected keyword argument 'colour' (it takes positions, indices, normals, "
     "uvs, color, name, texture, alpha_mode, alpha_cutoff, colors, double_sided)"),
    (lambda: zraster.Mesh(), "Mesh() missing argument 'positions'"),
    (lambda: zraster.load("builtin:cube", max_tris=3),
     "load() got an unexpected keyword argument 'max_tris'"),
    (lambda: zraster.Renderer(8, 8, 3, 4, 5), "Renderer() takes at most 4 arguments (width, "
                                             "height, threads, max_pixels), got 5"),
    (lambda: zraster.Scene([], extra=1), "Scene() got an unexpected keyword argument 'extra'"),
])
def test_calls_matching_no_signature_are_one_line_type_errors(call, message):
    with pytest.raises(TypeError) as caught:
        call()
    assert str(caught.value).startswith(message), str(caught.value)
    assert "\n" not in str(caught.value)


def test_camera_and_placement_keywords_conflict(cube):
    camera = zraster.Camera.fit(cube, 16, 16)
    with raises(zraster.InputError, "eye", "camera= is given"):
        zraster.Renderer(16, 16).render(cube, camera, eye=(1, 2, 3))
    with raises(TypeError, "camera", "Camera or None", "tuple"):
        zraster.Renderer(16, 16).render(cube, (1, 2, 3))


def test_errors_do_not_break_the_renderer(cube):
    r = zraster.Renderer(16, 16)
    good = r.render(cube)["color"]
    with raises(zraster.InputError):
        r.render(cube, shading="nope")
    np.testing.assert_array_equal(r.render(cube)["color"], good)


def test_load_warnings_are_python_warnings(tmp_path):
    (tmp_path / "quad.mtl").write_text("newmtl skin\nKd 1 1 1\nmap_Kd missing.png\n")
    model = tmp_path / "quad.obj"
    model.write_text("mtllib quad.mtl\nusemtl skin\n"
                     "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                     "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")
    with pytest.warns(zraster.LoadWarning) as caught:
        scene = zraster.load(model)
    assert issubclass(zraster.LoadWarning, UserWarning)
    messages = [str(w.message) for w in caught]
    assert len(messages) == len(scene.warnings) >= 1
    assert any("missing.png" in m for m in messages), messages
    for message, kept in zip(messages, scene.warnings):
        assert message.startswith(str(model)) and message.endswith(kept)
    # The scene still renders (the texture left out).
    out = zraster.Renderer(32, 32, threads=1).render(scene, outputs=("depth",))
    assert (out["depth"] < 1).any()
    # A clean file warns about nothing.
    (tmp_path / "plain.obj").write_text("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert zraster.load(tmp_path / "plain.obj").warnings == []
