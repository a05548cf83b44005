"""Chapter 22: why a lit floor shadows itself without a depth bias, to scale.

A cut through the near cascade's shadow map, along the way the floor falls away from the light. The
map's texels there are 15.73 / 1024 = 0.0154 units wide (the near cascade's box,
chapters/22_shadows/cascades.hpp, computed by cascade_fit.py as 22_cascades.py draws it), and the light
meets the floor at a slope of 0.75 (its direction (-0.6, -1, -0.45) / 1.25
makes cos 0.8 and sin 0.6 with the floor's normal), so across one texel the
floor's depth from the light grows by 0.75 x 0.0154 = 0.0115 units. Left: no
bias; each texel stores the floor's depth at its centre, and the half of the
texel beyond the centre lies deeper than what is stored: in shadow. Right:
the slope bias 4 pushes every stored depth 4 x 0.0115 = 0.046 units away
from the light (the constant term, a few 1e-5 units with D32_SFLOAT, is too
small to draw), and the whole floor lies in front. Both axes share one
scale.
"""

from cascade_fit import FLOOR_SLOPE, check_page, texel
from svg import BLUE, GREEN, INK, MUTED, RED, Svg

W, H = 1000, 680
TEXEL = texel(0)             # units across one texel of the near cascade
SLOPE = FLOOR_SLOPE          # the floor's depth per unit across the map
BIAS = 4 * SLOPE * TEXEL     # depthBiasSlopeFactor 4 times the depth slope per texel
TEXELS = 5
SCALE = 60 / TEXEL           # pixels per unit, the same on both axes


def panel(s: Svg, x0: float, y0: float, bias: float, title: str) -> None:
    s.text(x0, y0 - 46, title, size=14, bold=True)
    width = TEXELS * TEXEL * SCALE
    # The light, straight down the page: depth grows downwards.
    for k in range(3):
        x = x0 + 40 + k * 110
        s.line(x, y0 - 34, x, y0 - 6, stroke=MUTED, width=1.1, arrow="end")
    s.text(x0 + width + 8, y0 - 14, "light", size=12.5, fill=MUTED)
    for t in range(TEXELS):
        left = x0 + t * TEXEL * SCALE
        right = left + TEXEL * SCALE
        centre_depth = (t + 0.5) * TEXEL * SLOPE + bias
        y_stored = y0 + centre_depth * SCALE
        # The texel's borders, faint, and what it stores: one depth for its width.
        s.line(left, y0, left, y0 + (TEXELS * TEXEL * SLOPE + BIAS) * SCALE + 10, stroke="#d1d9e0",
               width=1)
        s.line(left, y_stored, right, y_stored, stroke=BLUE, width=3)
        # The floor under the texel: lit where it is no deeper than what is stored.
        y_left = y0 + t * TEXEL * SLOPE * SCALE
        y_right = y0 + (t + 1) * TEXEL * SLOPE * SCALE
        if bias > 0:
            s.line(left, y_left, right, y_right, stroke=GREEN, width=3.5)
        else:
            y_mid = (y_left + y_right) / 2
            s.line(left, y_left, (left + right) / 2, y_mid, stroke=GREEN, width=3.5)
            s.line((left + right) / 2, y_mid, right, y_right, stroke=RED, width=3.5)
    s.line(x0 + width, y0, x0 + width, y0 + (TEXELS * TEXEL * SLOPE + BIAS) * SCALE + 10,
           stroke="#d1d9e0", width=1)
    s.text(x0 + TEXEL * SCALE / 2, y0 + (TEXELS * TEXEL * SLOPE + BIAS) * SCALE + 30,
           f"one texel: {TEXEL:.4f} units", size=12.5, anchor="middle", fill=MUTED)


def main() -> None:
    check_page()
    s = Svg(W, H, "Chapter 22: shadow acne on the floor, and the slope bias that removes it, to scale",
            f"A cut through the near cascade's shadow map, five texels wide, each {TEXEL:.4f} units; the "
            "light shines down the page and the floor, which the light meets at a slope of 0.75, "
            f"goes {SLOPE * TEXEL:.4f} units deeper across each texel. Left, no bias: each texel stores the "
            "floor's depth at its centre (blue), and the half of each texel beyond the centre is "
            "deeper than that, so it is shadowed (red) and the rest is lit (green): bands half a "
            f"texel wide. Right, slope bias 4: every stored depth is pushed {BIAS:.3f} units further "
            "from the light, below the whole floor under its texel, and the floor is lit.")
    panel(s, 60, 100, 0.0, "No bias: half of every texel shadows itself")
    panel(s, 560, 100, BIAS, f"Slope bias 4: stored {BIAS:.3f} units deeper")
    s.lines(60, 330, ["Bands half a texel wide, and the", "3x3 filter blurs them to part-shadow."],
            size=12.5, fill=MUTED)
    y = 560
    s.line(40, y, 70, y, stroke=BLUE, width=3)
    s.text(78, y + 4, "the depth a texel stores", size=12.5)
    s.line(300, y, 330, y, stroke=GREEN, width=3.5)
    s.text(338, y + 4, "floor lit: no deeper than stored", size=12.5)
    s.line(600, y, 630, y, stroke=RED, width=3.5)
    s.text(638, y + 4, "floor in shadow: deeper than stored", size=12.5)
    s.lines(40, y + 34, [f"To scale, both axes: the floor goes {SLOPE * TEXEL:.4f} units deeper per "
                         f"texel; the slope bias adds 4 x {SLOPE * TEXEL:.4f} = {BIAS:.3f} units.",
                         "The constant term (a few 1e-5 units with D32_SFLOAT) is too small to "
                         "draw.",
                         "Why 4 and not just over half a texel's worth: the 3x3 filter also "
                         "compares a point with the texels either",
                         "side of its own, so the bias must cover 1.5 texels' worth "
                         f"({1.5 * SLOPE * TEXEL:.3f} units); 4 leaves room."],
            size=12.5, fill=INK)
    s.write()


if __name__ == "__main__":
    main()
