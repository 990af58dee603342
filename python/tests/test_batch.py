"""zraster.batch: render_files() here and on a Dask LocalCluster, `python3 -m zraster.batch`.

Every path renders the same files as `zraster batch`, byte for byte; broken files are error
records; a worker killed mid-run loses no file and logs none twice.
"""

import collections
import json
import logging
import math
import os
import pathlib
import signal
import subprocess
import sys
import threading
import time

import pytest

import zraster
import zraster.batch
from conftest import CLI

OPTIONS = {"size": (96, 72), "views": 3, "depth": "npy", "normal": True}
FLAGS = ["--size", "96x72", "--views", "3", "--depth", "npy", "--normal"]


def sphere_obj(path, segments, offset):
    """A UV sphere of 2*segments*(segments-1) triangles, moved by `offset` along x."""
    lines = []
    rings = segments
    for i in range(rings + 1):
        theta = math.pi * i / rings
        for j in range(segments):
            phi = 2 * math.pi * j / segments
            lines.append(f"v {math.sin(theta) * math.cos(phi) + offset:.6f} "
                         f"{math.cos(theta):.6f} {math.sin(theta) * math.sin(phi):.6f}")
    for i in range(rings):
        for j in range(segments):
            a = i * segments + j + 1
            b = i * segments + (j + 1) % segments + 1
            c, d = a + segments, b + segments
            if i > 0:
                lines.append(f"f {a} {b} {d}")
            if i < rings - 1:
                lines.append(f"f {a} {d} {c}")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text("\n".join(lines) + "\n")


def write_collection(root, good=22):
    """`good` meshes in two folders and four broken files; returns the broken ones' names."""
    for i in range(good):
        sphere_obj(root / ("a" if i % 2 else "b") / f"mesh{i:02}.obj", 24 + 4 * i, 0.05 * i)
    broken = {
        "empty.obj": b"",
        "bad_index.obj": b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n",
        "garbage.ply": b"ply\nformat nonsense 7\nend_header\n\x01\x02",
        # A binary STL claiming 1000 triangles, holding one.
        "truncated.stl": b" " * 80 + b"\xe8\x03\x00\x00" + b"\0" * 50,
    }
    for name, data in broken.items():
        (root / "b" / name).write_bytes(data)
    return set(broken)


def outputs(folder):
    """{relative path: bytes} of every output file (not the log, not hidden temporaries)."""
    folder = pathlib.Path(folder)
    return {str(p.relative_to(folder)): p.read_bytes() for p in sorted(folder.rglob("*"))
            if p.is_file() and p.name != "batch.jsonl" and not p.name.startswith(".")}


def log_records(folder):
    return [json.loads(line) for line in (pathlib.Path(folder) / "batch.jsonl").read_text()
            .splitlines()]


def comparable(record, out_dir):
    """A record without its timings, its outputs relative to the output folder."""
    return (record["input"], record["status"], record["error"], record["triangles"],
            [os.path.relpath(p, out_dir) for p in record["outputs"]])


@pytest.fixture(scope="module")
def collection(tmp_path_factory):
    """The meshes, and `zraster batch`'s outputs and log for them."""
    root = tmp_path_factory.mktemp("batch")
    broken = write_collection(root / "in")
    command_out = root / "command"
    result = subprocess.run([str(CLI), "batch", str(root / "in"), "-o", str(command_out),
                             "--progress", "none", *FLAGS], capture_output=True, text=True)
    assert result.returncode == 3, result.stderr  # some files failed, the others rendered
    return root, broken, command_out


def expect_same_as_command(collection, out_dir, records):
    """The outputs and records of `zraster batch` (a file whose worker died after writing its
    outputs is rendered again by the worker that redoes it: the log has no record of it)."""
    root, broken, command_out = collection
    expected = outputs(command_out)
    assert len(expected) == 22 * 3 * 3  # 22 meshes, 3 views, color + depth + normal
    assert outputs(out_dir) == expected
    command_records = {r["input"]: comparable(r, command_out) for r in log_records(command_out)}
    logged = log_records(out_dir)
    counts = collections.Counter(r["input"] for r in logged)
    assert sorted(counts) == sorted(command_records)
    assert set(counts.values()) == {1}, "an input logged more than once"
    assert {r["input"]: comparable(r, out_dir) for r in logged} == command_records
    assert [comparable(r, out_dir) for r in records] == sorted(command_records.values())
    failed = {pathlib.Path(r["input"]).name for r in logged if r["status"] == "error"}
    assert failed == broken
    for record in logged:
        if record["status"] == "error":
            assert record["error"].startswith(record["input"] + ": ")
            assert "\n" not in record["error"]


