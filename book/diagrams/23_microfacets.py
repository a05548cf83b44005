"""Chapter 23: the vectors of the BRDF at one surface point.

A rough surface drawn as tiny mirror facets; at one point the normal n, the
directions to the eye (v) and to the light (l), and the half vector h between
them: the facets whose normal is h are the ones that mirror l into v. Angles
as drawn, not to scale. The frame's two passes, which this figure once showed
beside it, are page 23b's (23b_two_passes.py); D, G and F as facet sketches
are 23_dfg_facets.py.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
figure is 400 units wide: narrower facets, the four lines on D, G and F
wrapped under it.
"""

import math
import os

from svg import BLUE, GREEN, GREY, INK, MUTED, ORANGE, Svg, wrap

W, H = 520, 350
NARROW_W = 400
TERMS = ["D(n·h): how many facets face h (GGX, width α = roughness²)",
         "G(n·l, n·v): how many of those are both lit and seen (Smith)",
         "F(v·h): how much a facet reflects at that angle (Schlick, from F₀)",
         "specular = D G F / (4 n·l n·v);  diffuse = (1 − F) c / π"]


def ray(s, x0, y0, angle_deg, length, colour, label, dx=0, dy=0):
    a = math.radians(angle_deg)
    x1, y1 = x0 + length * math.sin(a), y0 - length * math.cos(a)
    s.line(x0, y0, x1, y1, stroke=colour, width=2.2, arrow="end")
    s.text(x1 + dx, y1 + dy, label, size=15, anchor="middle", fill=colour, bold=True)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    s = Svg(NARROW_W if narrow else W, H, "Chapter 23: the BRDF's vectors at one point of a rough surface",
            "A rough surface seen as tiny mirror facets; at the point, the normal n, the direction v "
            "to the eye and l to the light, and the half vector h between them. D counts the facets "
            "facing h, G the ones neither hidden nor shadowed, F how much a facet reflects at the "
            "angle v.h.")
    s.text(20, 28, "At one point: n, v, l and the half vector h", size=15, bold=True)
    # The surface as a row of small facets, tilted this way and that.
    x0, y0 = (44, 220) if narrow else (50, 220)
    w = 26 if narrow else 30  # one facet's width
    tilts = [12, -18, 8, -6, 20, -12, 4, -20, 14, -8, 10, -14]
    x = x0
    for t in tilts:
        dy = w * math.tan(math.radians(t)) / 2
        s.line(x, y0 + dy, x + w, y0 - dy, stroke=GREY, width=2)
        x += w
    cx = x0 + 6 * w
    s.line(x0 - 10, y0 + 14, x + 10, y0 + 14, stroke=MUTED, width=1, dash="4 4")
    s.text(x + 4, y0 + 34, "surface", size=13, fill=MUTED, anchor="end")
    ray(s, cx, y0, 0, 150, INK, "n", dy=-8)
    ray(s, cx, y0, -55, 170, BLUE, "v (to the eye)", dx=18 if narrow else -6, dy=-10)
    ray(s, cx, y0, 35, 170, ORANGE, "l (to the light)", dx=20, dy=-8)
    ray(s, cx, y0, -10, 130, GREEN, "h = normalize(v + l)", dx=-78, dy=-6)
    if narrow:  # a line too wide breaks before its bracket, the rest indented
        y = 272
        for term in TERMS:
            head, bracket, rest = term.rpartition(" (")
            lines = [head, bracket.strip() + rest] if head and len(wrap(term, NARROW_W - 40, 13.5)) > 1 \
                else wrap(term, NARROW_W - 40, 13.5)
            s.text(20, y, lines[0], size=13.5)
            s.lines(34, y + 13.5 * 1.3, lines[1:], size=13.5)
            y += len(lines) * 13.5 * 1.3
        s.height = y + 4
    else:
        s.lines(20, 272, TERMS, size=13.5)
    s.write()


if __name__ == "__main__":
    main()
