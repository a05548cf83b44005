"""Chapter 28b: one sphere's meshlets, seen from above, coloured by their fate.

A schematic, not a picture the chapter draws: the sphere is cut into patches of
a latitude-longitude grid (SEGMENTS x RINGS quads, PATCH x PATCH quads a patch),
which stand in for chapter 26's meshlets. Each patch gets the bounds the builder
gives a meshlet, a sphere around its corners and a cone around its normals, and
the two tests of shaders/28_gpu_culling/meshlet_cull.glsl are made here, for an
eye at the bottom whose vertical field of view is read from
chapters/28_gpu_culling/scene.hpp, in a 4:3 picture:

- outside the frustum: the patch's sphere lies wholly beyond the right edge's plane;
- facing away: dot(centre - eye, axis) >= cutoff * |centre - eye| + radius, with
  cutoff = sin(half-angle) (never culled at 90 degrees or more).

The sphere straddles the right edge of the view. Drawn from above, upper half
only (the lower half mirrors it), the patches lie over each other in height
order. `python3 28b_sphere_meshlets.py --numbers` prints the counts.
With VKT_DIAGRAM_LAYOUT=narrow the text stands below the drawing, 400 units wide.
"""

import importlib
import math
import os
import sys

from svg import GREEN, INK, MUTED, Svg

SEGMENTS, RINGS, PATCH = 32, 16, 2
RADIUS = 1.0
ASPECT = 4.0 / 3.0
DISTANCE = 4.0  # from the eye to the sphere's centre
MAGENTA, MAGENTA_FILL = "#a01fb0", "#e23fed"  # --view culled's magenta (linear 0.75, 0.05, 0.85)
YELLOW, YELLOW_FILL = "#9a7400", "#ffe100"    # --view culled's yellow (linear 1, 0.75, 0)


# The camera's vertical field of view, read from scene.hpp as 28b_cone_rays.py reads it.
field_of_view = importlib.import_module("28b_cone_rays").field_of_view


def half_width() -> float:
    """The horizontal half-angle of the view, in radians."""
    return math.atan(math.tan(math.radians(field_of_view() / 2)) * ASPECT)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    n = norm(a)
    return tuple(x / n for x in a)


def on_sphere(seg: float, ring: float):
    """(x, y, z) with y up; ring 0 at the top."""
    phi = math.pi * ring / RINGS
    theta = 2 * math.pi * seg / SEGMENTS
    return (math.sin(phi) * math.cos(theta), math.cos(phi), math.sin(phi) * math.sin(theta))


def patches():
    """Each patch: its outline (unit sphere), its bounds and its fate."""
    h = half_width()
    # The sphere's centre: on a ray just inside the right edge, so that it straddles the edge.
    along = h + math.radians(3)
    centre = (DISTANCE * math.sin(along), 0.0, DISTANCE * math.cos(along))
    outward = (math.cos(h), 0.0, -math.sin(h))  # the right plane's outward normal (the eye at 0)
    out = []
    for r0 in range(0, RINGS, PATCH):
        for s0 in range(0, SEGMENTS, PATCH):
            grid = [on_sphere(s, r) for r in range(r0, r0 + PATCH + 1) for s in range(s0, s0 + PATCH + 1)]
            normals = [on_sphere(s + 0.5, r + 0.5) for r in range(r0, r0 + PATCH) for s in range(s0, s0 + PATCH)]
            mid = tuple(sum(c) / len(grid) for c in zip(*grid))
            radius = max(norm(sub(p, mid)) for p in grid) * RADIUS
            centre_w = tuple(c + RADIUS * m for c, m in zip(centre, mid))
            axis = unit(tuple(sum(c) for c in zip(*normals)))
            half = max(math.acos(max(-1.0, min(1.0, dot(axis, n)))) for n in normals)
            cutoff = math.sin(half) if half < math.pi / 2 else 2.0
            if dot(centre_w, outward) > radius:
                fate = "outside"
            elif dot(centre_w, axis) >= cutoff * norm(centre_w) + radius:
                fate = "away"
            else:
                fate = "kept"
            outline = ([on_sphere(s, r0) for s in range(s0, s0 + PATCH + 1)]
                       + [on_sphere(s0 + PATCH, r) for r in range(r0, r0 + PATCH + 1)]
                       + [on_sphere(s, r0 + PATCH) for s in range(s0 + PATCH, s0 - 1, -1)]
                       + [on_sphere(s0, r) for r in range(r0 + PATCH, r0 - 1, -1)])
            world = [tuple(c + RADIUS * p for c, p in zip(centre, q)) for q in outline]
            out.append({"fate": fate, "outline": world, "height": mid[1]})
    return centre, out


