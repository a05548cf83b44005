"""Chapter 23d: the bloom's mip chain, down and back up, at the tests' 320x240.

Top row, the down pass: the HDR image (320x240) is halved into level 0 of
one image (160x120), and each level into the next, down to level 5 (5x3:
320 >> 6 = 5, 240 >> 6 = 3), every texel the mean of four bilinear
taps of the level above (vkt::Bloom, bloom_down.comp). Bottom row, the up
pass: from level 4 to level 0, each level adds the level below it, spread by
a 3x3 tent (bloom_up.comp). Level 0 then holds the sum of six blurs, each
twice as wide as the one before; the tone-mapping pass divides it by six and
mixes it in. The levels to scale, one pixel of the page per texel (the HDR
image at half scale).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
chain stands upright, 430 units wide: one row per level, the down pass in the
left column, the up pass in the right one, the level's name between them.
"""

import os

from svg import BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, ORANGE, ORANGE_FILL, Svg, wrap

W, H = 1000, 470
NARROW_W = 430
SIZES = [(160, 120), (80, 60), (40, 30), (20, 15), (10, 7), (5, 3)]
TITLE = "Chapter 23d: the bloom's mip chain, halved down and added back up"
WORDS = ("Level 0 ends as the sum of six blurs, each twice as wide as the last; the tone-mapping "
         "pass reads it, divides by six and mixes: radiance' = (1 - F) radiance + F blur. Each step "
         "keeps the mean, so the glow moves light from bright pixels to their neighbours without "
         "adding any: no threshold, and a pixel blooms in proportion to its radiance.")


def narrow() -> Svg:
    """Upright: a row per level, down on the left (arrows down), up on the right (arrows up)."""
    s = Svg(NARROW_W, 100, TITLE,
            "Left column, top to bottom: the HDR image, 320 by 240, is halved by a compute pass "
            "into level 0 of the bloom's image, 160 by 120, then level by level down to level 5, "
            "5 by 3; each texel is the mean of four bilinear taps of the level above. Right "
            "column, bottom to top: back up from level 4 to level 0, each level adds the level "
            "below it, spread by a 3x3 tent. Level 0 then holds six blurs, each twice as wide as "
            "the last; the tone-mapping pass divides by six and mixes a fraction F of it into the "
            "picture.")
    y = 24
    for text, colour in (("Left, down: each level the mean of the one above (bloom_down.comp)", BLUE),
                         ("Right, up: each level adds the one below it, spread by a 3x3 tent "
                          "(bloom_up.comp)", GREEN)):
        lines = wrap(text, NARROW_W - 40, 13, bold=True)
        s.lines(20, y, lines, size=13, bold=True, fill=colour)
        y += len(lines) * 13 * 1.3 + 4
    left, mid, right = 100, 215, 330  # the columns' centres
    gap = 34  # between one row and the next
    top = y + 8
    s.rect(left - 80, top, 160, 120, fill=ORANGE_FILL, stroke=ORANGE, width=1.4)
    s.text(left, top + 54, "HDR image", size=13, anchor="middle")
    s.lines(left, top + 74, ["320x240", "drawn at half scale"], size=12, anchor="middle", fill=MUTED)
    y = top + 120
    rows = []
    for level, (w, h) in enumerate(SIZES):
        s.line(left, y + 4, left, y + gap - 4, stroke=INK, width=1.4, arrow="end")
        y += gap
        row_h = max(h, 30)  # a small level's row still holds its two lines of name
        cy = y + row_h / 2
        s.rect(left - w / 2, cy - h / 2, w, h, fill=BLUE_FILL, stroke=BLUE, width=1.4)
        s.rect(right - w / 2, cy - h / 2, w, h, fill=GREEN_FILL, stroke=GREEN, width=1.4)
        s.text(mid, cy - 3, f"level {level}", size=12.5, anchor="middle")
        s.text(mid, cy + 13, f"{320 >> (level + 1)}x{240 >> (level + 1)}", size=12,
               anchor="middle", fill=MUTED)
        rows.append((cy, h))
        y += row_h
    for level in range(len(SIZES) - 1):  # up: level + 1, spread, added into level
        (cy, h), (ny, nh) = rows[level], rows[level + 1]
        a, b = ny - nh / 2 - 4, cy + h / 2 + 4
        s.line(right, a, right, b, stroke=INK, width=1.4, arrow="end")
        s.text(right + 14, (a + b) / 2 + 6, "+", size=16, anchor="middle", bold=True)
    y += 30
    lines = wrap(WORDS, NARROW_W - 40, 12.5)
    s.lines(20, y, lines, size=12.5)
    s.height = y + len(lines) * 12.5 * 1.3
    return s


def wide() -> Svg:
    s = Svg(W, H, TITLE,
            "Top: the HDR image, 320 by 240, is halved by a compute pass into level 0 of the "
            "bloom's image, 160 by 120, then level by level down to level 5, 5 by 3; each texel is "
            "the mean of four bilinear taps of the level above. Bottom: back up from level 4 to "
            "level 0, each level adds the level below it, spread by a 3x3 tent. Level 0 then holds "
            "six blurs, each twice as wide as the last; the tone-mapping pass divides by six and "
            "mixes a fraction F of it into the picture.")
    s.text(20, 28, "Down: each level the mean of the one above (bloom_down.comp)", size=14,
           bold=True)
    sizes = SIZES
    y0 = 60
    s.rect(20, y0, 160, 120, fill=ORANGE_FILL, stroke=ORANGE, width=1.4)
    s.text(100, y0 + 66, "HDR image", size=13, anchor="middle")
    s.text(100, y0 + 140, "320x240, drawn at half scale", size=12, anchor="middle", fill=MUTED)
    x = 230
    centres = []
    for level, (w, h) in enumerate(sizes):
        s.line(x - 40, y0 + 60, x - 6, y0 + 60, stroke=INK, width=1.4, arrow="end")
        s.rect(x, y0 + 60 - h / 2, w, h, fill=BLUE_FILL, stroke=BLUE, width=1.4)
        s.text(x + w / 2, y0 + 60 + max(h / 2, 10) + 20, f"level {level}", size=12.5,
               anchor="middle")
        tw, th = 320 >> (level + 1), 240 >> (level + 1)
        s.text(x + w / 2, y0 + 60 + max(h / 2, 10) + 38, f"{tw}x{th}", size=12, anchor="middle",
               fill=MUTED)
        centres.append((x, w, h))
        x += w + 60
    y1 = 300
    s.text(20, y1 - 50, "Up: each level adds the one below it, spread by a 3x3 tent (bloom_up.comp)",
           size=14, bold=True)
    for level in range(len(sizes) - 1, -1, -1):
        cx, w, h = centres[level]
        s.rect(cx, y1 + 40 - h / 2, w, h, fill=GREEN_FILL, stroke=GREEN, width=1.4)
        if level < len(sizes) - 1:
            nx, nw, _ = centres[level + 1]
            s.line(nx - 6, y1 + 40, cx + w + 6, y1 + 40, stroke=INK, width=1.4, arrow="end")
            s.text((nx + cx + w) / 2, y1 + 30, "+", size=16, anchor="middle", bold=True)
    s.lines(20, y1 + 120, [
        "Level 0 ends as the sum of six blurs, each twice as wide as the last; the tone-mapping "
        "pass reads it,",
        "divides by six and mixes: radiance' = (1 - F) radiance + F blur. Each step keeps the "
        "mean, so the glow moves light",
        "from bright pixels to their neighbours without adding any: no threshold, and a pixel "
        "blooms in proportion to its radiance."], size=12.5)
    return s


def main() -> None:
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
