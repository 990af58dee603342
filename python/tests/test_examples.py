"""The example scripts of examples/python run and write what they say."""

import os
import pathlib
import subprocess
import sys

import numpy as np

EXAMPLES = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python"


def run(script, *args, cwd):
    env = dict(os.environ)
    result = subprocess.run([sys.executable, str(EXAMPLES / script), *map(str, args)], cwd=cwd,
                            env=env, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return result.stdout


def test_render_mesh(tmp_path):
    run("render_mesh.py", "sphere:2000", tmp_path / "out", cwd=tmp_path)
    color = np.load(tmp_path / "out-color.npy")
    depth = np.load(tmp_path / "out-depth.npy")
    assert color.ndim == 3 and color.shape[2] == 3 and depth.shape == color.shape[:2]
    assert (depth < 1.0).any() and (depth == 1.0).any()


def test_depth_camera(tmp_path):
    out = run("depth_camera.py", "builtin:default", tmp_path / "dc", cwd=tmp_path)
    z = np.load(tmp_path / "dc-z.npy")
    measured = np.load(tmp_path / "dc-kinect-z.npy")
    points = np.load(tmp_path / "dc-points.npy")
    assert z.shape == (480, 640) and measured.shape == z.shape
    assert ((measured > 0) <= (z > 0)).all() and (measured > 0).sum() > 1000
    assert points.shape == (int((measured > 0).sum()), 3)
    assert f"{len(points)} points" in out
