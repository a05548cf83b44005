"""Chapter 24: the shadow ray of scene.frag's ray_visibility, and its three calls.

Left, a side view: the fragment's point on the floor, its normal n, the ray's
origin a little off the surface along n, the ray towards the light
(-frame.light.xyz, the light's direction reversed), a pillar in its way and
the hit the query commits; the pillar's far face, which a query without
TerminateOnFirstHit could still go on to test, faded. Right, the three calls
in the order the shader makes them. A schematic: the offset is drawn far
larger than it is.

The numbers and flags are read from shaders/24_ray_queries/scene.frag's
rayQueryInitializeEXT call, and the origin's offset from the default of its
specialization constant ray_offset, so the figure cannot drift from the shader.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the calls
go under the picture, 400 units wide.
"""

import math
import os
import re
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, RED, Svg)

ROOT = Path(__file__).resolve().parents[2]
FRAG = ROOT / "shaders" / "24_ray_queries" / "scene.frag"

CALL = re.compile(r"rayQueryInitializeEXT\(query, scene, (?P<flags>[^,]+),\s*(?P<mask>0x[0-9A-Fa-f]+), "
                  r"origin, (?P<tmin>[0-9.]+), -frame\.light\.xyz, (?P<tmax>[0-9.]+)\);")
# The origin, by default (no --ray-offset): ray_offset along the normal, the
# specialization constant's default value.
OFFSET = re.compile(r"const float ray_offset = (?P<offset>[0-9.]+);")
ORIGIN = "const vec3 origin = use_float_offset ? float_offset(world, n) : world + ray_offset * n;"


def read_call() -> dict:
    text = " ".join(FRAG.read_text(encoding="utf-8").split())
    match, offset = CALL.search(text), OFFSET.search(text)
    if match is None or offset is None or ORIGIN not in text \
            or "while (rayQueryProceedEXT(query)) { }" not in text \
            or "rayQueryGetIntersectionTypeEXT(query, true) == gl_RayQueryCommittedIntersectionNoneEXT" \
            not in text:
        raise SystemExit("shaders/24_ray_queries/scene.frag: its ray query no longer reads as the "
                         "figure draws it; redraw book/diagrams/24_ray_query.py")
    call = match.groupdict() | offset.groupdict()
    call["flags"] = [f.strip().replace("gl_RayFlags", "").replace("EXT", "")
                     for f in call["flags"].split("|")]
    return call


