"""Chapter 23c: the split sum in one picture, one lobe at r.

On top, the real integral: the sky around a point times the BRDF's lobe for a
view v 70 degrees from the normal n, roughness 0.6. Below, its two factors:
(a) the prefiltered sky, the sky averaged under a lobe centred on r and drawn
as the prefilter draws it, with n = v = r; (b) the BRDF table's A and B, the
same real lobe under a white sky. Their product approximates the top; the
real lobe drawn dashed in (a) shows what the n = v = r assumption loses.

The lobes are computed here, in the plane of n and v, from GGX as pbr.glsl
writes it (alpha = roughness^2, distribution_ggx and the height-correlated
visibility): the real one is D V (n.l) for the view v, the prefiltered one
D(r.h) (r.l) with h halfway between l and r, the weight prefilter.comp gives
its samples. Each is scaled to the same peak length, so shapes compare, not
sizes. With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones)
each panel sits above the next. Standard library only.
"""

import math
import os

from svg import BLUE, GREEN, GREY, INK, MUTED, ORANGE, PURPLE, Svg

ROUGHNESS = 0.6
VIEW_DEG = 70.0  # the view's angle from n, on n's left; r lies as far on its right
SUN_DEG = 40.0   # the sun's angle from n, between n and r: the two lobes weigh it differently


def distribution_ggx(n_dot_h: float, alpha: float) -> float:
    a2 = alpha * alpha
    d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0
    return a2 / (math.pi * d * d)


def visibility(n_dot_v: float, n_dot_l: float, alpha: float) -> float:
    a2 = alpha * alpha
    gv = n_dot_l * math.sqrt(n_dot_v * n_dot_v * (1 - a2) + a2)
    gl = n_dot_v * math.sqrt(n_dot_l * n_dot_l * (1 - a2) + a2)
    return 0.5 / (gv + gl)


def unit(deg: float) -> tuple[float, float]:
    """The direction deg degrees from n (up), clockwise, as (x, y) with y up."""
    return math.sin(math.radians(deg)), math.cos(math.radians(deg))


def real_lobe(angle: float) -> float:
    """f(l, v) (n.l) for l at angle degrees from n, in the plane of n and v."""
    alpha = ROUGHNESS * ROUGHNESS
    lx, ly = unit(angle)
    vx, vy = unit(-VIEW_DEG)
    if ly <= 0:
        return 0.0
    hx, hy = lx + vx, ly + vy
    length = math.hypot(hx, hy)
    n_dot_h = hy / length
    return distribution_ggx(n_dot_h, alpha) * visibility(vy, ly, alpha) * ly


def prefilter_lobe(offset: float) -> float:
    """The prefilter's weight for l at offset degrees from r, with n = v = r."""
    if abs(offset) >= 90:
        return 0.0
    alpha = ROUGHNESS * ROUGHNESS
    r_dot_h = math.cos(math.radians(offset / 2))
    return distribution_ggx(r_dot_h, alpha) * math.cos(math.radians(offset))


def sky_colour(angle: float, white: bool) -> str:
    if white:
        return "#e6e9ed"
    if abs(angle - SUN_DEG) < 5:
        return "#f5b400"
    t = 1 - abs(angle) / 90  # 0 at the horizon, 1 at the zenith
    top, low = (58, 110, 196), (186, 214, 240)
    return "#%02x%02x%02x" % tuple(round(low[i] + (top[i] - low[i]) * t) for i in range(3))


