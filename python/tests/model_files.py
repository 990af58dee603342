"""Model files written from numpy arrays (OBJ + MTL, glTF 2.0 with embedded buffers, PNG), so that
a Mesh built from the same arrays can be compared with what zraster.load() makes of the file.

Values are written exactly: floats with 9 significant digits (float32 round-trips), and the tests
use coordinates that are multiples of powers of two, so that the OBJ reader's 1 - v is exact.
"""

import base64
import json
import struct
import zlib

import numpy as np


def png_bytes(image):
    """An 8-bit RGB or RGBA PNG of an (H, W, 3|4) uint8 array, rows top to bottom."""
    image = np.ascontiguousarray(image, np.uint8)
    height, width, channels = image.shape
    raw = b"".join(b"\0" + image[y].tobytes() for y in range(height))

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))

    header = struct.pack(">IIBBBBB", width, height, 8, {3: 2, 4: 6}[channels], 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw))
            + chunk(b"IEND", b""))


def _number(value):
    return f"{float(np.float32(value)):.9g}"


def _row(prefix, values):
    return prefix + " " + " ".join(_number(v) for v in values) + "\n"


def write_obj(folder, name, objects):
    """Writes NAME.obj and NAME.mtl into `folder`: one OBJ object and material per entry of
    `objects`, a dict with positions, faces, normals, optional uvs, and the material: kd (RGB),
    d (opacity, optional), texture (an image array, written as a PNG beside the file),
    opacity_texture (map_d, likewise), ks and ns. A vertex's position, uv and normal are at the
    same place in their object's lists (each kind counted over the file on its own: objects
    without uvs add none). Returns the OBJ's path."""
    obj = [f"mtllib {name}.mtl\n"]
    mtl = []
    base = uv_base = 1
    for k, o in enumerate(objects):
        material = f"m{k}"
        mtl.append(f"newmtl {material}\n")
        mtl.append(_row("Kd", o["kd"]))
        mtl.append(_row("Ks", o.get("ks", (0.25, 0.25, 0.25))))
        mtl.append(f"Ns {_number(o.get('ns', 32))}\n")
        if "d" in o:
            mtl.append(f"d {_number(o['d'])}\n")
        if o.get("texture") is not None:
            texture_name = f"{name}_{k}.png"
            (folder / texture_name).write_bytes(png_bytes(o["texture"]))
            mtl.append(f"map_Kd {texture_name}\n")
        if o.get("opacity_texture") is not None:
            texture_name = f"{name}_{k}_opacity.png"
            (folder / texture_name).write_bytes(png_bytes(o["opacity_texture"]))
            mtl.append(f"map_d {texture_name}\n")
        obj.append(f"o object{k}\nusemtl {material}\n")
        obj.extend(_row("v", p) for p in o["positions"])
        uvs = o.get("uvs")
        if uvs is not None:
            obj.extend(_row("vt", (u, 1.0 - v)) for u, v in uvs)  # OBJ's v points up
        obj.extend(_row("vn", n) for n in o["normals"])
        for face in np.asarray(o["faces"]).reshape(-1, 3):
            if uvs is not None:
                obj.append("f " + " ".join(f"{int(i) + base}/{int(i) + uv_base}/{int(i) + base}"
                                           for i in face) + "\n")
            else:
                obj.append("f " + " ".join(f"{int(i) + base}//{int(i) + base}" for i in face)
                           + "\n")
        base += len(o["positions"])
        if uvs is not None:
            uv_base += len(uvs)
    (folder / f"{name}.mtl").write_text("".join(mtl))
    path = folder / f"{name}.obj"
    path.write_text("".join(obj))
    return path


