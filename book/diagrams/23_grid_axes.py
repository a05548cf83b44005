"""Chapter 23's sphere grid under --sky uniform, with its axes labelled.

The picture is the reviewed test picture tests/golden/23_materials_uniform.png
(headless, 320x240), embedded whole, each pixel drawn 2 x 2 (1 x 1 in the
narrow layout). The labels sit at the spheres' centres as the chapter's camera
projects them: columns, rows, spacing, the eye and fov_y are read from
chapters/23_materials/grid.hpp, and the script checks that grid.hpp still
gives metallic row / (rows - 1) down and roughness 0.1 + 0.9 column /
(columns - 1) across, the values the labels print.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
picture is drawn at its own size, 400 units wide in all.
"""

import os
from fractions import Fraction

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg
from grid23 import COLUMNS, ROWS, SPACING, pixels_per_unit  # book/diagrams/grid23.py




def fraction(value: Fraction) -> str:
    return str(value) if value.denominator <= 3 else f"{float(value):g}"


def main() -> None:
    pixels = read_png(GOLDEN / "23_materials_uniform.png")
    height, width = len(pixels), len(pixels[0])
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    zoom, size = (1, 11) if narrow else (2, 13)
    x0, y0 = (58, 56) if narrow else (104, 66)
    total_w = x0 + width * zoom + (22 if narrow else 30)
    s = Svg(total_w, y0 + height * zoom + (40 if narrow else 48),
            "Chapter 23's spheres under --sky uniform: metallic down, roughness across",
            f"The test picture 23_materials_uniform.png, {width}x{height}: twenty gold spheres on a "
            f"dark blue sky, {ROWS} rows of {COLUMNS}. Metallic grows down the rows, 0, 1/3, 2/3 and 1: "
            "pale yellow plastic at the top, gold metal at the bottom. Roughness grows across the "
            "columns from 0.1 to 1: small sharp highlights on the left, broad soft ones on the right.")
    enlarged(s, pixels, 0, 0, width, height, x0, y0, zoom)
    # Where the camera puts each sphere's centre (grid.hpp's camera: eye on +z, looking at 0).
    per_unit = pixels_per_unit(height, "23_grid_axes.py")  # picture pixels per world unit at z = 0

    def column_x(column: int) -> float:
        return x0 + zoom * (width / 2 + per_unit * SPACING * (column - 0.5 * (COLUMNS - 1)))

    def row_y(row: int) -> float:
        return y0 + zoom * (height / 2 - per_unit * SPACING * (0.5 * (ROWS - 1) - row))

    s.text(x0 + width * zoom / 2, 18 if narrow else 22, "roughness →", size=size, anchor="middle",
           bold=True)
    for column in range(COLUMNS):
        rough = Fraction(1, 10) + Fraction(9, 10) * Fraction(column, COLUMNS - 1)
        x = column_x(column)
        s.text(x, y0 - 10, fraction(rough), size=size, anchor="middle")
        s.line(x, y0 - 6, x, y0 - 1, stroke=MUTED, width=1)
    s.text(16 if narrow else 22, y0 + height * zoom / 2, "metallic →", size=size, anchor="middle",
           bold=True, rotate=90)
    for row in range(ROWS):
        y = row_y(row)
        s.text(x0 - 9, y + size * 0.35, fraction(Fraction(row, ROWS - 1)), size=size, anchor="end")
        s.line(x0 - 6, y, x0 - 1, y, stroke=MUTED, width=1)
    s.text(x0, y0 + height * zoom + (18 if narrow else 22),
           f"tests/golden/23_materials_uniform.png, {width}x{height}", size=size, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
