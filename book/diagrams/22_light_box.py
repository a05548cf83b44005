"""Chapter 22: the one map's light box, to scale, seen from the light and from the side.

Computed as chapters/22_shadows/cascades.hpp computes it for --cascades 1 (book/diagrams/
cascade_fit.py does the arithmetic): the camera's whole view, 0.1 to 60 units, its eight
corners' bounding sphere, and the light's orthographic box around that sphere, 2 * half a side
(the radius and half a texel each way) and 2 * radius + behind deep. The box's centre is drawn
on the sphere's; the code snaps it to the texel grid, by less than a texel, which does not show
at this scale. The floor is the chapter's (chapters/22_shadows/scene.hpp places it).

Left, seen from the light, in the light's x and y (glm::lookAt's axes, as 22_cascades.py draws
them): the box is the square of the map, the sphere a circle, the view the outline of its
corners. Right, seen from the side, along the light's x axis: across the page the light's y,
down the page the light's direction, from the box's near face (depth 0) to its far face (depth
1). The light's x axis is horizontal in the world, so the floor, the plane y = 0, is seen edge
on, as a line, and the sphere's centre lies below it.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two views are stacked,
400 units wide.
"""

import importlib
import math
import os
import re
from pathlib import Path

from cascade_fit import (BEHIND, EYE, FAR, LIGHT, NEAR, add, cross, dot, mul, one_cascade_box_side,
                         one_cascade_centre, one_cascade_radius, slice_corners, unit)
from svg import BLUE, BLUE_FILL, GREY, INK, MUTED, ORANGE, RED, Svg, wrap

hull = importlib.import_module("22_cascades").hull  # the convex hull 22b's figure draws slices with

SCENE = Path(__file__).resolve().parents[2] / "chapters" / "22_shadows" / "scene.hpp"
# The floor's placement in scene.hpp: transform(position, angle, axis, scale) of a unit square.
_FLOOR = re.search(r"transform\(\{([^}]*)\}, 0, \{0, 1, 0\}, \{([^}]*)\}\)[^;]*floor\}",
                   SCENE.read_text(encoding="utf-8"))
FLOOR_AT = tuple(float(v) for v in _FLOOR.group(1).split(","))
FLOOR_SIZE = tuple(float(v) for v in _FLOOR.group(2).split(","))

F = unit(LIGHT)                 # the light's direction: down the side view
AX = unit(cross(F, (0, 1, 0)))  # the light's x: across the map, horizontal in the world
AY = cross(AX, F)               # the light's y: up the map
FORWARD = unit((0.0, -0.25, -1.0))

