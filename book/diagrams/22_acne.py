"""Chapter 22: why a lit floor shadows itself without a depth bias, to scale.

A cut through the one shadow map of --cascades 1, the map the page teaches, along the way the
floor falls away from the light. Its texels are 110.95 / 1024 = 0.108 units wide (the box around
the whole view, chapters/22_shadows/cascades.hpp, computed by cascade_fit.py), and the light
meets the floor at a slope of 0.75 (its direction (-0.6, -1, -0.45) / 1.25
makes cos 0.8 and sin 0.6 with the floor's normal), so across one texel the
floor's depth from the light grows by 0.75 x 0.108 = 0.0813 units. Left: no
bias; each texel stores the floor's depth at its centre, and the half of the
texel beyond the centre lies deeper than what is stored: in shadow. Right:
the slope bias 4 pushes every stored depth 4 x 0.0813 = 0.325 units away
from the light (the constant term, 2 to 4 x 1e-5 units with D32_SFLOAT, is too
small to draw), and the whole floor lies in front. Both axes share one
scale.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
figure is 400 units wide: the two panels stacked, at five sixths of the wide
scale, and the key and the notes below them in one column.
"""

import os

from cascade_fit import FLOOR_SLOPE, check_page, one_map_constant_bias, one_map_texel
from svg import BLUE, GREEN, INK, MUTED, RED, Svg, wrap

W, H = 1000, 680
TEXEL = one_map_texel()      # units across one texel of the one map (--cascades 1)
SLOPE = FLOOR_SLOPE          # the floor's depth per unit across the map
BIAS = 4 * SLOPE * TEXEL     # depthBiasSlopeFactor 4 times the depth slope per texel
TEXELS = 5
SCALE = 60 / TEXEL           # pixels per unit, the same on both axes
NARROW_SCALE = 50 / TEXEL    # the narrow layout's, so that a panel fits a phone's width


def panel(s: Svg, x0: float, y0: float, bias: float, title: str, scale: float = SCALE,
          reach: float = BIAS, one_texel_anchor: str = "middle") -> None:
    """Five texels at (x0, y0), the texel borders drawn down to the floor's far end
    plus reach (in units), the one-texel label under the first texel."""
    if isinstance(title, str):
        title = [title]
    s.lines(x0, y0 - 46 - 14 * 1.3 * (len(title) - 1), title, size=14, bold=True)
    width = TEXELS * TEXEL * scale
    bottom = y0 + (TEXELS * TEXEL * SLOPE + reach) * scale + 10
    # The light, straight down the page: depth grows downwards.
    for k in range(3):
        x = x0 + width * (40 + k * 110) / 300
        s.line(x, y0 - 34, x, y0 - 6, stroke=MUTED, width=1.1, arrow="end")
    s.text(x0 + width + 8, y0 - 14, "light", size=12.5, fill=MUTED)
    for t in range(TEXELS):
        left = x0 + t * TEXEL * scale
        right = left + TEXEL * scale
        centre_depth = (t + 0.5) * TEXEL * SLOPE + bias
        y_stored = y0 + centre_depth * scale
        # The texel's borders, faint, and what it stores: one depth for its width.
        s.line(left, y0, left, bottom, stroke="#d1d9e0", width=1)
        s.line(left, y_stored, right, y_stored, stroke=BLUE, width=3)
        # The floor under the texel: lit where it is no deeper than what is stored.
        y_left = y0 + t * TEXEL * SLOPE * scale
        y_right = y0 + (t + 1) * TEXEL * SLOPE * scale
        if bias > 0:
            s.line(left, y_left, right, y_right, stroke=GREEN, width=3.5)
        else:
            y_mid = (y_left + y_right) / 2
            s.line(left, y_left, (left + right) / 2, y_mid, stroke=GREEN, width=3.5)
            s.line((left + right) / 2, y_mid, right, y_right, stroke=RED, width=3.5)
    s.line(x0 + width, y0, x0 + width, bottom, stroke="#d1d9e0", width=1)
    s.text(x0 + (TEXEL * scale / 2 if one_texel_anchor == "middle" else 0), bottom + 20,
           f"one texel: {TEXEL:.3f} units", size=12.5, anchor=one_texel_anchor, fill=MUTED)


