"""Chapter 22: the view split into cascades, each with its own light box, and the frame's passes.

The top is computed as chapters/22_shadows/cascades.hpp computes it, from
the chapter's camera (eye (0, 3, 8), looking along (0, -0.25, -1), 50 degrees
high, 4:3 as at the default 800x600 and the tests' 320x240), its near 0.1 and
far 60, three cascades split by the practical scheme with lambda 0.6 (at 8.5
and 20.3), and its light along (-0.6, -1, -0.45). It is drawn as the light
sees it, to scale: in the light's x and y (glm::lookAt's axes), each slice of
the view projected, its bounding sphere (a circle of the same radius) and the
square of side 2r (and half a texel more each way, as the code makes it) that
is the cascade's shadow map; book/diagrams/cascade_fit.py does the arithmetic.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
figure is 400 units wide: the drawing at 360 units instead of 440, the key
under it, and the frame's three passes stacked, the arrows pointing down.
"""

import os

from cascade_fit import LIGHT, EYE, MAP_SIZE, box_side, cross, dot, sphere, splits, texel, unit
from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, RED, Svg, wrap)

W, H = 1000, 720
SPLITS = splits()
COLOURS = [(RED, "#fbe3e1"), (GREEN, GREEN_FILL), (BLUE, BLUE_FILL)]


def hull(points):
    """The convex hull of 2D points, counter-clockwise (Andrew's monotone chain)."""
    pts = sorted(set(points))

    def half(seq):
        out = []
        for p in seq:
            while len(out) >= 2 and ((out[-1][0] - out[-2][0]) * (p[1] - out[-2][1]) -
                                     (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])) <= 0:
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(reversed(pts))
    return lower[:-1] + upper[:-1]


TITLE = "Chapter 22: the view split into three cascades, and the passes of one frame"
DESCRIPTION = (
    f"Top, to scale, as the light sees it: the camera's view split at {SPLITS[1]:.1f} and {SPLITS[2]:.1f} units into "
    "three slices; around each, its bounding circle and the square of the same width that is "
    f"that cascade's shadow map, {MAP_SIZE} texels a side whatever its size. The near slice's square "
    f"is {box_side(0):.1f} units wide, the middle one's {box_side(1):.1f}, the far one's "
    f"{box_side(2):.1f}: fine texels near the eye, "
    "coarse ones far away. Bottom: each frame draws the scene from the light into each "
    "cascade's layer of one depth image, a barrier from depth writes to fragment shader "
    "reads, then the lit pass, which picks a cascade by distance and compares.")
HEADING = ("Seen from the light, to scale: each slice of the view, its bounding sphere and "
           "the map around it")
KEY_SLICES = ["Filled: the slice of the camera's view", "that each cascade covers: 0.1 to 8.5,",
              "8.5 to 20.3 and 20.3 to 60 units."]
KEY_SHAPES = ["Circle: the slice's bounding sphere.", "Dashed square: the light's box around it,",
              "side 2r: the cascade's shadow map,", f"{MAP_SIZE} texels a side."]
KEY_SNAP = ["The square keeps its size as the camera", "turns, and its centre moves by whole",
            "texels only: the shadows' edges stay still."]
PASSES_HEADING = "One frame: the shadow pass, the barrier, the lit pass"
SHADOW_BOX = ["shadow pass, per cascade c", "depth only into layer c", "light_from_world[c] · world",
              "depth bias: constant + slope"]
BARRIER_BOX = ["barrier: layers 0..N-1", "DEPTH_ATTACHMENT → SHADER_READ_ONLY",
               "fragment tests' writes → fragment shader's reads"]
LIT_BOX = ["lit pass", "cascade: by the point's distance", "compare its light depth (sampler)",
           "3x3 taps averaged: PCF"]
NEXT_FRAME = ("next frame: its shadow pass waits for this lit pass's reads before it clears the map")


