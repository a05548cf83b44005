"""Chapter 23c: the sphere grid under the uniform sky and under the environment.

Drawn from two reviewed test pictures, headless at 320x240 after 10 frames,
the same flags but the sky: tests/golden/23_materials_uniform.png (--sky
uniform) and tests/golden/23_materials.png (--sky environment).
Above, both whole, a picture pixel to a unit, with a frame round two spheres;
below, those two spheres enlarged 3 times: the roughest plastic (top row,
last column) and the most polished gold (bottom row, first column), each
under the uniform sky and under the environment. The plastic changes little,
so beside it is the difference of the two, environment minus uniform, 8
times over a grey of 128 (cut at 0 and 255), on the sphere only: where the
uniform picture shows its flat background, the difference is drawn grey.
The key and fill lights are the same in both pictures, so the difference is
the sky's light alone. The spheres' centres come from the grid's camera
(grid23.py, which reads chapters/23_materials/grid.hpp).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
pictures are stacked and the crops made 2.5 times, 400 units wide in all.
"""

import os
import sys
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg
from grid23 import COLUMNS, ROWS, SPACING, pixels_per_unit  # book/diagrams/grid23.py

W, H, CROP, GAIN = 320, 240, 46, 8
PICTURES = [("23_materials_uniform.png", "--sky uniform"),
            ("23_materials.png", "--sky environment")]
# (row, column, label): the roughest plastic and the most polished gold.
PICKED = [(0, COLUMNS - 1, "plastic, roughness 1"), (ROWS - 1, 0, "gold, roughness 0.1")]
ORANGE = "#d9480f"
PAGE = Path(__file__).resolve().parents[1] / "23c_image_based_light.md"


def check_page() -> None:
    """The page says how much the difference is brightened; the build stops if it says otherwise."""
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    phrase = f"the difference, brightened {GAIN} times"
    if phrase not in text:
        sys.exit(f"book/23c_image_based_light.md: the page should say '{phrase}' "
                 "(book/diagrams/23c_two_skies.py draws it so)")


def read(name: str):
    pixels = read_png(GOLDEN / name)
    if len(pixels) != H or len(pixels[0]) != W:
        raise SystemExit(f"tests/golden/{name}: {len(pixels[0])}x{len(pixels)}, not {W}x{H}; "
                         "redraw book/diagrams/23c_two_skies.py")
    return pixels


def difference(a, b):
    """128 + GAIN (b - a) per channel, cut to 0..255, where a is not its background
    (a's top left pixel, give or take 12 in the sum of the channels); grey elsewhere."""
    background = a[0][0]

    def one(pa, pb):
        if sum(abs(p - q) for p, q in zip(pa, background)) <= 12:
            return (128, 128, 128)
        return tuple(max(0, min(255, 128 + GAIN * (q - p))) for p, q in zip(pa, pb))
    return [[one(pa, pb) for pa, pb in zip(ra, rb)] for ra, rb in zip(a, b)]


def corner(row: int, column: int) -> tuple[int, int]:
    """The top left of the CROP-square round a sphere's centre."""
    per_unit = pixels_per_unit(H, "23c_two_skies.py")
    cx = W / 2 + per_unit * SPACING * (column - 0.5 * (COLUMNS - 1))
    cy = H / 2 - per_unit * SPACING * (0.5 * (ROWS - 1) - row)
    return round(cx - CROP / 2), round(cy - CROP / 2)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    check_page()
    zoom = 2.5 if narrow else 3
    uniform, environment = (read(name) for name, _ in PICTURES)
    shown = [uniform, environment, difference(uniform, environment)]
    corners = [corner(r, c) for r, c, _ in PICKED]
    title = "Chapter 23c: the sphere grid under the uniform sky and under the environment"
    description = (
        "Two test pictures of the sphere grid, the same but for the sky. Left (above on a phone), "
        "--sky uniform: a flat dark blue background, and the polished gold sphere at the bottom left one "
        "flat dark olive colour with two small highlights. Right (below), --sky environment: a pale blue "
        "sky over a dark brown ground, and that gold sphere a curved mirror: blue-green sky in its upper "
        "half, a bright band of horizon, brown ground below. Under them, two spheres enlarged "
        f"{zoom:g} times, "
        "each under the uniform sky and under the environment. 1, the roughest plastic, top right, looks "
        "nearly the same under both skies, so beside it is the difference, environment minus uniform, "
        f"{GAIN} times over grey: blue-grey over its upper part, brown along its lower edge. 2, the "
        "polished gold, bottom left: flat olive under the uniform sky, the mirrored sky, horizon and "
        "ground under the environment.")
    if narrow:
        width, x0 = 400, 40
        side = CROP * zoom
        top, step = 30, 30 + H + 14
        crops_y = top + step + H + 24
        row_h = 28 + side + 22
        s = Svg(width, crops_y + 2 * row_h + 4, title, description)
        places = [(x0, top + i * step) for i in range(2)]
        gap = (width - 3 * side) / 4
        crop_x = [gap + i * (side + gap) for i in range(3)]
    else:
        gap, x0 = 30, 10
        side = CROP * zoom
        width = 2 * x0 + 2 * W + gap
        top = 30
        crops_y = top + H + 24
        row_h = 28 + side + 22
        s = Svg(width, crops_y + 2 * row_h + 4, title, description)
        places = [(x0 + i * (W + gap), top) for i in range(2)]
        inner = (width - 3 * side) / 4
        crop_x = [inner + i * (side + inner) for i in range(3)]
    size = 13
    for (x, y), pixels, (_, flag) in zip(places, shown, PICTURES):
        s.text(x + W / 2, y - 10, flag, size=size + 0.5, anchor="middle", bold=True, mono=True)
        enlarged(s, pixels, 0, 0, W, H, x, y, 1)
        for (left, upper), number in zip(corners, "12"):
            s.rect(x + left, y + upper, CROP, CROP, stroke=ORANGE, width=2)
            if left + CROP / 2 > W / 2:  # the label on the side of the frame with no sphere
                s.text(x + left + CROP + 4, y + upper + 14, number, size=size, bold=True, fill=ORANGE)
            else:
                s.text(x + left - 4, y + upper + 14, number, size=size, bold=True, fill=ORANGE, anchor="end")
    captions = ["uniform", "environment", f"difference ×{GAIN}"]
    for i, ((left, upper), (_, _, label)) in enumerate(zip(corners, PICKED)):
        y = crops_y + i * row_h
        s.text(crop_x[0], y + 18, f"{i + 1}: {label}", size=size + 0.5, bold=True, fill=ORANGE)
        for x, pixels, caption in list(zip(crop_x, shown, captions))[:3 if i == 0 else 2]:
            enlarged(s, pixels, left, upper, CROP, CROP, x, y + 28, zoom)
            s.text(x + side / 2, y + 28 + side + 16, caption, size=12, anchor="middle", fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
