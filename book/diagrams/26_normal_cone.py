"""Chapter 26: the normal-cone test, in a cut through the eye and a meshlet.

A meshlet (a curved strip of triangles, seen edge on) with its triangles'
normals; its normal cone, the axis and the half-angle a that holds every
normal; its bounding sphere (a circle of radius r) around the centre; the
eye, from which the sphere lies within b = asin(r / d) of the direction to
the centre. The meshlet faces away as a whole when the direction from the
eye to the centre is within 90 - a - b degrees of the axis: then every
point of the sphere is seen from behind every triangle's plane. Angles as
drawn (a = 25 degrees, b as the circle and the eye's place make it), not to
scale.
"""

import math

from svg import BLUE, GREEN, INK, MUTED, ORANGE, PURPLE, Svg

W, H = 1000, 520
A = 25.0  # the cone's half-angle, in degrees


def point(cx, cy, r, degrees):
    """A point r from (cx, cy) at `degrees` counter-clockwise from +x (y down on the page)."""
    return cx + r * math.cos(math.radians(degrees)), cy - r * math.sin(math.radians(degrees))


def main() -> None:
    s = Svg(W, H, "Chapter 26: the normal-cone test that culls a meshlet facing away from the eye",
            "A cut through the eye and a meshlet. The meshlet is a curved strip of triangles seen "
            "edge on, each with its normal, all pointing away from the eye, to the right. Its "
            "normal cone has an axis and a half-angle a that holds every normal; its bounding "
            "sphere has radius r. From the eye, at distance d, the sphere lies within b = asin(r / "
            "d) of the direction to its centre. When that direction is within 90 - a - b degrees "
            "of the cone's axis, every triangle faces away and the meshlet is culled.")
    cx, cy = 640, 250
    # The bounding sphere.
    r = 95
    s.circle(cx, cy, r, stroke=PURPLE, width=1.4, dash="6 4")
    s.text(cx + 10, cy + r + 22, "bounding sphere, radius r", size=12.5, fill=PURPLE)
    # The meshlet: a strip bent round the centre, its normals pointing right.
    strip = [point(cx + 60, cy, 110, 180 + t) for t in (-20, -12, -4, 4, 12, 20)]
    s.polyline(strip, stroke=INK, width=3)
    for (x0, y0), (x1, y1) in zip(strip, strip[1:]):
        mx, my = (x0 + x1) / 2, (y0 + y1) / 2
        nx, ny = (cx + 60) - mx, cy - my  # towards the bend's centre: away from the eye
        length = math.hypot(nx, ny)
        s.line(mx, my, mx + 38 * nx / length, my + 38 * ny / length, stroke=GREEN, width=1.6,
               arrow="end")
    s.text(cx - 30, cy - r - 14, "triangle normals, all within a of the axis", size=12.5,
           fill=GREEN, anchor="middle")
    # The cone: its axis and the half-angle a.
    ax, ay = point(cx, cy, 250, 0)
    s.line(cx, cy, ax, ay, stroke=BLUE, width=2, arrow="end")
    s.text(ax - 4, ay - 10, "cone axis", size=12.5, fill=BLUE, anchor="end")
    for sign in (1, -1):
        ex, ey = point(cx, cy, 230, sign * A)
        s.line(cx, cy, ex, ey, stroke=BLUE, width=1.2, dash="5 4")
    s.arc_arrow(cx, cy, 150, 0, A, stroke=BLUE)
    tx, ty = point(cx, cy, 166, A / 2)
    s.text(tx, ty + 5, "a", size=14, fill=BLUE, bold=True)
    # The eye, the direction to the centre and the sphere's half-angle b.
    ex, ey = 120, 330
    s.circle(ex, ey, 5, fill=INK, stroke=INK)
    s.text(ex, ey + 26, "eye", size=13, anchor="middle")
    s.line(ex, ey, cx, cy, stroke=ORANGE, width=1.6, dash="7 4")
    d = math.hypot(cx - ex, cy - ey)
    to_centre = math.degrees(math.atan2(-(cy - ey), cx - ex))
    half = math.degrees(math.asin(r / d))
    for sign in (1, -1):
        tx, ty = point(ex, ey, d * math.cos(math.radians(half)), to_centre + sign * half)
        s.line(ex, ey, tx, ty, stroke=ORANGE, width=1.1)
    s.arc_arrow(ex, ey, 120, to_centre, to_centre + half, stroke=ORANGE)
    bx, by = point(ex, ey, 136, to_centre + half / 2)
    s.text(bx, by + 4, "b", size=14, fill=ORANGE, bold=True)
    s.text((ex + cx) / 2 - 30, (ey + cy) / 2 + 30, "distance d", size=12.5, fill=ORANGE)
    # The rule.
    s.lines(40, 420, [
        "b = asin(r / d): seen from the eye, the sphere lies within b of the direction to its centre.",
        "Every triangle faces away when the angle between that direction and the axis is under "
        "90 - a - b degrees:",
        "then every point of the sphere lies behind the plane of every triangle. Here the angle is "
        f"about {abs(to_centre):.0f} degrees,",
        f"far under 90 - {A:.0f} - {half:.0f} = {90 - A - half:.0f}: the whole meshlet is culled "
        "before one of its triangles is set up."], size=13)
    s.text(40, 40, "The normal cone: a whole meshlet facing away", size=14, bold=True)
    s.text(40, 62, "a cut through the eye and the meshlet; angles as drawn, not to scale",
           size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
