"""Chapter 23's sphere grid and where its two lights shine from.

Three panels. From above: one row of the grid's spheres (x across, the eye
towards the bottom of the page) and each light's direction seen from above.
From the side: one column of spheres (y up, the eye towards the right) and
each light's direction seen from the side. The picture: the polished metal
sphere at the bottom left of the reviewed test picture
tests/golden/23_materials_uniform.png (320x240), enlarged, with a ring round
each light's highlight, where the chapter's camera puts the mirror point of
that light (the point whose normal halves the way to the light and to the
eye). The grid's size, spacing, camera and radius, and the lights' directions
and irradiances, are read from chapters/23_materials/grid.hpp.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
panels stand one above the other, 400 units wide in all.
"""

import math
import os
import re

from golden import GOLDEN, enlarged, read_png
from svg import BLUE, GREY, GREY_FILL, INK, MUTED, ORANGE, Svg
from grid23 import COLUMNS, FOV_Y, GRID_HPP, ROWS, SPACING, eye_distance  # book/diagrams/grid23.py

FIGURE = "23_grid_lights.py"
RADIUS = 0.5
NUMBER = r"(-?[0-9.]+)f"
VEC3 = rf"glm::vec3\({NUMBER}, {NUMBER}, {NUMBER}\)"


def lights() -> list[tuple[tuple[float, float, float], tuple[float, float, float]]]:
    """grid.hpp's two lights: (direction towards the light, normalized; irradiance)."""
    text = " ".join(GRID_HPP.read_text(encoding="utf-8").split())
    found = re.findall(rf"\{{glm::normalize\({VEC3}\), {VEC3}\}}", text)
    radius = re.search(r"float spacing = [0-9.]+f, radius = ([0-9.]+)f;", text)
    if len(found) != 2 or not radius or float(radius.group(1)) != RADIUS:
        raise SystemExit("chapters/23_materials/grid.hpp: not two lights "
                         "`{glm::normalize(glm::vec3(...)), glm::vec3(...)}` and radius 0.5; "
                         f"redraw book/diagrams/{FIGURE}")
    out = []
    for numbers in found:
        d = [float(n) for n in numbers[:3]]
        length = math.sqrt(sum(c * c for c in d))
        out.append((tuple(c / length for c in d), tuple(float(n) for n in numbers[3:])))
    return out


def normalize(v):
    length = math.sqrt(sum(c * c for c in v))
    return tuple(c / length for c in v)


def highlight(centre, light, eye):
    """The point of a sphere that mirrors a directional light into the eye."""
    n = normalize(tuple(l + e - c for l, e, c in zip(light, eye, centre)))
    for _ in range(8):
        p = tuple(c + RADIUS * k for c, k in zip(centre, n))
        n = normalize(tuple(l + v for l, v in zip(light, normalize(tuple(e - q for e, q in zip(eye, p))))))
    return tuple(c + RADIUS * k for c, k in zip(centre, n))


def numbers(v) -> str:
    return ", ".join(f"{c:g}" for c in v)