RADIUS = one_cascade_radius()
HALF = one_cascade_box_side() / 2
CENTRE = one_cascade_centre()
CORNERS = slice_corners(NEAR, FAR)
FLOOR = [add(FLOOR_AT, (sx * FLOOR_SIZE[0] / 2, 0.0, sz * FLOOR_SIZE[2] / 2))
         for sx, sz in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
ALONG = math.dist(CENTRE, EYE)
BOX_FILL = "#fff4e6"

TITLE = "Chapter 22: the one map's light box, to scale, from the light and from the side"
DESCRIPTION = (
    f"To scale, for the chapter's camera with --cascades 1. Left, seen from the light: the camera's "
    f"view from {NEAR} to {FAR:.0f} units, drawn as the outline of its corners from the eye; its "
    f"bounding sphere, a circle of radius {RADIUS:.1f}; and the dashed square of the light's box "
    f"around it, {2 * HALF:.0f} units a side; the floor is a thin parallelogram inside. Right, seen "
    f"from the side with the light coming down the page: the same box, {2 * HALF:.0f} units across and "
    f"{2 * RADIUS + BEHIND:.0f} deep, {BEHIND:.0f} units of it above the sphere towards the light "
    f"and {2 * RADIUS:.1f} through the sphere; the floor is a line, the eye {EYE[1]:.0f} units above "
    f"it, and the sphere's centre on the line of sight, {ALONG:.2f} units from the eye, "
    f"{-CENTRE[1]:.1f} units below the floor.")
HEADING = "The one map's box, to scale: the view, the sphere around it, the box around the sphere"
LEFT_HEAD = "Seen from the light"
LEFT_SUB = "x and y across the map; the light goes into the page"
RIGHT_HEAD = "Seen from the side"
RIGHT_SUB = "the light's y across, its direction down the page"
KEY = [(BLUE, f"Blue: the camera's view, from the eye out to {FAR:.0f} units."),
       (RED, f"Red: the sphere around it, radius {RADIUS:.1f}, and its centre."),
       (ORANGE, "Dashed orange: the light's box, which the map covers."),
       (GREY, f"Grey: the floor, {FLOOR_SIZE[0]:.0f} by {FLOOR_SIZE[2]:.0f} units, at y = {FLOOR_AT[1]:.0f}.")]
CENTRE_NOTE = (f"The centre lies on the line of sight (dashed), {ALONG:.2f} units from the eye, "
               f"{-CENTRE[1]:.1f} units below the floor.")


def key(s: Svg, x: float, y: float, width: float, size: float) -> float:
    """The key's lines from baseline y; returns the baseline after the last."""
    for colour, label in KEY:
        for line in wrap(label, width, size):
            s.text(x, y, line, size=size, fill=colour if colour != GREY else MUTED)
            y += size * 1.35
    return y


def note(s: Svg, x: float, y: float, width: float, size: float) -> float:
    lines = wrap(CENTRE_NOTE, width, size)
    s.lines(x, y, lines, size=size, fill=RED)
    return y + len(lines) * size * 1.3


def frame(points, x, y, scale, top):
    """A function from drawing units (u across, v up) to the page, u = points' least at x,
    v = top at y."""
    left = min(p[0] for p in points)
    return lambda p: (x + (p[0] - left) * scale, y + (top - p[1]) * scale)


def from_light(s: Svg, x: float, y: float, scale: float, size: float) -> float:
    """The view from the light, the box's top left corner at (x, y); returns its bottom."""
    def light(p):
        return (dot(p, AX), dot(p, AY))

    cx, cy = light(CENTRE)
    box = [(cx - HALF, cy - HALF), (cx + HALF, cy + HALF)]
    page = frame(box, x, y, scale, cy + HALF)
    s.rect(x, y, 2 * HALF * scale, 2 * HALF * scale, fill=BOX_FILL, stroke=ORANGE, width=1.6, dash="7 4")
    s.polygon([page(light(p)) for p in FLOOR], fill="#ecebe4", stroke=GREY, width=1.0)
    s.polygon([page(p) for p in hull([light(p) for p in CORNERS])], fill=BLUE_FILL, stroke=BLUE,
              width=1.6, opacity=0.85)
    pc = page((cx, cy))
    s.circle(*pc, RADIUS * scale, stroke=RED, width=1.5)
    s.circle(*pc, 3, fill=RED, stroke=RED)
    # The radius, drawn towards the lower right, where the box is empty.
    a = math.radians(-60)
    end = (pc[0] + RADIUS * scale * math.cos(a), pc[1] - RADIUS * scale * math.sin(a))
    s.line(*pc, *end, stroke=RED, width=1.1)
    s.text(pc[0] + 10, pc[1] + 44, f"r = {RADIUS:.1f}", size=size, fill=RED, bold=True)
    ex, ey = page(light(EYE))
    s.circle(ex, ey, 3.5, fill=INK, stroke=INK)
    s.text(ex - 6, ey + 16, "eye", size=size, anchor="end")
    far = page(light(add(EYE, mul(FAR, FORWARD))))
    s.text(far[0] - 4, far[1] - 20, f"view, to {FAR:.0f}", size=size, anchor="middle", fill=BLUE, bold=True)
    fl = page(light(FLOOR_AT))
    s.text(fl[0] - 30, fl[1] + 4, "floor", size=size, anchor="middle", fill=GREY)
    # The box's side, above it.
    s.line(x + 2, y - 10, x + 2 * HALF * scale - 2, y - 10, stroke=ORANGE, width=1.0, arrow="both")
    s.text(x + HALF * scale, y - 16, f"box: {2 * HALF:.0f} units a side", size=size, anchor="middle",
           fill=ORANGE, bold=True)
    return y + 2 * HALF * scale


def from_side(s: Svg, x: float, y: float, scale: float, size: float) -> float:
    """The view from the side, the box's near face's left end at (x, y); returns its bottom.
    Across: the light's y; up the page: against the light."""
    def side(p):
        return (dot(p, AY), -dot(p, F))

    cu, cv = side(CENTRE)
    near = cv + RADIUS + BEHIND
    page = frame([(cu - HALF, 0)], x, y, scale, near)
    w, h = 2 * HALF * scale, (2 * RADIUS + BEHIND) * scale
    s.rect(x, y, w, h, fill=BOX_FILL, stroke=ORANGE, width=1.6, dash="7 4")
    # The light, coming down onto the near face.
    for k in range(1, 6):
        ax = x + w * k / 6
        s.line(ax, y - 26, ax, y - 3, stroke=ORANGE, width=1.3, arrow="end")
    s.text(x + w + 6, y - 12, "light", size=size, fill=ORANGE, bold=True)
    # The sphere's top: where `behind` ends.
    top = page((cu, cv + RADIUS))[1]
    s.line(x, top, x + w, top, stroke=ORANGE, width=0.8, dash="2 3")
    s.text(x + 6, y + size + 4, "depth 0", size=size, fill=ORANGE)
    s.text(x + 6, y + h - 7, "depth 1", size=size, fill=ORANGE)
    s.text(x + w / 2, (y + top) / 2 + size * 0.35, f"behind: {BEHIND:.0f}", size=size, anchor="middle",
           fill=ORANGE, bold=True)
    # Dimensions at the right: behind, then the sphere's 2r.
    dx = x + w + 8
    for a, b, labels in ((y, top, [f"{BEHIND:.0f}"]), (top, y + h, ["2r =", f"{2 * RADIUS:.1f}"])):
        s.line(dx, a + 2, dx, b - 2, stroke=MUTED, width=1.0, arrow="both")
        s.lines(dx + 5, (a + b) / 2 + size * 0.35 - (len(labels) - 1) * size * 0.65, labels, size=size,
                fill=MUTED)
    f0, f1 = min((side(p) for p in FLOOR)), max((side(p) for p in FLOOR))
    s.line(*page(f0), *page(f1), stroke=GREY, width=2.2)
    s.polygon([page(p) for p in hull([side(p) for p in CORNERS])], fill=BLUE_FILL, stroke=BLUE,
              width=1.6, opacity=0.85)
    s.line(*page(f0), *page(f1), stroke=GREY, width=2.2, dash="3 3")
    pc = page((cu, cv))
    s.circle(*pc, RADIUS * scale, stroke=RED, width=1.5)
    eye = page(side(EYE))
    far = page(side(add(EYE, mul(FAR, FORWARD))))
    s.line(*eye, *far, stroke=INK, width=1.0, dash="5 3")
    s.circle(*pc, 3, fill=RED, stroke=RED)
    s.circle(*eye, 3.5, fill=INK, stroke=INK)
    s.text(eye[0] - 6, eye[1] - 8, "eye", size=size, anchor="end")
    s.text(page(f1)[0] + 6, page(f1)[1] + 4, "floor", size=size, fill=GREY, bold=True)
    s.text(pc[0] - 8, pc[1] + size + 6, "centre", size=size, anchor="end", fill=RED, bold=True)
    return y + h


def wide() -> Svg:
    scale, size = 2.9, 13
    s = Svg(1000, 100, TITLE, DESCRIPTION)
    s.text(20, 28, HEADING, size=14, bold=True)
    lx, rx, top = 40, 560, 126
    s.text(lx, 62, LEFT_HEAD, size=14, bold=True)
    s.text(lx, 80, LEFT_SUB, size=size, fill=MUTED)
    s.text(rx, 62, RIGHT_HEAD, size=14, bold=True)
    s.text(rx, 80, RIGHT_SUB, size=size, fill=MUTED)
    left = from_light(s, lx, top, scale, size)
    key(s, lx, left + 34, 480, size)
    bottom = note(s, rx, from_side(s, rx, top, scale, size) + 26, 330, size)
    s.height = bottom + 6
    return s


def narrow() -> Svg:
    scale, size = 2.7, 12.5
    s = Svg(400, 100, TITLE, DESCRIPTION)
    x, width = 20, 360
    heading = wrap(HEADING, width, 14, bold=True)
    s.lines(x, 26, heading, size=14, bold=True)
    y = 26 + len(heading) * 14 * 1.3 + 12
    s.text(x, y, LEFT_HEAD, size=14, bold=True)
    s.text(x, y + 18, LEFT_SUB, size=size, fill=MUTED)
    y = from_light(s, x, y + 62, scale, size) + 28
    y = key(s, x, y, width, size) + 24
    s.text(x, y, RIGHT_HEAD, size=14, bold=True)
    s.text(x, y + 18, RIGHT_SUB, size=size, fill=MUTED)
    y = from_side(s, x, y + 62, scale, size)
    y = note(s, x, y + 26, width, size)
    s.height = y + 6
    return s


def main() -> None:
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
