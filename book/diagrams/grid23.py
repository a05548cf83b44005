"""Chapter 23's sphere grid as its camera sees it, read from grid.hpp, for
the figures that place labels or crops on its pictures (23_grid_axes.py,
23c_spheres_levels.py, 23_grid_lights.py): the grid's size and spacing, the field of view, the
eye's distance, and each sphere's centre in pixels of a width x height
picture. A figure stops the book's build when grid.hpp no longer says what
this reads."""

import math
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

GRID_HPP = Path(__file__).resolve().parents[2] / "chapters" / "23_materials" / "grid.hpp"
COLUMNS, ROWS = int(constant(GRID_HPP, "columns")), int(constant(GRID_HPP, "rows"))
SPACING, FOV_Y = float(constant(GRID_HPP, "spacing")), float(constant(GRID_HPP, "fov_y"))
MATERIAL = ("{glm::vec3(1.0f, 0.71f, 0.29f), float(row) / float(rows - 1), "
            "0.1f + 0.9f * float(column) / float(columns - 1)}")


def eye_distance(figure: str) -> float:
    text = GRID_HPP.read_text(encoding="utf-8")
    if MATERIAL not in " ".join(text.split()):
        raise SystemExit("chapters/23_materials/grid.hpp: the spheres' material is no longer "
                         f"`{MATERIAL}`; redraw book/diagrams/{figure}")
    found = re.search(r"glm::vec3 eye\{0\.0f, 0\.0f, ([0-9.]+)f\}", text)
    if not found:
        raise SystemExit("chapters/23_materials/grid.hpp: no `glm::vec3 eye{0.0f, 0.0f, Z}`; "
                         f"redraw book/diagrams/{figure}")
    return float(found.group(1))


def pixels_per_unit(height: int, figure: str) -> float:
    """Pixels per world unit in the plane of the spheres' centres."""
    return (height / 2) / (eye_distance(figure) * math.tan(FOV_Y / 2))
