"""Chapter 22: percentage-closer filtering, nine comparisons around a point.

A patch of one cascade's shadow map near a shadow's edge, seen from the
light: each texel stores a depth, the caster's (near the light) on the left,
the floor's on the right. The point being lit lands at the cross; its depth
from the light is the floor's. Each of the nine taps (the point's position
plus -1, 0 or +1 texel in x and y, as scene.frag's pcf block takes them)
compares the point's depth with one texel's: lit where the stored depth is
not nearer, in shadow where the caster is. Here 6 of the 9 taps are lit, so
the point gets 6/9 of the light. Averaging the depths first would compare
against a depth where nothing is. Numbers as drawn, not the chapter's.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
figure is 400 units wide: the patch on top, the words under it.
"""

import os

from svg import GREEN, GREEN_FILL, GREY, INK, MUTED, RED, RED_FILL, Svg, wrap

W, H = 1000, 390
CELL = 56
# Stored depths of a 5 x 5 patch (0 near the light, 1 far): a caster covers
# the two left columns, the floor the rest.
DEPTHS = [[0.31, 0.31, 0.72, 0.72, 0.72] for _ in range(5)]
POINT_DEPTH = 0.72  # the point being lit lies on the floor


TITLE = "Chapter 22: percentage-closer filtering, nine comparisons around the point"
DESCRIPTION = ("A five by five patch of a shadow map near a shadow's edge: the two left columns store "
               "the caster's depth, 0.31, the rest the floor's, 0.72. The point being lit lies on the "
               "floor at depth 0.72, one texel right of the edge. The nine taps around it compare "
               "0.72 with each stored depth: the three in the caster's column are in shadow, the six "
               "others lit, so the point gets six ninths of the light. Averaging the nine depths first "
               "would give 0.58, a depth where nothing is.")
HEADING = "PCF: nine comparisons, then the average of the answers"
PX, PY = 2, 2  # the point's texel
AVERAGE = sum(DEPTHS[r][c] for r in range(PY - 1, PY + 2) for c in range(PX - 1, PX + 2)) / 9


def patch(s: Svg, x0: float, y0: float) -> int:
    """The 5 x 5 patch at (x0, y0), the taps coloured by their answer; returns the taps lit."""
    lit = 0
    for row in range(5):
        for col in range(5):
            x, y = x0 + col * CELL, y0 + row * CELL
            depth = DEPTHS[row][col]
            tap = abs(row - PY) <= 1 and abs(col - PX) <= 1
            if tap:
                passes = POINT_DEPTH <= depth + 1e-6
                lit += passes
                fill, stroke = (GREEN_FILL, GREEN) if passes else (RED_FILL, RED)
                s.rect(x, y, CELL, CELL, fill=fill, stroke=stroke, width=2)
            else:
                s.rect(x, y, CELL, CELL, fill="#f2f4f6", stroke=GREY, width=1)
            s.text(x + CELL / 2, y + CELL / 2 + 5, f"{depth:.2f}", size=13, anchor="middle",
                   fill=INK if tap else MUTED)
    cx, cy = x0 + PX * CELL + CELL / 2, y0 + PY * CELL + CELL / 2
    s.circle(cx, cy + 14, 4, fill=INK, stroke=INK)
    return lit


def paragraphs(lit: int) -> list[str]:
    return ["The point lies on the floor, at depth 0.72 from the light (the dot). Each tap compares "
            "0.72 with one texel's stored depth: lit (green) where the stored depth is not nearer "
            "the light, in shadow (red) where the caster's 0.31 is.",
            f"Taps lit: {lit} of 9, so the point gets {lit}/9 of the light: a soft edge three texels "
            "wide instead of a step.",
            f"Averaging the nine depths first would give {AVERAGE:.2f}: a depth where nothing is, "
            "which says nothing about how much of the light the point sees."]


def wide() -> Svg:
    s = Svg(W, H, TITLE, DESCRIPTION)
    s.text(20, 28, HEADING, size=14, bold=True)
    x0, y0 = 40, 60
    lit = patch(s, x0, y0)
    s.text(x0 + 2.5 * CELL, y0 + 5 * CELL + 24, "stored depths: the caster (0.31), the floor (0.72)",
           size=12.5, anchor="middle", fill=MUTED)
    tx = 380
    s.lines(tx, 90, [
        "The point lies on the floor, at depth 0.72 from the light (the dot).",
        "Each tap compares 0.72 with one texel's stored depth:",
        "lit (green) where the stored depth is not nearer the light,",
        "in shadow (red) where the caster's 0.31 is.",
        "",
        f"Taps lit: {lit} of 9, so the point gets {lit}/9 of the light: a soft",
        "edge three texels wide instead of a step.",
        "",
        "Averaging the nine depths first would give",
        f"{AVERAGE:.2f}: a depth where nothing is, which says",
        "nothing about how much of the light the point sees."], size=13)
    return s


def narrow() -> Svg:
    """The patch on top, centred; the words under it, wrapped to the width."""
    s = Svg(400, 100, TITLE, DESCRIPTION)
    x = 20
    s.lines(x, 26, wrap(HEADING, 360, 14, bold=True), size=14, bold=True)
    x0, y0 = (400 - 5 * CELL) / 2, 70
    lit = patch(s, x0, y0)
    y = y0 + 5 * CELL + 24
    s.lines(x, y, wrap("stored depths: the caster (0.31), the floor (0.72)", 360, 12.5), size=12.5,
            fill=MUTED)
    y += 40
    for text in paragraphs(lit):
        lines = wrap(text, 360, 13)
        s.lines(x, y, lines, size=13)
        y += len(lines) * 13 * 1.3 + 10
    s.height = y
    return s


def main() -> None:
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
