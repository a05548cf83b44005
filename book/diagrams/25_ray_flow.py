"""Chapter 25: which shader runs for which ray, and how deep, for one pixel.

The ray-generation shader traces the camera's ray (depth 1, payload `hit`
at its location 0). Where it meets nothing, sky.rmiss (miss index 0) writes
the sky into that payload. Where it meets a triangle, closest.rchit runs:
it traces a shadow ray (payload `shadowed`, its location 2; miss index 1;
no closest-hit shader, stops at the first hit), and, for a mirror, a
reflected ray (payload `reflected`, its location 1; miss index 0) that runs
closest.rchit again one level deeper. The depths are those of
chapters/25_ray_tracing (payload depth, push constants bounces and
max_depth = bounces + 2), drawn for --bounces 2.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
depths are stacked as rows, 400 units wide: the closest-hit shaders down the
left, the miss shaders on the right.
"""

import os

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE,
                 PURPLE_FILL, Svg, wrap)

W, H = 1000, 660
TITLE = "Chapter 25: the shaders one pixel runs, and each ray's depth"
DESCRIPTION = ("The ray-generation shader traces the camera's ray at depth 1. If it misses, the sky "
               "miss shader writes the sky colour into its payload. If it hits, the closest-hit "
               "shader runs for it: it traces a shadow ray towards the light at depth 2, which runs "
               "only the shadow miss shader if nothing is in the way, and, on a mirror, a reflected "
               "ray at depth 2 that runs the closest-hit shader again. With --bounces 2 that repeats "
               "to depth 3, and the last surface's shadow ray is at depth 4, the pipeline's recursion "
               "depth.")
# The note under the figure, broken into the wide layout's three lines.
NOTE = [
    "Every closest.rchit traces a shadow ray if the light faces the point and hit.depth < "
    "max_depth, and a reflected ray if the surface reflects and",
    "hit.depth <= bounces. A reflected ray that misses runs sky.rmiss, as the camera's does; a "
    "shadow ray that hits something runs no shader at all",
    "(it asks for no closest hit), so `shadowed` keeps the 1 set before tracing it."]


def main() -> None:
    if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow":
        narrow()
        return
    s = Svg(W, H, TITLE, DESCRIPTION)
    s.text(20, 28, "One pixel, --bounces 2: which shader runs for which ray, by the ray's depth",
           size=14, bold=True)
    col = [200, 400, 600, 800]  # the left edge of each depth's column
    for d, x in enumerate(col, start=1):
        s.text(x + 95, 62, f"rays at depth {d}", size=13, anchor="middle", fill=MUTED, bold=True)
        s.line(x - 6, 72, x - 6, 560, stroke="#d1d9e0", width=1)
    s.box(20, 90, 160, 60, ["raygen.rgen", "payload hit (loc. 0)"], fill=ORANGE_FILL,
          stroke=ORANGE, bold_first=True, size=12.5)
    s.box(col[0] + 10, 270, 170, 50, ["sky.rmiss", "miss index 0: the sky"], fill=BLUE_FILL,
          stroke=BLUE, bold_first=True, size=12.5)
    s.line(100, 150, col[0] + 8, 292, stroke=BLUE, width=1.4, arrow="end")
    s.text(30, 250, "camera ray misses", size=12, fill=BLUE)
    rows = [90, 270, 430]
    for level in range(3):
        x, y = col[level] + 10, rows[level]
        if level == 0:
            s.box(x, y, 170, 60, ["closest.rchit", "hit.depth = 1"], fill=GREEN_FILL,
                  stroke=GREEN, bold_first=True, size=12.5)
            s.line(180, 120, x - 2, 120, stroke=INK, width=1.6, arrow="end")
            s.text(190, 112, "hits", size=12)
        # The shadow ray: depth level + 2, towards the next column.
        nx = col[level + 1] + 10
        sy = y + 80 if level < 2 else y + 70
        s.box(nx, sy, 170, 50, ["shadow.rmiss", f"miss index 1, depth {level + 2}"],
              fill=PURPLE_FILL, stroke=PURPLE, bold_first=True, size=12.5)
        s.line(x + 120, y + 60, nx - 2, sy + 25, stroke=PURPLE, width=1.4, arrow="end")
        if level == 0:
            s.text(x + 8, y + 96, "shadow ray, nothing", size=12, fill=PURPLE)
            s.text(x + 8, y + 111, "in the way", size=12, fill=PURPLE)
        if level < 2:
            # The reflected ray, one level deeper, runs this shader again.
            ny = rows[level + 1]
            s.box(nx, ny, 170, 60, ["closest.rchit", f"hit.depth = {level + 2}"],
                  fill=GREEN_FILL, stroke=GREEN, bold_first=True, size=12.5)
            s.path(f"M{x + 170:.0f},{y + 30:.0f} C{x + 215:.0f},{y + 30:.0f} {nx - 40:.0f},"
                   f"{ny + 30:.0f} {nx - 2:.0f},{ny + 30:.0f}", stroke=INK, width=1.6,
                   arrow="end")
            s.text(x + 150, y - 8, "mirror: reflected ray hits", size=12)
    s.text(990, 572, "depth 4 = bounces + 2: the pipeline's recursion depth", size=12,
           fill=PURPLE, anchor="end")
    s.lines(20, 600, NOTE, size=12.5)
    s.write()


