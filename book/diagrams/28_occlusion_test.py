"""Chapter 28: the occlusion test against the depth pyramid, in three steps.

Left: the screen with a wall drawn last frame and, behind it, an instance's
box projected to a rectangle of pixels. Middle: the pyramid level at which
that rectangle falls into at most 2 x 2 texels; each texel holds the
minimum (reversed depth: the farthest) depth of the pixels under it. Right:
the test. The box's nearest depth (its largest corner depth, reversed) is
compared with the least of the four texels: nearer than that, it may be
seen; not nearer, it is hidden behind what was drawn there everywhere it
could appear. Numbers as drawn, not the chapter's.
"""

from svg import BLUE_FILL, GREEN, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL, RED, Svg

W, H = 1000, 430


def main() -> None:
    s = Svg(W, H, "Chapter 28: an instance's box tested against the depth pyramid",
            "Left: the screen, 16 by 12 pixels here, with a wall drawn in the last frame and, "
            "behind it, an instance's box projected to a rectangle of 4 by 3 pixels. Middle: at "
            "level 2 of the pyramid each texel covers 4 by 4 pixels and holds the farthest depth "
            "drawn under them (reversed depth: the minimum); the rectangle falls into 2 by 1 "
            "texels, both inside the wall, 0.40 and 0.42. Right: the box's nearest depth is 0.25; "
            "the least of the texels is 0.40, which is nearer, so something nearer than any point "
            "of the box was drawn everywhere the box could appear: the box is hidden.")
    s.text(20, 28, "The occlusion test: project, pick a level, compare", size=14, bold=True)
    # The screen: 16 x 12 pixels of 16 page pixels.
    p = 16
    x0, y0 = 30, 70
    s.rect(x0, y0, 16 * p, 12 * p, fill=BLUE_FILL, stroke=GREY, width=1)
    s.rect(x0 + 4 * p, y0 + 2 * p, 9 * p, 10 * p, fill=GREY_FILL, stroke=GREY, width=1.2)
    s.text(x0 + 8.5 * p, y0 + 3.4 * p, "wall, depth 0.40-0.45", size=11.5, anchor="middle",
           fill=MUTED)
    s.rect(x0 + 6 * p, y0 + 5 * p, 4 * p, 3 * p, fill="none", stroke=ORANGE, width=2.2,
           dash="5 3")
    s.lines(x0, y0 + 12 * p + 20, ["the screen: the box's corners", "projected to a rectangle (orange)",
                                   "reversed depth: 1 near, 0 far"], size=12.5)
    # The pyramid level: 4 x 3 texels of 4 x 4 pixels.
    q = 4 * p
    x1, y1 = 360, 70
    values = [[0.0, 0.0, 0.0, 0.0], [0.0, 0.40, 0.42, 0.0], [0.0, 0.41, 0.43, 0.0]]
    for r in range(3):
        for c in range(4):
            chosen = (r, c) in ((1, 2), (1, 1))
            s.rect(x1 + c * q, y1 + r * q, q, q, fill=ORANGE_FILL if chosen else "#f2f4f6",
                   stroke=ORANGE if chosen else GREY, width=2 if chosen else 1)
            s.text(x1 + c * q + q / 2, y1 + r * q + q / 2 + 5, f"{values[r][c]:.2f}", size=13,
                   anchor="middle", fill=INK if chosen else MUTED)
    s.rect(x1 + 6 * p, y1 + 5 * p, 4 * p, 3 * p, fill="none", stroke=ORANGE, width=2.2, dash="5 3")
    s.lines(x1, y1 + 3 * q + 20, ["level 2: each texel the minimum of 4 x 4 pixels,",
                                  "the farthest depth drawn there; the rectangle",
                                  "falls into 2 x 1 texels (at most 2 x 2)"], size=12.5)
    # The test.
    x2 = 660
    s.lines(x2, 90, ["least of the texels under the box:", "min(0.40, 0.42) = 0.40"], size=13)
    s.lines(x2, 150, ["the box's nearest depth:", "its largest corner depth = 0.25"], size=13)
    s.line(x2, 200, x2 + 280, 200, stroke=GREY, width=1)
    s.text(x2, 226, "0.25 < 0.40: something nearer than", size=13, fill=RED, bold=True)
    s.text(x2, 244, "every point of the box was drawn", size=13, fill=RED, bold=True)
    s.text(x2, 262, "everywhere the box could appear:", size=13, fill=RED, bold=True)
    s.text(x2, 280, "hidden, not drawn.", size=13, fill=RED, bold=True)
    s.lines(x2, 318, ["Had the box's nearest depth been 0.45,", "it would be kept: it might show "
                      "in front", "of the texel whose farthest depth is 0.40."], size=13,
            fill=GREEN)
    s.write()


if __name__ == "__main__":
    main()
