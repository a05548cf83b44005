"""Chapter 08: the view frustum in camera space, and Vulkan's clip space.

Numbers from chapters/08_depth/main.cpp: glm::perspective(45 degrees, aspect,
0.1, 100) with GLM_FORCE_DEPTH_ZERO_TO_ONE and proj[1][1] negated. The depth
curve is depth = F (d - n) / (d (F - n)), as book/08_depth.md derives.
"""

import math

from svg import BLUE, GREY, INK, MUTED, ORANGE, PURPLE, PURPLE_FILL, Svg

W, H = 1000, 620
NEAR, FAR = 0.1, 100.0


def main() -> None:
    s = Svg(W, H, "Chapter 08: the view frustum and Vulkan's clip space",
            "Left: the camera looks down minus z; its frustum is cut by the near plane (0.1) and the "
            "far plane (100), 45 degrees high. Right: after the projection and the divide by w, x and "
            "y run from -1 to 1 with y pointing down, depth from 0 at the near plane to 1 at the far "
            "plane. Below: depth against distance, half the range used by twice the near distance.")

    # ---- Left: camera space, seen from the side -----------------------------------------
    s.text(20, 28, "Camera space, from the side (not to scale)", size=14, bold=True)
    ex, ey = 50, 196
    half = math.radians(22.5)
    near_x, far_x = 215, 390
    top = lambda x: ey - (x - ex) * math.tan(half)
    bottom = lambda x: ey + (x - ex) * math.tan(half)
    s.polygon([(near_x, top(near_x)), (far_x, top(far_x)), (far_x, bottom(far_x)), (near_x, bottom(near_x))],
              fill=PURPLE_FILL, stroke="none", opacity=0.7)
    s.line(ex, ey, far_x + 20, top(far_x + 20), stroke=GREY, dash="4 3")
    s.line(ex, ey, far_x + 20, bottom(far_x + 20), stroke=GREY, dash="4 3")
    s.line(near_x, top(near_x), near_x, bottom(near_x), stroke=BLUE, width=2.4)
    s.line(far_x, top(far_x), far_x, bottom(far_x), stroke=ORANGE, width=2.4)
    # Axes: y up, -z to the right.
    s.line(ex, ey, ex, ey - 130, stroke=INK, width=1.4, arrow="end")
    s.text(ex - 8, ey - 134, "+y", size=12.5, anchor="end", italic=True)
    s.line(ex, ey, far_x + 60, ey, stroke=INK, width=1.4, arrow="end")
    s.text(far_x + 62, ey + 18, "\u2212z", size=12.5, anchor="end", italic=True)
    s.circle(ex, ey, 5, fill=INK, stroke=INK)
    s.text(ex - 8, ey + 20, "eye", size=12, anchor="end")
    # The field of view.
    s.arc_arrow(ex, ey, 50, 0, 22.5, stroke=PURPLE)
    s.text(ex + 56, ey - 7, "fovy / 2 = 22.5\u00b0", size=11.5, fill=PURPLE)
    s.text(near_x, top(near_x) - 8, "near: d = n = 0.1", size=11.5, fill=BLUE, anchor="middle")
    s.text(far_x + 6, top(far_x) + 12, "far: d = F = 100", size=11.5, fill=ORANGE)
    # A point and its distance d, which becomes w.
    px, py = 300, 150
    s.circle(px, py, 4.5, fill=INK, stroke=INK)
    s.text(px + 8, py - 6, "point (x, y, z)", size=11.5)
    s.line(px, py, px, ey, stroke=MUTED, dash="2 3")
    s.line(ex, ey + 88, px, ey + 88, stroke=MUTED, width=1.1, arrow="both")
    s.text((ex + px) / 2, ey + 104, "d = \u2212z: the projection puts it in w", size=11.5, anchor="middle",
           fill=MUTED)

    # ---- The arrow between --------------------------------------------------------------
    s.line(530, 160, 600, 160, stroke=INK, width=2, arrow="end")
    s.lines(565, 128, ["P, then", "\u00f7 w"], size=12, anchor="middle", bold=True)

    # ---- Right: Vulkan's normalised device coordinates ----------------------------------
    s.text(620, 28, "Vulkan clip space, after \u00f7 w", size=14, bold=True)
    fx, fy, size = 650, 78, 170  # the front face (depth 0)
    dx, dy = 90, -34             # depth 1 lies behind
    back = [(fx + dx, fy + dy), (fx + dx + size, fy + dy), (fx + dx + size, fy + dy + size),
            (fx + dx, fy + dy + size)]
    front = [(fx, fy), (fx + size, fy), (fx + size, fy + size), (fx, fy + size)]
    s.polygon(back, fill="#fff7ee", stroke=ORANGE, width=2)
    for a, b in zip(front, back):
        s.line(*a, *b, stroke=GREY, dash="3 3")
    s.polygon(front, fill="#eef4fd", stroke=BLUE, width=2, opacity=0.85)
    s.text(fx + size / 2, fy + size - 12, "depth 0: near plane", size=11.5, anchor="middle", fill=BLUE)
    s.text(fx + dx + size + 6, fy + dy + 14, "depth 1: far", size=11.5, fill=ORANGE)
    # Corner labels.
    s.text(fx - 6, fy - 6, "(\u22121, \u22121)", size=11, anchor="end", mono=True)
    s.text(fx - 6, fy + size + 14, "(\u22121, +1)", size=11, anchor="end", mono=True)
    s.text(fx + size + 6, fy + size + 14, "(+1, +1)", size=11, mono=True)
    # Axes through the centre.
    cx, cy = fx + size / 2, fy + size / 2
    s.line(cx, cy + 10, cx + 120, cy + 10, stroke=INK, width=1.4, arrow="end")
    s.text(cx + 124, cy + 14, "+x", size=12.5, italic=True)
    s.line(cx, cy + 10, cx, cy + 130, stroke=INK, width=1.4, arrow="end")
    s.text(cx + 6, cy + 130, "+y: down", size=12.5, italic=True)
    s.line(cx, cy + 10, cx + 52, cy + 10 - 20, stroke=INK, width=1.4, arrow="end")
    s.text(cx + 56, cy - 12, "depth", size=12, italic=True)
    s.lines(620, 340, ["The top of the view lands on y = \u22121 because",
                       "the chapter negates proj[1][1]: GLM builds for",
                       "OpenGL's y up, Vulkan's y points down."], size=11.5, leading=1.35, fill=MUTED)
    s.text(620, 430, "With f = 1 / tan(fovy / 2) and a = width / height:", size=12, bold=True)
    s.lines(620, 456, ["x_{c} = (f / a) x      y_{c} = \u2212f y",
                       "w_{c} = \u2212z = d",
                       "depth = z_{c} / w_{c} = F (d \u2212 n) / (d (F \u2212 n))"], size=12.5, leading=1.6, mono=True)

    # ---- Below: depth against distance ---------------------------------------------------
    gx, gy, gw, gh = 80, 400, 440, 150
    s.text(20, gy - 16, "Depth after \u00f7 w against distance d (n = 0.1, F = 100)", size=13, bold=True)
    s.rect(gx, gy, gw, gh, fill="#ffffff", stroke=GREY)
    lo, hi = math.log10(NEAR), math.log10(FAR)
    to_x = lambda d: gx + (math.log10(d) - lo) / (hi - lo) * gw
    to_y = lambda z: gy + gh - z * gh
    for d in (0.1, 1, 10, 100):
        s.line(to_x(d), gy, to_x(d), gy + gh, stroke="#e6e9ed", width=1)
        s.text(to_x(d), gy + gh + 16, f"{d:g}", size=11, anchor="middle")
    for z in (0, 0.5, 1):
        s.line(gx, to_y(z), gx + gw, to_y(z), stroke="#e6e9ed", width=1)
        s.text(gx - 6, to_y(z) + 4, f"{z:g}", size=11, anchor="end")
    points = []
    for i in range(121):
        d = 10 ** (lo + (hi - lo) * i / 120)
        z = FAR * (d - NEAR) / (d * (FAR - NEAR))
        points.append((to_x(d), to_y(z)))
    s.polyline(points, stroke=PURPLE, width=2.2)
    d_half = 2 * NEAR * FAR / (FAR + NEAR)  # depth 0.5 exactly here: about 2n
    s.circle(to_x(d_half), to_y(0.5), 4, fill=PURPLE, stroke=PURPLE)
    s.text(to_x(d_half) + 8, to_y(0.5) + 16, "0.5 at d \u2248 0.2 = 2n", size=11.5, fill=PURPLE)
    s.text(gx + gw / 2, gy + gh + 34, "distance from the eye d (log scale)", size=11.5, anchor="middle")
    s.text(gx - 38, gy + gh / 2, "depth", size=11.5, anchor="middle", rotate=-90)
    s.write()


if __name__ == "__main__":
    main()
