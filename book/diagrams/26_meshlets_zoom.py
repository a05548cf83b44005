"""Chapter 26's --view meshlets, the knot enlarged: the test's reviewed picture
(tests/golden/26_mesh_shaders_meshlets.png, 320x240) is small on the page, and its
patches, one colour per meshlet, are a few pixels each. The crop is the knot's own
box in that picture, found here (every pixel that is not the background), plus a
margin, so the figure follows the golden if it is blessed again.

Usage: python3 26_meshlets_zoom.py  (writes the SVG to stdout; VKT_DIAGRAM_LAYOUT=narrow
for the phone layout)
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

PICTURE = GOLDEN / "26_mesh_shaders_meshlets.png"
MARGIN = 4


def knot_box(pixels) -> tuple[int, int, int, int]:
    """(left, top, width, height) of every pixel unlike the corner's background, with
    MARGIN pixels around it, inside the picture."""
    background = pixels[0][0]
    xs = [x for row in pixels for x, c in enumerate(row) if c != background]
    ys = [y for y, row in enumerate(pixels) for c in row if c != background]
    if not xs:
        raise SystemExit(f"26_meshlets_zoom.py: {PICTURE.name} is all background; redraw the figure")
    left, top = max(min(xs) - MARGIN, 0), max(min(ys) - MARGIN, 0)
    right = min(max(xs) + MARGIN, len(pixels[0]) - 1)
    bottom = min(max(ys) + MARGIN, len(pixels) - 1)
    return left, top, right - left + 1, bottom - top + 1


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    pixels = read_png(PICTURE)
    left, top, w, h = knot_box(pixels)
    width = 400 if narrow else 760
    zoom = int((width - 20) // w)
    title = "Chapter 26's --view meshlets: the knot enlarged"
    description = (f"The knot of the 320x240 test picture, pixels x {left}..{left + w - 1}, "
                   f"y {top}..{top + h - 1}, each pixel enlarged {zoom} times: the tube is a patchwork "
                   "of small patches in pastel colours, one colour per meshlet")
    x0, y0 = (width - w * zoom) / 2, 8
    s = Svg(width, y0 + h * zoom + 30, title, description)
    enlarged(s, pixels, left, top, w, h, x0, y0, zoom)
    s.text(width / 2, y0 + h * zoom + 20,
           f"--view meshlets, x {left}..{left + w - 1}, y {top}..{top + h - 1} of the 320x240 picture, "
           f"enlarged {zoom} times" if not narrow else f"x {left}..{left + w - 1}, y {top}..{top + h - 1}, "
           f"enlarged {zoom} times", size=12, anchor="middle", fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