def counts() -> dict:
    _, ps = patches()
    return {f: sum(p["fate"] == f for p in ps) for f in ("kept", "away", "outside")}


def draw(s: Svg, eye, k: float, size: float) -> None:
    h = half_width()
    centre, ps = patches()

    def at(p):
        return (eye[0] + p[0] * k, eye[1] - p[2] * k)

    reach = (DISTANCE + 1.5) / math.cos(h)
    for side, length in ((1, reach), (-1, 0.55 * reach)):
        end = (side * length * math.sin(h), 0.0, length * math.cos(h))
        s.line(*eye, *at(end), stroke=INK, width=1.5)
    s.line(*eye, *at((0, 0, DISTANCE + 1.5)), stroke=MUTED, width=1.0, dash="5 4")
    s.circle(*eye, 5, fill=INK, stroke=INK)
    s.text(eye[0], eye[1] + size + 8, "eye", size=size, anchor="middle", bold=True)
    edge_label = at((reach * 0.12 * math.sin(h), 0, reach * 0.12 * math.cos(h)))
    s.text(edge_label[0] + 8, edge_label[1] + 10, "edge of the view", size=size,
           rotate=-(90 - math.degrees(h)))
    fills = {"kept": (GREEN, "#8fd19e"), "away": (YELLOW, YELLOW_FILL), "outside": (MAGENTA, MAGENTA_FILL)}
    for p in sorted((p for p in ps if p["height"] >= 0), key=lambda p: p["height"]):
        stroke, fill = fills[p["fate"]]
        s.polygon([at(q) for q in p["outline"]], fill=fill, stroke=INK, width=0.7)
    # Redraw the edge over the sphere, so the reader sees where it cuts.
    s.line(*at((0.45 * reach * math.sin(h), 0, 0.45 * reach * math.cos(h))),
           *at((reach * math.sin(h), 0, reach * math.cos(h))), stroke=INK, width=1.5, dash="4 3")


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    c = counts()
    description = ("A schematic seen from above: an eye at the bottom, the two edges of its view fanning out, and "
                   "one sphere cut into patches that stand in for meshlets, straddling the right edge. Patches on "
                   "the near side, which face the eye, are green: launched. Patches on the far side face away "
                   "from the eye and are yellow: culled by their normal cone. Patches wholly beyond the right "
                   "edge are magenta: culled by the frustum test.")
    title = "Chapter 28b: one sphere's meshlets, by fate (a schematic)"
    text = [
        (INK, True, "One sphere, seen from above (a schematic)."),
        (INK, False, "Each patch stands for one meshlet."),
        (None, False, None),
        (GREEN, True, f"Green: launched ({c['kept']})."),
        (GREEN, False, "The near side, facing the eye."),
        (None, False, None),
        (YELLOW, True, f"Yellow: facing away ({c['away']})."),
        (YELLOW, False, "The far side: every normal in the"),
        (YELLOW, False, "patch's cone points away from the eye."),
        (None, False, None),
        (MAGENTA, True, f"Magenta: outside the frustum ({c['outside']})."),
        (MAGENTA, False, "The patch's sphere lies wholly beyond"),
        (MAGENTA, False, "the right edge's plane."),
        (None, False, None),
        (MUTED, False, f"Counts for all {len(patches()[1])} patches; drawn: the upper half."),
    ]
    lead = 1.35
    if narrow:
        size = 11
        s = Svg(400, 100, title, description)
        draw(s, (130, 330), 50, size)
        y = 368
        x = 10
    else:
        size = 12.5
        s = Svg(900, 100, title, description)
        draw(s, (220, 470), 80, size)
        y, x = 70, 560
    for fill, bold, line in text:
        if line is None:
            y += size * lead * 0.6
            continue
        s.text(x, y, line, size=size, fill=fill, bold=bold)
        y += size * lead
    s.height = max(y + 6, 500 if not narrow else y + 6)
    s.write()


if __name__ == "__main__":
    if sys.argv[1:] == ["--numbers"]:
        print(counts())
    else:
        main()