def slices(s: Svg, area_x: float, area_y: float, area_h: float) -> float:
    """The three slices, circles and squares, the far square area_h high at (area_x, area_y);
    returns the drawing's right edge."""
    # The light's axes, as glm::lookAt(0, light, (0, 1, 0)) makes them: x across, y up the map.
    f = unit(LIGHT)
    ax = unit(cross(f, (0, 1, 0)))
    ay = cross(ax, f)
    fits = []
    for i in range(3):
        corners, centre, radius = sphere(i)
        fits.append(([(dot(p, ax), dot(p, ay)) for p in corners], (dot(centre, ax), dot(centre, ay)),
                     radius))
    # Fit every square into the drawing area.
    left = min(c[0] - r for _, c, r in fits)
    right = max(c[0] + r for _, c, r in fits)
    top = max(c[1] + r for _, c, r in fits)
    bottom = min(c[1] - r for _, c, r in fits)
    scale = area_h / (top - bottom)

    def to_page(p):
        return (area_x + (p[0] - left) * scale, area_y + (top - p[1]) * scale)

    for i in reversed(range(3)):  # the far, large ones first, so the near ones stay on top
        points, centre, radius = fits[i]
        stroke, fill = COLOURS[i]
        cx, cy = to_page(centre)
        r = radius * scale
        s.rect(cx - r, cy - r, 2 * r, 2 * r, stroke=stroke, width=1.4, dash="6 4")
        s.circle(cx, cy, r, stroke=stroke, width=1.0, opacity=0.7)
        s.polygon([to_page(p) for p in hull(points)], fill=fill, stroke=stroke, width=1.6)
    for i, (points, centre, radius) in enumerate(fits):
        stroke, _ = COLOURS[i]
        cx, cy = to_page(centre)
        r = radius * scale
        s.text(cx + r - 5, cy - r + 16, f"{i}", size=14, anchor="end", bold=True, fill=stroke)
    ex, ey = to_page((dot(EYE, ax), dot(EYE, ay)))
    s.circle(ex, ey, 3.5, fill=INK, stroke=INK)
    s.text(ex - 4, ey + 46, "eye", size=12, anchor="middle")
    s.line(ex - 2, ey + 34, ex - 1, ey + 6, stroke=INK, width=1.0)
    return area_x + (right - left) * scale


def key(s: Svg, kx: float, y: float, size: float) -> float:
    """The key's lines from baseline y; returns the baseline after the last."""
    step = size * 1.3
    s.lines(kx, y, KEY_SLICES, size=size)
    y += len(KEY_SLICES) * step + 24
    s.lines(kx, y, KEY_SHAPES, size=size)
    y += len(KEY_SHAPES) * step + 24
    for i in range(3):
        stroke, _ = COLOURS[i]
        s.text(kx, y, f"cascade {i}: {box_side(i):.1f} units wide, texel {texel(i):.4f}",
               size=size, bold=True, fill=stroke)
        y += size * 1.7
    y += 20
    s.lines(kx, y, KEY_SNAP, size=size, fill=MUTED)
    return y + len(KEY_SNAP) * step


def wide() -> Svg:
    s = Svg(W, H, TITLE, DESCRIPTION)
    s.text(20, 28, HEADING, size=14, bold=True)
    right = slices(s, 30, 50, 440)
    # The key, at the right of the drawing.
    key(s, right + 36, 80, 14)

    # The passes of one frame.
    y = 560
    s.text(20, y - 24, PASSES_HEADING, size=14, bold=True)
    s.box(20, y, 270, 110, SHADOW_BOX, fill=ORANGE_FILL, stroke=ORANGE, bold_first=True)
    s.box(320, y + 15, 340, 80, BARRIER_BOX, fill="#eee6fa", stroke=PURPLE, bold_first=True, size=12)
    s.box(690, y, 290, 110, LIT_BOX, fill=GREEN_FILL, stroke=GREEN, bold_first=True)
    s.line(290, y + 55, 320, y + 55, stroke=INK, width=1.6, arrow="end")
    s.line(660, y + 55, 690, y + 55, stroke=INK, width=1.6, arrow="end")
    s.text(500, y + 140, NEXT_FRAME, size=12.5, anchor="middle", fill=GREY)
    return s


def narrow() -> Svg:
    """The drawing, the key under it, then the passes stacked."""
    s = Svg(400, 100, TITLE, DESCRIPTION)
    x, width = 20, 360
    heading = wrap(HEADING, width, 14, bold=True)
    s.lines(x, 26, heading, size=14, bold=True)
    top = 26 + len(heading) * 14 * 1.3 + 8
    slices(s, x, top, width)
    y = key(s, x, top + width + 40, 13.5) + 30
    heading = wrap(PASSES_HEADING, width, 14, bold=True)
    s.lines(x, y, heading, size=14, bold=True)
    y += (len(heading) - 1) * 14 * 1.3 + 16
    gap = 36
    for lines, h, fill, stroke, size in ((SHADOW_BOX, 100, ORANGE_FILL, ORANGE, 13),
                                         (BARRIER_BOX, 80, "#eee6fa", PURPLE, 12.5),
                                         (LIT_BOX, 100, GREEN_FILL, GREEN, 13)):
        if lines is not SHADOW_BOX:
            s.line(200, y - gap + 4, 200, y - 4, stroke=INK, width=1.6, arrow="end")
        s.box(x, y, width, h, lines, fill=fill, stroke=stroke, bold_first=True, size=size)
        y += h + gap
    y -= gap - 28
    lines = wrap(NEXT_FRAME, width, 12.5)
    s.lines(x, y, lines, size=12.5, fill=GREY)
    s.height = y + len(lines) * 12.5 * 1.3 + 4
    return s


def main() -> None:
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
