"""Chapter 23g: the two screen steps, on OpenGL and on Vulkan, and the frame they give.

A face towards the eye (N = +z, out of the page), the texture upright on it (u
grows to the right, v down the image). dFdx steps one pixel right on both APIs.
dFdy steps one pixel along the window's y: up on OpenGL, whose window y runs up,
and down on Vulkan, whose y runs down. So det = N . (dp1 x dp2) is +1 on OpenGL
and -1 on Vulkan.

The frames are not typed here: shaders/23_materials/surface.glsl's own lines
make them (tangent_frame.py runs them), once as written and once with det_sign
set to 1, OpenGL's formula as it came. On Vulkan the second comes out turned
half round: T points where u falls.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
panels stand one above the other, 400 units wide.
"""

from __future__ import annotations

import os

from svg import BLUE, GREEN, GREY, INK, MUTED, ORANGE, RED, Svg
from tangent_frame import _run, check_vulkan_steps

WHO = "book/diagrams/23g_screen_steps.py"
FLAT = (128, 128, 255)
# (title, dFdy's step in the world (y up on the page), and its (du, dv)), per API.
APIS = [("OpenGL: window y runs up", (0, 1, 0), (0, -1)),
        ("Vulkan: window y runs down", (0, -1, 0), (0, 1))]
SIDE = 150  # the face, drawn as a square in the window
STEP = 52  # one pixel's step, drawn


def fmt(v):
    return "(" + ", ".join(f"{c:.0f}".replace("-0", "0") for c in v.c) + ")"


def frames(dp2, duv2):
    """det, and (T, B) with det_sign and without it, by the shader's lines."""
    p = ((0, 0, 0), (1, 0, 0), dp2)
    uv = ((0, 0), (1, 0), duv2)
    kept = _run(p, uv, (0, 0, 1), FLAT, WHO)
    dropped = _run(p, uv, (0, 0, 1), FLAT, WHO, keep_sign=False)
    det = dp2[1]  # N . (dp1 x dp2) with dp1 = +x, N = +z: dp2's y
    return det, kept[4:6], dropped[4:6]


def panel(s, x, y, title, dp2, duv2, beside=True):
    """One API's window: the face, the two steps, the turn and the frames; its bottom."""
    det, (t, b), (t0, b0) = frames(dp2, duv2)
    s.text(x, y, title, size=14, bold=True)
    left, top = x + 24, y + 34
    s.rect(left, top, SIDE, SIDE, fill="#f6f8fa", stroke=GREY, width=1.2)
    for f in (0.25, 0.5, 0.75):
        s.line(left + f * SIDE, top, left + f * SIDE, top + SIDE, stroke="#e6eaef", width=1)
        s.line(left, top + f * SIDE, left + SIDE, top + f * SIDE, stroke="#e6eaef", width=1)
    s.line(left, top - 8, left + SIDE, top - 8, stroke=MUTED, width=1, arrow="end")
    s.text(left + SIDE + 4, top - 4, "u", size=13, fill=MUTED, italic=True)
    s.line(left - 10, top, left - 10, top + SIDE, stroke=MUTED, width=1, arrow="end")
    s.text(left - 14, top + SIDE + 4, "v", size=13, fill=MUTED, italic=True, anchor="end")
    up = dp2[1] > 0
    ydir = "up" if up else "down"
    cx, cy = left + 92, top + (92 if up else 58)
    s.circle(cx, cy, 3, fill=INK, stroke=INK)
    s.line(cx, cy, cx + STEP, cy, stroke=BLUE, width=2.4, arrow="end")
    s.text(cx + STEP + 4, cy + 4, "dFdx", size=13, fill=BLUE, bold=True)
    ey = cy - STEP if up else cy + STEP
    s.line(cx, cy, cx, ey, stroke=ORANGE, width=2.4, arrow="end")
    s.text(cx + 5, ey + (-4 if up else 14), "dFdy", size=13, fill=ORANGE, bold=True)
    # The turn from the first step to the second, a quarter circle.
    r = 22
    s.path(f"M{cx + r:.1f},{cy:.1f} A{r},{r} 0 0 {0 if up else 1} {cx:.1f},{cy + (-r if up else r):.1f}",
           stroke=INK, width=1.4, arrow="end")
    # The frame the shader makes, from the face's lower left: solid with det_sign,
    # dashed without it where that differs.
    ox, oy, L = left + 38, top + SIDE - 20, 36
    for v, colour, dash in ((t0, RED, "5 4"), (b0, GREEN, "5 4"), (t, RED, None), (b, GREEN, None)):
        if dash and (v is t0 and t0.c == t.c or v is b0 and b0.c == b.c):
            continue
        s.line(ox, oy, ox + L * v.x, oy - L * v.y, stroke=colour, width=2.2, dash=dash, arrow="end")
    s.text(ox + L * t.x + (4 if t.x > 0 else -4), oy + 14, "T", size=13, fill=RED, bold=True,
           anchor="start" if t.x > 0 else "end")
    s.text(ox - 6, oy - L * b.y, "B", size=13, fill=GREEN, bold=True, anchor="end")
    turn = "counter-clockwise" if det > 0 else "clockwise"
    facts = [f"dFdy: one pixel {ydir}", f"the turn: {turn}",
             f"det = N \u00b7 (dp_{{1}} \u00d7 dp_{{2}}) = {det:+.0f}"]
    bottom = top + SIDE + 30
    if beside:
        s.lines(left + SIDE + 26, top + 16, facts, size=12.5)
    else:
        s.lines(x, bottom, facts, size=12.5)
        bottom += len(facts) * 17 + 6
    rows = [(f"without det_sign: T = {fmt(t0)}", RED if t0.x < 0 else INK),
            (f"  B = {fmt(b0)}" + (": turned half round" if t0.x < 0 else ""), RED if t0.x < 0 else INK),
            (f"with det_sign: T = {fmt(t)}", INK),
            (f"  B = {fmt(b)}: T where u grows", INK)]
    for i, (row, colour) in enumerate(rows):
        s.text(x, bottom + i * 17, row, size=12.5, fill=colour)
    return bottom + len(rows) * 17


def main() -> None:
    check_vulkan_steps(WHO)
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23g: the screen steps dFdx and dFdy on OpenGL and on Vulkan"
    description = (
        "Two windows, each with a face towards the eye and its texture upright: u grows to the right, "
        "v down. dFdx steps one pixel right in both. On OpenGL dFdy steps one pixel up, a "
        "counter-clockwise turn from dFdx, and det is +1; the formula then gives T pointing right, "
        "where u grows, and B up. On Vulkan dFdy steps one pixel down, a clockwise turn, and det is "
        "-1; without det_sign the formula gives T pointing left and B down, turned half round "
        "(dashed); with det_sign T points right and B up again (solid).")
    if narrow:
        height = 2 * 345 + 96
        s = Svg(400, height, title, description)
        bottom = panel(s, 14, 26, *APIS[0], beside=False)
        panel(s, 14, bottom + 40, *APIS[1], beside=False)
        s.lines(14, height - 28, ["N points out of the page. T and B from the shader's lines;",
                                  "dashed: without det_sign, where that differs."], size=12, fill=MUTED)
        s.write()
        return
    s = Svg(860, 340, title, description)
    for i, api in enumerate(APIS):
        panel(s, 20 + i * 430, 26, *api)
    s.text(20, 328, "N points out of the page, towards the eye. T and B from the shader's own "
           "lines; dashed: without det_sign, where that differs.", size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
