"""Chapter 21b: the panel with its colours decoded from sRGB, and without.

Drawn from two pictures of the same run,
21_multisampling --headless --frames 3 --size 640x480 --overlay on:
tests/golden/21_multisampling_overlay.png (the reviewed picture, the committed
shader) and book/images/21b_undecoded.png (the page's "Try it" edit, the colours
written undecoded; book/images/21b_undecoded.txt says how it was made). The
same crop of each, the panel and a little of the scene around it, at its own
size. Two pixels are ringed, the ones chapter.21_multisampling.overlay checks:
the title bar's and the background's. Their values under each crop are read
from the pictures when the book is built.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
crops are stacked, 400 units wide, instead of side by side. A phone's column
shows that a little smaller than the crop's own size, so there the crop is
scaled smoothly rather than pixelated, which would break the panel's text.
"""

import base64
import os
from pathlib import Path

from golden import GOLDEN, enlarged, png_bytes, read_png
from svg import INK, Svg

IMAGES = Path(__file__).resolve().parents[1] / "images"
LEFT, TOP, CROP_W, CROP_H = 0, 0, 338, 156
PIXELS = [((300, 18), "title bar"), ((300, 60), "background")]
COLUMNS = [(GOLDEN / "21_multisampling_overlay.png", "decoded (as committed)"),
           (IMAGES / "21b_undecoded.png", "written undecoded (Try it)")]


def smooth(s, pixels, x: float, y: float) -> None:
    """The crop drawn at (x, y) at its own size, left to the viewer to scale smoothly."""
    crop = [row[LEFT:LEFT + CROP_W] for row in pixels[TOP:TOP + CROP_H]]
    data = base64.b64encode(png_bytes(crop)).decode("ascii")
    s.add(f'<image x="{x:g}" y="{y:g}" width="{CROP_W}" height="{CROP_H}" '
          f'href="data:image/png;base64,{data}"/>')
    s.rect(x, y, CROP_W, CROP_H, stroke=INK, width=1)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 13
    pictures = [(read_png(path), label) for path, label in COLUMNS]
    values = [[p[y][x] for (x, y), _ in PIXELS] for p, _ in pictures]
    below = 22 + 18 * len(PIXELS)  # the value lines under each crop
    block_h = 24 + CROP_H + below
    if narrow:
        width, height, x0 = 400, 2 * block_h + 8, (400 - CROP_W) / 2
        places = [(x0, 8), (x0, 8 + block_h)]
    else:
        gap, x0 = 28, 16
        width, height = 2 * x0 + 2 * CROP_W + gap, block_h + 8
        places = [(x0, 8), (x0 + CROP_W + gap, 8)]
    title = "Chapter 21b: the panel with its colours decoded from sRGB, and written undecoded"
    said = "; ".join(f"{name} {v}" for (_, name), v in zip(PIXELS, values[0]))
    said_bad = "; ".join(f"{name} {v}" for (_, name), v in zip(PIXELS, values[1]))
    description = (f"The top left {CROP_W} by {CROP_H} pixels of chapter 21 at 640x480 with --overlay on, "
                   "twice. First, with the vertex shader's decode: a dark grey panel under a deep blue "
                   f"title bar ({said}). Then with the colours written as they are: the same panel "
                   f"washed out, the title bar a pale blue and the background a lighter grey ({said_bad}). "
                   "The two ringed pixels are the ones the test checks.")
    s = Svg(width, height, title, description)
    for ((pixels, label), vals, (x, y)) in zip(pictures, values, places):
        s.text(x, y + 14, label, size=size + 0.5, bold=True)
        top = y + 24
        if narrow:
            smooth(s, pixels, x, top)
        else:
            enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, x, top, 1)
        for n, ((px, py), _) in enumerate(PIXELS, start=1):
            cx, cy = x + px - LEFT + 0.5, top + py - TOP + 0.5
            s.circle(cx, cy, 6, stroke="#ffffff", width=2.4)
            s.circle(cx, cy, 8, stroke=INK, width=1)
            s.text(cx - 14, cy + 4.5, str(n), size=12, anchor="end", fill="#ffffff", bold=True)
        for n, (((px, py), name), v) in enumerate(zip(PIXELS, vals), start=1):
            s.text(x, top + CROP_H + 20 + 18 * (n - 1), f"{n}: {name} ({px}, {py}) = {v}",
                   size=size)
    s.write()


if __name__ == "__main__":
    main()
