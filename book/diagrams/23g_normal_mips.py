"""Chapter 23g: the test model's normal map down its mip chain.

Read out of assets/gltf/pbr_cubes.gltf when the book is built (through
23e_texture_maps.maps()), then halved level by level as the chapter's loader
does it (common/resources/src/texture.cpp: vkCmdBlitImage with VK_FILTER_LINEAR,
each level from the one above; halving a power-of-two image that way is the
mean of 2x2 texels, which this script computes and rounds to a byte, as the
8-bit _UNORM level stores it). Each level is drawn at the same size, and under
it the mean length of its decoded normals and the steepest lean among them.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the levels
stand one above the other, 400 units wide, each label beside its map.
"""

from __future__ import annotations

import importlib
import math
import os

from golden import enlarged
from svg import MUTED, Svg, text_width

SHOWN = 5  # levels 0 to 4; from level 4 (4x4) on, each texel is a whole stud's cell


def halve(level):
    """The next mip level: each texel the mean of 2x2 texels, rounded to a byte."""
    size = len(level) // 2
    return [[tuple(int(sum(level[2 * y + dy][2 * x + dx][c] for dy in (0, 1) for dx in (0, 1)) / 4 + 0.5)
                   for c in range(3)) for x in range(size)] for y in range(size)]


def decode(texel):
    return [c / 255 * 2 - 1 for c in texel]


def stats(level):
    """The mean length of the level's decoded normals and its steepest lean from N, in degrees."""
    lengths, leans = [], []
    for row in level:
        for texel in row:
            x, y, z = decode(texel)
            length = math.sqrt(x * x + y * y + z * z)
            lengths.append(length)
            leans.append(math.degrees(math.acos(z / length)))
    return sum(lengths) / len(lengths), max(leans)


def levels():
    normal = importlib.import_module("23e_texture_maps").maps()[0]["normal"]
    out = [normal]
    while len(out[-1]) > 1:
        out.append(halve(out[-1]))
    return out


def labels(chain, i):
    level = chain[i]
    size, stud = len(level), len(level) // 4
    mean, lean = stats(level)
    lines = [f"a stud: {stud}x{stud} texel{'s' if stud > 1 else ''}",
             f"mean length {mean:.3f}", f"steepest lean {lean:.0f}\u00b0" if lean >= 1 else "steepest lean under 1\u00b0"]
    if stud == 1:
        lines.append(f"every texel {level[0][0]}")
    return f"level {i}: {size}x{size}", lines


def check_tail(chain) -> None:
    """Levels 5 and 6 (2x2, 1x1) repeat level 4's texel: the caption says so."""
    texel = chain[SHOWN - 1][0][0]
    if any(t != texel for level in chain[SHOWN - 1:] for row in level for t in row):
        raise SystemExit("book/diagrams/23g_normal_mips.py: the levels past 4 are not all one texel")


def fits(lines, size, room) -> None:
    for line in lines:
        if text_width(line, size) > room:
            raise SystemExit(f"book/diagrams/23g_normal_mips.py: '{line}' is wider than its column")


def main() -> None:
    chain = levels()
    check_tail(chain)
    last = chain[-1][0][0]
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23g: the test model's normal map down its mip levels"
    desc = ("Levels 0 to 4 of the normal map of assets/gltf/pbr_cubes.gltf, each made from the one "
            "above by averaging 2x2 texels and rounding to a byte, a CPU model of the loader's blits, "
            "drawn at the same size. Level 0 shows 4 by 4 studs, each "
            "shaded to its sides; the studs blur level by level, and at level 4 every texel is one "
            "plain blue-violet, a normal straight out of the surface but shorter than 1. Under each, "
            "the mean length of the decoded normals and the steepest lean among them.")
    note = f"Levels 5 and 6 (2x2, 1x1): the texel {last} again."
    if narrow:
        tile, gap = 104, 22
        s = Svg(400, 40 + SHOWN * (tile + gap) + 14, title, desc)
        s.text(10, 22, "The normal map, level by level (a CPU model)", size=14, bold=True)
        for i in range(SHOWN):
            y = 40 + i * (tile + gap)
            level = chain[i]
            enlarged(s, level, 0, 0, len(level), len(level), 10, y, tile / len(level))
            head, lines = labels(chain, i)
            s.text(130, y + 16, head, size=13, bold=True)
            fits(lines, 12.5, 400 - 130 - 6)
            s.lines(130, y + 36, lines, size=12.5, leading=1.3)
        fits([note], 12, 400 - 10 - 6)
        s.text(10, 40 + SHOWN * (tile + gap) + 2, note, size=12, fill=MUTED)
    else:
        tile, col = 128, 176
        s = Svg(20 + SHOWN * col, 290, title, desc)
        s.text(20, 26, "The normal map of assets/gltf/pbr_cubes.gltf down its mip levels: the blits' 2x2 "
               "means, modelled on the CPU", size=14, bold=True)
        for i in range(SHOWN):
            x = 20 + i * col
            level = chain[i]
            enlarged(s, level, 0, 0, len(level), len(level), x, 44, tile / len(level))
            head, lines = labels(chain, i)
            s.text(x, 44 + tile + 20, head, size=13, bold=True)
            fits(lines, 12, col - 8)
            s.lines(x, 44 + tile + 38, lines, size=12, leading=1.35)
        s.text(20, 280, note, size=12, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
