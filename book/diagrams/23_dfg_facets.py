"""Chapter 23: the specular BRDF's three factors, D, G and F, as facet sketches.

One small panel per factor, schematic but drawn from the geometry:

- D: two surfaces as rows of facets, each facet with its own normal. A facet
  counts for D when its normal lies within 7 degrees of h (25 degrees from n
  here). The smooth surface's normals all lie within 6 degrees of n, so none
  faces h; the rough surface's spread, and some do. The counts are counted
  from the tilts when the figure is drawn.
- G: one rough profile (V-grooves of several depths). For every short piece
  of it a ray is cast towards the light (shadowing) or towards the eye
  (masking), both 75 degrees from the normal; a piece whose ray meets the
  profile again is in a neighbour's shadow, or hidden from the eye.
- F: Schlick's F = F0 + (1 - F0)(1 - cos)^5 against the angle between v and
  h, for a dielectric (F0 = 0.04) and for gold, the chapter's metal, one
  curve per channel (F0 = 1, 0.71, 0.29).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three panels are stacked, 400 units wide; otherwise they stand side by side.
"""

import math
import os

from svg import BLUE, GREY, INK, MUTED, ORANGE, RED, Svg

SIZE = 13
H_ANGLE = 25      # h, degrees from n (towards the light's side, to the right)
FACES_H = 7       # a facet faces h when its normal lies this close to h
SMOOTH = [3, -4, 5, -2, 6, -5, 1, -3, 4, -6, 2, -1]
ROUGH = [28, -35, 12, 24, -18, 40, -30, 8, 26, -22, 33, -14]
GOLD = [(1.0, RED, "R"), (0.71, "#1e7b34", "G"), (0.29, BLUE, "B")]


def facet_row(s, x, y, tilts, width):
    """A chain of facets from (x, y), each tilted as given (degrees, + towards the right);
    each with a short normal, orange when it faces h. Returns how many face h."""
    w = width / len(tilts)
    facing = 0
    for t in tilts:
        a = math.radians(t)
        x1, y1 = x + w * math.cos(a), y + w * math.sin(a)
        faces = abs(t - H_ANGLE) <= FACES_H
        facing += faces
        mx, my = (x + x1) / 2, (y + y1) / 2
        length = 22 if faces else 14
        s.line(mx, my, mx + length * math.sin(a), my - length * math.cos(a),
               stroke=ORANGE if faces else GREY, width=2 if faces else 1, arrow="end" if faces else None)
        s.line(x, y, x1, y1, stroke=ORANGE if faces else INK, width=3 if faces else 1.8)
        x, y = x1, y1
    return facing


def panel_d(s, x, y, w):
    s.text(x, y + 14, "D: how many facets face h", size=SIZE + 1, bold=True)
    # h, drawn once at the panel's top right.
    hx, hy = x + w - 24, y + 74
    a = math.radians(H_ANGLE)
    s.line(hx, hy, hx + 40 * math.sin(a), hy - 40 * math.cos(a), stroke=ORANGE, width=2, arrow="end")
    s.line(hx, hy, hx, hy - 40, stroke=MUTED, width=1, dash="3 3")
    s.text(hx + 20, hy - 44, "h", size=SIZE + 1, bold=True, fill=ORANGE, anchor="middle")
    s.text(hx - 4, hy - 44, "n", size=SIZE, fill=MUTED, anchor="end")
    rows = [("smooth: normals within 6° of n", SMOOTH), ("rough: normals spread to 40°", ROUGH)]
    for i, (label, tilts) in enumerate(rows):
        top = y + 46 + i * 118
        s.text(x, top, label, size=SIZE, fill=MUTED)
        n = facet_row(s, x + 4, top + 52, tilts, w - 80)
        s.text(x, top + 88, f"{n} of {len(tilts)} face h (within {FACES_H}°)", size=SIZE,
               fill=ORANGE if n else INK)
    s.lines(x, y + 290, ["D is the density of facet normals at h:",
                         "a tall, narrow peak round n when smooth,",
                         "low and wide when rough"], size=SIZE)
    return 350


