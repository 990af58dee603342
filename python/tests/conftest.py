"""Shared helpers of the zraster Python tests: the built command, file readers, shared data.

ctest runs these with PYTHONPATH=build/python, ZRASTER_CLI and ZRASTER_SHARED_DATA set
(python/CMakeLists.txt); run by hand, they fall back to build/ and ../shared/data.
"""

import os
import pathlib
import struct
import subprocess
import zlib

import numpy as np
import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
CLI = pathlib.Path(os.environ.get("ZRASTER_CLI", ROOT / "build" / "zraster"))
SHARED_DATA = pathlib.Path(os.environ.get("ZRASTER_SHARED_DATA", ROOT.parent / "shared" / "data"))


def shared_mesh(relative):
    """A file of ../shared/data/meshes, or a skip saying it is absent."""
    path = SHARED_DATA / "meshes" / relative
    if not path.is_file():
        pytest.skip(f"{path} is absent (the shared data set is not checked out)")
    return path


def run_cli(*args):
    """Runs the built `zraster` command; fails the test with its stderr when it fails."""
    if not CLI.is_file():
        pytest.fail(f"the zraster command {CLI} is not built")
    result = subprocess.run([str(CLI), *map(str, args)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    return result


def read_png(path):
    """Decodes the PNGs the command writes (8-bit gray/RGB/RGBA or 16-bit gray, not interlaced)
    into an array of shape (H, W, channels) or (H, W)."""
    data = pathlib.Path(path).read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is no PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, color_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    assert interlace == 0
    channels = {0: 1, 2: 3, 6: 4}[color_type]
    bpp = channels * depth // 8
    stride = width * bpp
    raw = zlib.decompress(idat)
    out = np.zeros((height, stride), dtype=np.uint8)
    prev = np.zeros(stride, dtype=np.int32)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = np.frombuffer(raw, np.uint8, stride, y * (stride + 1) + 1).astype(np.int32)
        if kind == 0:
            cur = line
        elif kind == 2:
            cur = (line + prev) & 0xFF
        else:  # Sub, Average, Paeth: byte by byte
            cur = np.zeros(stride, dtype=np.int32)
            for x in range(stride):
                a = cur[x - bpp] if x >= bpp else 0
                b, c = prev[x], (prev[x - bpp] if x >= bpp else 0)
                if kind == 1:
                    pred = a
                elif kind == 3:
                    pred = (a + b) // 2
                else:
                    p = a + b - c
                    pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                    pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
                cur[x] = (line[x] + pred) & 0xFF
        out[y] = cur
        prev = cur
    if depth == 16:
        return out.view(">u2").reshape(height, width).astype(np.uint16)
    return out.reshape(height, width, channels) if channels > 1 else out.reshape(height, width)


def bits(array):
    """The array's bytes as unsigned integers, for bit-exact comparisons of floats."""
    a = np.ascontiguousarray(array)
    return a.view({4: np.uint32, 2: np.uint16, 1: np.uint8}[a.dtype.itemsize])
