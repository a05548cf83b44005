#!/usr/bin/env python3
"""How many triangles and vertices a glTF scene draws, counted from its JSON
alone, against what chapter 26 says when it loads the same file.

    python3 tests/chapters/gltf_counts.py CHAPTER_26 MODEL [MODEL ...]

For each MODEL (.gltf or .glb) this walks the default scene's node tree and,
for every node with a mesh, adds each triangle primitive's vertex count (its
POSITION accessor's count) and triangle count (its index or vertex count: n / 3
for a list, n - 2 for a strip or fan). A mesh used by two nodes counts twice,
as chapter 26 flattens the scene into one mesh. Nothing of the chapter's
loader is used: only the accessors' "count" fields, read with Python's json.

It then runs the chapter on MODEL (one frame, headless, validation on) and
requires its line "MODEL: T triangles, V vertices -> M meshlets" to name the
same T and V with no validation message, and M within what any meshlet builder must produce: at least
T / 124 meshlets (124 triangles each at most), at least V / 64 (64 vertices
each at most, every vertex in at least one), at most T (one triangle each at
least). Exit 0 when every model agrees, 1 naming the first that does not.
"""
import json
import math
import os
import re
import struct
import subprocess
import sys

TRIANGLES, STRIP, FAN = 4, 5, 6
MAX_VERTICES, MAX_TRIANGLES = 64, 124


def read_json(path):
    with open(path, "rb") as f:
        data = f.read()
    if data[:4] != b"glTF":
        return json.loads(data)
    # .glb: a 12-byte header, then the JSON chunk (length, type "JSON", bytes).
    length, kind = struct.unpack_from("<I4s", data, 12)
    if kind != b"JSON":
        raise ValueError(f"{path}: the first chunk is not JSON")
    return json.loads(data[20:20 + length])


def count(gltf):
    accessors, meshes, nodes = gltf["accessors"], gltf["meshes"], gltf.get("nodes", [])
    scene = gltf["scenes"][gltf.get("scene", 0)]
    triangles = vertices = 0
    stack = list(scene["nodes"])
    while stack:
        node = nodes[stack.pop()]
        stack.extend(node.get("children", []))
        if "mesh" not in node:
            continue
        for primitive in meshes[node["mesh"]]["primitives"]:
            mode = primitive.get("mode", TRIANGLES)
            if mode not in (TRIANGLES, STRIP, FAN):
                continue
            n_vertices = accessors[primitive["attributes"]["POSITION"]]["count"]
            n = accessors[primitive["indices"]]["count"] if "indices" in primitive else n_vertices
            vertices += n_vertices
            triangles += n // 3 if mode == TRIANGLES else max(n - 2, 0)
    return triangles, vertices


def said_all(run):
    return run.stdout + run.stderr


def main():
    chapter, models = sys.argv[1], sys.argv[2:]
    for model in models:
        triangles, vertices = count(read_json(model))
        run = subprocess.run([chapter, "--headless", "--validation", "--frames", "1",
                              "--size", "320x240", "--model", model],
                             capture_output=True, text=True, timeout=300)
        name = re.escape(os.path.basename(model))
        said = re.search(name + r": (\d+) triangles, (\d+) vertices -> (\d+) meshlets",
                         said_all(run))
        if "[validation" in said_all(run) or "Validation Error:" in said_all(run):
            print(f"{model}: the chapter reported a validation message")
            print(said_all(run))
            return 1
        if run.returncode != 0 or not said:
            print(f"{model}: the chapter exited {run.returncode} without its count line")
            print(said_all(run))
            return 1
        t, v, m = map(int, said.groups())
        low = max(math.ceil(triangles / MAX_TRIANGLES), math.ceil(vertices / MAX_VERTICES))
        print(f"{model}: the JSON says {triangles} triangles, {vertices} vertices "
              f"(so {low} to {triangles} meshlets); the chapter says {t}, {v}, {m}")
        if (t, v) != (triangles, vertices) or not low <= m <= triangles:
            print(f"{model}: the chapter's counts differ from the file's")
            return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