def profile():
    """V-grooves of several depths: the profile's corners, x from 0 to 1."""
    depths = [0.10, 0.06, 0.13, 0.05, 0.11, 0.08]
    points, step = [], 1 / len(depths)
    for i, d in enumerate(depths):
        points.append((i * step, 0.0))
        points.append(((i + 0.5) * step, -d))
    points.append((1.0, 0.0))
    return points


def blocked(px, py, dx, dy, segments, skip):
    """Whether the ray from (px, py) in direction (dx, dy) meets a segment other than skip."""
    for k, ((ax, ay), (bx, by)) in enumerate(segments):
        if k == skip:
            continue
        ex, ey = bx - ax, by - ay
        det = dx * (-ey) + ex * dy
        if abs(det) < 1e-12:
            continue
        qx, qy = ax - px, ay - py
        t = (qx * (-ey) + ex * qy) / det
        u = (dx * qy - dy * qx) / det
        if t > 1e-6 and 0 <= u <= 1:
            return True
    return False


def grooves(s, x, y, w, towards, colour, lit_word):
    """The profile at (x, y), w wide, its pieces coloured by whether a ray towards
    `towards` (degrees from the normal, + to the right) leaves it freely."""
    pts = [(x + px * w, y - py * 260) for px, py in profile()]  # depths in units of 1/260
    segments = list(zip(pts, pts[1:]))
    a = math.radians(towards)
    dx, dy = math.sin(a), -math.cos(a)  # screen: y down
    pieces = 24
    counts = {"free": 0, "blocked": 0, "away": 0}
    for k, ((ax, ay), (bx, by)) in enumerate(segments):
        nx, ny = (by - ay), -(bx - ax)  # the normal on the profile's upper side
        if ny > 0:
            nx, ny = -nx, -ny
        away = nx * dx + ny * dy <= 0
        for j in range(pieces):
            t0, t1 = j / pieces, (j + 1) / pieces
            x0, y0 = ax + (bx - ax) * t0, ay + (by - ay) * t0
            x1, y1 = ax + (bx - ax) * t1, ay + (by - ay) * t1
            mx, my = (x0 + x1) / 2, (y0 + y1) / 2
            state = "away" if away else ("blocked" if blocked(mx, my, dx, dy, segments, k) else "free")
            counts[state] += 1
            style = {"free": (colour, 3.2, None), "blocked": (INK, 1.6, None), "away": (GREY, 1, "2 2")}
            stroke, width, dash = style[state]
            s.line(x0, y0, x1, y1, stroke=stroke, width=width, dash=dash)
    # Three parallel rays, coming from (or going to) the side named.
    for i in range(3):
        ox, oy = x + w * (0.18 + 0.32 * i), y - 16
        s.line(ox + 46 * dx, oy + 46 * dy, ox, oy, stroke=colour, width=1.4,
               arrow="end" if lit_word == "lit" else None)
        if lit_word != "lit":
            s.line(ox, oy, ox + 46 * dx, oy + 46 * dy, stroke=colour, width=1.4, arrow="end")
    return counts


def panel_g(s, x, y, w):
    s.text(x, y + 14, "G: facets hide each other", size=SIZE + 1, bold=True)
    s.text(x, y + 34, "shadowing: the light 75° from n", size=SIZE, fill=MUTED)
    grooves(s, x + 4, y + 96, w - 8, -75, ORANGE, "lit")
    s.text(x, y + 146, "masking: the eye 75° from n", size=SIZE, fill=MUTED)
    grooves(s, x + 4, y + 204, w - 8, 75, BLUE, "seen")
    ly = y + 266
    s.line(x, ly - 4, x + 22, ly - 4, stroke=ORANGE, width=3.2)
    s.line(x + 24, ly - 4, x + 46, ly - 4, stroke=BLUE, width=3.2)
    s.text(x + 52, ly, "lit, or seen", size=SIZE)
    s.line(x + 150, ly - 4, x + 172, ly - 4, stroke=INK, width=1.6)
    s.text(x + 178, ly, "behind a neighbour", size=SIZE)
    s.line(x, ly + 16, x + 46, ly + 16, stroke=GREY, width=1, dash="2 2")
    s.text(x + 52, ly + 20, "faces away", size=SIZE)
    s.lines(x, y + 312, ["G is the share of the facets facing h that",
                         "neither is hidden: near 1 from above, falling",
                         "at grazing angles, faster on rough surfaces"], size=SIZE)
    return 350


