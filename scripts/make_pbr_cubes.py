#!/usr/bin/env python3
"""Writes assets/gltf/pbr_cubes.gltf: chapter 23's test model, two cubes with
every texture of glTF's metallic-roughness model (base colour, metallic-
roughness, normal, occlusion, emissive; PNGs as data: URIs). The left cube's
vertices carry TANGENT, the right cube's do not (the shader then makes its
tangent frame from screen-space derivatives). Everything is computed here,
so the file can be made again:

    python3 scripts/make_pbr_cubes.py OUT.gltf
    python3 scripts/make_pbr_cubes.py --check    # fails if the stored file differs

One cube alone at the middle, the same turn, with the file's TANGENT or with
the frame the shader makes (chapter 23's test draws both: the pictures must
agree):

    python3 scripts/make_pbr_cubes.py --single tangent|made OUT.gltf

The same single cube (with TANGENT) with only the first N of the five maps,
in the order base colour, metallic-roughness, normal, occlusion, emissive
(page 23e switches them on in turn; N = 5 is --single tangent). A map left
out takes its factor with it, so glTF 2.0's defaults apply: metallic 1 and
roughness 1 without the metallic-roughness map, no glow without the
emissive one:

    python3 scripts/make_pbr_cubes.py --maps N OUT.gltf"""
import base64, json, math, os, struct, sys, zlib

N = 64  # texels per side


def png(pixels):  # pixels: N*N (r, g, b) tuples, 0..255
    raw = b"".join(b"\0" + bytes(c for p in pixels[y * N:(y + 1) * N] for c in p) for y in range(N))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    head = struct.pack(">IIBBBBB", N, N, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", head) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def texels(f):
    return [f((x + 0.5) / N, (y + 0.5) / N) for y in range(N) for x in range(N)]


def bump(u, v):  # a 4x4 grid of round studs: height and its gradient
    cu, cv = (u * 4) % 1 - 0.5, (v * 4) % 1 - 0.5
    r2 = cu * cu + cv * cv
    if r2 >= 0.16:
        return 0.0, 0.0, 0.0
    h = math.sqrt(0.16 - r2)
    return h, -cu / h, -cv / h


def base(u, v):
    return (200, 60, 40) if (int(u * 4) + int(v * 4)) % 2 else (230, 220, 200)


def metal_rough(u, v):  # G roughness, B metallic: the studs are polished metal
    return (0, 40, 255) if bump(u, v)[0] > 0 else (0, 200, 0)


def normal(u, v):
    # Tangent space: x along +u, y up the image (where v decreases), z out.
    # A height field h(u, v) there has the normal (-dh/du, +dh/dv, 1).
    _, gx, gy = bump(u, v)
    n = (-gx * 0.6, gy * 0.6, 1.0)
    k = 1 / math.sqrt(sum(c * c for c in n))
    return tuple(int(round((c * k * 0.5 + 0.5) * 255)) for c in n)


def occlusion(u, v):  # darker around each stud's foot
    cu, cv = (u * 4) % 1 - 0.5, (v * 4) % 1 - 0.5
    r = math.sqrt(cu * cu + cv * cv)
    o = 1.0 if r < 0.4 else 0.55 + 0.45 * min(1.0, (r - 0.4) / 0.1)
    return (int(o * 255),) * 3


def emissive(u, v):  # one glowing ring in the middle of each face
    r = math.hypot(u - 0.5, v - 0.5)
    return (255, 140, 20) if 0.05 < r < 0.08 else (0, 0, 0)


def cube():
    pos, nrm, uv, tan, idx = [], [], [], [], []
    faces = [((1, 0, 0), (0, 0, -1)), ((-1, 0, 0), (0, 0, 1)), ((0, 1, 0), (1, 0, 0)),
             ((0, -1, 0), (1, 0, 0)), ((0, 0, 1), (1, 0, 0)), ((0, 0, -1), (-1, 0, 0))]
    for n, t in faces:
        b = (n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0])
        first = len(pos)
        for su, sv in ((0, 0), (1, 0), (1, 1), (0, 1)):
            pos.append(tuple(0.5 * n[i] + (su - 0.5) * t[i] + (sv - 0.5) * b[i] for i in range(3)))
            nrm.append(n)
            uv.append((su, 1 - sv))  # v grows down the image, b up the face
            tan.append(t + (1.0,))  # glTF: bitangent n x t, towards decreasing v (image up)
        idx += [first, first + 1, first + 2, first, first + 2, first + 3]
    return pos, nrm, uv, tan, idx