def test_render_files_here_equals_the_command(collection, tmp_path):
    root = collection[0]
    records = zraster.batch.render_files([root / "in"], tmp_path / "out", jobs=2, **OPTIONS)
    expect_same_as_command(collection, tmp_path / "out", records)
    # A rerun skips every rendered file (and retries the broken ones); force redoes them.
    again = zraster.batch.render_files(root / "in", tmp_path / "out", **OPTIONS)
    assert collections.Counter(r["status"] for r in again) == {"skipped": 22, "error": 4}
    forced = zraster.batch.render_files(str(root / "in"), tmp_path / "out", force=True, **OPTIONS)
    assert collections.Counter(r["status"] for r in forced) == {"ok": 22, "error": 4}
    assert len(log_records(tmp_path / "out")) == 3 * 26


def test_render_files_refuses_bad_options_before_any_work(collection, tmp_path):
    root = collection[0]
    with pytest.raises(TypeError, match="unexpected keyword argument 'colour'"):
        zraster.batch.render_files(root / "in", tmp_path / "out", colour="red")
    with pytest.raises(zraster.InputError) as error:
        zraster.batch.render_files(root / "in", tmp_path / "out", depth="tiff")
    assert error.value.source == "depth"
    with pytest.raises(zraster.InputError, match="views_json"):
        zraster.batch.render_files(root / "in", tmp_path / "out", views=2,
                                   views_json=str(tmp_path / "v.json"))
    with pytest.raises(TypeError, match="size"):
        zraster.batch.render_files(root / "in", tmp_path / "out", size="big")
    with pytest.raises(TypeError, match="inputs"):
        zraster.batch.render_files([root / "in", 7], tmp_path / "out")
    assert not (tmp_path / "out" / "batch.jsonl").exists()


@pytest.fixture(scope="module")
def cluster():
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None,
                                  silence_logs=logging.CRITICAL) as local:
        with distributed.Client(local) as client:
            yield local, client


def test_render_files_on_a_cluster_survives_a_killed_worker(collection, cluster, tmp_path):
    _, client = cluster
    root = collection[0]
    out_dir = tmp_path / "out"
    pids = client.run(os.getpid)
    result = {}

    def render():
        try:
            result["records"] = zraster.batch.render_files(root / "in", out_dir, client=client,
                                                           **OPTIONS)
        except BaseException as error:  # noqa: BLE001: reported by the main thread
            result["error"] = error

    thread = threading.Thread(target=render)
    thread.start()
    # Once the first file is logged, kill a worker that holds tasks: they are redone elsewhere.
    killed = None
    deadline = time.monotonic() + 60
    while killed is None and thread.is_alive() and time.monotonic() < deadline:
        log = out_dir / "batch.jsonl"
        if log.exists() and log.read_text().count("\n") >= 1:
            for address, tasks in client.processing().items():
                if tasks and address in pids:
                    os.kill(pids[address], signal.SIGKILL)
                    killed = address
                    break
        time.sleep(0.002)
    thread.join(120)
    assert not thread.is_alive()
    assert "error" not in result, result.get("error")
    assert killed is not None, "the batch ended before a worker could be killed mid-run"
    expect_same_as_command(collection, out_dir, result["records"])


def test_module_command_line_with_a_scheduler(collection, cluster, tmp_path):
    local, _ = cluster
    root = collection[0]
    env = dict(os.environ)
    run = subprocess.run([sys.executable, "-m", "zraster.batch", "--scheduler",
                          local.scheduler_address, str(root / "in"), "-o", str(tmp_path / "out"),
                          *FLAGS], capture_output=True, text=True, env=env, timeout=300)
    assert run.returncode == 3, run.stderr
    assert "22 ok, 4 failed, 0 skipped" in run.stderr
    expect_same_as_command(collection, tmp_path / "out",
                           sorted(log_records(tmp_path / "out"), key=lambda r: r["input"]))
    usage = subprocess.run([sys.executable, "-m", "zraster.batch", str(root / "in")],
                           capture_output=True, text=True, env=env)
    assert usage.returncode == 2
    assert "--output-dir is required" in usage.stderr
    unreachable = subprocess.run([sys.executable, "-m", "zraster.batch", "--scheduler",
                                  "tcp://127.0.0.1:9", str(root / "in"), "-o",
                                  str(tmp_path / "x")], capture_output=True, text=True, env=env,
                                 timeout=120)
    assert unreachable.returncode == 2
    assert "--scheduler tcp://127.0.0.1:9: cannot connect" in unreachable.stderr
