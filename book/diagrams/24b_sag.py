"""Chapter 24b: the tessellation's sag, and why the shadow ray starts 0.01 off.

A cut through the centre of chapter 24's sphere (MeshBuilder::sphere(32, 16),
diameter 1, scaled 1.4: radius 0.7) along the diagonals of the quads at its
equator, the edges each quad's two triangles share. By the mesh's symmetry
(a half turn about any vertex's radius) the cut runs along one diagonal after
another, so the mesh's section is a polygon of equal chords, each
acos(cos^2(pi / 16)) = 15.9 degrees of arc: the flat surface at its lowest
under the round one (0.0067, the page's 0.007 in a quad's middle). Along an
edge the interpolated normal is the radius through the point. A point Q near
a vertex, lit by a grazing light (88 degrees from its normal, an example):
the ray from Q itself dips under its own flat triangle and hits the next one
from inside; the ray from Q + 0.01 n (scene.frag) starts outside the round
sphere and leaves clear. Drawn to scale, 1 unit = K page units.

The numbers are read from the sources: the offset from
shaders/24_ray_queries/scene.frag, the slices, stacks and scale from
chapters/24_ray_queries/main.cpp, the diameter from meshes.hpp.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
cut is drawn 400 units wide, at a smaller scale, the text in short lines.
"""

import math
import os
import re
from pathlib import Path

from svg import BLUE, GREEN, GREY, GREY_FILL, INK, MUTED, ORANGE, PURPLE, RED, Svg

ROOT = Path(__file__).resolve().parents[2]


def read(path: Path, pattern: str) -> str:
    match = re.search(pattern, path.read_text(encoding="utf-8"))
    if match is None:
        raise SystemExit(f"{path.relative_to(ROOT)}: no `{pattern}`; redraw book/diagrams/24b_sag.py")
    return match.group(1)


OFFSET = float(read(ROOT / "shaders/24_ray_queries/scene.frag", r"const float ray_offset = ([0-9.]+);"))
SLICES, STACKS = (int(v) for v in read(ROOT / "chapters/24_ray_queries/main.cpp",
                                       r"builder\.sphere\((\d+, \d+)\)").split(", "))
SCALE = float(read(ROOT / "chapters/24_ray_queries/main.cpp",
                   r"glm::vec3\(([0-9.]+)f\)\),\s*\{[^}]*\},\s*mesh\[sphere_mesh\]"))
HALF = float(read(ROOT / "common/scene/include/vkt/scene/meshes.hpp", r"vertex\(([0-9.]+)f \* n, n\)"))
R = HALF * SCALE
STEP = math.pi / STACKS
assert abs(2 * math.pi / SLICES - STEP) < 1e-12, "the figure assumes square quads at the equator"
ALPHA = math.acos(math.cos(STEP) ** 2)  # the arc one diagonal spans
SAG = R * (1 - math.cos(ALPHA / 2))
GRAZE = 88.0  # degrees between the light and Q's normal: an example

W, H = 840, 380
K = 4300.0  # page units per world unit
X_LEFT, X_RIGHT = -0.14, 0.03  # the part of the cut shown, world x (0: the chord's middle)
OX, TOP = 60.0, 150.0  # where X_LEFT and the sphere's top (y = R) fall on the page


def page(x: float, y: float) -> tuple[float, float]:
    return OX + (x - X_LEFT) * K, TOP + (R - y) * K


def polar(angle: float, radius: float = R) -> tuple[float, float]:
    return radius * math.cos(angle), radius * math.sin(angle)


def intersect(p, d, a, b):
    """Where the ray p + t d meets the line through a and b: (t, point)."""
    ex, ey = b[0] - a[0], b[1] - a[1]
    den = d[0] * ey - d[1] * ex
    t = ((a[0] - p[0]) * ey - (a[1] - p[1]) * ex) / den
    return t, (p[0] + t * d[0], p[1] + t * d[1])


