"""Chapter 23b: the same highlight at --exposure -2, from the float HDR image and from an 8-bit one.

Left, the reviewed test picture tests/golden/23_materials_exposure_minus_2.png
(--sky uniform --exposure -2, headless at 320x240 after 10 frames, the HDR image
R16G16B16A16_SFLOAT). Right, book/images/23b_unorm_exposure_minus_2.png, the same
command with the scene pass's output clamped to 0..1 and rounded to 8 bits, as an
R8G8B8A8_UNORM target stores it; book/images/23b_unorm_exposure_minus_2.txt says how
it was made. The crop is 23b_highlight_zoom.py's: the bottom row's second sphere.
Under each crop, read from the pictures when the book is built: its brightest pixel
and how many pixels of the crop have exactly that colour.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two crops
stay side by side, 400 units wide, enlarged 4 times instead of 6.
"""

import os
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP_W, CROP_H = 92, 164, 44, 44
IMAGES = Path(__file__).resolve().parents[1] / "images"
COLUMNS = [(GOLDEN / "23_materials_exposure_minus_2.png", "float, -2 EV"),
           (IMAGES / "23b_unorm_exposure_minus_2.png", "8-bit, -2 EV")]


def brightest(pixels) -> tuple[tuple[int, int, int], int]:
    """The crop's brightest pixel (largest channel sum) and how many pixels share its colour."""
    crop = [p for row in pixels[TOP:TOP + CROP_H] for p in row[LEFT:LEFT + CROP_W]]
    top = max(crop, key=sum)
    return top, crop.count(top)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    zoom, x0, gap, size = (4, 16, 16, 12.5) if narrow else (6, 20, 30, 13.5)
    w, h, y0 = CROP_W * zoom, CROP_H * zoom, 34
    pictures = [(read_png(path), label) for path, label in COLUMNS]
    title = "Chapter 23b: one highlight at --exposure -2, from a float and an 8-bit HDR image"
    description = (f"The same {CROP_W} by {CROP_H} pixels of two pictures made with --sky uniform "
                   "--exposure -2, around the second sphere of the bottom row (metal, fairly smooth), "
                   f"each pixel enlarged {zoom} times. Left, from the 16-bit float HDR image: the two "
                   "highlights are white at the centre and fade into the gold. Right, from an image "
                   "that stores 0 to 1 in 8 bits: every value above 1 was stored as 1, so the large "
                   "highlight is a flat grey disc and the small one a flat grey patch, and the exposure "
                   "only darkened them.")
    width = 400 if narrow else 2 * x0 + 2 * w + gap
    s = Svg(width, y0 + h + (78 if narrow else 66), title, description)
    for c, (pixels, label) in enumerate(pictures):
        x = x0 + c * (w + gap)
        (r, g, b), count = brightest(pixels)
        s.text(x + w / 2, y0 - 10, label, size=size + 0.5, anchor="middle", bold=True)
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, x, y0, zoom)
        caption = [f"brightest ({r}, {g}, {b})", f"× {count}"] if narrow else \
            [f"brightest ({r}, {g}, {b}) × {count}"]
        for i, line in enumerate(caption):
            s.text(x + w / 2, y0 + h + 18 + 16 * i, line, size=size, anchor="middle", fill=MUTED)
    where = f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 picture"
    s.lines(x0, y0 + h + (56 if narrow else 40), [where + ",", f"--sky uniform --exposure -2, enlarged {zoom} times"],
            size=size, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
