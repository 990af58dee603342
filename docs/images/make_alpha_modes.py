"""Writes alpha-modes.gltf: four panels with the same texture (its alpha falls from 1 at the top
to 0 at the bottom) in front of a checkerboard wall, one per glTF alpha mode: OPAQUE, BLEND,
MASK with alphaCutoff 0.25 and MASK with alphaCutoff 0.75 (after Khronos' AlphaBlendModeTest).

    python3 docs/images/make_alpha_modes.py docs/images/alpha-modes.gltf
"""
import base64
import json
import struct
import sys
import zlib


def png(width, height, pixel):
    """An 8-bit RGBA PNG of pixel(x, y) -> (r, g, b, a)."""
    rows = b"".join(b"\0" + bytes(c for x in range(width) for c in pixel(x, y))
                    for y in range(height))

    def chunk(kind, data):
        return (struct.pack(">I", len(data)) + kind + data +
                struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff))

    header = struct.pack(">IIBBBBB", width, height, 8, 6, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def panel_texel(x, y):
    stripe = (x // 8) % 2 == 0
    alpha = round(255 * (1 - y / 63))
    return (40, 170, 90, alpha) if stripe else (240, 200, 60, alpha)


def wall_texel(x, y):
    light = ((x // 16) + (y // 16)) % 2 == 0
    return (220, 220, 220, 255) if light else (60, 60, 70, 255)


def data_uri(data, kind):
    return f"data:{kind};base64," + base64.b64encode(data).decode()


def main():
    positions, uvs, indices, meshes = [], [], [], []

    # (Texture coordinates repeat: the panels stop short of v = 0 and 1, where filtering would
    # reach the opposite edge.)
    def quad(x0, y0, x1, y1, z, material, u1=1.0, v0=0.02, v1=0.98):
        first = len(positions)
        positions.extend([(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)])
        uvs.extend([(0, v1), (u1, v1), (u1, v0), (0, v0)])
        start = len(indices)
        indices.extend([first, first + 1, first + 2, first, first + 2, first + 3])
        meshes.append((start, material))

    quad(-2.3, -0.9, 2.3, 0.9, -0.4, 0, u1=4.6 / 1.8 * 2, v0=0.0, v1=2.0)  # the wall
    for k in range(4):
        x = -1.65 + 1.1 * k
        quad(x - 0.45, -0.7, x + 0.45, 0.7, 0.0, 1 + k)
    vertex_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    uv_bytes = b"".join(struct.pack("<2f", *t) for t in uvs)
    index_bytes = b"".join(struct.pack("<I", i) for i in indices)
    buffer = vertex_bytes + uv_bytes + index_bytes
    views = [
        {"buffer": 0, "byteOffset": 0, "byteLength": len(vertex_bytes)},
        {"buffer": 0, "byteOffset": len(vertex_bytes), "byteLength": len(uv_bytes)},
        {"buffer": 0, "byteOffset": len(vertex_bytes) + len(uv_bytes),
         "byteLength": len(index_bytes)},
    ]
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": len(positions), "type": "VEC3",
         "min": [min(p[i] for p in positions) for i in range(3)],
         "max": [max(p[i] for p in positions) for i in range(3)]},
        {"bufferView": 1, "componentType": 5126, "count": len(uvs), "type": "VEC2"},
    ]
    gltf_meshes = []
    for start, material in meshes:
        accessors.append({"bufferView": 2, "byteOffset": 4 * start, "componentType": 5125,
                          "count": 6, "type": "SCALAR"})
        gltf_meshes.append({"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1},
                                            "indices": len(accessors) - 1,
                                            "material": material}]})
    panel = {"pbrMetallicRoughness": {"baseColorTexture": {"index": 1}}}
    materials = [
        {"name": "wall", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
        dict(panel, name="opaque", alphaMode="OPAQUE"),
        dict(panel, name="blend", alphaMode="BLEND"),
        dict(panel, name="mask 0.25", alphaMode="MASK", alphaCutoff=0.25),
        dict(panel, name="mask 0.75", alphaMode="MASK", alphaCutoff=0.75),
    ]
    gltf = {
        "asset": {"version": "2.0", "generator": "zraster docs/images/make_alpha_modes.py"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(gltf_meshes)))}],
        "nodes": [{"mesh": i} for i in range(len(gltf_meshes))],
        "meshes": gltf_meshes,
        "materials": materials,
        "textures": [{"source": 0, "sampler": 0}, {"source": 1, "sampler": 0}],
        "samplers": [{"wrapS": 10497, "wrapT": 10497}],
        "images": [{"uri": data_uri(png(32, 32, wall_texel), "image/png")},
                   {"uri": data_uri(png(64, 64, panel_texel), "image/png")}],
        "buffers": [{"byteLength": len(buffer),
                     "uri": data_uri(buffer, "application/octet-stream")}],
        "bufferViews": views,
        "accessors": accessors,
    }
    with open(sys.argv[1], "w") as out:
        json.dump(gltf, out, indent=1)
        out.write("\n")


if __name__ == "__main__":
    main()
