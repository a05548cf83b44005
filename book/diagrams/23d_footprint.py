"""Chapter 23d: where the bloom's taps land, down and up.

Left, the way down (shaders/common/bloom/bloom_down.comp): one texel of the
smaller level, whose centre sits on a texel corner of the level above, takes
four bilinear taps at (+-1, +-1) texels of the level above. Each tap sits on
the corner of four texels, so the filter hands it their mean; the four 2x2
blocks together cover 4x4 texels, each texel weighted 1/16.

Right, the way up (bloom_up.comp, radius 1 as in chapter 23): one texel of
the larger level takes a 3x3 tent of taps of the smaller level, spaced one
texel of it apart, weights (1, 2, 1) by (1, 2, 1) over 16. Its centre sits a
quarter texel from a texel centre of the smaller level, so every tap blends
neighbours too: the nine taps reach 4x4 texels.

Nothing here is typed in: the down taps' offsets and the tent's weight formula
are read from the shaders (a shader that no longer says them stops the build),
and every texel's weight is worked out by running the taps through bilinear
filtering, as the sampler does, at an even size (8 to 4, 4 to 8).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
panels are stacked, 400 units wide.
"""

import os
import re
from fractions import Fraction
from pathlib import Path

from svg import BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE, \
    PURPLE_FILL, Svg, wrap

ROOT = Path(__file__).resolve().parents[2]
BLOOM = ROOT / "shaders" / "common" / "bloom"
BLOOM_HPP = ROOT / "common" / "resources" / "include" / "vkt" / "resources" / "bloom.hpp"


def folded(path: Path) -> str:
    return " ".join(path.read_text(encoding="utf-8").split())


def need(path: Path, line: str) -> None:
    if " ".join(line.split()) not in folded(path):
        raise SystemExit(f"{path.relative_to(ROOT)} no longer says `{line}`; "
                         "redraw book/diagrams/23d_footprint.py")


# The way down: four taps at texel * vec2(x, y), averaged with 0.25 each.
DOWN_TAPS = [(Fraction(x), Fraction(y)) for x, y in re.findall(
    r"texture\(source, uv \+ texel \* vec2\(([-0-9.]+), ([-0-9.]+)\)\)",
    folded(BLOOM / "bloom_down.comp"))]
if len(DOWN_TAPS) != 4:
    raise SystemExit("bloom_down.comp: expected four taps; redraw book/diagrams/23d_footprint.py")
need(BLOOM / "bloom_down.comp", "imageStore(target, p, vec4(0.25 * (a + b + c + d), 1.0));")
DOWN_NAMES = "abcd"  # the shader's names for the four taps, in its order

# The way up: a tent of radius r, weight (r + 1 - |x|) (r + 1 - |y|) over (r + 1)^4.
need(BLOOM / "bloom_up.comp", "sum += float((r + 1 - abs(x)) * (r + 1 - abs(y))) *")
need(BLOOM / "bloom_up.comp", "texture(source, uv + texel * vec2(x, y)).rgb;")
need(BLOOM / "bloom_up.comp", "float total = float((r + 1) * (r + 1));")
RADIUS = int(re.search(r"uint32_t radius = (\d+)", folded(BLOOM_HPP)).group(1))


def tent(x: int) -> int:
    return RADIUS + 1 - abs(x)


def bilinear(size: int, at: Fraction) -> dict[int, Fraction]:
    """The texels (of a row of `size`) that linear filtering blends at `at`, in texel units."""
    s = at - Fraction(1, 2)  # texel k's centre is at k + 1/2
    k = s.numerator // s.denominator
    f = s - k
    out: dict[int, Fraction] = {}
    for texel, weight in ((k, 1 - f), (k + 1, f)):
        texel = min(max(texel, 0), size - 1)  # clamp to the edge
        if weight:
            out[texel] = out.get(texel, 0) + weight
    return out


def centre(p: int, target: int, source: int) -> Fraction:
    """uv = (p + 0.5) / target, in texels of the source: what both shaders sample around."""
    return (p + Fraction(1, 2)) / target * source


# Per axis: (texel -> weight) and the taps (position, weight), for one target texel.
def down_axis():
    source, target, p = 8, 4, 1
    c = centre(p, target, source)
    offsets = sorted({x for x, _ in DOWN_TAPS})
    weights: dict[int, Fraction] = {}
    for dx in offsets:
        for texel, w in bilinear(source, c + dx).items():
            weights[texel] = weights.get(texel, 0) + w / len(offsets)
    return c, weights, [c + dx for dx in offsets]


