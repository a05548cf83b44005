"""Chapter 18: projection from n dimensions to 2, one dimension at a time, and a rotation plane.

From common/domains/include/vkt/domains/ndim.hpp: project_to_2d (for k = n-1
down to 2, multiply x_0 .. x_(k-1) by d / (d - x_k) and drop x_k), plane_rotation
(R_ij: R[i][i] = R[j][j] = cos a, R[i][j] = -sin a, R[j][i] = sin a). The worked
example is the appendix's: d = 4, (1, 1, 1, 1) -> (4/3, 4/3, 4/3) -> (2, 2).
"""

import math

from svg import (BLUE, BLUE_FILL, GREEN, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE,
                 PURPLE_FILL, RED, Svg)

W, H = 1000, 640


def main() -> None:
    s = Svg(W, H, "Chapter 18: the projection chain from n dimensions to 2, and a rotation plane",
            "Top: a point of n coordinates loses its last coordinate in each step, scaled by d / (d - "
            "x_k), until two remain: n, n-1, ..., 3, 2. Below left: one step as similar triangles, the "
            "eye on axis k at distance d. Below right: a rotation in the plane of axes i and j turns "
            "e_i towards e_j and leaves every other coordinate alone.")

    # ---- The chain ---------------------------------------------------------------------------
    s.text(20, 30, "Projection to the screen, one dimension at a time (project_to_2d)", size=15, bold=True)
    stages = [("n", "x_{0} ... x_{n\u22121}", "(1, 1, 1, 1)"), ("n \u2212 1", "x_{0} ... x_{n\u22122}", "(4/3, 4/3, 4/3)"),
              ("...", "", ""), ("3", "x_{0}, x_{1}, x_{2}", ""), ("2", "x_{0}, x_{1}", "(2, 2)")]
    y = 56
    widths = [150 if dim != "..." else 40 for dim, _, _ in stages]
    gap = 66
    xs = []
    x = 20
    for w in widths:
        xs.append(x)
        x += w + gap
    for i, (dim, coords, example) in enumerate(stages):
        x, box_w = xs[i], widths[i]
        if dim == "...":
            s.text(x + box_w / 2, y + 38, "...", size=22, anchor="middle", bold=True, fill=MUTED)
            continue
        fill, stroke = (BLUE_FILL, BLUE) if dim != "2" else (ORANGE_FILL, ORANGE)
        s.rect(x, y, box_w, 66, fill=fill, stroke=stroke, rx=8, width=1.6)
        s.text(x + box_w / 2, y + 26, f"{dim} dimensions" if dim != "2" else "2: the screen", size=13.5,
               anchor="middle", bold=True)
        s.text(x + box_w / 2, y + 48, coords, size=12, anchor="middle")
    drops = ["n\u22121", "n\u22122", "3", "2"]
    for i in range(len(stages) - 1):
        x0, x1 = xs[i] + widths[i], xs[i + 1]
        s.line(x0 + 4, y + 33, x1 - 4, y + 33, stroke=INK, width=1.6, arrow="end")
        s.text((x0 + x1) / 2, y + 24, f"drop x_{{{drops[i]}}}", size=12, anchor="middle")
    s.text(20, y + 92, "Each step: the eye on axis k at distance d; the coordinates left are scaled by "
           "f = d / (d \u2212 x_{k}) and x_{k} is dropped. k = n \u2212 1, n \u2212 2, ..., 2.", size=12.5)
    s.text(20, y + 114, "Worked for n = 4, d = 4:", size=12.5, bold=True)
    s.text(190, y + 114, "(1, 1, 1, 1)  \u00d7 4/(4 \u2212 1) = 4/3  \u2192  (4/3, 4/3, 4/3)  "
           "\u00d7 4/(4 \u2212 4/3) = 3/2  \u2192  (2, 2)", size=12.5, mono=True)
    s.text(20, y + 136, "In code one running factor does it: f \u2190 f \u00b7 d / (d \u2212 f x_{k}); "
           "a point with f x_{k} \u2265 d is at or behind an eye and is left out.", size=12.5, fill=MUTED)

    # ---- One step as similar triangles ----------------------------------------------------
    py = 250
    s.text(20, py, "One step: similar triangles", size=14, bold=True)
    ox, oy = 120, py + 190   # the origin; axis k runs right, the other coordinates up
    scale = 52
    d = 4.0
    to = lambda k, v: (ox + k * scale, oy - v * scale)
    s.line(ox - 90, oy, ox + 5.6 * scale, oy, stroke=INK, width=1.3, arrow="end")
    s.text(ox + 5.6 * scale, oy - 8, "axis k", size=12, anchor="end", italic=True)
    s.line(ox, oy + 30, ox, oy - 3.4 * scale, stroke=INK, width=1.3, arrow="end")
    s.text(ox - 6, oy - 3.4 * scale + 4, "other axes", size=12, anchor="end", italic=True)
    # The screen: the hyperplane x_k = 0 through the origin.
    s.line(ox, oy + 24, ox, oy - 3.2 * scale, stroke=ORANGE, width=3)
    s.text(ox - 8, oy + 22, "screen: x_{k} = 0", size=11.5, anchor="end", fill=ORANGE)
    # The eye at x_k = d, a point at (x_k, x), and its image at x d / (d - x_k).
    eye = to(d, 0)
    xk, xv = 1.6, 1.2
    point = to(xk, xv)
    image = to(0, xv * d / (d - xk))
    s.circle(*eye, 5, fill=INK, stroke=INK)
    s.text(eye[0] + 6, eye[1] + 20, "eye at x_{k} = d", size=12)
    s.line(*eye, *image, stroke=PURPLE, width=1.5, dash="5 3")
    s.circle(*point, 5, fill=BLUE, stroke=BLUE)
    s.text(point[0] + 8, point[1] - 8, "point: x_{k}, x", size=12, fill=BLUE)
    s.circle(*image, 5, fill=ORANGE, stroke=ORANGE)
    s.text(image[0] + 10, image[1] - 2, "image: x \u00b7 d / (d \u2212 x_{k})", size=12, fill=ORANGE)
    s.line(point[0], point[1], point[0], oy, stroke=MUTED, dash="2 3")
    s.line(point[0], oy + 42, eye[0], oy + 42, stroke=MUTED, arrow="both")
    s.text((point[0] + eye[0]) / 2, oy + 58, "d \u2212 x_{k}", size=12, anchor="middle", fill=MUTED)
    s.line(ox, oy + 70, eye[0], oy + 70, stroke=MUTED, arrow="both")
    s.text((ox + eye[0]) / 2, oy + 86, "d", size=12, anchor="middle", fill=MUTED)
    s.text(20, H - 16, "Nearer the eye (x_{k} > 0) looks larger, farther smaller; orthographic: d \u2192 \u221e, f = 1.",
           size=12, fill=MUTED)

    # ---- A rotation plane ------------------------------------------------------------------
    rx0 = 540
    s.text(rx0, py, "A rotation turns a plane, not an axis", size=14, bold=True)
    cx, cy, r = rx0 + 40, py + 190, 100
    s.polygon([(cx, cy), (cx + r, cy), (cx + r, cy - r), (cx, cy - r)], fill=PURPLE_FILL, stroke="none",
              opacity=0.6)
    s.line(cx - 24, cy, cx + r + 36, cy, stroke=INK, width=1.3, arrow="end")
    s.text(cx + r + 36, cy + 20, "e_{i}", size=13, anchor="end", italic=True)
    s.line(cx, cy + 24, cx, cy - r - 36, stroke=INK, width=1.3, arrow="end")
    s.text(cx + 8, cy - r - 26, "e_{j}", size=13, italic=True)
    s.text(cx + r / 2, cy - r + 18, "the plane (i, j)", size=12, anchor="middle", fill=PURPLE)
    a = math.radians(35)
    v = (cx + r * 0.85 * math.cos(a), cy - r * 0.85 * math.sin(a))
    s.line(cx, cy, cx + r * 0.85, cy, stroke=BLUE, width=2.2, arrow="end")
    s.line(cx, cy, *v, stroke=GREEN, width=2.2, arrow="end")
    s.arc_arrow(cx, cy, 44, 2, 33, stroke=GREEN)
    s.text(cx + 50, cy - 12, "a", size=13, italic=True, fill=GREEN)
    s.text(cx + 30, cy + 40, "R_{ij}(a) turns e_{i} towards e_{j}", size=12, fill=GREEN)
    mx, my = rx0 + 200, py + 36
    s.text(mx, my, "R_{ij}(a) is the identity, except", size=12.5)
    s.lines(mx, my + 24, ["R[i][i] =  cos a", "R[i][j] = \u2212sin a", "R[j][i] =  sin a", "R[j][j] =  cos a"],
            size=12, leading=1.45, mono=True)
    s.lines(mx, my + 112, ["Every coordinate but i and j stays", "as it is. In 4D two axes are left",
                           "over, so an axis of rotation", "names nothing: name the plane."], size=12,
            leading=1.35, fill=MUTED)
    s.lines(rx0, py + 300, ["n(n \u2212 1)/2 planes: (0,1), (0,2), ..., (n\u22122, n\u22121), one angle each;",
                            "R = R_{(n\u22122,n\u22121)} \u00b7\u00b7\u00b7 R_{(0,2)} R_{(0,1)}: plane (0,1) acts first."],
            size=12, leading=1.5)
    s.write()


if __name__ == "__main__":
    main()
