"""Chapter 23g: a mirrored UV island, and why TANGENT carries a sign.

One half of a texture (a UV triangle) is used twice on a face: on the right
triangle as it is, on the left one mirrored, so that u grows to the right on
one side and to the left on the other. T and B on each side are computed by
the shader's own lines (tangent_frame.py runs surface.glsl's frame on each
triangle, with one texel that leans towards +u): T turns round on the left, B
does not, so T, B, N turns the other way there, and the sign N . (T x B) is
the w a file's TANGENT stores. Without it, B = N x T would point down the left
triangle, and the map's y would turn round with it.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
panels stand one above the other, 400 units wide.
"""

from __future__ import annotations

import os

from svg import GREEN, GREY, GREY_FILL, INK, MUTED, ORANGE, PURPLE, RED, Svg
from tangent_frame import Vec, cross, dot, shader_frame

NORMAL = (0.0, 0.0, 1.0)
TEXEL = (200, 128, 220)  # a texel of a stud's right flank: it leans towards +u
# The face: two triangles that share the edge x = 0, each counter-clockwise round N.
RIGHT = [(0.0, 0.0, 0.0), (2.0, 0.0, 0.0), (0.0, 2.0, 0.0)]
LEFT = [(0.0, 0.0, 0.0), (0.0, 2.0, 0.0), (-2.0, 0.0, 0.0)]
# The one UV island, corner for corner: on the left, mirrored (u grows the other way).
ISLAND = {(0.0, 0.0): (0.2, 0.85), (2.0, 0.0): (0.8, 0.85), (0.0, 2.0): (0.2, 0.25)}
UV_RIGHT = [ISLAND[(x, y)] for x, y, _ in RIGHT]
UV_LEFT = [ISLAND[(abs(x), y)] for x, y, _ in LEFT]
WHO = "book/diagrams/23g_mirrored_uv.py"


def fmt(v):
    return "(" + ", ".join(f"{c:.2f}".replace("-0.00", "0.00") for c in v.c) + ")"


def side(p, uv):
    """T, B, the texel's normal and w = the sign of N . (T x B), as the shader makes them."""
    _, _, _, _, t, b, _, normal = shader_frame(p, uv, NORMAL, TEXEL, WHO)
    return t, b, normal, 1 if dot(Vec(*NORMAL), cross(t, b)) > 0 else -1


def island_panel(s, x, y):
    s.text(x, y, "The texture: one UV island", size=13, bold=True)
    side_px, left, top = 150, x + 14, y + 18
    s.rect(left, top, side_px, side_px, fill="#ffffff", stroke=GREY, width=1)
    pts = [(left + u * side_px, top + v * side_px) for u, v in ISLAND.values()]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    s.line(pts[0][0], pts[0][1], pts[1][0], pts[1][1], stroke=ORANGE, width=2, arrow="end")
    s.text(pts[1][0] - 4, pts[1][1] + 16, "u grows", size=12, fill=ORANGE, anchor="end")
    s.text(left, top + side_px + 18, "its one stud texel leans to +u:", size=12, fill=MUTED)
    s.text(left, top + side_px + 34, f"RGB {TEXEL}", size=12, fill=MUTED)
    return top + side_px + 34


