"""The package: version, docstrings, type stubs and the command's options as keywords."""

import ast
import pathlib
import re
import subprocess

import zraster
from conftest import run_cli

STUBS = pathlib.Path(zraster.__file__).with_name("__init__.pyi")


def test_version_matches_the_command():
    assert re.fullmatch(r"\d+\.\d+\.\d+", zraster.__version__)
    assert run_cli("--version").stdout.strip() == f"zraster {zraster.__version__}"


def test_every_render_flag_of_the_command_is_a_keyword():
    help_text = run_cli("render", "--help").stdout
    flags = set(re.findall(r"^\s+(?:-\w,\s*)?--([a-z][a-z0-9-]*)", help_text, re.M))
    # The Renderer's arguments, and the command's file outputs and printing.
    not_keywords = {"help", "size", "threads", "max-pixels", "output", "depth-out",
                    "normal-out", "id-out", "stats", "load-in-process",
                    "allow-outside-references", "max-instances", "max-triangles", "version",
                    # The depth camera's files and flags: the outputs argument, Camera.from_intrinsics
                    # and the sensor are the module's own ways to them.
                    "z-out", "range-out", "points-out", "camera-json", "intrinsics",
                    # A file for the scene's cell graph, which the module does not bind.
                    "pvs"}
    flags = {f for f in flags if not f.startswith("sensor")}
    expected = {f.replace("-", "_") for f in flags - not_keywords}
    assert expected == set(zraster.RENDER_OPTIONS)


def test_help_explains_every_option_and_output():
    doc = zraster.Renderer.render.__doc__
    for name in zraster.RENDER_OPTIONS:
        assert f"    {name}: " in doc, name
    for output in ("color", "rgba", "depth", "normal", "instance_id", "primitive_id"):
        assert f"  {output} " in doc, output
    for thing in (zraster.Mesh, zraster.Scene, zraster.Camera, zraster.Renderer, zraster.load,
                  zraster.render, zraster.Camera.from_intrinsics, zraster.Camera.fit,
                  zraster.Camera.orbit, zraster.Camera.look_at, zraster.InputError):
        assert thing.__doc__ and len(thing.__doc__) > 40, thing


def test_stubs_name_every_public_name_and_keyword():
    tree = ast.parse(STUBS.read_text())
    names = {n.name for n in tree.body if isinstance(n, (ast.ClassDef, ast.FunctionDef))}
    names |= {t.id for n in tree.body if isinstance(n, ast.AnnAssign) for t in [n.target]}
    assert set(zraster.__all__) <= names
    renderer = next(n for n in tree.body if isinstance(n, ast.ClassDef) and n.name == "Renderer")
    render = next(n for n in renderer.body if isinstance(n, ast.FunctionDef) and n.name == "render")
    keywords = [a.arg for a in render.args.kwonlyargs]
    assert keywords == list(zraster.RENDER_OPTIONS)


def test_import_with_debians_python_from_the_build_tree():
    import sys
    result = subprocess.run([sys.executable, "-c", "import zraster; print(zraster.__version__)"],
                            capture_output=True, text=True)
    assert result.returncode == 0 and result.stdout.strip() == zraster.__version__
