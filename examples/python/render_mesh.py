#!/usr/bin/env python3
"""Renders a mesh file (or a built-in scene) to color and depth with the zraster module.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/render_mesh.py [SCENE] [OUT_PREFIX]

SCENE is a mesh file or a procedural spec (default: a numpy sphere next to a box, built here);
writes OUT_PREFIX-color.npy, OUT_PREFIX-depth.npy and OUT_PREFIX-color.png.
"""

import struct
import sys
import zlib

import numpy as np

import zraster


def numpy_scene():
    """A scene from numpy arrays: a UV sphere and a box, placed by 4x4 transforms."""
    sphere = zraster.Mesh.uv_sphere(1.0, 48, 96, color=(0.9, 0.4, 0.2))
    box = zraster.Mesh(zraster.Mesh.box().positions * 1.5, zraster.Mesh.box().indices,
                       color=(0.3, 0.6, 0.9))
    right = np.eye(4)
    right[0, 3] = 2.2
    return zraster.Scene([sphere, (box, right)])


def write_png(path, rgb):
    """An 8-bit RGB PNG with the standard library only (filter 0 on every row)."""
    height, width, _ = rgb.shape
    rows = b"".join(b"\x00" + np.ascontiguousarray(row).tobytes() for row in rgb)

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n")
        f.write(chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)))
        f.write(chunk(b"IDAT", zlib.compress(rows, 6)))
        f.write(chunk(b"IEND", b""))


def main():
    scene = zraster.load(sys.argv[1]) if len(sys.argv) > 1 else numpy_scene()
    prefix = sys.argv[2] if len(sys.argv) > 2 else "zraster"
    renderer = zraster.Renderer(640, 480)
    camera = zraster.Camera.fit(scene, 640, 480)  # the command's default framing
    out = renderer.render(scene, camera, outputs=("color", "depth"), shading="phong")
    np.save(f"{prefix}-color.npy", out["color"])
    np.save(f"{prefix}-depth.npy", out["depth"])
    drawn = out["depth"] < 1.0
    print(f"{scene}: {drawn.mean():.1%} of the pixels drawn, "
          f"depth {out['depth'][drawn].min():.4f}..{out['depth'][drawn].max():.4f}, "
          f"{renderer.stats['total_ms']:.1f} ms")
    write_png(f"{prefix}-color.png", out["color"])


if __name__ == "__main__":
    main()
