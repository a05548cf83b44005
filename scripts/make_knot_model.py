#!/usr/bin/env python3
"""Makes chapter 26's default model: assets/gltf/knot.glb, a trefoil knot
drawn as a tube (320 rings of 48 vertices, 30,720 triangles), positions and
normals only, 16-bit indices, one mesh, one node. Enough triangles for a few
hundred meshlets, small enough to keep in the repository.

Standard library only (json, math, struct), deterministic:

    python3 scripts/make_knot_model.py            # writes assets/gltf/knot.glb
    python3 scripts/make_knot_model.py --check    # fails if the file differs

The same knot, finer, for book/perf_26_mesh_shaders.md's dense case (2560
rings of 384: 1,966,080 triangles, 32-bit indices past 65,535 vertices):

    python3 scripts/make_knot_model.py --rings 2560 --sides 384 --out knot_dense.glb
"""

import json
import math
import os
import struct
import sys

RINGS, SIDES = 320, 48  # along the knot, around the tube
P, Q = 2, 3  # a (2, 3) torus knot: the trefoil
TUBE = 0.16  # the tube's radius


def centre(t):
    """The knot's centre line, lying around the y axis (y up)."""
    ring = 1.0 + 0.42 * math.cos(Q * t)
    return (ring * math.cos(P * t), -0.42 * math.sin(Q * t), ring * math.sin(P * t))


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def unit(a):
    length = math.sqrt(dot(a, a))
    return tuple(x / length for x in a)


def knot(RINGS=RINGS, SIDES=SIDES):
    positions, normals, indices = [], [], []
    step = 1e-4
    for i in range(RINGS + 1):
        t = 2.0 * math.pi * i / RINGS
        c, ahead, behind = centre(t), centre(t + step), centre(t - step)
        tangent = unit(sub(ahead, behind))
        # The curvature's direction (the knot never runs straight) and the
        # third axis of the ring's frame.
        bend = unit(sub(sub(ahead, c), sub(c, behind)))
        side = cross(tangent, bend)
        for j in range(SIDES + 1):
            a = 2.0 * math.pi * j / SIDES
            n = tuple(math.cos(a) * x + math.sin(a) * y for x, y in zip(bend, side))
            positions.append(tuple(p + TUBE * m for p, m in zip(c, n)))
            normals.append(n)
    row = SIDES + 1
    for i in range(RINGS):
        for j in range(SIDES):
            a, b, c, d = i * row + j, (i + 1) * row + j, i * row + j + 1, (i + 1) * row + j + 1
            for tri in ((a, b, c), (c, b, d)):
                # Counter-clockwise seen from outside: the face's normal agrees
                # with the vertices' normals.
                face = cross(sub(positions[tri[1]], positions[tri[0]]),
                             sub(positions[tri[2]], positions[tri[0]]))
                if dot(face, normals[tri[0]]) < 0.0:
                    tri = (tri[0], tri[2], tri[1])
                indices.extend(tri)
    return positions, normals, indices


def glb(rings=RINGS, sides=SIDES):
    positions, normals, indices = knot(rings, sides)
    wide = len(positions) > 65536  # 32-bit indices only where 16 bits cannot
    vertex_bytes = b"".join(struct.pack("<3f", *p) for p in positions)
    normal_bytes = b"".join(struct.pack("<3f", *n) for n in normals)
    index_bytes = struct.pack("<%d%s" % (len(indices), "I" if wide else "H"), *indices)
    binary = vertex_bytes + normal_bytes + index_bytes
    binary += b"\0" * (-len(binary) % 4)
    count = len(positions)
    lo = [min(p[k] for p in positions) for k in range(3)]
    hi = [max(p[k] for p in positions) for k in range(3)]
    document = {
        "asset": {"version": "2.0", "generator": "scripts/make_knot_model.py"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0, "name": "knot"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2,
                                    "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.55, 0.3, 1.0]}}],
        "buffers": [{"byteLength": len(binary)}],
        "bufferViews": [
            {"buffer": 0, "byteOffset": 0, "byteLength": len(vertex_bytes), "target": 34962},
            {"buffer": 0, "byteOffset": len(vertex_bytes), "byteLength": len(normal_bytes),
             "target": 34962},
            {"buffer": 0, "byteOffset": 2 * len(vertex_bytes), "byteLength": len(index_bytes),
             "target": 34963},
        ],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": count, "type": "VEC3",
             "min": [round(x, 6) for x in lo], "max": [round(x, 6) for x in hi]},
            {"bufferView": 1, "componentType": 5126, "count": count, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5125 if wide else 5123, "count": len(indices), "type": "SCALAR"},
        ],
    }
    text = json.dumps(document, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    body = (struct.pack("<II", len(text), 0x4E4F534A) + text +
            struct.pack("<II", len(binary), 0x004E4942) + binary)
    return struct.pack("<III", 0x46546C67, 2, 12 + len(body)) + body


def whole(name, text, lo, hi):
    """A command-line count, or exit 1 saying what was wanted."""
    if not text.isdigit() or not lo <= int(text) <= hi:
        sys.exit("make_knot_model.py: %s wants a whole number from %d to %d, not '%s'" %
                 (name, lo, hi, text))
    return int(text)


def main():
    root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")
    path = os.path.join(root, "assets", "gltf", "knot.glb")
    rings, sides, args = RINGS, SIDES, sys.argv[1:]
    while args and args[0] in ("--rings", "--sides", "--out"):
        if len(args) < 2:
            sys.exit("make_knot_model.py: %s wants a value" % args[0])
        if args[0] == "--rings":
            rings = whole("--rings", args[1], 3, 4096)
        elif args[0] == "--sides":
            sides = whole("--sides", args[1], 3, 1024)
        else:
            path = args[1]
        args = args[2:]
    if args not in ([], ["--check"]):
        sys.exit("make_knot_model.py: unknown argument '%s' (--rings N, --sides N, --out FILE, "
                 "--check)" % args[0])
    data = glb(rings, sides)
    if args == ["--check"]:
        with open(path, "rb") as f:
            if f.read() != data:
                sys.exit(path + " differs from what scripts/make_knot_model.py makes")
        return
    with open(path, "wb") as f:
        f.write(data)


if __name__ == "__main__":
    main()
