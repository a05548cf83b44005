"""Chapter 23b: one highlight cut at 1 and through the ACES curve, enlarged.

Drawn from two reviewed test pictures made with the same flags but the curve,
headless at 320x240 after 10 frames: tests/golden/23_materials_clamp.png
(--sky uniform --tone-map clamp) and tests/golden/23_materials_uniform.png
(--sky uniform, ACES by default). The same crop of each, around the bottom row's
second sphere (metal, roughness 0.325), whose two highlights show the page's
claim most clearly: cut at 1, a flat yellow disc with a hard edge; through ACES,
a white centre that fades out. Every pixel is enlarged (nearest neighbour, as
23d's zoom does through golden.enlarged). The count under each crop, pixels
with a channel at 255, is taken from the pictures when the book is built.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
crops stay side by side, 400 units wide, enlarged 4 times instead of 6.
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP_W, CROP_H = 92, 164, 44, 44
COLUMNS = [("23_materials_clamp.png", "--tone-map clamp"), ("23_materials_uniform.png", "--tone-map aces")]


def saturated(pixels) -> int:
    """Pixels of the crop with at least one channel at 255."""
    return sum(255 in p for row in pixels[TOP:TOP + CROP_H] for p in row[LEFT:LEFT + CROP_W])


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    zoom, x0, gap, size = (4, 16, 16, 13) if narrow else (6, 20, 30, 13.5)
    w, h, y0 = CROP_W * zoom, CROP_H * zoom, 34
    pictures = [(read_png(GOLDEN / name), flag) for name, flag in COLUMNS]
    counts = [saturated(p) for p, _ in pictures]
    title = f"Chapter 23b: one highlight cut at 1 and through ACES, enlarged {zoom} times"
    description = (f"The same {CROP_W} by {CROP_H} pixels of two test pictures under the uniform sky, "
                   "around the second sphere of the bottom row (metal, fairly smooth), each pixel "
                   f"enlarged {zoom} times. Left, cut at 1: the large highlight is a flat yellow disc "
                   "with a hard edge, every pixel in it the same colour, and the small one a flat "
                   "pale patch. Right, through ACES: each highlight is white at its centre and fades "
                   "smoothly into the gold around it.")
    width = 400 if narrow else 2 * x0 + 2 * w + gap
    s = Svg(width, y0 + h + (62 if narrow else 66), title, description)
    for c, ((pixels, flag), count) in enumerate(zip(pictures, counts)):
        x = x0 + c * (w + gap)
        s.text(x + w / 2, y0 - 10, flag, size=size + 0.5, anchor="middle", bold=True, mono=True)
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, x, y0, zoom)
        s.text(x + w / 2, y0 + h + 18, f"{count} pixels at 255", size=size, anchor="middle", fill=MUTED)
    where = f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 picture"
    s.lines(x0, y0 + h + 40, [where + ",", f"--sky uniform, each pixel enlarged {zoom} times"],
            size=size, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
