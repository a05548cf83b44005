"""Chapter 22b: what the snap of each cascade's box to whole texels is for, computed to scale.

The camera takes the step tests/unit/test_cascades.cpp takes, (0.31, 0, -0.2), 0.37 units, and the
near cascade is fitted before and after it as chapters/22_shadows/cascades.hpp fits it (with
cascade_fit.py), once without the snap (the box's centre exactly on the slice's) and once with
it. The caster is the chapter's sphere, radius 0.7 at (-0.8, 0.7, 3), whose outline as the light
sees it is a circle (drawn here as a true circle; the chapter's mesh has 32 slices). A texel of the
map holds the sphere where its centre lies inside that circle, as the rasteriser decides it.

Each panel shows the same patch of the world, 8 of the near cascade's texels a side, at the
sphere's upper left edge as the light sees it: the texels the sphere covers before the step (blue
outline) and after it (orange, dashed), and in red the places where the two maps disagree, which
are shadowed in one frame and lit in the next. Below each, the count over the sphere's whole
outline: the texels of the second map, on the sphere's outline, that hold the sphere where the
first map at the same place did not, or the other way round. Each count is over the map after
the step, and the two panels' grids after it sit at different offsets against the sphere, so
their staircases hold slightly different numbers of texels. With VKT_DIAGRAM_LAYOUT=narrow the
two panels are stacked, 400 units wide. The page quotes the counts; check_snap_page() stops the
build if it no longer agrees.
"""

import math
import os
import sys
from pathlib import Path

import cascade_fit as cf
from cascade_fit import add, cross, dot, unit
from svg import BLUE, INK, MUTED, ORANGE, Svg

LIGHT = unit(cf.LIGHT)
# The light's axes as glm::lookAt(0, light, (0, 1, 0)) makes them: x and y across the map.
X_AXIS = unit(cross(LIGHT, (0, 1, 0)))
Y_AXIS = cross(X_AXIS, LIGHT)
STEP = (0.31, 0.0, -0.2)             # the camera's step in test_cascades.cpp
SPHERE, RADIUS = (-0.8, 0.7, 3.0), 0.7
PATCH = 8                            # texels a side in each panel
CHANGED = "#f3aaa4"                  # where the two maps disagree (a stronger red fill than the palette's)


def across(p):
    """A world point's place across the map, in the light's axes."""
    return (dot(X_AXIS, p), dot(Y_AXIS, p))


def fit(eye, snap):
    """The near cascade's box as light_from_world() fits it: its centre across the map, half its
    side and its texel."""
    saved, cf.EYE = cf.EYE, eye
    try:
        _, centre, radius = cf.sphere(0)
    finally:
        cf.EYE = saved
    half = radius * cf.MAP_SIZE / (cf.MAP_SIZE - 1)
    texel = 2 * half / cf.MAP_SIZE
    c = across(centre)
    if snap:  # snap_to_texels()
        c = tuple(round(v / texel) * texel for v in c)
    return c, half, texel


class Map:
    """One frame's map: which texels the sphere covers."""

    def __init__(self, eye, snap):
        self.c, self.half, self.texel = fit(eye, snap)
        self.s = across(SPHERE)

    def edge(self, axis, i):
        return self.c[axis] - self.half + i * self.texel

    def index(self, p):
        return tuple(math.floor((p[k] - self.c[k] + self.half) / self.texel) for k in range(2))

    def covers(self, i, j):
        centre = (self.edge(0, i + 0.5), self.edge(1, j + 0.5))
        return math.dist(centre, self.s) <= RADIUS

    def covers_at(self, p):
        return self.covers(*self.index(p))


def changed(before, after):
    """The texels of `after` on the sphere's outline, and how many of them disagree with `before`
    at their centres."""
    s, r, t = before.s, RADIUS, after.texel
    i0, j0 = after.index((s[0] - r - 2 * t, s[1] - r - 2 * t))
    i1, j1 = after.index((s[0] + r + 2 * t, s[1] + r + 2 * t))
    outline = differ = 0
    for i in range(i0, i1 + 1):
        for j in range(j0, j1 + 1):
            here = after.covers(i, j)
            neighbours = [after.covers(i + di, j + dj) for di, dj in ((1, 0), (-1, 0), (0, 1), (0, -1))]
            if here != all(neighbours) or here != any(neighbours):
                outline += 1  # on the outline: a covered texel next to an empty one, or the reverse
                centre = (after.edge(0, i + 0.5), after.edge(1, j + 0.5))
                differ += here != before.covers_at(centre)
    return outline, differ