def panel(s: Svg, cx: float, cy: float, scale: float, size: float, heading: list[str],
          lobe: str, white: bool = False) -> None:
    """A surface point at (cx, cy): the sky as an arc, n, v, r and one lobe."""
    sky_r = 92 * scale
    for a in range(-90, 90, 3):  # the sky, a coloured band above the surface
        x0, y0 = unit(a)
        x1, y1 = unit(a + 3)
        r0, r1 = sky_r, sky_r + 12 * scale
        s.polygon([(cx + r0 * x0, cy - r0 * y0), (cx + r1 * x0, cy - r1 * y0),
                   (cx + r1 * x1, cy - r1 * y1), (cx + r0 * x1, cy - r0 * y1)],
                  fill=sky_colour(a + 1.5, white), stroke=sky_colour(a + 1.5, white), width=0.6)
    s.line(cx - sky_r - 14 * scale, cy, cx + sky_r + 14 * scale, cy, stroke=INK, width=1.6)
    peak = 78 * scale

    def outline(fn, centre, dash=None, colour=PURPLE, fill=True):
        values = [(o, fn(o)) for o in [i * 0.5 - 90 for i in range(361)]]
        top = max(v for _, v in values)
        points = []
        for o, v in values:
            x, y = unit(centre + o)
            points.append((cx + peak * v / top * x, cy - peak * v / top * y))
        s.polygon(points, fill="#e9e0f7" if fill else "none", stroke=colour, width=1.6,
                  dash=dash, opacity=None)

    if lobe == "real":
        outline(real_lobe, 0.0)
    else:
        outline(real_lobe, 0.0, dash="4 3", colour=GREY, fill=False)
        outline(prefilter_lobe, VIEW_DEG)
    for deg, name, colour in ((0, "n", INK), (-VIEW_DEG, "v", ORANGE), (VIEW_DEG, "r", BLUE)):
        x, y = unit(deg)
        length = (sky_r - 6 * scale) if name != "n" else sky_r * 0.55
        s.line(cx, cy, cx + length * x, cy - length * y, stroke=colour, width=1.8, arrow=colour)
        s.text(cx + (length + 10 * scale) * x, cy - (length + 10 * scale) * y + size * 0.35,
               name, size=size + 1, anchor="middle", fill=colour, bold=True, italic=True)
    s.lines(cx, cy - sky_r - 14 * scale - size * 1.3 * len(heading) + size * 0.2, heading,
            size=size, anchor="middle", bold=False)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23c: the split sum, one lobe at r, roughness 0.6, v 70° from n"
    description = ("Top, the real integral: a point on a surface under the sky, with the normal n "
                   "up, the view v 70 degrees to its left and the mirror direction r as far to its "
                   "right, and the BRDF's lobe for that view, computed from GGX: it leans past r "
                   "towards the horizon and is longer than wide. The sky is a band above, blue at "
                   "the top, pale at the horizon, with a yellow sun between n and r. Below, the "
                   "two factors the split sum multiplies: (a) the prefiltered sky, the sky averaged "
                   "under a lobe centred on r drawn with n = v = r, symmetric about r and reaching "
                   "below the surface, the real lobe dashed over it; (b) the same real lobe under a white sky, whose "
                   "integral is F0 A + B from the BRDF table.")
    size = 11.5 if narrow else 12.5
    notes = ["Purple: the lobe each factor weighs the sky with; dashed in (a), the real lobe. At a grazing",
             "view the real lobe is cut off by the surface and leans up from r towards n. The lobe of",
             "n = v = r stays symmetric about r and reaches below the horizon, into the ground, so (a)",
             "weighs the sky between n and r too little. The lobes are scaled to one length: shapes, not sizes."]
    big = 1.75 if narrow else 1.9  # each panel's scale: lobes about twice the earlier 1.0
    if narrow:  # the three panels one above the other, each as wide as the phone allows
        s = Svg(400, 960, title, description)
        s.text(12, 20, "Chapter 23c: the split sum, roughness 0.6,", size=size + 1, bold=True)
        s.text(12, 37, "v 70° from n", size=size + 1, bold=True)
        panel(s, 200, 272, big, size, ["the real integral:", "the sky times the lobe for this v"], "real")
        s.text(200, 308, "≈", size=26, anchor="middle", fill=INK)
        panel(s, 200, 545, big, size, ["(a) prefiltered sky: its mean", "under a lobe at r, n = v = r"],
              "prefilter")
        s.text(200, 581, "×", size=24, anchor="middle", fill=INK)
        panel(s, 200, 818, big, size, ["(b) BRDF table: the lobe under", "a white sky, F₀A + B"],
              "real", white=True)
        notes = ["Purple: the lobe each factor weighs the sky with;",
                 "dashed in (a), the real lobe. At a grazing view the",
                 "real lobe is cut off by the surface and leans up",
                 "from r towards n. The lobe of n = v = r stays",
                 "symmetric about r and reaches into the ground, so",
                 "(a) weighs the sky between n and r too little.",
                 "Lobes scaled to one length: shapes, not sizes."]
        foot_x, foot_y = 12, 850
    else:  # the real integral on top beside the notes, its two factors below
        s = Svg(900, 610, title, description)
        s.text(16, 24, title, size=size + 1.5, bold=True)
        panel(s, 225, 282, big, size, ["the real integral:", "the sky times the lobe for this v"], "real")
        s.text(225, 322, "≈", size=30, anchor="middle", fill=INK)
        for cx, heading, lobe, white in (
                (225, ["(a) the prefiltered sky: the sky's", "mean under a lobe at r, n = v = r"], "prefilter", False),
                (675, ["(b) the BRDF table: the lobe's", "integral under a white sky, F₀A + B"], "real", True)):
            panel(s, cx, 580, big, size, heading, lobe, white)
        s.text(450, 500, "×", size=28, anchor="middle", fill=INK)
        notes = ["Purple: the lobe each factor weighs the sky with;",
                 "dashed in (a), the real lobe.",
                 "",
                 "At a grazing view the real lobe is cut off by the",
                 "surface and leans up from r towards n. The lobe of",
                 "n = v = r stays symmetric about r and reaches",
                 "below the horizon, into the ground, so (a) weighs",
                 "the sky between n and r too little.",
                 "",
                 "The lobes are scaled to one length: shapes, not sizes."]
        foot_x, foot_y = 470, 120
    s.lines(foot_x, foot_y, notes, size=size - 0.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