TITLE = "Chapter 22: shadow acne on the floor, and the slope bias that removes it, to scale"
DESCRIPTION = (f"A cut through the one shadow map of --cascades 1, five texels wide, each {TEXEL:.3f} units; the "
            "light shines down the page and the floor, which the light meets at a slope of 0.75, "
            f"goes {SLOPE * TEXEL:.4f} units deeper across each texel. Left, no bias: each texel stores the "
            "floor's depth at its centre (blue), and the half of each texel beyond the centre is "
            "deeper than that, so it is shadowed (red) and the rest is lit (green): bands half a "
            f"texel wide. Right, slope bias 4: every stored depth is pushed {BIAS:.3f} units further "
            "from the light, below the whole floor under its texel, and the floor is lit.")
KEY = [(BLUE, 3, "the depth a texel stores"), (GREEN, 3.5, "floor lit: no deeper than stored"),
       (RED, 3.5, "floor in shadow: deeper than stored")]
BANDS = ["Bands half a texel wide, and the", "3x3 filter blurs them to part-shadow."]
NOTES = [f"To scale, both axes: the floor goes {SLOPE * TEXEL:.4f} units deeper per texel; the slope "
         f"bias adds 4 x {SLOPE * TEXEL:.4f} = {BIAS:.3f} units.",
         f"The constant term ({one_map_constant_bias()[0] * 1e5:.0f} to {one_map_constant_bias()[1] * 1e5:.0f} "
         "x 1e-5 units with D32_SFLOAT) is too small to draw.",
         "Why 4 and not just over half a texel's worth: the 3x3 filter also compares a point with "
         "the texels either side of its own, so the bias must cover 1.5 texels' worth "
         f"({1.5 * SLOPE * TEXEL:.3f} units); 4 leaves room."]


def wide() -> Svg:
    s = Svg(W, H, TITLE, DESCRIPTION)
    panel(s, 60, 100, 0.0, "No bias: half of every texel shadows itself")
    panel(s, 560, 100, BIAS, f"Slope bias 4: stored {BIAS:.3f} units deeper")
    s.lines(60, 330, BANDS, size=12.5, fill=MUTED)
    y = 560
    for x, (colour, stroke, label) in zip((40, 300, 600), KEY):
        s.line(x, y, x + 30, y, stroke=colour, width=stroke)
        s.text(x + 38, y + 4, label, size=12.5)
    lines = []
    for note in NOTES:
        lines += wrap(note, 920, 12.5)
    s.lines(40, y + 34, lines, size=12.5, fill=INK)
    return s


def narrow() -> Svg:
    """The panels stacked, each 250 units wide, the key and the notes under them."""
    s = Svg(400, 100, TITLE, DESCRIPTION.replace("Left, no bias", "Top, no bias")
            .replace("Right, slope bias 4", "Below it, slope bias 4"))
    x0 = 24
    reach = BIAS  # both panels' texel borders reach as deep, so the two share one frame
    depth = (TEXELS * TEXEL * SLOPE + reach) * NARROW_SCALE + 10
    y0 = 86
    panel(s, x0, y0, 0.0, ["No bias: half of every texel", "shadows itself"], NARROW_SCALE,
          reach=0.0, one_texel_anchor="start")
    y = y0 + (TEXELS * TEXEL * SLOPE) * NARROW_SCALE + 10 + 48
    s.lines(x0, y, BANDS, size=12.5, fill=MUTED)
    y0 = y + 134
    panel(s, x0, y0, BIAS, ["Slope bias 4: stored", f"{BIAS:.3f} units deeper"], NARROW_SCALE,
          reach=reach, one_texel_anchor="start")
    y = y0 + depth + 56
    for colour, stroke, label in KEY:
        s.line(x0, y, x0 + 30, y, stroke=colour, width=stroke)
        s.text(x0 + 38, y + 4, label, size=12.5)
        y += 22
    y += 14
    for note in NOTES:
        lines = wrap(note, 400 - 2 * x0, 12.5)
        s.lines(x0, y, lines, size=12.5, fill=INK)
        y += len(lines) * 12.5 * 1.3 + 8
    s.height = y
    return s


def main() -> None:
    check_page()
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