def moved(before, after):
    return tuple((after.c[k] - before.c[k]) / after.texel for k in range(2))


def results():
    out = {}
    for snap in (False, True):
        before = Map(cf.EYE, snap)
        after = Map(add(cf.EYE, STEP), snap)
        out[snap] = (before, after, moved(before, after), *changed(before, after))
    return out


def check_snap_page(res) -> None:
    """book/22b_cascades.md quotes these numbers; a page that disagrees stops the build."""
    page = Path(__file__).resolve().parents[1] / "22b_cascades.md"
    text = " ".join(page.read_text(encoding="utf-8").split())
    differ0, differ1 = res[False][4], res[True][4]
    for phrase in (f"{differ0} texels change without the snap, {differ1} with it",):
        if phrase not in text:
            sys.exit(f"book/22b_cascades.md: the snap's figure: the page should say '{phrase}' "
                     "(book/diagrams/22b_snap.py computes it as cascades.hpp does)")


def panel(s, x0, y0, side, before, after, title, lines, size):
    t = before.texel
    scale = side / (PATCH * t)
    # The patch: PATCH texels of the first map, around the sphere's outline towards the upper left.
    angle = math.radians(135)
    p = (before.s[0] + RADIUS * math.cos(angle), before.s[1] + RADIUS * math.sin(angle))
    i0, j0 = before.index(p)
    i0, j0 = i0 - PATCH // 2, j0 - PATCH // 2
    left, bottom = before.edge(0, i0), before.edge(1, j0)
    right, top = left + PATCH * t, bottom + PATCH * t

    def sx(u):
        return x0 + (u - left) * scale

    def sy(v):
        return y0 + (top - v) * scale

    s.text(x0, y0 - 12, title, size=size + 1, bold=True)
    # Where the maps disagree: the cells between both grids' lines, each wholly in or out of each.
    xs = sorted({before.edge(0, i) for i in range(i0 - 1, i0 + PATCH + 2)} |
                {after.edge(0, i) for i in range(after.index((left, 0))[0] - 1,
                                                 after.index((right, 0))[0] + 2)})
    ys = sorted({before.edge(1, j) for j in range(j0 - 1, j0 + PATCH + 2)} |
                {after.edge(1, j) for j in range(after.index((0, bottom))[1] - 1,
                                                 after.index((0, top))[1] + 2)})
    for a, b in zip(xs, xs[1:]):
        for c, d in zip(ys, ys[1:]):
            a2, b2, c2, d2 = max(a, left), min(b, right), max(c, bottom), min(d, top)
            if b2 - a2 < 1e-9 or d2 - c2 < 1e-9:
                continue
            mid = ((a + b) / 2, (c + d) / 2)
            if before.covers_at(mid) != after.covers_at(mid):
                s.rect(sx(a2), sy(d2), (b2 - a2) * scale, (d2 - c2) * scale, fill=CHANGED,
                       stroke="none")
    # The first map's grid.
    for k in range(PATCH + 1):
        s.line(sx(left + k * t), sy(bottom), sx(left + k * t), sy(top), stroke="#d1d9e0", width=1)
        s.line(sx(left), sy(bottom + k * t), sx(right), sy(bottom + k * t), stroke="#d1d9e0", width=1)
    # Each map's outline: the edges between a covered texel and an empty one, clipped to the patch.
    for m, colour, dash, width in ((before, BLUE, None, 4.5), (after, ORANGE, "7 5", 2.5)):
        ia, ja = m.index((left - t, bottom - t))
        ib, jb = m.index((right + t, top + t))
        for i in range(ia, ib + 1):
            for j in range(ja, jb + 1):
                if not m.covers(i, j):
                    continue
                x_lo, x_hi = m.edge(0, i), m.edge(0, i + 1)
                y_lo, y_hi = m.edge(1, j), m.edge(1, j + 1)
                for (di, dj), seg in (((1, 0), ((x_hi, y_lo), (x_hi, y_hi))),
                                      ((-1, 0), ((x_lo, y_lo), (x_lo, y_hi))),
                                      ((0, 1), ((x_lo, y_hi), (x_hi, y_hi))),
                                      ((0, -1), ((x_lo, y_lo), (x_hi, y_lo)))):
                    if m.covers(i + di, j + dj):
                        continue
                    (u0, v0), (u1, v1) = seg
                    u0, u1 = max(min(u0, right), left), max(min(u1, right), left)
                    v0, v1 = max(min(v0, top), bottom), max(min(v1, top), bottom)
                    if abs(u1 - u0) + abs(v1 - v0) < 1e-9:
                        continue
                    s.line(sx(u0), sy(v0), sx(u1), sy(v1), stroke=colour, width=width, dash=dash)
    # The sphere's true outline across the patch.
    points = []
    for k in range(0, 91):
        a = math.radians(90 + k)
        u, v = before.s[0] + RADIUS * math.cos(a), before.s[1] + RADIUS * math.sin(a)
        if left <= u <= right and bottom <= v <= top:
            points.append((sx(u), sy(v)))
    s.polyline(points, stroke=INK, width=1.2)
    s.rect(x0, y0, side, side, stroke=MUTED, width=1)
    s.text(sx(right - 0.3 * t), sy(bottom + 0.4 * t), "the sphere", size=size, fill=INK, anchor="end")
    s.text(sx(left + 0.3 * t), sy(top - 0.4 * t) + size, "beside it", size=size, fill=MUTED)
    s.lines(x0, y0 + side + size * 1.6, lines, size=size, fill=INK)