def main() -> None:
    call = read_call()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 11 if narrow else 12.5
    lead = size * 1.35
    W = 400 if narrow else 960
    s = Svg(W, 100, "Chapter 24: the shadow ray, and the three calls that trace it",
            f"A side view: the fragment's point on the floor, its normal n, the ray's origin "
            f"{call['offset']} along n above it (drawn enlarged), and the ray towards the light, "
            f"from tMin {call['tmin']} to tMax {call['tmax']}. A pillar stands in its way: where the "
            "ray enters it is the hit the query commits, and the query stops there "
            "(TerminateOnFirstHit); the pillar's far face is never tested. Then the three calls: "
            "rayQueryInitializeEXT starts the ray, rayQueryProceedEXT walks the acceleration "
            "structure and, the ray being opaque, leaves no candidate for the shader, and "
            "rayQueryGetIntersectionTypeEXT(query, true) asks about the committed hit: none means "
            "lit, a triangle means shadow.")

    # ---- the side view -----------------------------------------------------------------
    f = 0.8 if narrow else 1.0
    ox, oy = (10, 0) if narrow else (20, 0)

    def at(x, y):
        return ox + x * f, oy + y * f

    s.text(ox, 22, "The shadow ray, seen from the side", size=size + 1.5, bold=True)
    floor_y = 330
    fx0, fy = at(0, floor_y)
    fx1, _ = at(460, floor_y)
    s.rect(fx0, fy, fx1 - fx0, 16 * f, fill=GREY_FILL, stroke=GREY)
    s.text(fx1 - 6, fy + 16 * f + size + 4, "the floor: opaque triangles", size=size, anchor="end",
           fill=MUTED)
    # The pillar.
    p0x, p0y = at(300, 100)
    p1x, _ = at(360, 100)
    s.rect(p0x, p0y, p1x - p0x, fy - p0y, fill=ORANGE_FILL, stroke=ORANGE, width=1.3)
    s.text((p0x + p1x) / 2, fy - 10, "pillar", size=size, anchor="middle", fill=ORANGE, bold=True)

    # The point, the normal, the origin, the ray.
    wx, wy = at(60, floor_y)
    lift = 38.0  # the offset, drawn enlarged
    s.line(wx, wy, wx, wy - 78 * f, stroke=BLUE, width=1.5, arrow="end")
    s.text(wx - 8, wy - 66 * f, "n", size=size + 2, bold=True, fill=BLUE, anchor="end", italic=True)
    rx, ry = wx, wy - lift
    dx, dy = 1.0, -0.62  # towards the light, on the page
    t_hit = (p0x - rx) / dx
    hx, hy = p0x, ry + dy * t_hit
    t_far = (p1x - rx) / dx
    gx, gy = p1x, ry + dy * t_far
    t_end = (at(440, 0)[0] - rx) / dx
    ex, ey = rx + dx * t_end, ry + dy * t_end
    s.line(rx, ry, hx, hy, stroke=GREEN, width=2.2)
    s.line(hx, hy, ex, ey, stroke=GREY, width=1.3, dash="5 4", arrow="end")
    s.circle(wx, wy, 4, fill=INK, stroke=INK)
    s.circle(rx, ry, 4, fill=GREEN, stroke=GREEN)
    s.circle(gx, gy, 4.5, fill="#ffffff", stroke=GREY, dash="2 2")
    s.circle(hx, hy, 5.5, fill=RED, stroke=RED)
    # The light: a sun past the ray's end.
    sx, sy = ex + 14 * f, ey - 10 * f
    s.circle(sx, sy, 11, fill="#fff3c4", stroke=ORANGE, width=1.3)
    s.text(sx, sy - 16, "light", size=size, anchor="middle", fill=ORANGE, bold=True)

    # Labels.
    s.text(max(wx - 40, 4), wy + 16 * f + size + 4, "world: the fragment's point", size=size)
    s.text(rx + 10, ry + 12, f"origin = world + {call['offset']} * n", size=size, mono=True,
           fill=GREEN)
    s.text(rx + 10, ry + 12 + lead, f"({call['offset']}: drawn enlarged)", size=size, fill=MUTED)
    mx, my = (rx + hx) / 2, (ry + hy) / 2
    angle = -math.degrees(math.atan2(-dy, dx))
    nx, ny = 0.53, 0.85  # the ray's normal, below it
    s.text(mx + 14 * nx, my + 14 * ny + size * 0.35, "direction = −frame.light.xyz", size=size,
           mono=True, fill=GREEN, anchor="middle", rotate=angle)
    s.text(hx - 8, hy - 40, "the hit the query", size=size, fill=RED, bold=True, anchor="end")
    s.text(hx - 8, hy - 40 + lead, "commits: it stops", size=size, fill=RED, bold=True, anchor="end")
    gl = gx + 12
    s.text(gl, gy + 4, "far face:", size=size, fill=MUTED)
    s.text(gl, gy + 4 + lead, "never tested", size=size, fill=MUTED)
    s.text(ex - 24, ey + 2, f"tMax = {call['tmax']}", size=size, mono=True, fill=MUTED, anchor="end")
    pic_bottom = fy + 16 * f + size + 10

    # ---- the three calls ---------------------------------------------------------------
    if narrow:
        bx, by, bw = 10, pic_bottom + 20, 380
    else:
        bx, by, bw = 520, 30, 426
    flags = " | ".join(call["flags"])
    steps = [
        ("rayQueryInitializeEXT(query, scene, …)",
         [f"from world + {call['offset']} * n, t from {call['tmin']}",
          f"along −frame.light.xyz, to t = {call['tmax']}",
          f"flags {flags}", f"cull mask {call['mask']}: every instance"], BLUE_FILL, BLUE),
        ("while (rayQueryProceedEXT(query)) {}",
         ["walks the boxes to the triangles; each hit", "it finds is a candidate. An opaque hit is",
          "committed at once, so none waits for the", "shader to judge: the first call returns false"],
         BLUE_FILL, BLUE),
        ("rayQueryGetIntersectionTypeEXT(query, true)",
         ["true: the committed intersection", "none committed: lit, 1.0",
          "a triangle committed: in shadow, 0.0"], GREEN_FILL, GREEN),
    ]
    y = by
    for i, (head, lines, fill, stroke) in enumerate(steps):
        h = (len(lines) + 1) * lead + 10
        s.rect(bx, y, bw, h, fill=fill, stroke=stroke, rx=6, width=1.3)
        s.text(bx + 9, y + 5 + size, head, size=size, bold=True, mono=True)
        for k, line in enumerate(lines):
            s.text(bx + 9, y + 5 + size + (k + 1) * lead, line, size=size)
        y += h
        if i < len(steps) - 1:
            s.line(bx + bw / 2, y, bx + bw / 2, y + 14, stroke=GREY, width=1.3, arrow="end")
            y += 14
    s.height = max(y, pic_bottom) + 12
    s.write()


if __name__ == "__main__":
    main()
