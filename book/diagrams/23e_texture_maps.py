"""Chapter 23e: the five texture maps of the test model, as the file stores them.

Read out of assets/gltf/pbr_cubes.gltf when the book is built (the images are
PNGs in data: URIs, written by scripts/make_pbr_cubes.py), each 64x64 texel
map drawn enlarged, pixelated, with what its channels mean to glTF and to
shaders/23_materials/surface.glsl, and a few texels read from the map itself.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the five
stand one above the other, 400 units wide, each label beside its map.
"""

from __future__ import annotations

import base64
import json
import os
from pathlib import Path

from golden import enlarged, read_png
from svg import MUTED, Svg, text_width

MODEL = Path(__file__).resolve().parents[2] / "assets" / "gltf" / "pbr_cubes.gltf"
NAME = "assets/gltf/pbr_cubes.gltf"


class _Uri:
    """A data: URI's bytes, read as read_png reads a file (and named like one in its errors)."""

    def __init__(self, uri: str, index: int):
        head, _, body = uri.partition(",")
        if head != "data:image/png;base64":
            raise SystemExit(f"{NAME}: images[{index}]: not a PNG data: URI")
        self.data, self.name = base64.b64decode(body), f"{NAME}: images[{index}]"

    def read_bytes(self) -> bytes:
        return self.data

    def __str__(self) -> str:
        return self.name


def maps():
    gltf = json.loads(MODEL.read_text())
    material = gltf["materials"][0]
    slots = [("base colour", material["pbrMetallicRoughness"]["baseColorTexture"]),
             ("metallic-roughness", material["pbrMetallicRoughness"]["metallicRoughnessTexture"]),
             ("normal", material["normalTexture"]), ("occlusion", material["occlusionTexture"]),
             ("emissive", material["emissiveTexture"])]
    out = {}
    for name, ref in slots:
        source = gltf["textures"][ref["index"]]["source"]
        out[name] = read_png(_Uri(gltf["images"][source]["uri"], source))
    return out, material


def labels(px, material):
    """What each map's channels mean, with texels read from it: (x, y) = (8, 8) is on a
    stud's top, (0, 0) between studs, (32, 32) at the middle of the face."""
    stud, flat, mid = (8, 8), (0, 0), (32, 32)

    def at(name, p):
        return px[name][p[1]][p[0]]

    mr_s, mr_f = at("metallic-roughness", stud), at("metallic-roughness", flat)
    occ_foot = min(row[x][0] for row in px["occlusion"] for x in range(len(row)))
    emis = max(px["emissive"][y][x] for y in range(64) for x in range(64))
    return [
        ("Base colour", "sRGB", ["RGB: the surface's colour", "a red and cream checker"]),
        ("Metallic-roughness", "linear", ["G: roughness, B: metallic",
                                          f"studs G {mr_s[1]}, B {mr_s[2]}: metal",
                                          f"else G {mr_f[1]}, B {mr_f[2]}: rough", "(R unused)"]),
        ("Normal", "linear", ["RGB: x, y, z along T, B, N", "0..255 for -1..1",
                              f"flat: {at('normal', flat)}", "the studs lean: relief"]),
        ("Occlusion", "linear", ["R: the share of sky light", f"255 open, {occ_foot} at",
                                 "a stud's foot"]),
        ("Emissive", "sRGB", ["RGB: light given off,", "times emissiveFactor "
                              f"{material['emissiveFactor'][0]:g}", f"ring {emis}"]),
    ]


def fits(lines, size, room) -> None:
    for line in lines:
        if text_width(line, size) > room:
            raise SystemExit(f"book/diagrams/23e_texture_maps.py: '{line}' is wider than its column")


def main() -> None:
    px, material = maps()
    rows = labels(px, material)
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23e: the five texture maps of assets/gltf/pbr_cubes.gltf"
    desc = ("The five 64 by 64 texel maps of the test model, enlarged, each labelled with what its "
            "channels mean. Base colour: a red and cream checker, sRGB. Metallic-roughness: green "
            "squares (rough, not metal) with a blue disc for each stud (blue is metallic, a little "
            "green: polished). Normal: light blue-violet, flat, with each stud shaded pink to one side "
            "and blue to the other, its relief. Occlusion: white, with a grey ring around each stud's "
            "foot. Emissive: black, with a thin orange ring at the middle.")
    names = list(px)
    if narrow:
        zoom, tile, gap = 1.75, 112, 26
        s = Svg(400, 40 + 5 * (tile + gap) - gap + 10, title, desc)
        s.text(10, 22, "The five maps, as the file stores them", size=14, bold=True)
        for i, (name, (head, space, lines)) in enumerate(zip(names, rows)):
            y = 40 + i * (tile + gap)
            enlarged(s, px[name], 0, 0, 64, 64, 10, y, zoom)
            s.text(136, y + 14, head, size=13, bold=True)
            s.text(136, y + 31, space, size=12, fill=MUTED)
            fits(lines, 12.5, 400 - 136 - 6)
            s.lines(136, y + 50, lines, size=12.5, leading=1.3)
    else:
        zoom, tile, col = 2, 128, 180
        s = Svg(20 + 5 * col, 300, title, desc)
        s.text(20, 26, "The five maps of --model assets/gltf/pbr_cubes.gltf, as the file stores "
               "them (64x64 texels, enlarged twice)", size=14, bold=True)
        for i, (name, (head, space, lines)) in enumerate(zip(names, rows)):
            x = 20 + i * col
            enlarged(s, px[name], 0, 0, 64, 64, x, 44, zoom)
            s.text(x, 44 + tile + 20, head, size=13, bold=True)
            s.text(x, 44 + tile + 37, space, size=12, fill=MUTED)
            fits(lines, 12, col - 10)
            s.lines(x, 44 + tile + 56, lines, size=12, leading=1.35)
    s.write()


if __name__ == "__main__":
    main()