def write_gltf(folder, name, objects):
    """Writes NAME.gltf (buffers and images embedded as data URIs) into `folder`: one mesh,
    node and material per entry of `objects`, a dict with positions, faces, normals, optional
    uvs and colors (COLOR_0, RGB or RGBA floats), and the material: color (RGBA baseColorFactor), alpha_mode ("OPAQUE", "MASK",
    "BLEND"), alpha_cutoff, double_sided, texture (an image array, embedded as a PNG). Returns
    the path."""
    blob = bytearray()
    views, accessors, meshes, nodes, materials, images, textures = [], [], [], [], [], [], []

    def add(array, target, kind, component, bounds=False):
        offset = len(blob)
        blob.extend(array.tobytes())
        while len(blob) % 4:
            blob.append(0)
        views.append({"buffer": 0, "byteOffset": offset, "byteLength": array.nbytes,
                      "target": target})
        accessor = {"bufferView": len(views) - 1, "componentType": component,
                    "count": int(array.shape[0]), "type": kind}
        if bounds:  # glTF requires them for positions
            accessor["min"] = [float(v) for v in array.min(axis=0)]
            accessor["max"] = [float(v) for v in array.max(axis=0)]
        accessors.append(accessor)
        return len(accessors) - 1

    for k, o in enumerate(objects):
        attributes = {
            "POSITION": add(np.asarray(o["positions"], np.float32), 34962, "VEC3", 5126, True),
            "NORMAL": add(np.asarray(o["normals"], np.float32), 34962, "VEC3", 5126),
        }
        if o.get("uvs") is not None:
            attributes["TEXCOORD_0"] = add(np.asarray(o["uvs"], np.float32), 34962, "VEC2", 5126)
        if o.get("colors") is not None:
            colors = np.asarray(o["colors"], np.float32)
            attributes["COLOR_0"] = add(colors, 34962, f"VEC{colors.shape[1]}", 5126)
        faces = np.asarray(o["faces"], np.uint32).reshape(-1)
        indices = add(faces.reshape(-1, 1), 34963, "SCALAR", 5125)
        pbr = {"baseColorFactor": [float(c) for c in o["color"]], "metallicFactor": 0.0}
        if o.get("texture") is not None:
            uri = "data:image/png;base64," + base64.b64encode(png_bytes(o["texture"])).decode()
            images.append({"uri": uri})
            textures.append({"source": len(images) - 1})
            pbr["baseColorTexture"] = {"index": len(textures) - 1}
        material = {"name": f"m{k}", "pbrMetallicRoughness": pbr,
                    "alphaMode": o.get("alpha_mode", "OPAQUE")}
        if "alpha_cutoff" in o:
            material["alphaCutoff"] = float(o["alpha_cutoff"])
        if "double_sided" in o:
            material["doubleSided"] = bool(o["double_sided"])
        materials.append(material)
        meshes.append({"primitives": [{"attributes": attributes, "indices": indices,
                                       "material": k}]})
        nodes.append({"mesh": k, "name": f"object{k}"})
    document = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": list(range(len(nodes)))}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "buffers": [{"byteLength": len(blob), "uri": "data:application/octet-stream;base64,"
                     + base64.b64encode(bytes(blob)).decode()}],
        "bufferViews": views,
        "accessors": accessors,
    }
    if images:
        document["images"] = images
        document["textures"] = textures
    path = folder / f"{name}.gltf"
    path.write_text(json.dumps(document))
    return path


def plane_grid(n=8, size=1.0, z=0.0, uv_repeat=2.0):
    """An n x n grid of quads (n a power of two) in a plane z = const: positions, faces, normals (0, 0, 1) and uvs
    repeating `uv_repeat` times across it. Every coordinate is a dyadic fraction, exact in
    float32 and in the OBJ reader's 1 - v."""
    steps = np.arange(n + 1, dtype=np.float64) / n
    y, x = np.meshgrid(steps, steps, indexing="ij")
    positions = np.stack([(x - 0.5) * size, (y - 0.5) * size, np.full_like(x, z)], -1)
    positions = positions.reshape(-1, 3).astype(np.float32)
    uvs = np.stack([x * uv_repeat, (1.0 - y) * uv_repeat], -1).reshape(-1, 2).astype(np.float32)
    normals = np.tile(np.float32([0, 0, 1]), (len(positions), 1))
    quads = [(i * (n + 1) + j, i * (n + 1) + j + 1, (i + 1) * (n + 1) + j + 1,
              (i + 1) * (n + 1) + j) for i in range(n) for j in range(n)]
    faces = np.array([[a, b, c] for a, b, c, _ in quads] + [[a, c, d] for a, _, c, d in quads],
                     dtype=np.uint32)
    return positions, faces, normals, uvs
