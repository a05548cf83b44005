"""Chapter 23c: three gold spheres beside the prefiltered level each one reads.

Drawn from two reviewed test pictures, headless after 10 frames:
tests/golden/23_materials.png (the sphere grid under --sky environment,
320x240) and tests/golden/23_materials_view_prefiltered.png (--view
prefiltered, 640x480: the prefiltered cube's levels as panoramas, three
across, two down, level 0 at the top left). Three spheres of the bottom row
(metallic 1, the clearest mirrors), columns 0, 2 and 4, each cropped 46 by 46
around where the chapter's camera puts its centre and enlarged 2 times; beside
each, the panorama of the level its roughness reads, level = roughness x
(specular_levels - 1). Roughness, the camera and the number of levels are read
from chapters/23_materials/grid.hpp and environment.hpp; the panoramas are
found in the picture (everything not its background colour).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) each
row's label stands above its pictures, 400 units wide in all.
"""

import math
import os
import sys
from fractions import Fraction
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg
from grid23 import COLUMNS, ROWS, SPACING, pixels_per_unit  # book/diagrams/grid23.py

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

CHAPTER = Path(__file__).resolve().parents[2] / "chapters" / "23_materials"
ENVIRONMENT_HPP = CHAPTER / "environment.hpp"
LEVELS = int(constant(ENVIRONMENT_HPP, "specular_levels"))
PICKED, CROP, ZOOM = (0, 2, 4), 46, 2



def runs(flags: list[bool]) -> list[tuple[int, int]]:
    """The (first, last) index of each run of True."""
    out, start = [], None
    for i, flag in enumerate(flags + [False]):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            out.append((start, i - 1))
            start = None
    return out


def panoramas(pixels) -> list[tuple[int, int, int, int]]:
    """(left, top, width, height) of each level's panorama, level 0 first."""
    background = pixels[0][0]
    used = [[sum(abs(a - b) for a, b in zip(p, background)) > 6 for p in row] for row in pixels]
    ys = runs([any(row) for row in used])
    xs = runs([any(row[x] for row in used) for x in range(len(pixels[0]))])
    if len(ys) * len(xs) != LEVELS:
        raise SystemExit(f"23_materials_view_prefiltered.png: {len(xs)} x {len(ys)} panoramas, "
                         f"not the {LEVELS} levels of environment.hpp")
    return [(x0, y0, x1 - x0 + 1, y1 - y0 + 1) for (y0, y1) in ys for (x0, x1) in xs]


def number(value: Fraction) -> str:
    return f"{float(value):g}"


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    grid = read_png(GOLDEN / "23_materials.png")
    view = read_png(GOLDEN / "23_materials_view_prefiltered.png")
    panels = panoramas(view)
    height, width = len(grid), len(grid[0])
    per_unit = pixels_per_unit(height, "23c_spheres_levels.py")
    row = ROWS - 1
    cy = height / 2 - per_unit * SPACING * (0.5 * (ROWS - 1) - row)
    items = []
    for column in PICKED:
        rough = Fraction(1, 10) + Fraction(9, 10) * Fraction(column, COLUMNS - 1)
        level = rough * (LEVELS - 1)
        shown = math.floor(level)
        cx = width / 2 + per_unit * SPACING * (column - 0.5 * (COLUMNS - 1))
        if level == shown:
            note = f"level {shown} shown"
        else:
            note = f"between {shown} and {shown + 1}; {shown} shown"
        items.append((rough, level, shown, round(cx - CROP / 2), note))
    top = round(cy - CROP / 2)
    pw, ph = panels[0][2], panels[0][3]
    side = CROP * ZOOM
    title = "Chapter 23c: three gold spheres beside the prefiltered level each one reads"
    description = ("Three rows. In each, one gold sphere of the bottom row of the grid under the environment, "
                   "enlarged 2 times, and beside it the panorama of the prefiltered cube's level that its "
                   "roughness reads, level = roughness × " + str(LEVELS - 1) + ". " +
                   "; ".join(f"roughness {number(r)}, level {number(lv)} ({n})" for r, lv, _, _, n in items) +
                   ". The smooth sphere mirrors a sharp horizon and a small sun, as the sharp panorama shows; "
                   "the middle one a blurred horizon and a glow; the roughest only an even wash of sky "
                   "above and ground below, like the last panorama.")
    if narrow:
        label_h, row_h = 34, max(side, ph) + 48
        s = Svg(400, 20 + 3 * row_h + 24, title, description)
        x_sphere = 14
        x_panel = x_sphere + side + 24
        for i, (rough, level, shown, left, note) in enumerate(items):
            y = 20 + i * row_h
            s.text(x_sphere, y, f"roughness {number(rough)}: level {number(rough)} × {LEVELS - 1} = "
                   f"{number(level)}", size=12, bold=True)
            s.text(x_sphere, y + 16, note, size=12, fill=MUTED)
            y += label_h - 10
            enlarged(s, grid, left, top, CROP, CROP, x_sphere, y + (ph - side) / 2, ZOOM)
            s.line(x_sphere + side + 4, y + ph / 2, x_panel - 4, y + ph / 2, arrow="end")
            px, py, _, _ = panels[shown]
            enlarged(s, view, px, py, pw, ph, x_panel, y, 1)
        s.text(x_sphere, 20 + 3 * row_h + 4, "23_materials.png and 23_materials_view_prefiltered.png",
               size=11, fill=MUTED)
        s.write()
        return
    x_text, x_sphere = 20, 215
    x_panel = x_sphere + side + 40
    row_h = max(side, ph) + 24
    s = Svg(x_panel + pw + 20, 40 + 3 * row_h + 20, title, description)
    s.text(x_sphere + side / 2, 24, "sphere (×2)", size=13, anchor="middle", fill=MUTED)
    s.text(x_panel + pw / 2, 24, "prefiltered level (--view prefiltered)", size=13, anchor="middle",
           fill=MUTED)
    for i, (rough, level, shown, left, note) in enumerate(items):
        y = 40 + i * row_h
        mid = y + max(side, ph) / 2
        s.text(x_text, mid - 12, f"roughness {number(rough)}", size=14, bold=True)
        s.text(x_text, mid + 6, f"level {number(rough)} × {LEVELS - 1} = {number(level)}", size=13)
        s.text(x_text, mid + 23, note, size=12, fill=MUTED)
        enlarged(s, grid, left, top, CROP, CROP, x_sphere, mid - side / 2, ZOOM)
        s.line(x_sphere + side + 6, mid, x_panel - 6, mid, arrow="end")
        px, py, _, _ = panels[shown]
        enlarged(s, view, px, py, pw, ph, x_panel, mid - ph / 2, 1)
    s.text(x_text, 40 + 3 * row_h + 6, "tests/golden/23_materials.png (bottom row) and "
           "23_materials_view_prefiltered.png", size=12, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
