"""Chapter 21: the same pixels at 1 sample, 4 samples, and 4 samples with sample shading.

Drawn from the chapter's three reviewed test pictures (tests/golden/
21_multisampling_1x.png, 21_multisampling.png, 21_multisampling_sample_shading.png,
headless at 320x240 after 10 frames): two crops of 32x24 pixels each, every
pixel a square 7 units wide. The PNGs are decoded by golden.py (standard
library only), so the figure always shows what the tests check.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
crops are 400 units wide: the three settings stacked, each a row of the two
crops, every pixel a square 5.5 units wide.
"""

import os

from golden import GOLDEN, read_png
from svg import INK, MUTED, Svg

COLUMNS = [("21_multisampling_1x.png", "1 sample per pixel", "--samples 1"),
           ("21_multisampling.png", "4 samples, resolved", "the default"),
           ("21_multisampling_sample_shading.png", "4 samples, sample shading", "--sample-shading 1")]
# (left, top) of each crop in the 320x240 picture, and what it shows.
CROPS = [((130, 95), "a spoke's edges"), ((222, 100), "depth edge, stripes")]
CROP_W, CROP_H, ZOOM = 32, 24, 7


def draw_crop(s: Svg, pixels, left: int, top: int, x0: float, y0: float, zoom: float = ZOOM) -> None:
    """The crop as squares, runs of one colour along a row merged into one rectangle.
    Edges are rounded to whole units, so a zoom that is not whole leaves no gaps."""
    def edge(origin: float, i: int) -> int:
        return round(origin + i * zoom)
    for y in range(CROP_H):
        row = pixels[top + y][left:left + CROP_W]
        x = 0
        while x < CROP_W:
            end = x
            while end + 1 < CROP_W and row[end + 1] == row[x]:
                end += 1
            r, g, b = row[x]
            s.add(f'<rect x="{edge(x0, x)}" y="{edge(y0, y)}" width="{edge(x0, end + 1) - edge(x0, x)}" '
                  f'height="{edge(y0, y + 1) - edge(y0, y)}" fill="#{r:02x}{g:02x}{b:02x}" '
                  f'shape-rendering="crispEdges"/>')
            x = end + 1
    s.rect(x0, y0, CROP_W * zoom, CROP_H * zoom, stroke=INK, width=1)


TITLE = "Chapter 21: the same pixels at 1 sample, 4 samples, and 4 samples with sample shading"
DESCRIPTION = ("Two crops of chapter 21's picture, each pixel enlarged into a square. At 1 sample per pixel the "
               "thin spoke is a staircase and every pixel is either spoke or background; at 4 samples the "
               "pixels along the edges take in-between shades, and so does the line where the two quads cut "
               "through each other, but the stripes inside the teal quad stay hard; with sample shading the "
               "stripes are smoothed too.")


def narrow(pictures) -> Svg:
    """The three settings stacked, each a titled row of the two crops."""
    zoom, margin, gap = 5.5, 16, 16
    cell_w, cell_h = CROP_W * zoom, CROP_H * zoom
    s = Svg(2 * margin + 2 * cell_w + gap, 100, TITLE, DESCRIPTION)
    for c, ((left, top), label) in enumerate(CROPS):
        x = margin + c * (cell_w + gap) + cell_w / 2
        s.text(x, 20, label, size=13, anchor="middle", bold=True)
        s.text(x, 37, f"x {left}..{left + CROP_W - 1}, y {top}..{top + CROP_H - 1}", size=11,
               anchor="middle", fill=MUTED)
    y = 50
    for (_, title, flag), pixels in zip(COLUMNS, pictures):
        y += 22
        s.text(margin, y, title, size=13.5, bold=True)
        s.text(margin + 2 * cell_w + gap, y, flag, size=11.5, anchor="end", fill=MUTED,
               mono=flag.startswith("--"))
        y += 8
        for c, ((left, top), _) in enumerate(CROPS):
            draw_crop(s, pixels, left, top, margin + c * (cell_w + gap), y, zoom)
        y += cell_h + 12
    s.height = y
    return s


def main() -> None:
    pictures = [read_png(GOLDEN / name) for name, _, _ in COLUMNS]
    if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow":
        narrow(pictures).write()
        return
    cell_w, cell_h, left_margin, top_margin, gap = CROP_W * ZOOM, CROP_H * ZOOM, 170, 62, 16
    width = left_margin + len(COLUMNS) * (cell_w + gap)
    height = top_margin + len(CROPS) * (cell_h + gap) + 16
    s = Svg(width, height, TITLE, DESCRIPTION)
    for c, (_, title, flag) in enumerate(COLUMNS):
        x = left_margin + c * (cell_w + gap) + cell_w / 2
        s.text(x, 24, title, size=14, anchor="middle", bold=True)
        s.text(x, 44, flag, size=12.5, anchor="middle", fill=MUTED, mono=flag.startswith("--"))
    for r, ((left, top), label) in enumerate(CROPS):
        y = top_margin + r * (cell_h + gap)
        s.text(left_margin - 12, y + cell_h / 2 - 4, label, size=13, anchor="end")
        s.text(left_margin - 12, y + cell_h / 2 + 14, f"x {left}..{left + CROP_W - 1}, "
               f"y {top}..{top + CROP_H - 1}", size=11, anchor="end", fill=MUTED)
        for c, pixels in enumerate(pictures):
            draw_crop(s, pixels, left, top, left_margin + c * (cell_w + gap), y)
    s.write()


if __name__ == "__main__":
    main()