def face_panel(s, x, y, w, right, left):
    s.text(x, y, "On the face: used twice, mirrored on the left", size=13, bold=True)
    k = min(w / 4.6, 80)
    ox, oy = x + w / 2, y + 30 + 2.2 * k

    def at(p):
        return ox + k * p[0], oy - k * p[1]

    for tri, uv_side in ((LEFT, "mirrored"), (RIGHT, "as it is")):
        s.polygon([at(p) for p in tri], fill=GREY_FILL, stroke=GREY, width=1.2)
    s.line(*at((0, 0)), *at((0, 2)), stroke=INK, width=1, dash="4 3")
    rows = []
    for (t, b, normal, w_sign), centre, name in ((left, (-0.7, 0.6), "left"), (right, (0.7, 0.6), "right")):
        o = at(centre)
        s.line(*o, *at((centre[0] + 0.9 * t.x, centre[1] + 0.9 * t.y)), stroke=RED, width=2.4, arrow="end")
        s.line(*o, *at((centre[0] + 0.9 * b.x, centre[1] + 0.9 * b.y)), stroke=GREEN, width=2.4, arrow="end")
        tip = at((centre[0] + 0.9 * t.x, centre[1] + 0.9 * t.y))
        s.text(tip[0] + (-6 if t.x < 0 else 6), tip[1] + 16, "T", size=13, bold=True, fill=RED,
               anchor="end" if t.x < 0 else "start")
        btip = at((centre[0] + 0.9 * b.x, centre[1] + 0.9 * b.y))
        s.text(btip[0] + 6, btip[1] + 4, "B", size=13, bold=True, fill=GREEN)
        s.circle(*o, 3, fill=INK, stroke=INK)
        # The texel's normal, its part along the face: the stud's lean, mirrored on the left.
        lean = (centre[0], centre[1] + 0.45)
        s.line(*at(lean), *at((lean[0] + normal.x, lean[1] + normal.y)), stroke=PURPLE, width=2, arrow="end")
        ltip = at((lean[0] + normal.x, lean[1] + normal.y))
        s.text(ltip[0] + (-4 if normal.x < 0 else 4), ltip[1] - 6, "n'", size=13, bold=True, fill=PURPLE,
               anchor="end" if normal.x < 0 else "start")
        if w_sign < 0:  # B as N x T alone, without w: down the face
            wrong = cross(Vec(*NORMAL), t)
            end = at((centre[0] + 0.9 * wrong.x, centre[1] + 0.9 * wrong.y))
            s.line(*o, *end, stroke=GREEN, width=1.4, dash="4 3", arrow="end")
            s.text(end[0] - 6, end[1] + 4, "N × T, no w", size=12, fill=GREEN, anchor="end")
        s.text(o[0] + (-30 if w_sign < 0 else 0), oy + 22 + (30 if w_sign < 0 else 0), f"w = {w_sign:+d}", size=13, bold=True, anchor="middle",
               fill=PURPLE if w_sign < 0 else INK)
        rows.append((name, t, b, normal, w_sign))
    s.text(ox, oy - 2.2 * k - 6, "N out of the page", size=12, fill=MUTED, anchor="middle")
    ty = oy + 78
    for name, t, b, normal, w_sign in rows:
        s.text(x, ty, f"{name}: T = {fmt(t)}, B = {fmt(b)}", size=12)
        s.text(x, ty + 16, f"    the texel's normal n' = {fmt(normal)}", size=12, fill=PURPLE)
        ty += 36
    return ty, rows


def main() -> None:
    right, left = side(RIGHT, UV_RIGHT), side(LEFT, UV_LEFT)
    without = cross(Vec(*NORMAL), left[0])  # B as N x T alone, on the left
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23g: a mirrored UV island turns T round, and TANGENT's w says so"
    desc = (f"One UV island used twice on a face: on the right as it is, on the left mirrored. On the right "
            f"T = {fmt(right[0])} and B = {fmt(right[1])}, w = {right[3]:+d}; on the left T = {fmt(left[0])}, "
            f"B = {fmt(left[1])}, w = {left[3]:+d}. A texel leaning towards +u gives the normal "
            f"{fmt(right[2])} on the right and {fmt(left[2])} on the left: a mirror image, as the texture is. "
            f"Without w, B = N x T on the left would be {fmt(without)}: the map's y turned round.")
    foot = [f"w = sign of N \u00b7 (T \u00d7 B): a file's TANGENT stores it, and the shader's B is w N \u00d7 T.",
            f"Without it, B on the left would be N \u00d7 T = {fmt(without)}: down the face, so the",
            "map's y would turn round there. The frame made from dFdx and dFdy needs no w:",
            "it follows u's and v's gradients on each triangle, as these numbers do."]
    if narrow:
        s = Svg(400, 1200, title, desc)
        y = island_panel(s, 15, 24)
        y, _ = face_panel(s, 15, y + 36, 370, right, left)
        foot = ["w = sign of N \u00b7 (T \u00d7 B): a file's TANGENT",
                "stores it, and the shader's B is w N \u00d7 T.",
                "Without it, B on the left would be",
                f"N \u00d7 T = {fmt(without)}: down the face,",
                "so the map's y would turn round there.",
                "The frame made from dFdx and dFdy needs",
                "no w: it follows u's and v's gradients."]
        s.lines(15, y + 10, foot, size=11.5, fill=INK)
        s.height = y + 10 + len(foot) * 11.5 * 1.3 + 4
    else:
        s = Svg(760, 600, title, desc)
        island_panel(s, 20, 24)
        y, _ = face_panel(s, 260, 24, 480, right, left)
        s.lines(20, y + 14, foot, size=12, fill=INK)
        s.height = y + 14 + len(foot) * 12 * 1.3 + 2
    s.write()


if __name__ == "__main__":
    main()
