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
"""

from svg import GREEN, GREEN_FILL, GREY, INK, MUTED, RED, RED_FILL, Svg

W, H = 1000, 390
CELL = 56
# Stored depths of a 5 x 5 patch (0 near the light, 1 far): a caster covers
# the two left columns, the floor the rest.
DEPTHS = [[0.31, 0.31, 0.72, 0.72, 0.72] for _ in range(5)]
POINT_DEPTH = 0.72  # the point being lit lies on the floor


def main() -> None:
    s = Svg(W, H, "Chapter 22: percentage-closer filtering, nine comparisons around the point",
            "A five by five patch of a shadow map near a shadow's edge: the two left columns store "
            "the caster's depth, 0.31, the rest the floor's, 0.72. The point being lit lies on the "
            "floor at depth 0.72, one texel right of the edge. The nine taps around it compare "
            "0.72 with each stored depth: the three in the caster's column are in shadow, the six "
            "others lit, so the point gets six ninths of the light. Averaging the nine depths first "
            "would give 0.58, a depth where nothing is.")
    s.text(20, 28, "PCF: nine comparisons, then the average of the answers", size=14, bold=True)
    x0, y0 = 40, 60
    px, py = 2, 2  # the point's texel
    lit = 0
    for row in range(5):
        for col in range(5):
            x, y = x0 + col * CELL, y0 + row * CELL
            depth = DEPTHS[row][col]
            tap = abs(row - py) <= 1 and abs(col - px) <= 1
            if tap:
                passes = POINT_DEPTH <= depth + 1e-6
                lit += passes
                fill, stroke = (GREEN_FILL, GREEN) if passes else (RED_FILL, RED)
                s.rect(x, y, CELL, CELL, fill=fill, stroke=stroke, width=2)
            else:
                s.rect(x, y, CELL, CELL, fill="#f2f4f6", stroke=GREY, width=1)
            s.text(x + CELL / 2, y + CELL / 2 + 5, f"{depth:.2f}", size=13, anchor="middle",
                   fill=INK if tap else MUTED)
    cx, cy = x0 + px * CELL + CELL / 2, y0 + py * CELL + CELL / 2
    s.circle(cx, cy + 14, 4, fill=INK, stroke=INK)
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
        f"{sum(DEPTHS[r][c] for r in range(1, 4) for c in range(1, 4)) / 9:.2f}: a depth where "
        "nothing is, which says",
        "nothing about how much of the light the point sees."], size=13)
    s.write()


if __name__ == "__main__":
    main()