def main() -> None:
    global W, K, X_LEFT, X_RIGHT, OX, TOP
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size, small = (11.5, 11) if narrow else (12.5, 12)
    if narrow:
        W, K, X_LEFT, X_RIGHT, OX, TOP = 400, 2700.0, -0.125, 0.011, 16.0, 222.0
    s = Svg(W, H, "Chapter 24b: the sag of the sphere's flat triangles and the shadow ray's offset",
            f"A cut through chapter 24's sphere, radius {R:g}, drawn to scale: the round surface an arc, the "
            f"mesh's flat triangles straight chords under it, {math.degrees(ALPHA):.1f} degrees of arc each, "
            f"{SAG:.4f} below the arc at a chord's middle. A point Q near a vertex with its smooth normal n; a "
            f"light {GRAZE:g} degrees from n, so smooth shading calls Q lit. The ray from Q dips under Q's own "
            f"flat triangle and hits the next one: a shadow speck. The ray from Q + {OFFSET:g} n starts outside "
            f"the round sphere and leaves clear.")
    if narrow:
        s.lines(16, 26, ["The sag: a ray from the flat surface,", f"and from {OFFSET:g} above it"], size=14, bold=True)
        s.lines(16, 68, [f"A cut through the sphere (sphere({SLICES}, {STACKS}) \u00d7 {SCALE:g}:",
                         f"radius {R:g}) along its equator's quad diagonals,",
                         "the edges each quad's two triangles share. To",
                         f"scale: 0.01 = {0.01 * K:.0f} page units."], size=small, fill=MUTED)
    else:
        s.text(20, 28, f"The sag: a ray from the flat surface, and from {OFFSET:g} above it", size=14, bold=True)
        s.lines(20, 50, [f"A cut through the sphere (sphere({SLICES}, {STACKS}) \u00d7 {SCALE:g}: radius {R:g}) along "
                         "its equator's quad diagonals, the edges each quad's",
                         f"two triangles share. To scale: 0.01 = {0.01 * K:.0f} page units."], size=12, fill=MUTED)
    # The mesh's section: chords between vertices ALPHA apart, one centred on x = 0.
    verts = [polar(math.pi / 2 + (k + 0.5) * ALPHA) for k in range(-1, 3)]  # B, A, and beyond
    b, a, a2 = verts[0], verts[1], verts[2]
    floor_y = a[1] - (150 if narrow else 120) / K
    left_y = a[1] + (X_LEFT - a[0]) * (a2[1] - a[1]) / (a2[0] - a[0])
    solid = [page(X_LEFT, left_y), page(*a), page(X_RIGHT, a[1]), page(X_RIGHT, floor_y),
             page(X_LEFT, floor_y)]
    s.polygon(solid, fill=GREY_FILL, stroke="none", width=0)
    s.polyline([page(X_LEFT, left_y), page(*a), page(X_RIGHT, a[1])], stroke=INK, width=2.2)
    ax, ay = page(*a)
    s.circle(ax, ay, 4, fill=INK, stroke=INK)
    s.text(ax + 6, ay + 20, "vertex", size=small)
    s.text(page(X_RIGHT, 0)[0] - 10, page(0, floor_y)[1] - 12, "inside the mesh", size=size, fill=MUTED,
           anchor="end")
    s.text(*page(X_LEFT + 0.004, left_y - 0.0042 * (1.4 if narrow else 1)), "the next flat triangle", size=size)
    # The round sphere.
    arc = [page(x, math.sqrt(R * R - x * x)) for x in [X_LEFT + i * (X_RIGHT - X_LEFT) / 80 for i in range(81)]]
    s.polyline(arc, stroke=BLUE, width=1.6, dash="7 4")
    if narrow:  # above the rays' labels, with a line down to the arc
        lx, ly = page(X_RIGHT - 0.004, R)
        s.line(lx, TOP - 76, lx, ly - 2, stroke=BLUE, width=1)
        s.text(lx + 4, TOP - 82, f"the round sphere, radius {R:g}", size=size, fill=BLUE, anchor="end")
    else:
        s.text(*page(X_RIGHT - 0.003, R + 0.0012), f"the round sphere, radius {R:g}", size=size, fill=BLUE,
               anchor="end")
    # The sag at the chord's middle.
    mx, my_top = page(0, R)
    _, my_bottom = page(0, a[1])
    s.line(mx, my_top, mx, my_bottom, stroke=PURPLE, width=1.6, arrow="both")
    if narrow:
        s.text(mx - 6, my_bottom + 18, f"sag {SAG:.4f}", size=size, fill=PURPLE, bold=True, anchor="end")
    else:
        s.text(mx + 8, my_bottom - 8, f"sag {SAG:.4f}", size=size, fill=PURPLE, bold=True)
        s.text(mx + 8, my_bottom + 20, "at the chord's middle", size=size, fill=PURPLE)
    # Q, its normal, and the two rays.
    qx = a[0] + 0.17 * (b[0] - a[0])
    q = (qx, a[1])
    n = (q[0] / math.hypot(*q), q[1] / math.hypot(*q))
    theta = math.atan2(n[1], n[0]) + math.radians(GRAZE)  # towards the vertex side
    light = (math.cos(theta), math.sin(theta))
    start = (q[0] + OFFSET * n[0], q[1] + OFFSET * n[1])
    t, hit = intersect(q, light, a, a2)
    px_, py_ = page(*q)
    s.circle(px_, py_, 4, fill=ORANGE, stroke=ORANGE)
    s.text(px_ + 8, py_ + 20, "Q", size=13, bold=True, fill=ORANGE)
    if narrow:
        s.lines(px_ - 4, py_ + 40, ["Q's flat triangle (in the cut:", "the edge its quad's two", "triangles share)"],
                size=size)
    else:
        s.lines(px_ + 30, py_ + 20, ["Q's flat triangle (in the cut: the edge", "its quad's two triangles share)"],
                size=size)
    sx, sy = page(*start)
    s.line(px_, py_, sx, sy, stroke=GREEN, width=1.8, arrow="end")
    s.text(sx + 8, sy - 18, f"Q + {OFFSET:g} n", size=size, fill=GREEN, bold=True)
    s.text(sx + 8, sy - 3, "(n: the radius through Q)", size=small, fill=GREEN)
    hx, hy = page(*hit)
    s.line(px_, py_, hx, hy, stroke=RED, width=1.8, dash="5 3")
    s.path(f"M{hx - 6:.1f},{hy - 6:.1f} L{hx + 6:.1f},{hy + 6:.1f} M{hx - 6:.1f},{hy + 6:.1f} "
           f"L{hx + 6:.1f},{hy - 6:.1f}", stroke=RED, width=2.2)
    if narrow:
        s.lines(16, hy + 92, ["from Q: dips under Q's own", "triangle and hits the next one", "from inside: a shadow speck"],
                size=size, fill=RED)
    else:
        s.lines(hx + 20, hy + 62, ["from Q: dips under Q's own triangle and hits",
                                   "the next one from inside: a shadow speck"], size=size, fill=RED)
    t_end, _ = intersect(start, light, (X_LEFT, 0), (X_LEFT, 1))
    ex, ey = page(start[0] + t_end * light[0], start[1] + t_end * light[1])
    s.line(sx, sy, ex, ey, stroke=GREEN, width=1.8, arrow="end")
    s.lines(ex + 4, ey - 42, [f"from Q + {OFFSET:g} n: starts outside the", "round sphere, leaves clear"],
            size=size, fill=GREEN)
    past = GRAZE + math.degrees(math.atan2(-q[0], q[1])) - 90
    outside = OFFSET - (R - math.hypot(*q))
    if narrow:
        text = [f"The light: {GRAZE:g} degrees from n (an example),",
                f"so the smooth normal calls Q lit; it is {past:.1f}",
                "degrees past the flat triangle's plane.",
                f"Q + {OFFSET:g} n lies {outside:.4f} outside the round",
                "sphere: no ray the smooth normal calls lit can",
                "reach the mesh from there, since every such ray",
                "moves away from the sphere's centre."]
    else:
        text = [f"The light: {GRAZE:g} degrees from n (an example), so the smooth normal calls Q lit; it is "
                f"{past:.1f} degrees past the",
                f"flat triangle's plane. Q + {OFFSET:g} n lies {outside:.4f} outside the round "
                "sphere: no ray the smooth normal calls lit",
                "can reach the mesh from there, since every such ray moves away from the sphere's centre."]
    ty = page(0, floor_y)[1] + 26
    s.lines(16 if narrow else 20, ty, text, size=size)
    s.height = ty + len(text) * size * 1.3 + 4
    s.write()


if __name__ == "__main__":
    main()
