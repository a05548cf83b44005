"""Chapter 23g: the tangent frame made from a triangle's edges and its UVs.

One triangle with texture coordinates, in three panels: the triangle in
position space with its edges e1 and e2; the same triangle in UV space (v down
the image, as glTF has it) with the edges' (du, dv); and the frame that comes
out, T, B and N drawn on the surface, with one normal-map texel's (x, y, z)
turned into a direction in that frame.

The numbers are not typed here: T, B and the texel's normal are computed by the
very lines of shaders/23_materials/surface.glsl (tangent_frame.py reads and runs
them), with dFdx and dFdy standing for e1 and e2 and their (du, dv). e1 and e2
turn counter-clockwise round N, so the formula's A is positive (the page says
why that matters).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the three
panels stand one above the other, 400 units wide.
"""

from __future__ import annotations

import os

from svg import BLUE, GREEN, GREY, GREY_FILL, INK, MUTED, ORANGE, PURPLE, RED, Svg
from tangent_frame import Vec, shader_frame

# The example: a triangle in the plane z = 0 (its normal +z), its UVs, and one texel.
P = [(0.0, 0.0, 0.0), (4.0, 1.0, 0.0), (1.0, 3.0, 0.0)]
UV = [(0.10, 0.85), (0.90, 0.65), (0.25, 0.15)]
NORMAL = (0.0, 0.0, 1.0)
TEXEL = (215, 150, 205)  # the normal map's RGB at the point, 0..255


# ---- drawing --------------------------------------------------------------------------

def view(p, ox, oy, k):
    """A point of the plane z = 0 (and above it) on the page: x to the right, y going
    back (up and a little to the left), z straight up: the plane drawn as a floor."""
    x, y, z = p
    return ox + k * (x - 0.3 * y), oy - k * (0.5 * y + z)


def fmt(v):
    return "(" + ", ".join(f"{c:.2f}".replace("-0.00", "0.00") for c in v.c) + ")"


def arrow(s, a, b, colour, width=2.0, dash=None):
    s.line(a[0], a[1], b[0], b[1], stroke=colour, width=width, arrow="end", dash=dash)


def position_panel(s, x, y, w, e1, e2):
    s.text(x, y, "1. The triangle in position space", size=13, bold=True)
    k = w / 5.2
    ox, oy = x + 0.5 * k, y + 30 + 1.6 * k
    pts = [view(p, ox, oy, k) for p in P]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    arrow(s, pts[0], pts[1], BLUE)
    arrow(s, pts[0], pts[2], ORANGE)
    for i, ((px, py), (dx, dy)) in enumerate(zip(pts, [(-6, 18), (6, 4), (0, -8)])):
        s.text(px + dx, py + dy, f"P_{{{i}}}", size=12, anchor="end" if i == 0 else "start")
    m1 = view([(a + b) / 2 for a, b in zip(P[0], P[1])], ox, oy, k)
    m2 = view([(a + b) / 2 for a, b in zip(P[0], P[2])], ox, oy, k)
    s.text(m1[0] + 4, m1[1] + 18, "e_{1}", size=13, fill=BLUE, bold=True)
    s.text(m2[0] - 8, m2[1], "e_{2}", size=13, fill=ORANGE, bold=True, anchor="end")
    ty = oy + 46
    s.lines(x, ty, [f"e_{{1}} = P_{{1}} \u2212 P_{{0}} = {fmt(e1)}",
                    f"e_{{2}} = P_{{2}} \u2212 P_{{0}} = {fmt(e2)}",
                    "(in the plane z = 0, drawn as a floor)"], size=12)
    return ty + 3 * 12 * 1.3


def uv_panel(s, x, y, w, duv1, duv2):
    s.text(x, y, "2. The same triangle in UV space", size=13, bold=True)
    side = min(w - 90, 200)
    left, top = x + 26, y + 22
    s.rect(left, top, side, side, fill="#ffffff", stroke=GREY, width=1)
    for f in (0.25, 0.5, 0.75):
        s.line(left + f * side, top, left + f * side, top + side, stroke="#e6eaef", width=1)
        s.line(left, top + f * side, left + side, top + f * side, stroke="#e6eaef", width=1)
    s.text(left - 4, top + 4, "0", size=11, anchor="end", fill=MUTED)
    arrow(s, (left, top - 8), (left + side, top - 8), MUTED, width=1)
    s.text(left + side + 4, top - 4, "u", size=12, fill=MUTED, italic=True)
    arrow(s, (left - 12, top), (left - 12, top + side), MUTED, width=1)
    s.text(left - 16, top + side + 2, "v", size=12, fill=MUTED, italic=True, anchor="end")
    pts = [(left + u * side, top + v * side) for u, v in UV]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    arrow(s, pts[0], pts[1], BLUE)
    arrow(s, pts[0], pts[2], ORANGE)
    for i, (px, py) in enumerate(pts):
        s.text(px + (8 if i else -4), py + (14 if i == 0 else 4), f"uv_{{{i}}}", size=12,
               anchor="end" if i == 0 else "start")
    tx = left + side + 12
    s.lines(tx, top + 40, ["v grows", "down the", "image"], size=11.5, fill=MUTED)
    ty = top + side + 24
    s.lines(x, ty, [f"(du_{{1}}, dv_{{1}}) = uv_{{1}} \u2212 uv_{{0}} = {fmt(duv1)}",
                    f"(du_{{2}}, dv_{{2}}) = uv_{{2}} \u2212 uv_{{0}} = {fmt(duv2)}"], size=12)
    return ty + 2 * 12 * 1.3


