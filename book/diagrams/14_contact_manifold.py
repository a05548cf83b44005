"""Chapter 14: a contact manifold, the incident face clipped against the reference face.

The geometry is computed here the way common/domains/src/physics_collision.cpp
does it (face_contact and clip): the incident face's corners c0..c3 go around
it, corner c lying on edges c - 1 and c (lines 0..3); the reference face's
sides s0..s3 (lines 4..7) are the planes +s, -s, +t, -t at its half extent;
Sutherland-Hodgman clips against them in that order, and each crossing it adds
is named by the line the clipped edge lies on and the side that cut it. Box b
rests flat on box a, turned about the normal and pushed d into it; the side
view is the same two boxes seen from the front, with d exaggerated.
"""

import math

from svg import (BLUE, BLUE_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL, RED, Svg)

W, H = 880, 450

# The scene, in metres (schematic sizes). The reference face: box a's top, a
# square of half extent 1 in the (s, t) plane, normal n up.
REF_HALF = 1.0
# The incident face: box b's bottom, half extent 0.68, turned 18 degrees about
# n, its centre 0.95 towards s0.
INC_HALF, INC_TURN, INC_CENTRE = 0.68, math.radians(18.0), (0.95, 0.0)
DEPTH = 0.2          # how far box b is pushed into box a (drawn exaggerated)
A_HEIGHT, B_HEIGHT = 0.9, 0.9
CLIP_TOLERANCE = 0.001  # kClipTolerance: a corner outside by less counts as inside

SCALE = 100.0        # pixels per metre, in both views


def line_name(line: int) -> str:
    return f"e{line}" if line < 4 else f"s{line - 4}"


def shared_line(p, q) -> int:
    """The line two neighbouring vertices share (the segment between them lies on it)."""
    for line in p[1]:
        if line in q[1]:
            return line
    raise AssertionError("neighbours always share a line")


def clip(polygon, axis, limit, side):
    """Sutherland-Hodgman: keep the part where dot(p, axis) <= limit, adding crossings."""
    out = []
    for i, p in enumerate(polygon):
        q = polygon[(i + 1) % len(polygon)]
        dp = p[0][0] * axis[0] + p[0][1] * axis[1] - limit - CLIP_TOLERANCE
        dq = q[0][0] * axis[0] + q[0][1] * axis[1] - limit - CLIP_TOLERANCE
        if dp <= 0.0:
            out.append(p)
        if (dp <= 0.0) != (dq <= 0.0):
            t = dp / (dp - dq)
            point = (p[0][0] + t * (q[0][0] - p[0][0]), p[0][1] + t * (q[0][1] - p[0][1]))
            out.append((point, (shared_line(p, q), side)))
    return out


def manifold():
    """The incident face's corners, and the clipped polygon: ((s, t), (line, line)) each."""
    cx, cy = INC_CENTRE
    c, s = math.cos(INC_TURN), math.sin(INC_TURN)
    u = (INC_HALF * c, INC_HALF * s)   # the incident face's axes, u x v along n
    v = (-INC_HALF * s, INC_HALF * c)
    corners = [((cx - u[0] - v[0], cy - u[1] - v[1]), (3, 0)),
               ((cx + u[0] - v[0], cy + u[1] - v[1]), (0, 1)),
               ((cx + u[0] + v[0], cy + u[1] + v[1]), (1, 2)),
               ((cx - u[0] + v[0], cy - u[1] + v[1]), (2, 3))]
    sides = [((1.0, 0.0), REF_HALF), ((-1.0, 0.0), REF_HALF), ((0.0, 1.0), REF_HALF),
             ((0.0, -1.0), REF_HALF)]
    polygon = corners
    for side, (axis, limit) in enumerate(sides):
        polygon = clip(polygon, axis, limit, 4 + side)
    return corners, polygon


def feature(lines) -> str:
    """The point's name as the feature id orders it: the lower line first."""
    low, high = sorted(lines)
    return f"{line_name(low)}\u00b7{line_name(high)}"


