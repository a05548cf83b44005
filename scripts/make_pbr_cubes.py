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

    python3 scripts/make_pbr_cubes.py --maps N OUT.gltf

One of the studs alone, large, on a square tile of plain grey paint with only
a normal map (128 texels a side), the tile turned so that the chapter's key
light grazes it from the upper left (page 23g). `raised` writes the file's
TANGENT as it should be; `turned` turns T and B half round (TANGENT's xyz
negated, w kept), as the made frame is turned without det_sign; `made` leaves
TANGENT out, so the shader makes the frame:

    python3 scripts/make_pbr_cubes.py --stud raised|turned|made OUT.gltf"""
import base64, json, math, os, struct, sys, zlib

N = 64  # texels per side


def png(pixels, n=N):  # pixels: n*n (r, g, b) tuples, 0..255
    raw = b"".join(b"\0" + bytes(c for p in pixels[y * n:(y + 1) * n] for c in p) for y in range(n))
    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
    head = struct.pack(">IIBBBBB", n, n, 8, 2, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", head) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def texels(f, n=N):
    return [f((x + 0.5) / n, (y + 0.5) / n) for y in range(n) for x in range(n)]


def bump(u, v, studs=4):  # a studs x studs grid of round studs: height and its gradient
    cu, cv = (u * studs) % 1 - 0.5, (v * studs) % 1 - 0.5
    r2 = cu * cu + cv * cv
    if r2 >= 0.16:
        return 0.0, 0.0, 0.0
    h = math.sqrt(0.16 - r2)
    return h, -cu / h, -cv / h


def base(u, v):
    return (200, 60, 40) if (int(u * 4) + int(v * 4)) % 2 else (230, 220, 200)


def metal_rough(u, v):  # G roughness, B metallic: the studs are polished metal
    return (0, 40, 255) if bump(u, v)[0] > 0 else (0, 200, 0)


def normal(u, v, studs=4):
    # Tangent space: x along +u, y up the image (where v decreases), z out.
    # A height field h(u, v) there has the normal (-dh/du, +dh/dv, 1).
    _, gx, gy = bump(u, v, studs)
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
    "made": {"name": "no TANGENT", "primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1,
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


STUD_SIZE = 128  # texels a side of the large stud's normal map


def stud_text(kind):
    """One square tile, its normal map one stud; kind: raised, turned or made."""
    # The tile's normal: the direction the chapter's camera looks from
    # (grid::frame_model, (0.35, 0.3, 1)) turned 30 degrees to the right about
    # y, so that the key light (-0.5, 0.7, 0.6) meets it at about 80 degrees.
    c = (0.35, 0.3, 1.0)
    a = math.radians(30)
    n = (c[0] * math.cos(a) + c[2] * math.sin(a), c[1], -c[0] * math.sin(a) + c[2] * math.cos(a))
    k = 1 / math.sqrt(sum(x * x for x in n))
    n = tuple(x * k for x in n)
    t = (n[2], 0.0, -n[0])  # y x n: level, towards the right
    k = 1 / math.sqrt(sum(x * x for x in t))
    t = tuple(x * k for x in t)
    b = (n[1] * t[2] - n[2] * t[1], n[2] * t[0] - n[0] * t[2], n[0] * t[1] - n[1] * t[0])  # n x t: up
    pos, uv = [], []
    for su, sv in ((0, 0), (1, 0), (1, 1), (0, 1)):
        pos.append(tuple((su - 0.5) * t[i] + (sv - 0.5) * b[i] for i in range(3)))
        uv.append((su, 1 - sv))  # v grows down the image, b up the tile
    tangent = (t + (1.0,)) if kind != "turned" else (tuple(-x for x in t) + (1.0,))
    idx = [0, 1, 2, 0, 2, 3]
    bin_ = b"".join(struct.pack("<3f", *p) for p in pos)
    off_n = len(bin_); bin_ += struct.pack("<3f", *n) * 4
    off_uv = len(bin_); bin_ += b"".join(struct.pack("<2f", *p) for p in uv)
    off_t = len(bin_); bin_ += struct.pack("<4f", *tangent) * 4
    off_i = len(bin_); bin_ += struct.pack("<6H", *idx)
    while len(bin_) % 4:
        bin_ += b"\0"
    views = [(0, off_n), (off_n, off_uv - off_n), (off_uv, off_t - off_uv), (off_t, off_i - off_t), (off_i, 12)]
    attributes = {"POSITION": 0, "NORMAL": 1, "TEXCOORD_0": 2}
    if kind != "made":
        attributes["TANGENT"] = 3
    image = png(texels(lambda u, v: normal(u, v, 1), STUD_SIZE), STUD_SIZE)
    gltf = {
        "asset": {"version": "2.0", "generator": "scripts/make_pbr_cubes.py --stud " + kind},
        "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
        "meshes": [{"name": "one stud, " + kind, "primitives": [{"attributes": attributes, "indices": 4,
                                                              "material": 0}]}],
        "materials": [{"name": "grey paint, one stud", "pbrMetallicRoughness": {
            "baseColorFactor": [0.7, 0.7, 0.7, 1.0], "metallicFactor": 0.0, "roughnessFactor": 0.6},
            "normalTexture": {"index": 0}}],
        "textures": [{"source": 0}],
        "images": [{"uri": "data:image/png;base64," + base64.b64encode(image).decode()}],
        "accessors": [
            {"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
             "min": [min(p[i] for p in pos) for i in range(3)], "max": [max(p[i] for p in pos) for i in range(3)]},
            {"bufferView": 1, "componentType": 5126, "count": 4, "type": "VEC3"},
            {"bufferView": 2, "componentType": 5126, "count": 4, "type": "VEC2"},
            {"bufferView": 3, "componentType": 5126, "count": 4, "type": "VEC4"},
            {"bufferView": 4, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "bufferViews": [{"buffer": 0, "byteOffset": o, "byteLength": n_} for o, n_ in views],
        "buffers": [{"byteLength": len(bin_),
                     "uri": "data:application/octet-stream;base64," + base64.b64encode(bin_).decode()}],
    }
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
    if len(args) == 3 and args[0] == "--stud":
        if args[1] not in ("raised", "turned", "made"):
            sys.exit("make_pbr_cubes.py: --stud wants one of raised, turned, made, not '%s'" % args[1])
        with open(args[2], "w") as f:
            f.write(stud_text(args[1]))
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
                 " | --maps N OUT.gltf | --stud raised|turned|made OUT.gltf")
    with open(args[0], "w") as f:
        f.write(gltf_text(single, maps))


if __name__ == "__main__":
    main()