def up_axis():
    source, target, p = 4, 8, 4
    c = centre(p, target, source)
    total = sum(tent(x) for x in range(-RADIUS, RADIUS + 1))
    weights: dict[int, Fraction] = {}
    for dx in range(-RADIUS, RADIUS + 1):
        for texel, w in bilinear(source, c + dx).items():
            weights[texel] = weights.get(texel, 0) + w * tent(dx) / total
    return c, weights, [(c + dx, tent(dx)) for dx in range(-RADIUS, RADIUS + 1)]


DOWN = down_axis()
UP = up_axis()
for _, w, _ in (DOWN, UP):
    assert sum(w.values()) == 1 and len(w) == 4  # the mean is kept; 4 texels a side
DOWN_FIRST = min(DOWN[1])
UP_FIRST = min(UP[1])
UP_SIXTEENTHS = [int(UP[1][t] * 16) for t in sorted(UP[1])]
assert all(UP[1][t] * 16 == n for t, n in zip(sorted(UP[1]), UP_SIXTEENTHS))

TITLE = "Chapter 23d: where the bloom's taps land, on the way down and on the way up"
DESCRIPTION = (
    "Left, the way down: a 4 by 4 grid of texels of the level above, split into four 2 by 2 "
    "blocks in four colours, with a tap (a, b, c, d) on the corner at the middle of each block; "
    "the texel being written, dashed, covers the middle 2 by 2. Each tap is the mean of its "
    "block, so every texel weighs 1/4 across and 1/4 down, 1/16 in all. Right, the way up: a 4 by "
    "4 grid of texels of the smaller level, shaded by weight, with nine taps one texel apart "
    "marked with the tent's weights 1 2 1, 2 4 2, 1 2 1; the texel being written, dashed, is a "
    "quarter of a texel of the smaller level, and the taps sit a quarter texel from texel "
    "centres, so across and down the four texels weigh " + ", ".join(map(str, UP_SIXTEENTHS)) +
    " sixteenths.")

CELL_WIDE, CELL_NARROW = 60, 52
BLOCK_FILLS = [(BLUE_FILL, BLUE), (ORANGE_FILL, ORANGE), (PURPLE_FILL, PURPLE), (GREEN_FILL, GREEN)]


def shade(weight: Fraction, most: Fraction) -> str:
    """White for no weight to a mid green for the most."""
    t = float(weight / most)
    low, high = (255, 255, 255), (120, 196, 138)
    return "#" + "".join(f"{round(a + (b - a) * t):02x}" for a, b in zip(low, high))


def frac(w: Fraction) -> str:
    return f"{w.numerator}/{w.denominator}"


def headers(s: Svg, x0: float, y0: float, cell: float, weights: dict[int, Fraction],
            first: int, note: str) -> None:
    """Each column's and row's weight (per axis) above and left of the grid."""
    for i, texel in enumerate(sorted(weights)):
        label = frac(weights[texel])
        s.text(x0 + (i + 0.5) * cell, y0 - 8, label, size=12, anchor="middle", fill=MUTED)
        s.text(x0 - 8, y0 + (i + 0.5) * cell + 4, label, size=12, anchor="end", fill=MUTED)
    s.text(x0 - 8, y0 - 8, note, size=12, anchor="end", fill=MUTED, italic=True)


def down_grid(s: Svg, x0: float, y0: float, cell: float) -> None:
    c, weights, taps = DOWN
    first = DOWN_FIRST
    headers(s, x0, y0, cell, weights, first, "per axis")
    pos = lambda v: x0 + float(v - first) * cell  # noqa: E731  (texel units to the page)
    posy = lambda v: y0 + float(v - first) * cell  # noqa: E731
    for name, (dx, dy) in zip(DOWN_NAMES, DOWN_TAPS):
        tx, ty = c + dx, c + dy
        fill, stroke = BLOCK_FILLS[DOWN_NAMES.index(name)]
        for bx in (tx - Fraction(1, 2), tx + Fraction(1, 2)):
            for by in (ty - Fraction(1, 2), ty + Fraction(1, 2)):
                s.rect(pos(bx - Fraction(1, 2)), posy(by - Fraction(1, 2)), cell, cell, fill=fill,
                       stroke="#c2cad3", width=1)
        s.circle(pos(tx), posy(ty), 5, fill=stroke, stroke=stroke)
        s.text(pos(tx) + 8, posy(ty) - 7, f"`{name}`", size=13, fill=stroke, bold=True)
    s.rect(x0, y0, 4 * cell, 4 * cell, stroke=INK, width=1.2)
    # The texel being written: the middle 2x2 of the level above.
    s.rect(pos(c - 1), posy(c - 1), 2 * cell, 2 * cell, stroke=INK, width=2.2, dash="6 4")
    s.line(pos(c) - 6, posy(c), pos(c) + 6, posy(c), stroke=INK, width=1.6)  # its centre
    s.line(pos(c), posy(c) - 6, pos(c), posy(c) + 6, stroke=INK, width=1.6)