def view(s, ox, oy, title_y, scale, across, count, label, axis, eye_label, lights_2d, names, size):
    """One panel: count spheres in a line, across the page (top view) or down it (side
    view), centred at (ox, oy), the way to the eye dashed, and each light's arrow."""
    for i in range(count):
        offset = SPACING * (i - 0.5 * (count - 1)) * scale
        cx, cy = (ox + offset, oy) if across else (ox, oy + offset)
        s.circle(cx, cy, RADIUS * scale, fill=GREY_FILL, stroke=GREY, width=1)
    s.text(ox, title_y, label, size=size, anchor="middle", bold=True)
    s.text(ox, title_y + size * 1.25, axis, size=size - 1, anchor="middle", fill=MUTED)
    if across:  # the eye beyond the bottom edge
        s.line(ox, oy + 0.8 * scale, ox, oy + 2.9 * scale, stroke=MUTED, width=1.2, dash="4 3",
               arrow="end")
        s.text(ox + 5, oy + 2.9 * scale, eye_label, size=size - 1, fill=MUTED)
    else:  # the eye beyond the right edge
        s.line(ox + 0.8 * scale, oy, ox + 2.9 * scale, oy, stroke=MUTED, width=1.2, dash="4 3",
               arrow="end")
        s.text(ox + 2.9 * scale, oy - 5, eye_label, size=size - 1, anchor="end", fill=MUTED)
    for (dx, dy), colour, name in zip(lights_2d, (ORANGE, BLUE), names):
        d = normalize((dx, dy))
        tail = (ox + 2.9 * scale * d[0], oy + 2.9 * scale * d[1])
        head = (ox + 0.95 * scale * d[0], oy + 0.95 * scale * d[1])
        s.line(tail[0], tail[1], head[0], head[1], stroke=colour, width=2.2, arrow="end")
        s.circle(tail[0], tail[1], 5, fill=colour, stroke=colour, width=1)
        anchor = "end" if d[0] < -0.2 else "start"
        s.text(tail[0] + (-8 if anchor == "end" else 8), tail[1] + size * 0.35, name, size=size,
               anchor=anchor, fill=colour, bold=True)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    (key, key_e), (fill, fill_e) = lights()
    distance = eye_distance(FIGURE)
    eye = (0.0, 0.0, distance)
    pixels = read_png(GOLDEN / "23_materials_uniform.png")
    height, width = len(pixels), len(pixels[0])
    tan = math.tan(FOV_Y / 2)

    def project(p):
        depth = distance - p[2]
        return (width / 2 + p[0] / depth / tan * height / 2, height / 2 - p[1] / depth / tan * height / 2)

    # The polished metal sphere: bottom row (metallic 1), left column (roughness 0.1).
    centre = (SPACING * (0 - 0.5 * (COLUMNS - 1)), SPACING * (0.5 * (ROWS - 1) - (ROWS - 1)), 0.0)
    cx, cy = project(centre)
    spots = [project(highlight(centre, light, eye)) for light in (key, fill)]
    crop, zoom = 40, 4
    left, top = round(cx - crop / 2), round(cy - crop / 2)

    size = 11 if narrow else 12
    scale = 22 if narrow else 34
    names = ("key", "fill")
    picture = crop * zoom
    if narrow:
        ox1, ox2, px, py = 95.0, 262.0, (400 - picture) / 2, 56 + 2.3 * scale + 2.2 * scale + 36
    else:
        ox1, ox2, px, py = 130.0, 300.0, 470.0, 48.0
    oy1, oy2 = 56 + 0.5 * scale, 56 + 2.3 * scale
    total_w = 400 if narrow else px + picture + 30
    total_h = py + picture + 20 + 2 * size * 1.3
    s = Svg(total_w, total_h,
            "Chapter 23's sphere grid and its two lights, from above, from the side, and on one sphere",
            f"From above, a row of {COLUMNS} spheres with the eye {distance:g} units towards the "
            "bottom: the warm key light shines from the left and in front, the cool fill light from "
            "the right and in front. From the side, a column of "
            f"{ROWS} spheres with the eye to the right: the key shines from above and in front, the "
            "fill from in front and a little below. Below them, the polished metal sphere at the "
            "bottom left of the test picture, enlarged, with a ring round each light's highlight: "
            "the key's at its upper left, the fill's right of its centre and a little below."
            .replace("Below them", "Below them" if narrow else "On the right"))
    # From above: page x = world x, page y = world z (towards the eye is down the page).
    view(s, ox1, oy1, 20, scale, True, COLUMNS, "From above", "x across, z down",
         f"to the eye, {distance:g} away", [(key[0], key[2]), (fill[0], fill[2])], names, size)
    # From the side, the right side: page x = world z, page y = -world y.
    view(s, ox2, oy2, 20, scale, False, ROWS, "From the side", "z across, y up",
         "to the eye", [(key[2], -key[1]), (fill[2], -fill[1])], names, size)
    # The picture of one sphere.
    s.text(px + picture / 2, py - 22, "The highlights", size=size, anchor="middle", bold=True)
    s.text(px + picture / 2, py - 8, "metallic 1, roughness 0.1", size=size - 1, anchor="middle",
           fill=MUTED)
    enlarged(s, pixels, left, top, crop, crop, px, py, zoom)
    for (hx, hy), colour, name in zip(spots, (ORANGE, BLUE), names):
        x, y = px + (hx - left) * zoom, py + (hy - top) * zoom
        s.circle(x, y, 11, stroke=colour, width=2.4)
        s.circle(x, y, 12.5, stroke="#ffffff", width=0.8)
        s.text(x, y - 16 if name == "key" else y + 26, name, size=size, anchor="middle", fill="#ffffff",
               bold=True)
    notes = [f"key: warm, irradiance {numbers(key_e)}",
             f"fill: cool, irradiance {numbers(fill_e)}"]
    ny = py + picture + 20
    for note, colour in zip(notes, (ORANGE, BLUE)):
        s.text(px + picture / 2, ny, note, size=size - 1, anchor="middle", fill=colour)
        ny += size * 1.3
    s.write()


if __name__ == "__main__":
    main()