def main() -> None:
    res = results()
    check_snap_page(res)
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 12.5 if narrow else 14
    _, _, m0, outline0, differ0 = res[False]
    _, _, m1, outline1, differ1 = res[True]
    t = res[False][0].texel
    texts = {
        False: ("Without the snap", [f"The grid moves {abs(m0[0]):.2f} texels across and",
                                     f"{abs(m0[1]):.2f} down: {differ0} of the {outline0} texels either",
                                     "side of the sphere's outline change."]),
        True: ("With the snap", [f"The grid moves exactly {abs(m1[0]):.0f} and {abs(m1[1]):.0f} texels:",
                                 f"the outlines are one: {differ1} of the {outline1} texels",
                                 "either side of it change."]),
    }
    if narrow:
        W, side, H = 400, 340, 1040
        spots = {False: (30, 40), True: (30, 500)}
        legend_y = 960
    else:
        W, side, H = 960, 380, 660
        spots = {False: (50, 60), True: (530, 60)}
        legend_y = 575
    s = Svg(W, H, "Chapter 22b: the same patch of the near cascade's map before and after the "
            "camera steps 0.37 units, without and with the snap",
            f"A patch of the near cascade's shadow map, {PATCH} texels of {t:.4f} units a side, at "
            "the edge of the sphere as the light sees it. Blue: the texels that hold the sphere "
            "before the camera steps 0.37 units; orange, dashed: after. Red: where the two "
            f"disagree. Without the snap the grid slides by a fraction of a texel and "
            f"{differ0} of the {outline0} texels on the sphere's outline change; with it the grid "
            f"moves by whole texels and {differ1} change.")
    for snap in (False, True):
        title, lines = texts[snap]
        b, a = res[snap][0], res[snap][1]
        panel(s, *spots[snap], side, b, a, title, lines, size)
    x, y = spots[False][0], legend_y
    s.line(x, y, x + 30, y, stroke=BLUE, width=4.5)
    s.text(x + 38, y + 4, "the sphere's texels before the step", size=size)
    s.line(x, y + 22, x + 30, y + 22, stroke=ORANGE, width=2.5, dash="7 5")
    s.text(x + 38, y + 26, "after the camera steps 0.37 units", size=size)
    s.rect(x, y + 36, 30, 14, fill=CHANGED, stroke="none")
    s.text(x + 38, y + 48, "shadow in one frame, light in the other", size=size)
    s.write()


if __name__ == "__main__":
    main()