def narrow() -> None:
    """The same flow for a phone: one row per depth, top to bottom, 400 units wide."""
    size = 11
    s = Svg(400, 100, TITLE, DESCRIPTION)
    s.lines(20, 24, ["One pixel, --bounces 2: which shader runs", "for which ray, by the ray's depth"],
            size=13, bold=True)
    left, right, bw, bh = 20, 230, 150, 46  # the chain of closest hits; the miss shaders
    band = 118  # one row per depth
    top = [0, 160, 160 + band, 160 + 2 * band, 160 + 3 * band]  # where depth d's row starts
    s.box(left, 62, 170, bh, ["raygen.rgen", "payload hit (loc. 0)"], fill=ORANGE_FILL,
          stroke=ORANGE, bold_first=True, size=size)
    for d in range(1, 5):
        s.line(12, top[d], 388, top[d], stroke="#d1d9e0", width=1)
        s.text(left, top[d] + 15, f"rays at depth {d}", size=size, fill=MUTED, bold=True)
    ax = left + 130  # the vertical arrows down the chain
    # Depth 1: the camera ray misses (the sky) or hits (the first closest hit).
    s.box(right, top[1] + 24, bw, bh, ["sky.rmiss", "miss index 0: the sky"], fill=BLUE_FILL,
          stroke=BLUE, bold_first=True, size=size)
    s.line(left + 170, 62 + bh / 2, right - 2, top[1] + 24 + bh / 2, stroke=BLUE, width=1.4,
           arrow="end")
    s.lines(right + 2, 62 + bh + 16, ["camera ray", "misses"], size=size, fill=BLUE)
    s.line(ax, 62 + bh, ax, top[1] + 22, stroke=INK, width=1.6, arrow="end")
    s.text(ax - 6, 62 + bh + 20, "hits", size=size, anchor="end")
    for level in range(3):
        y, ny = top[level + 1] + 24, top[level + 2] + 24
        if level == 0:
            s.box(left, y, 170, bh, ["closest.rchit", "hit.depth = 1"], fill=GREEN_FILL,
                  stroke=GREEN, bold_first=True, size=size)
        # The shadow ray: depth level + 2, in the next row.
        s.box(right, ny, bw, bh, ["shadow.rmiss", f"miss index 1, depth {level + 2}"],
              fill=PURPLE_FILL, stroke=PURPLE, bold_first=True, size=size)
        s.line(left + 170, y + bh / 2, right - 2, ny + bh / 2, stroke=PURPLE, width=1.4,
               arrow="end")
        if level == 0:
            s.lines(right + 2, y + bh + 16, ["shadow ray, nothing", "in the way"], size=size,
                    fill=PURPLE)
        if level < 2:
            # The reflected ray, one level deeper, runs this shader again.
            s.box(left, ny, 170, bh, ["closest.rchit", f"hit.depth = {level + 2}"],
                  fill=GREEN_FILL, stroke=GREEN, bold_first=True, size=size)
            s.line(ax, y + bh, ax, ny - 2, stroke=INK, width=1.6, arrow="end")
            s.lines(ax - 6, y + bh + 16, ["mirror: reflected", "ray hits"], size=size,
                    anchor="end")
    y = top[4] + 24 + bh + 20
    s.lines(380, y, ["depth 4 = bounces + 2:", "the pipeline's recursion depth"], size=size,
            fill=PURPLE, anchor="end")
    y += 2 * size * 1.3 + 14
    note = wrap(" ".join(NOTE), 360, size)
    s.lines(20, y, note, size=size)
    s.height = y + (len(note) - 1) * size * 1.3 + 14
    s.write()


if __name__ == "__main__":
    main()