def main() -> None:
    corners, clipped = manifold()
    names = [feature(lines) for _, lines in clipped]
    # The page's prose and alt text name these four points.
    assert names == ["e0\u00b7e3", "e0\u00b7s0", "e2\u00b7s0", "e2\u00b7e3"], names

    s = Svg(W, H, "Chapter 14: a contact manifold, the incident face clipped against the reference face",
            "Seen from above: the reference face, box a's top, a square with sides s0 to s3; the incident "
            "face, box b's bottom, a turned square with edges e0 to e3, overhangs side s0. Clipping it "
            "against the four sides leaves the shaded part, whose corners are the contact points " +
            ", ".join(names) + ", each named by the two lines that cross there. Seen from the side: "
            "box b slightly into box a, the normal from a to b, the contact points halfway between the "
            "two surfaces.")

    # ---- Left: seen from above -------------------------------------------------------------
    s.text(20, 28, "Seen from above", size=14, bold=True)
    ox, oy = 150, 200
    top = lambda p: (ox + p[0] * SCALE, oy - p[1] * SCALE)  # s to the right, t up: n faces us
    r = REF_HALF
    ref = [(-r, -r), (r, -r), (r, r), (-r, r)]
    s.polygon([top(p) for p in ref], fill=GREY_FILL, stroke=GREY, width=2)
    inc = [top(p) for p, _ in corners]
    s.polygon(inc, fill=BLUE_FILL, stroke="none", opacity=0.7)
    s.polygon([top(p) for p, _ in clipped], fill=ORANGE_FILL, stroke=ORANGE, width=1.5)
    s.polygon(inc, stroke=BLUE, width=1.8, dash="6 4")
    # The sides redrawn over the fills, so that s0 shows where it cuts.
    for a, b in zip(ref, ref[1:] + ref[:1]):
        s.line(*top(a), *top(b), stroke=GREY, width=2)

    # Side names outside their sides (s0 over the part clipped away).
    s.text(*top((r + 0.05, -0.06)), "s0", size=13, fill=MUTED, bold=True)
    s.text(*top((-r - 0.06, -0.05)), "s1", size=13, fill=MUTED, bold=True, anchor="end")
    s.text(*top((-0.55, r + 0.07)), "s2", size=13, fill=MUTED, bold=True, anchor="middle")
    s.text(*top((-0.55, -r - 0.2)), "s3", size=13, fill=MUTED, bold=True, anchor="middle")
    rx, ry = top((-r, -r))
    s.text(rx, ry + 42, "reference face: box a's top", size=12, fill=INK)

    # Edge names outside the incident face, along each edge (e0's past the
    # crossing, clear of the contact point's name).
    centre = top(INC_CENTRE)
    for e, along in enumerate((0.72, 0.5, 0.5, 0.5)):
        (x0, y0), (x1, y1) = inc[e], inc[(e + 1) % 4]
        mx, my = x0 + along * (x1 - x0), y0 + along * (y1 - y0)
        dx, dy = mx - centre[0], my - centre[1]
        length = math.hypot(dx, dy)
        s.text(mx + dx / length * 15, my + dy / length * 15 + 4, f"e{e}", size=13, fill=BLUE, bold=True,
               anchor="middle")
    label_x = max(x for x, _ in inc) + 12
    s.lines(label_x, centre[1] - 8, ["incident face:", "box b's bottom"], size=12, fill=BLUE)
    # The overhang is too narrow for a label of a readable size: it goes
    # beside the incident face's, with a leader into the overhang.
    over = top((1.42, 0.06))
    s.line(over[0], over[1], label_x - 4, centre[1] + 36, stroke=MUTED, width=1)
    s.lines(label_x, centre[1] + 40, ["clipped away:", "the part past s0"], size=12, fill=MUTED)

    # The contact points, each labelled on its side of the clipped polygon's
    # middle: those on s0 below and right of it, clear of the dashed edges.
    mid_x = sum(top(p)[0] for p, _ in clipped) / len(clipped)
    mid_y = sum(top(p)[1] for p, _ in clipped) / len(clipped)
    for (p, _), name in zip(clipped, names):
        x, y = top(p)
        s.circle(x, y, 5, fill=RED, stroke="#ffffff", width=1.2)
        right = x >= mid_x
        s.text(x + (9 if right else -9), y + (17 if right else 4), name, size=12.5, fill=RED, bold=True,
               anchor="start" if right else "end")

    s.lines(20, H - 52, [
        "Red: the contact points, each named by the two lines that cross there",
        "(its feature id): e0..e3 the incident face's edges, s0..s3 the reference",
        "face's sides. Clipped against s0, s1, s2, s3 in turn; only s0 cuts here.",
    ], size=12, leading=1.35, fill=INK)

    # ---- Right: the same boxes from the front ------------------------------------------------
    sx0 = 470
    s.text(sx0, 28, "Seen from the side", size=14, bold=True)
    fx, fy = 590, 250
    side = lambda x, h: (fx + x * SCALE, fy - h * SCALE)  # s to the right, n up
    ax0, ay0 = side(-r, 0.0)
    s.rect(ax0, ay0, 2 * r * SCALE, A_HEIGHT * SCALE, fill=GREY_FILL, stroke=GREY, width=2)
    s.text(*side(-r + 0.1, -A_HEIGHT + 0.12), "box a", size=12.5, fill=INK)
    # Box b, turned only about n: its vertical edges stand at its corners' s.
    xs = [p[0] for p, _ in corners]
    bottom, top_b = -DEPTH, -DEPTH + B_HEIGHT
    bx0, by0 = side(min(xs), top_b)
    s.rect(bx0, by0, (max(xs) - min(xs)) * SCALE, B_HEIGHT * SCALE, fill=BLUE_FILL, stroke=BLUE, width=1.8,
           opacity=0.75)
    nearest = min(corners, key=lambda c: c[0][1])[0][0]  # the corner nearest us (least t)
    s.line(*side(nearest, bottom), *side(nearest, top_b), stroke=BLUE, width=1.2)
    s.text(*side((nearest + max(xs)) / 2, top_b - 0.3), "box b", size=12.5, fill=BLUE, anchor="middle")
    # Box a's top, the reference face's plane, over box b.
    s.line(*side(-r, 0.0), *side(r, 0.0), stroke=GREY, width=2)

    # The contact points: halfway between the surfaces, at the clipped corners' s.
    for p, _ in clipped:
        s.circle(*side(p[0], -DEPTH / 2), 4.5, fill=RED, stroke="#ffffff", width=1.2)
    px, py = side(r, -DEPTH / 2)
    s.lines(px - 8, py + 30, ["contact points: halfway", "between the two surfaces"], size=12, fill=RED,
            leading=1.3, anchor="end")

    # The depth d, beside box b: box a's top plane drawn on to it.
    dx = side(max(xs), 0.0)[0] + 12
    s.line(*side(r, 0.0), dx + 4, side(0, 0.0)[1], stroke=GREY, width=1.1, dash="3 3")
    s.line(dx - 4, side(0, 0.0)[1], dx + 4, side(0, 0.0)[1], stroke=INK, width=1.1)
    s.line(dx - 4, side(0, bottom)[1], dx + 4, side(0, bottom)[1], stroke=INK, width=1.1)
    s.line(dx, side(0, 0.0)[1], dx, side(0, bottom)[1], stroke=INK, width=1.1)
    s.text(dx + 8, side(0, -DEPTH / 2)[1] - 6, "d", size=13, italic=True)

    # The normal: from a to b, out of the reference face.
    nx = -0.6
    s.line(*side(nx, 0.0), *side(nx, 0.75), stroke=INK, width=2, arrow="end")
    s.text(*side(nx + 0.08, 0.55), "**n**, from a to b", size=12.5)

    s.lines(sx0, H - 52, [
        "The same boxes from the front, d exaggerated. n: the separating",
        "axis of least overlap. Each point sits halfway between the two",
        "surfaces, d deep: the points on s0 stand one behind the other.",
    ], size=12, leading=1.35, fill=INK)
    s.write()


if __name__ == "__main__":
    main()
