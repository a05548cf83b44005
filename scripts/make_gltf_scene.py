#!/usr/bin/env python3
"""Makes chapter 10's default scene: assets/gltf/scene.gltf (+ scene.bin and
three PNG textures) and the same scene as one binary file, scene.glb.

Standard library only (json, struct, zlib), so anyone can re-run it:

    python3 scripts/make_gltf_scene.py            # writes into assets/gltf/

Everything is made here: the geometry is computed, the textures are drawn
pixel by pixel. The scene exercises what the chapter 10 loader supports:

- a floor with 8-bit indices and a checker texture repeated 1.5 times;
- a cube whose vertices are interleaved in one bufferView (byteStride 32),
  used by two meshes with different materials (bricks, and bricks tinted blue
  by baseColorFactor), with 16-bit indices;
- a pyramid with no indices and no normals (the loader makes flat normals) and
  an orange baseColorFactor without a texture;
- a UV sphere with 32-bit indices and a striped texture;
- a node tree four levels deep, with both `matrix` and TRS transforms.
"""

import json
import math
import os
import struct
import sys
import zlib

# --- PNG, written by hand: signature, IHDR, one IDAT, IEND ------------------


def png_bytes(width, height, pixel):
    """pixel(x, y) -> (r, g, b); an 8-bit RGB PNG, every row with filter 0."""
    rows = bytearray()
    for y in range(height):
        rows.append(0)
        for x in range(width):
            rows.extend(pixel(x, y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8 bits, RGB
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
            chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + chunk(b"IEND", b""))


def checker(x, y):
    return (235, 235, 228) if (x // 8 + y // 8) % 2 == 0 else (60, 64, 72)


def bricks(x, y):
    row = y // 8
    offset = 8 if row % 2 else 0
    mortar = y % 8 == 7 or (x + offset) % 16 == 15
    if mortar:
        return (200, 196, 188)
    shade = ((x + offset) // 16 * 37 + row * 53) % 5  # a little variety per brick
    return (150 + shade * 8, 62 + shade * 3, 44 + shade * 2)


def stripes(x, y):
    return (240, 240, 240) if (x // 4) % 2 == 0 else (40, 150, 90)


# --- Geometry ----------------------------------------------------------------


def floor_mesh(half=3.0, repeat=1.5):
    p = [(-half, 0, -half), (half, 0, -half), (half, 0, half), (-half, 0, half)]
    n = [(0, 1, 0)] * 4
    t = [(0, 0), (repeat, 0), (repeat, repeat), (0, repeat)]
    # Counter-clockwise seen from above (+y), glTF's front face.
    return p, n, t, [0, 2, 1, 0, 3, 2]


def cube_mesh():
    p, n, t, idx = [], [], [], []
    faces = [  # normal, tangent u, tangent v (u x v = normal)
        ((1, 0, 0), (0, 0, -1), (0, 1, 0)), ((-1, 0, 0), (0, 0, 1), (0, 1, 0)),
        ((0, 1, 0), (1, 0, 0), (0, 0, -1)), ((0, -1, 0), (1, 0, 0), (0, 0, 1)),
        ((0, 0, 1), (1, 0, 0), (0, 1, 0)), ((0, 0, -1), (-1, 0, 0), (0, 1, 0)),
    ]
    for normal, u, v in faces:
        base = len(p)
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p.append(tuple(0.5 * normal[i] + 0.5 * su * u[i] + 0.5 * sv * v[i] for i in range(3)))
            n.append(normal)
            t.append(((su + 1) / 2, (1 - sv) / 2))  # v grows downwards in glTF
        idx += [base, base + 1, base + 2, base, base + 2, base + 3]
    return p, n, t, idx


def pyramid_positions(half=0.4, height=0.7):
    """Non-indexed triangles, counter-clockwise from outside; no normals."""
    a, b, c, d = (-half, 0, -half), (half, 0, -half), (half, 0, half), (-half, 0, half)
    apex = (0, height, 0)
    return [d, c, apex, c, b, apex, b, a, apex, a, d, apex, a, b, c, a, c, d]


def sphere_mesh(radius=0.8, segments=32, rings=16):
    p, n, t, idx = [], [], [], []
    for r in range(rings + 1):
        theta = math.pi * r / rings  # 0 at the top
        for s in range(segments + 1):
            phi = 2 * math.pi * s / segments
            normal = (math.sin(theta) * math.sin(phi), math.cos(theta), math.sin(theta) * math.cos(phi))
            p.append(tuple(radius * c for c in normal))
            n.append(normal)
            t.append((2 * s / segments, r / rings))
    for r in range(rings):
        for s in range(segments):
            a = r * (segments + 1) + s
            b = a + segments + 1
            idx += [a, b, a + 1, a + 1, b, b + 1]
    return p, n, t, idx


# --- The glTF document --------------------------------------------------------


class Builder:
    def __init__(self):
        self.bin = bytearray()
        self.views, self.accessors = [], []

    def view(self, data, stride=None, target=None):
        while len(self.bin) % 4:
            self.bin.append(0)
        v = {"buffer": 0, "byteOffset": len(self.bin), "byteLength": len(data)}
        if stride:
            v["byteStride"] = stride
        if target:
            v["target"] = target
        self.bin.extend(data)
        self.views.append(v)
        return len(self.views) - 1

    def accessor(self, view, component, count, kind, offset=0, bounds=None):
        a = {"bufferView": view, "componentType": component, "count": count, "type": kind}
        if offset:
            a["byteOffset"] = offset
        if bounds:
            a["min"], a["max"] = bounds
        self.accessors.append(a)
        return len(self.accessors) - 1

    def floats(self, values, kind):
        flat = [c for v in values for c in v]
        view = self.view(struct.pack("<%df" % len(flat), *flat), target=34962)
        return self.accessor(view, 5126, len(values), kind, bounds=self.bounds(values) if kind == "VEC3" else None)

    def indices(self, values, component):
        fmt = {5121: "B", 5123: "H", 5125: "I"}[component]
        view = self.view(struct.pack("<%d%s" % (len(values), fmt), *values), target=34963)
        return self.accessor(view, component, len(values), "SCALAR")

    @staticmethod
    def bounds(values):
        return ([min(v[i] for v in values) for i in range(3)], [max(v[i] for v in values) for i in range(3)])


def rotation_y(degrees):
    h = math.radians(degrees) / 2
    return [0.0, math.sin(h), 0.0, math.cos(h)]


def build():
    b = Builder()
    meshes = []

    fp, fn, ft, fi = floor_mesh()
    floor = {"POSITION": b.floats(fp, "VEC3"), "NORMAL": b.floats(fn, "VEC3"), "TEXCOORD_0": b.floats(ft, "VEC2")}
    meshes.append({"name": "floor", "primitives": [
        {"attributes": floor, "indices": b.indices(fi, 5121), "material": 0}]})

    # The cube: position, normal and uv of each vertex side by side (32 bytes).
    cp, cn, ct, ci = cube_mesh()
    interleaved = b"".join(struct.pack("<8f", *cp[i], *cn[i], *ct[i]) for i in range(len(cp)))
    cube_view = b.view(interleaved, stride=32, target=34962)
    cube = {"POSITION": b.accessor(cube_view, 5126, len(cp), "VEC3", 0, Builder.bounds(cp)),
            "NORMAL": b.accessor(cube_view, 5126, len(cp), "VEC3", 12),
            "TEXCOORD_0": b.accessor(cube_view, 5126, len(cp), "VEC2", 24)}
    cube_indices = b.indices(ci, 5123)
    meshes.append({"name": "brick_cube", "primitives": [
        {"attributes": cube, "indices": cube_indices, "material": 1}]})
    meshes.append({"name": "blue_cube", "primitives": [
        {"attributes": cube, "indices": cube_indices, "material": 2}]})

    pp = pyramid_positions()
    meshes.append({"name": "pyramid", "primitives": [
        {"attributes": {"POSITION": b.floats(pp, "VEC3")}, "material": 3}]})

    sp, sn, st, si = sphere_mesh()
    sphere = {"POSITION": b.floats(sp, "VEC3"), "NORMAL": b.floats(sn, "VEC3"), "TEXCOORD_0": b.floats(st, "VEC2")}
    meshes.append({"name": "sphere", "primitives": [
        {"attributes": sphere, "indices": b.indices(si, 5125), "material": 4}]})

    materials = [
        {"name": "checker", "pbrMetallicRoughness": {"baseColorTexture": {"index": 0}}},
        {"name": "bricks", "pbrMetallicRoughness": {"baseColorTexture": {"index": 1}}},
        {"name": "blue_bricks", "pbrMetallicRoughness": {
            "baseColorFactor": [0.35, 0.55, 1.0, 1.0], "baseColorTexture": {"index": 1}}},
        {"name": "orange", "pbrMetallicRoughness": {"baseColorFactor": [1.0, 0.45, 0.08, 1.0]}},
        {"name": "stripes", "pbrMetallicRoughness": {"baseColorTexture": {"index": 2}}},
    ]
    # The stand: turned 30 degrees about y and moved, written as a matrix
    # (column by column, as glTF stores it).
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))
    stand_matrix = [c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, -1.4, 0, 0.6, 1]
    nodes = [
        {"name": "root", "children": [1, 2, 6], "scale": [1, 1, 1]},
        {"name": "floor", "mesh": 0},
        {"name": "stand", "matrix": stand_matrix, "children": [3, 5]},
        {"name": "brick_cube", "mesh": 1, "translation": [0, 0.5, 0], "children": [4]},
        {"name": "pyramid", "mesh": 3, "translation": [0, 0.5, 0], "rotation": rotation_y(45)},
        {"name": "blue_cube", "mesh": 2, "translation": [1.9, 0.35, -1.3], "rotation": rotation_y(40),
         "scale": [0.7, 0.7, 0.7]},
        {"name": "sphere", "mesh": 4, "translation": [1.9, 0.8, 1.1]},
    ]
    doc = {
        "asset": {"version": "2.0", "generator": "scripts/make_gltf_scene.py"},
        "scene": 0,
        "scenes": [{"name": "chapter 10", "nodes": [0]}],
        "nodes": nodes,
        "meshes": meshes,
        "materials": materials,
        "samplers": [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}],
        "textures": [{"sampler": 0, "source": i} for i in range(3)],
        "accessors": b.accessors,
        "bufferViews": b.views,
    }
    images = [("checker.png", png_bytes(64, 64, checker)), ("bricks.png", png_bytes(64, 64, bricks)),
              ("stripes.png", png_bytes(32, 32, stripes))]
    return doc, b, images


def write(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    doc, b, images = build()

    # scene.gltf: JSON, the buffer in scene.bin, the images as PNG files.
    text = dict(doc)
    text["buffers"] = [{"uri": "scene.bin", "byteLength": len(b.bin)}]
    text["bufferViews"] = list(b.views)
    text["images"] = [{"uri": name} for name, _ in images]
    with open(os.path.join(out_dir, "scene.gltf"), "w") as f:
        json.dump(text, f, indent=1)
        f.write("\n")
    with open(os.path.join(out_dir, "scene.bin"), "wb") as f:
        f.write(b.bin)
    for name, data in images:
        with open(os.path.join(out_dir, name), "wb") as f:
            f.write(data)

    # scene.glb: the same JSON with the images in bufferViews of the one
    # buffer, which is the BIN chunk (no uri).
    binary = Builder()
    binary.bin = bytearray(b.bin)
    binary.views = list(b.views)
    glb_images = []
    for name, data in images:
        glb_images.append({"bufferView": binary.view(data), "mimeType": "image/png", "name": name})
    while len(binary.bin) % 4:
        binary.bin.append(0)
    packed = dict(doc)
    packed["buffers"] = [{"byteLength": len(binary.bin)}]
    packed["bufferViews"] = binary.views
    packed["images"] = glb_images
    json_chunk = json.dumps(packed, separators=(",", ":")).encode()
    json_chunk += b" " * (-len(json_chunk) % 4)  # the JSON chunk is padded with spaces
    total = 12 + 8 + len(json_chunk) + 8 + len(binary.bin)
    with open(os.path.join(out_dir, "scene.glb"), "wb") as f:
        f.write(struct.pack("<4sII", b"glTF", 2, total))
        f.write(struct.pack("<I4s", len(json_chunk), b"JSON") + json_chunk)
        f.write(struct.pack("<I4s", len(binary.bin), b"BIN\0") + bytes(binary.bin))


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    write(sys.argv[1] if len(sys.argv) > 1 else os.path.join(here, "..", "assets", "gltf"))