def up_grid(s: Svg, x0: float, y0: float, cell: float) -> None:
    c, weights, taps = UP
    first = UP_FIRST
    headers(s, x0, y0, cell, weights, first, "per axis")
    most = max(weights.values()) ** 2
    for i in sorted(weights):
        for j in sorted(weights):
            s.rect(x0 + (i - first) * cell, y0 + (j - first) * cell, cell, cell,
                   fill=shade(weights[i] * weights[j], most), stroke="#c2cad3", width=1)
    s.rect(x0, y0, 4 * cell, 4 * cell, stroke=INK, width=1.2)
    pos = lambda v: x0 + float(v - first) * cell  # noqa: E731
    posy = lambda v: y0 + float(v - first) * cell  # noqa: E731
    # The texel being written: half a texel of the smaller level each way.
    half = Fraction(1, 4)
    s.rect(pos(c - half), posy(c - half), cell / 2, cell / 2, stroke=INK, width=2.2, dash="5 3")
    for tx, wx in taps:
        for ty, wy in taps:
            s.circle(pos(tx), posy(ty), 4.5, fill=INK, stroke=INK)
            s.text(pos(tx) + 18, posy(ty) + 5, str(wx * wy), size=13, bold=True, fill=INK)


def down_words() -> list[str]:
    return [
        "The dashed texel of the smaller level covers 2x2 texels of the level above. Its four "
        "taps a, b, c, d sit at its corners, each on the corner of four texels, so the filter "
        "hands each the mean of its 2x2 block, and a quarter of their sum is the plain mean "
        f"of 4x4 texels: {frac(DOWN[1][DOWN_FIRST] ** 2)} each.",
        "Exact where the level above is twice as large; from an odd size, such as 15 to 7, "
        "the taps fall a little off the corners."]


def up_words() -> list[str]:
    return [
        "The dashed texel of the larger level is a quarter of a texel of the smaller one. Its "
        "nine taps, one texel apart, weigh 1-2-1 / 2-4-2 / 1-2-1, over 16.",
        "Its centre is a quarter texel from a texel centre, so every tap blends neighbours "
        "too: the nine taps reach 4x4 texels, weighted "
        + ", ".join(map(str, UP_SIXTEENTHS)) + " sixteenths across and down (shaded)."]


DOWN_HEAD = ("Down, `bloom_down.comp`", "4 taps, each the mean of 2x2 texels of the level above")
UP_HEAD = (f"Up, `bloom_up.comp` (radius {RADIUS})", "a 3x3 tent of taps of the smaller level")


def panel(s: Svg, x: float, y: float, width: float, cell: float, head, grid, words) -> float:
    """One panel at (x, y), `width` wide; returns its bottom."""
    s.text(x, y + 16, head[0], size=14, bold=True)
    lines = wrap(head[1], width, 12.5)
    s.lines(x, y + 36, lines, size=12.5, fill=MUTED)
    gy = y + 36 + len(lines) * 16 + 26
    gx = x + (width - 4 * cell) / 2 + 20
    grid(s, gx, gy, cell)
    ty = gy + 4 * cell + 26
    for text in words():
        lines = wrap(text, width, 12.5)
        s.lines(x, ty, lines, size=12.5)
        ty += len(lines) * 12.5 * 1.3 + 6
    return ty


def wide() -> Svg:
    s = Svg(900, 100, TITLE, DESCRIPTION)
    bottom = max(panel(s, 20, 10, 410, CELL_WIDE, DOWN_HEAD, down_grid, down_words),
                 panel(s, 470, 10, 410, CELL_WIDE, UP_HEAD, up_grid, up_words))
    s.line(450, 20, 450, bottom - 10, stroke="#d1d9e0", width=1)
    s.height = bottom + 4
    return s


def narrow() -> Svg:
    s = Svg(400, 100, TITLE, DESCRIPTION.replace("Left, the way down", "Top, the way down")
            .replace("Right, the way up", "Below it, the way up"))
    y = panel(s, 16, 8, 368, CELL_NARROW, DOWN_HEAD, down_grid, down_words)
    s.line(16, y + 4, 384, y + 4, stroke="#d1d9e0", width=1)
    y = panel(s, 16, y + 14, 368, CELL_NARROW, UP_HEAD, up_grid, up_words)
    s.height = y + 4
    return s


def main() -> None:
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
