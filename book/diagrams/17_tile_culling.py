"""Chapter 17: a tile's frustum, its depth range, and its light list.

From shaders/17_tiled_deferred/tiles.glsl (tile_frustum, sphere_touches_tile,
TILE_SIZE, MAX_TILE_LIGHTS, the TileCounts and TileLights buffers) and
tiles.comp (the depth range by atomicMin/atomicMax in shared memory, each
invocation testing lights k, k + 256, ...). The side view is schematic. The
tile size and the list's length are read from tiles.glsl when the diagram is
drawn (book/source_constants.py), so the drawing cannot disagree with the shader.
"""

import math
import sys
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, RED, Svg)

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

TILES_GLSL = Path(__file__).resolve().parents[2] / "shaders" / "17_tiled_deferred" / "tiles.glsl"
TILE = int(constant(TILES_GLSL, "TILE_SIZE"))
MAX_LIGHTS = int(constant(TILES_GLSL, "MAX_TILE_LIGHTS"))
INVOCATIONS = TILE * TILE

# The two panels one above the other, so that the figure is narrower than
# the page's column and its text is shown at its own size.
DY = 600          # where the lower panel (the tiles and one tile's list) starts
W, H = 660, DY + 600


def main() -> None:
    s = Svg(W, H, "Chapter 17: a tile's frustum, its depth range and its light list",
            "A side view of one tile: two of its four planes through the eye, cut at the nearest and "
            "farthest depth its pixels hold. Lights whose spheres touch that frustum are kept, those "
            "wholly outside one plane or the depth range are culled. Below: the tiles of a 1920x1080 "
            "screen and one tile's list in the TileCounts and TileLights buffers.")

    # ---- Left: the side view ---------------------------------------------------------------
    s.text(20, 28, "One tile, seen from the side (view space, schematic)", size=14, bold=True)
    ex, ey = 40, 330
    up, down = math.radians(16.0), math.radians(-10.0)  # the tile's rows: two planes through the eye
    y_at = lambda angle, x: ey - (x - ex) * math.tan(angle)
    near, far = 240, 450
    x_end = 600
    # The whole pyramid, faint; the frustum between near and far, filled.
    s.polygon([(ex, ey), (x_end, y_at(up, x_end)), (x_end, y_at(down, x_end))], fill=GREY_FILL, stroke="none")
    s.polygon([(near, y_at(up, near)), (far, y_at(up, far)), (far, y_at(down, far)), (near, y_at(down, near))],
              fill=PURPLE_FILL, stroke=PURPLE, width=1.6)
    s.line(ex, ey, x_end, y_at(up, x_end), stroke=PURPLE, width=1.3, dash="5 3")
    s.line(ex, ey, x_end, y_at(down, x_end), stroke=PURPLE, width=1.3, dash="5 3")
    s.circle(ex, ey, 5, fill=INK, stroke=INK)
    s.text(ex, ey + 22, "eye", size=12, anchor="middle")
    s.text(x_end, y_at(up, x_end) - 8, "top-row plane", size=12, anchor="end", fill=PURPLE)
    s.text(x_end, y_at(down, x_end) + 18, "bottom-row plane", size=12, anchor="end", fill=PURPLE)

    # What the tile's pixels see: an object's front, and the farthest surface
    # behind it (the floor, say, seen from above: a side view of depth only).
    oy0, oy1 = y_at(up, near) - 6, (y_at(up, near) + y_at(down, near)) / 2
    s.rect(near, oy0, 44, oy1 - oy0, fill="#c8d3df", stroke=GREY)
    s.text(near + 22, oy0 - 8, "object", size=12, anchor="middle", fill=MUTED)
    s.line(far, y_at(up, far) + 2, far, y_at(down, far) + 14, stroke=GREY, width=5)
    s.text(far - 6, y_at(down, far) + 30, "farthest surface", size=12, anchor="end", fill=MUTED)
    s.text(far - 6, y_at(down, far) + 45, "(e.g. the floor)", size=12, anchor="end", fill=MUTED)

    # The depth range.
    ry = ey + 138
    s.line(near, y_at(down, near) + 4, near, ry + 6, stroke=BLUE, dash="3 3")
    s.line(far, y_at(down, far) + 18, far, ry + 6, stroke=BLUE, dash="3 3")
    s.line(near, ry, far, ry, stroke=BLUE, width=1.5, arrow="both")
    s.text(near - 6, ry + 4, "near", size=12, anchor="end", fill=BLUE)
    s.text(far + 6, ry + 4, "far", size=12, fill=BLUE)
    s.text((near + far) / 2, ry + 20, "depth range: nearest and farthest depth", size=12.5, anchor="middle",
           fill=BLUE)
    s.text((near + far) / 2, ry + 35, "of the tile's pixels (background left out)", size=12.5, anchor="middle",
           fill=BLUE)

    # The lights.
    def light(cx, cy, r, kept, label, lx, ly, anchor="start"):
        stroke = GREEN if kept else RED
        s.circle(cx, cy, r, fill=GREEN_FILL if kept else "#ffffff", stroke=stroke, width=1.6,
                 dash=None if kept else "4 3", opacity=0.8 if kept else None)
        s.circle(cx, cy, 2.5, fill=stroke, stroke=stroke)
        s.lines(lx, ly, label, size=12, fill=stroke, anchor=anchor)

    light(350, 318, 28, True, ["kept: touches", "the frustum"], 350, 372, "middle")
    light(150, 330, 26, False, ["culled: wholly", "before near"], 150, 380, "middle")
    light(540, 318, 30, False, ["culled: wholly", "beyond far"], 540, 366, "middle")
    light(300, 168, 28, False, ["culled: wholly", "outside the", "top-row plane"], 262, 150, "end")
    # Near the top far corner: a little outside the top plane and a little
    # beyond far, but wholly outside neither, so the test keeps it.
    light(472, 186, 26, True, ["kept, conservatively: it misses the", "corner, but is wholly outside",
                               "no single plane"], 472, 110, "middle")

    s.lines(20, DY - 62, [
        "sphere_touches_tile culls a light only when its sphere lies wholly outside one of the four",
        "planes, or wholly before near or beyond far: a light that touches the frustum is never culled.",
    ], size=12, leading=1.45)

    # ---- Below: the tiles and one tile's list ----------------------------------------------
    rx = 20
    s.text(rx, DY + 28, f"The screen in tiles of {TILE} \u00d7 {TILE} pixels", size=14, bold=True)
    gx, gy, cols, rows, cell = rx, DY + 44, 12, 9, 21
    for r in range(rows):
        for c in range(cols):
            s.rect(gx + c * cell, gy + r * cell, cell, cell if r < rows - 1 else cell / 2,
                   fill="#ffffff" if (r, c) != (3, 7) else PURPLE_FILL, stroke=GREY if (r, c) != (3, 7) else PURPLE,
                   width=0.6 if (r, c) != (3, 7) else 1.8)
    s.text(gx, gy + rows * cell + 8, f"1920\u00d71080: {-(-1920 // TILE)} \u00d7 {-(-1080 // TILE)} tiles, "
           "the last row half a tile",
           size=12, fill=MUTED)
    s.text(gx + cols * cell + 8, gy + 3 * cell + 15, "tile t", size=12.5, fill=PURPLE, bold=True)
    s.text(gx + cols * cell + 8, gy + 3 * cell + 31, "one workgroup:", size=12, fill=MUTED)
    s.text(gx + cols * cell + 8, gy + 3 * cell + 45, f"{INVOCATIONS} invocations", size=12, fill=MUTED)

    sy = DY + 270
    s.text(rx, sy, "tiles.comp, one workgroup per tile", size=13, bold=True)
    steps = [
        (BLUE_FILL, BLUE, "1  each invocation reads its pixel's depth;",
         "    atomicMin / atomicMax in shared memory"),
        (PURPLE_FILL, PURPLE, "2  barrier(); the tile's frustum from the range", ""),
        (GREEN_FILL, GREEN, f"3  invocation k tests lights k, k + {INVOCATIONS}, ...;",
         "    atomicAdd appends a hit to the shared list"),
        (ORANGE_FILL, ORANGE, "4  barrier(); write found and the list", ""),
    ]
    y = sy + 12
    for fill, stroke, a, b in steps:
        h = 40 if b else 26
        s.rect(rx, y, 340, h, fill=fill, stroke=stroke, rx=5)
        s.text(rx + 8, y + 17, a, size=12.5)
        if b:
            s.text(rx + 8, y + 33, b, size=12.5)
        y += h + 6

    ly = y + 18
    s.text(rx, ly, "The buffers (set 1, bindings 4 and 5)", size=13, bold=True)
    s.text(rx, ly + 24, "tile_counts[t]", size=12.5, mono=True)
    s.rect(rx + 110, ly + 10, 44, 22, fill=ORANGE_FILL, stroke=ORANGE)
    s.text(rx + 132, ly + 25, "27", size=12.5, anchor="middle", mono=True)
    s.text(rx + 162, ly + 25, f"found: may exceed {MAX_LIGHTS:,}", size=12, fill=MUTED)
    s.text(rx, ly + 56, f"tile_lights[t \u00d7 {MAX_LIGHTS} + i]", size=12.5, mono=True)
    bx, by = rx, ly + 64
    values = ["12", "407", "3", "...", "", "", "..."]
    for i, v in enumerate(values):
        s.rect(bx + i * 44, by, 44, 22, fill=ORANGE_FILL if v and v != "..." or i < 4 else "#ffffff",
               stroke=ORANGE if i < 4 else GREY)
        s.text(bx + i * 44 + 22, by + 15, v, size=12, anchor="middle", mono=True)
    s.text(bx, by + 38, f"MAX_TILE_LIGHTS = {MAX_LIGHTS:,} slots per tile; an overflow", size=12, fill=MUTED)
    s.text(bx, by + 52, "is counted and reported, never silent", size=12, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
