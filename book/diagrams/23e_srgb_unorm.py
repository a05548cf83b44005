"""Chapter 23e: the base colour read through _SRGB, as the chapter does, and through _UNORM.

Drawn from two pictures of the page's model command (--sky uniform --model
assets/gltf/pbr_cubes.gltf, headless at 320x240 after 10 frames): left the
reviewed test picture tests/golden/23_materials_model.png, right
book/images/23e_base_unorm.png, made with the base colour's texture created
_UNORM instead of _SRGB (book/images/23e_base_unorm.txt says how). The same crop
of each, around the right cube, every pixel enlarged (nearest neighbour). Under
each crop, the mean colour of its red squares, taken from the pictures when the
book is built.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
crops stay side by side, 400 units wide, enlarged twice instead of 4 times.
"""

import os
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

IMAGES = Path(__file__).resolve().parents[1] / "images"
LEFT, TOP, CROP_W, CROP_H = 166, 72, 96, 118
COLUMNS = [(GOLDEN / "23_materials_model.png", "_SRGB (the chapter)"),
           (IMAGES / "23e_base_unorm.png", "_UNORM (wrong)")]


def red_places(pixels) -> list[tuple[int, int]]:
    """Where the crop is reddish in the chapter's picture (_SRGB): red well above
    green and blue. Both pictures are averaged over these same pixels, since the
    _UNORM picture's paler reds would fail the test and drop out."""
    return [(x, y) for y in range(TOP, TOP + CROP_H) for x in range(LEFT, LEFT + CROP_W)
            if (p := pixels[y][x])[0] > 60 and p[0] > 1.6 * p[1] and p[0] > 1.6 * p[2]]


def red_mean(pixels, places) -> tuple[int, int, int]:
    """The mean colour of `pixels` over `places`."""
    n = max(len(places), 1)
    return tuple(round(sum(pixels[y][x][c] for x, y in places) / n) for c in range(3))


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    zoom, x0, gap, size = (2, 6, 4, 12) if narrow else (4, 20, 30, 13.5)
    w, h, y0 = CROP_W * zoom, CROP_H * zoom, 40
    pictures = [(read_png(path), label) for path, label in COLUMNS]
    places = red_places(pictures[0][0])
    title = f"Chapter 23e: the base colour through _SRGB and through _UNORM, enlarged {zoom} times"
    description = (f"The same {CROP_W} by {CROP_H} pixels of two pictures of the test model, the "
                   "right cube, each pixel enlarged. Left, the base colour's texture created "
                   "_SRGB, as the chapter does: a deep red and cream checker. Right, the same "
                   "texture created _UNORM, so its sRGB-encoded bytes are read as linear numbers: "
                   "the red squares turn a pale, washed-out pink and the whole cube looks lighter "
                   "and greyer.")
    width = 400 if narrow else 2 * x0 + 2 * w + gap
    s = Svg(width, y0 + h + (72 if narrow else 56), title, description)
    for c, (pixels, label) in enumerate(pictures):
        x = x0 + c * (w + gap)
        s.text(x + w / 2, y0 - 12, label, size=size + 0.5, anchor="middle", bold=True, mono=True)
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, x, y0, zoom)
        s.text(x + w / 2, y0 + h + 18, "red squares, mean (%d, %d, %d)" % red_mean(pixels, places), size=size - (1 if narrow else 0),
               anchor="middle", fill=MUTED)
    where = f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 picture"
    foot = [where + ",", f"enlarged {zoom} times"] if narrow else [where + f", enlarged {zoom} times"]
    s.lines(x0, y0 + h + 40, foot, size=size, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
