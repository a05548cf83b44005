"""Chapter 23's BRDF factor by factor: --term d, f and v beside the whole BRDF.

The four pictures are the reviewed test pictures (tests/golden/
23_materials_term_d.png, _term_f.png, _term_v.png and 23_materials_clamp.png,
headless, 320x240, --sky uniform --tone-map clamp), each cropped to the
sphere grid and drawn pixel for pixel. The crop is where the chapter's camera
puts the grid (book/diagrams/grid23.py reads it from grid.hpp), with a few
pixels to spare.

Wide: the four in a row. With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for
it, for phones): one picture a row, its label to its right, 400 units wide.
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg
from grid23 import COLUMNS, ROWS, SPACING, pixels_per_unit  # book/diagrams/grid23.py

PANELS = (  # (golden image, title, how it is drawn, what to see: in the narrow layout)
    ("23_materials_term_d.png", "D alone", "--term d", ("narrows as", "roughness falls")),
    ("23_materials_term_f.png", "F alone (with n·v)", "--term f", ("whiter at the rims,", "gold on the metal")),
    ("23_materials_term_v.png", "V alone, as G", "--term v", ("rims darken on", "the rough spheres")),
    ("23_materials_clamp.png", "The whole BRDF", "no --term", ("all three, the", "diffuse and the sky")),
)
RADIUS = 0.5  # each sphere's, in world units (grid.hpp)
SPARE = 7     # pixels round the grid: the outer spheres bulge a little in perspective


def main() -> None:
    pictures = [read_png(GOLDEN / panel[0]) for panel in PANELS]
    height, width = len(pictures[0]), len(pictures[0][0])
    if any((len(p), len(p[0])) != (height, width) for p in pictures):
        raise SystemExit("23_brdf_terms.py: the four golden images differ in size")
    per_unit = pixels_per_unit(height, "23_brdf_terms.py")
    half_w = per_unit * (SPACING * (COLUMNS - 1) / 2 + RADIUS) + SPARE
    half_h = per_unit * (SPACING * (ROWS - 1) / 2 + RADIUS) + SPARE
    left, top = round(width / 2 - half_w), round(height / 2 - half_h)
    crop_w, crop_h = round(2 * half_w), round(2 * half_h)
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23's BRDF factor by factor: D, F and V alone, and the whole BRDF"
    description = (
        "Four pictures of the sphere grid (roughness 0.1 to 1 across, metallic 0 to 1 down), "
        "each a number per pixel through the clamp curve. D alone: black spheres with one "
        "highlight each, a tiny white dot on the left widening to a flat grey half disc at "
        "roughness 1; every row the same. F alone, with n·v for v·h: dark grey plastic with thin bright rims at the "
        "top, gold at the bottom; every column the same. V alone, as G: white lit halves on the "
        "polished spheres, greying towards the rims on the rough ones; every row the same. The "
        "whole BRDF: yellow plastic to gold, with highlights.")
    if narrow:
        gap, x0, size = 10, 8, 11
        s = Svg(400, 8 + len(PANELS) * (crop_h + gap), title, description)
        for i, (picture, (_, name, flag, note)) in enumerate(zip(pictures, PANELS)):
            y = 8 + i * (crop_h + gap)
            enlarged(s, picture, left, top, crop_w, crop_h, x0, y, 1)
            tx = x0 + crop_w + 10
            s.text(tx, y + 24, name, size=size + 1, bold=True)
            s.text(tx, y + 42, flag, size=size, mono=True)
            s.lines(tx, y + 66, note, size=size, fill=MUTED)
        s.write()
        return
    gap, x0, y0, size = 16, 10, 30, 15
    s = Svg(2 * x0 + len(PANELS) * crop_w + (len(PANELS) - 1) * gap, y0 + crop_h + 50, title,
            description)
    for i, (picture, (_, name, flag, _)) in enumerate(zip(pictures, PANELS)):
        x = x0 + i * (crop_w + gap)
        s.text(x + crop_w / 2, y0 - 10, name, size=size, bold=True, anchor="middle")
        enlarged(s, picture, left, top, crop_w, crop_h, x, y0, 1)
        s.text(x + crop_w / 2, y0 + crop_h + 20, flag, size=size - 2, mono=True, anchor="middle")
    s.text(x0, y0 + crop_h + 42, "roughness 0.1 to 1 across, metallic 0 to 1 down, as in the "
           "picture at the top of the page; cut at 1 (--tone-map clamp)", size=size - 2, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