def schlick(f0, degrees):
    return f0 + (1 - f0) * (1 - math.cos(math.radians(degrees))) ** 5


def panel_f(s, x, y, w):
    s.text(x, y + 14, "F: reflectance rises towards grazing", size=SIZE + 1, bold=True)
    left, top, pw, ph = x + 40, y + 58, w - 86, 170
    s.rect(left, top, pw, ph, stroke=GREY, width=1)
    for v in (0.5,):
        s.line(left, top + ph * (1 - v), left + pw, top + ph * (1 - v), stroke="#d1d9e0", width=1)
    for v, label in ((0, "0"), (0.5, "0.5"), (1, "1")):
        s.text(left - 6, top + ph * (1 - v) + 4, label, size=SIZE, anchor="end")
    for deg in (0, 30, 60, 90):
        s.text(left + pw * deg / 90, top + ph + 16, f"{deg}°", size=SIZE, anchor="middle")
    s.text(left + pw / 2, top + ph + 34, "angle between v and h", size=SIZE, anchor="middle", fill=MUTED)
    s.text(left - 6, top - 10, "F", size=SIZE, bold=True, anchor="end")

    def curve(f0, colour, width, dash=None):
        pts = [(left + pw * d / 90, top + ph * (1 - schlick(f0, d))) for d in range(0, 91)]
        s.polyline(pts, stroke=colour, width=width, dash=dash)

    for f0, colour, channel in GOLD:
        curve(f0, colour, 1.8, dash="5 3")
        s.text(left + pw + 6, top + ph * (1 - f0) + 4, f"{f0:g}", size=SIZE, fill=colour)
    curve(0.04, INK, 2.4)
    s.text(left + pw + 6, top + ph * (1 - 0.04) + 4, "0.04", size=SIZE)
    s.lines(x, top + ph + 60, ["F₀, at 0°: 0.04 for a dielectric (solid),",
                               "gold's R 1, G 0.71, B 0.29 (dashed).",
                               "At 90° every curve reaches 1"], size=SIZE)
    return 350


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    panels = [panel_d, panel_g, panel_f]
    title = "Chapter 23: D, G and F as facet sketches"
    description = ("Three panels. D: a smooth surface whose facet normals all lie within 6 degrees of n, "
                   "none facing h (25 degrees from n), and a rough one whose normals spread, several "
                   "facing h. G: a profile of V-grooves lit from 75 degrees, the bottoms of the grooves "
                   "in their neighbours' shadow, and seen from 75 degrees on the other side, the "
                   "bottoms hidden from the eye. F: Schlick's Fresnel against the angle between v and "
                   "h, 0.04 for a dielectric and 1, 0.71, 0.29 for gold's three channels, every curve "
                   "rising to 1 at 90 degrees.")
    if narrow:
        w, gap = 380, 24
        s = Svg(400, 10 + 3 * 350 + 2 * gap, title, description)
        y = 10
        for panel in panels:
            y += panel(s, 10, y, w) + gap
    else:
        w, gap = 310, 30
        s = Svg(20 + 3 * w + 2 * gap, 364, title, description)
        for i, panel in enumerate(panels):
            panel(s, 10 + i * (w + gap), 10, w)
    s.write()


if __name__ == "__main__":
    main()