def frame_panel(s, x, y, w, t, b, m, result, text_at=None):
    """The frame on the triangle; its numbers below it, or at text_at (x, y) beside it."""
    s.text(x, y, "3. The frame, and one texel in it", size=13, bold=True)
    k = w / 5.2
    ox, oy = x + 0.5 * k, y + 30 + 2.6 * k
    pts = [view(p, ox, oy, k) for p in P]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    centre = tuple(sum(c) / 3 for c in zip(*P))
    o = view(centre, ox, oy, k)
    L = 1.8  # the drawn length of a unit vector, in world units

    def tip(v):
        return view(tuple(c + L * d for c, d in zip(centre, v.c)), ox, oy, k)

    nvec = Vec(*NORMAL)
    arrow(s, o, tip(t), RED, width=2.4)
    arrow(s, o, tip(b), GREEN, width=2.4)
    arrow(s, o, tip(nvec), BLUE, width=2.4)
    # The texel's direction: x along T, then y along B, then z along N, dashed.
    along_t = tip(t * m.x)
    along_tb = tip(t * m.x + b * m.y)
    s.polyline([o, along_t, along_tb, tip(t * m.x + b * m.y + nvec * m.z)], stroke=MUTED, width=1,
               dash="3 3")
    arrow(s, o, tip(result), PURPLE, width=2.6)
    for v, name, colour, dx, dy in ((t, "T", RED, 6, 12), (b, "B", GREEN, -6, -4),
                                    (nvec, "N", BLUE, -8, 0), (result, "n'", PURPLE, 6, -2)):
        px, py = tip(v)
        s.text(px + dx, py + dy, name, size=13, bold=True, fill=colour, anchor="end" if dx < 0 else "start")
    tx, ty = text_at or (x, oy + 34)
    rows = [(f"T = {fmt(t)}: where u grows", RED),
            (f"B = {fmt(b)}: where v falls (image up)", GREEN),
            (f"N = {fmt(nvec)}", BLUE),
            (f"texel RGB {TEXEL} \u00d7 2/255 \u2212 1", INK),
            (f"  = (x, y, z) = {fmt(m.xyz)}", INK),
            ("n' = normalize(x T + y B + z N)", PURPLE),
            (f"   = {fmt(result)}", PURPLE)]
    for i, (row, colour) in enumerate(rows):
        s.text(tx, ty + i * 12 * 1.3, row, size=12, fill=colour)
    return max(ty + len(rows) * 12 * 1.3, oy + 20)


def main() -> None:
    e1, e2, duv1, duv2, t, b, m, result = shader_frame(P, UV, NORMAL, TEXEL,
                                                       "book/diagrams/23g_tangent_frame.py")
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23g: the tangent frame made from a triangle's edges and its texture coordinates"
    desc = (f"A triangle with corners P0, P1, P2 in the plane z = 0; its edges e1 = {fmt(e1)} and "
            f"e2 = {fmt(e2)}. The same triangle in UV space, v down the image: its edges' (du, dv) are "
            f"{fmt(duv1)} and {fmt(duv2)}. From them the shader's lines make T = {fmt(t)}, the direction "
            f"in which u grows, and B = {fmt(b)}, the direction in which v falls; N is (0, 0, 1). A "
            f"normal-map texel of RGB {TEXEL} is (x, y, z) = {fmt(m.xyz)}, and x T + y B + z N, "
            f"normalised, is {fmt(result)}: a normal leaning along T and B.")
    foot = ["Every number is computed by the lines of surface.glsl's normal map,",
            "with dFdx and dFdy standing for the steps along e1 and e2."]
    if narrow:
        w = 370
        s = Svg(400, 2000, title, desc)
        s.text(15, 24, "The tangent frame from edges and UVs", size=14, bold=True)
        y = position_panel(s, 15, 52, w, e1, e2)
        y = uv_panel(s, 15, y + 30, w, duv1, duv2)
        y = frame_panel(s, 15, y + 30, w, t, b, m, result)
        s.lines(15, y + 16, ["Every number is computed by the lines of", "surface.glsl's normal map, with dFdx and",
                             "dFdy standing for the steps along e1 and e2."], size=11.5, fill=MUTED)
        s.height = y + 16 + 3 * 11.5 * 1.3 + 4
    else:
        w = 340
        s = Svg(760, 900, title, desc)
        s.text(20, 26, "The tangent frame, made from a triangle's edges and its UVs", size=15, bold=True)
        y = max(position_panel(s, 20, 60, w, e1, e2), uv_panel(s, 400, 60, w, duv1, duv2))
        y = frame_panel(s, 20, y + 40, w, t, b, m, result, text_at=(400, y + 40 + 80))
        s.lines(20, y + 24, foot, size=12, fill=MUTED)
        s.height = y + 24 + 2 * 12 * 1.3
    s.write()


if __name__ == "__main__":
    main()