TURN = [0.2, 0.3, 0, 0.932]
MESHES = {
    "tangent": {"name": "with TANGENT", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1,
                "TEXCOORD_0": 2, "TANGENT": 3}, "indices": 4, "material": 0}]},
    "made": {"name": "tangents generated", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1,
             "TEXCOORD_0": 2}, "indices": 4, "material": 0}]}}


MAPS = ["base colour", "metallic-roughness", "normal", "occlusion", "emissive"]


def gltf_text(single=None, maps=5):
    pos, nrm, uv, tan, idx = cube()
    bin_ = b"".join(struct.pack("<3f", *p) for p in pos)
    off_n = len(bin_); bin_ += b"".join(struct.pack("<3f", *p) for p in nrm)
    off_uv = len(bin_); bin_ += b"".join(struct.pack("<2f", *p) for p in uv)
    off_t = len(bin_); bin_ += b"".join(struct.pack("<4f", *p) for p in tan)
    off_i = len(bin_); bin_ += struct.pack("<%dH" % len(idx), *idx)
    while len(bin_) % 4:
        bin_ += b"\0"
    views = [(0, off_n), (off_n, off_uv - off_n), (off_uv, off_t - off_uv), (off_t, off_i - off_t),
             (off_i, 2 * len(idx))]
    accessors = [
        {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3",
         "min": [-0.5] * 3, "max": [0.5] * 3},
        {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC3"},
        {"bufferView": 2, "componentType": 5126, "count": 24, "type": "VEC2"},
        {"bufferView": 3, "componentType": 5126, "count": 24, "type": "VEC4"},
        {"bufferView": 4, "componentType": 5123, "count": len(idx), "type": "SCALAR"},
    ]
    images = [base, metal_rough, normal, occlusion, emissive]
    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/make_pbr_cubes.py"},
        "scene": 0, "scenes": [{"nodes": [0, 1]}],
        "nodes": [
            {"mesh": 0, "translation": [-0.8, 0, 0], "rotation": TURN},
            {"mesh": 1, "translation": [0.8, 0, 0], "rotation": TURN}],
        "meshes": [MESHES["tangent"], MESHES["made"]],
        "materials": [{"name": "studs", "pbrMetallicRoughness": {
            "baseColorTexture": {"index": 0}, "metallicRoughnessTexture": {"index": 1}},
            "normalTexture": {"index": 2}, "occlusionTexture": {"index": 3},
            "emissiveTexture": {"index": 4}, "emissiveFactor": [4, 4, 4]}],
        "textures": [{"source": i} for i in range(5)],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(png(texels(f))).decode()}
                   for f in images],
        "accessors": accessors,
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n} for o, n in views],
        "buffers": [{"byteLength": len(bin_),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bin_).decode()}],
    }
    if single:
        gltf.update({"scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0, "rotation": TURN}],
                     "meshes": [MESHES[single]]})
    if maps < 5:  # the first `maps` maps; each one's texture index is its place in MAPS
        material = gltf["materials"][0]
        material["name"] = "studs: " + ", ".join(MAPS[:maps])
        pbr = material["pbrMetallicRoughness"]
        slots = [(pbr, "baseColorTexture"), (pbr, "metallicRoughnessTexture"),
                 (material, "normalTexture"), (material, "occlusionTexture"),
                 (material, "emissiveTexture")]
        for owner, key in slots[maps:]:
            del owner[key]
        del material["emissiveFactor"]  # glTF's default, 0: no glow
        gltf["textures"] = gltf["textures"][:maps]
        gltf["images"] = gltf["images"][:maps]
    return json.dumps(gltf, indent=1)


def main():
    args = sys.argv[1:]
    if args == ["--check"]:
        path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "assets", "gltf",
                            "pbr_cubes.gltf")
        with open(path) as f:
            if f.read() != gltf_text():
                sys.exit(path + " differs from what scripts/make_pbr_cubes.py makes")
        print(path + " is what scripts/make_pbr_cubes.py makes")
        return
    single, maps = None, 5
    if len(args) == 3 and args[0] == "--single":
        if args[1] not in MESHES:
            sys.exit("make_pbr_cubes.py: --single wants one of tangent, made, not '%s'" % args[1])
        single, args = args[1], args[2:]
    elif len(args) == 3 and args[0] == "--maps":
        if args[1] not in ("1", "2", "3", "4", "5"):
            sys.exit("make_pbr_cubes.py: --maps wants a number from 1 to 5, not '%s'" % args[1])
        single, maps, args = "tangent", int(args[1]), args[2:]
    if len(args) != 1 or args[0].startswith("-"):
        sys.exit("usage: make_pbr_cubes.py OUT.gltf | --check | --single tangent|made OUT.gltf"
                 " | --maps N OUT.gltf")
    with open(args[0], "w") as f:
        f.write(gltf_text(single, maps))


if __name__ == "__main__":
    main()
