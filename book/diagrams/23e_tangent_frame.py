"""Chapter 23e: the tangent frame made from a triangle's edges and its UVs.

One triangle with texture coordinates, in three panels: the triangle in
position space with its edges e1 and e2; the same triangle in UV space (v down
the image, as glTF has it) with the edges' (du, dv); and the frame that comes
out, T, B and N drawn on the surface, with one normal-map texel's (x, y, z)
turned into a direction in that frame.

The numbers are not typed here: T, B and the texel's normal are computed by the
very lines of shaders/23_materials/surface.glsl ([normal-map]: the branch that
makes the frame from dFdx and dFdy, then the lines that read the texel and
turn it), which this script reads and runs on small vector types that behave
like GLSL's. dFdx and dFdy stand for e1 and e2 and their (du, dv): the
formula only needs two steps across the triangle, and e1, e2 turn
counter-clockwise round N, so the formula's A is positive (the page says why that matters). If the shader's lines
change, the figure changes with them; if they stop being GLSL this script can
run, the book's build stops with one line naming the statement.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the three
panels stand one above the other, 400 units wide.
"""

from __future__ import annotations

import math
import os
import re
from pathlib import Path

from svg import BLUE, GREEN, GREY, GREY_FILL, INK, MUTED, ORANGE, PURPLE, RED, Svg

SHADER = Path(__file__).resolve().parents[2] / "shaders" / "23_materials" / "surface.glsl"
WHERE = "shaders/23_materials/surface.glsl [normal-map]"

# The example: a triangle in the plane z = 0 (its normal +z), its UVs, and one texel.
P = [(0.0, 0.0, 0.0), (4.0, 1.0, 0.0), (1.0, 3.0, 0.0)]
UV = [(0.10, 0.85), (0.90, 0.65), (0.25, 0.15)]
NORMAL = (0.0, 0.0, 1.0)
TEXEL = (215, 150, 205)  # the normal map's RGB at the point, 0..255


# ---- GLSL's vectors, enough of them to run the shader's lines -------------------------

class Vec:
    def __init__(self, *c):
        self.c = tuple(float(x) for x in c)

    def __add__(self, o):
        return Vec(*(a + b for a, b in zip(self.c, _v(o, len(self.c)).c)))

    __radd__ = __add__

    def __sub__(self, o):
        return Vec(*(a - b for a, b in zip(self.c, _v(o, len(self.c)).c)))

    def __rsub__(self, o):
        return _v(o, len(self.c)) - self

    def __mul__(self, o):
        return Vec(*(a * b for a, b in zip(self.c, _v(o, len(self.c)).c)))

    __rmul__ = __mul__

    def __neg__(self):
        return Vec(*(-a for a in self.c))

    def __getattr__(self, name):
        if name and set(name) <= set("xyzw"):
            picked = tuple(self.c["xyzw".index(ch)] for ch in name)
            return picked[0] if len(picked) == 1 else Vec(*picked)
        raise AttributeError(name)


def _v(o, n):
    return o if isinstance(o, Vec) else Vec(*([o] * n))


class Mat3:
    """mat3(a, b, c): the columns a, b, c."""

    def __init__(self, a, b, c):
        self.cols = (a, b, c)

    def __mul__(self, m):
        return self.cols[0] * m.x + self.cols[1] * m.y + self.cols[2] * m.z


class Varying:
    """A value interpolated across the triangle: dFdx and dFdy give its two steps."""

    def __init__(self, step1, step2):
        self.steps = (step1, step2)


def dot(a, b):
    return sum(x * y for x, y in zip(a.c, b.c))


def cross(a, b):
    (a0, a1, a2), (b0, b1, b2) = a.c, b.c
    return Vec(a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0)


def normalize(a):
    return a * (1 / math.sqrt(dot(a, a)))


GLSL = {
    "dot": dot, "cross": cross, "normalize": normalize, "max": max, "mat3": Mat3,
    "inversesqrt": lambda x: 1 / math.sqrt(x), "sign": lambda x: float((x > 0) - (x < 0)),
    "abs": abs, "length": lambda a: math.sqrt(dot(a, a)),
    "dFdx": lambda v: v.steps[0], "dFdy": lambda v: v.steps[1],
    "texture": lambda sampler, uv: Vec(*(c / 255 for c in TEXEL), 1.0), "normal_map": None,
}


def statements(code: str) -> list[str]:
    """The shader's statements, comments dropped, one declaration per name."""
    code = re.sub(r"//[^\n]*", "", code)
    out = []
    for statement in (s.strip() for s in code.split(";")):
        declared = re.match(r"(?:vec[234]|float|mat3)\s+(.*)", statement, re.S)
        if not declared:
            out.append(" ".join(statement.split()))
            continue
        depth, start, body = 0, 0, declared.group(1)
        for i, ch in enumerate(body + ","):  # split at the commas outside brackets
            depth += ch in "(" and 1 or ch in ")" and -1 or 0
            if ch == "," and depth == 0:
                out.append(" ".join(body[start:i].split()))
                start = i + 1
    return [s for s in out if s]


def shader_frame():
    """Runs the shader's own lines on the example: T, B, the texel's m and the normal."""
    text = SHADER.read_text(encoding="utf-8")
    region = re.search(r"// \[normal-map\]\n(.*?)// \[/normal-map\]", text, re.S)
    made = region and re.search(r"\} else \{\n(.*?)\n    \}\n(.*?)return (.*?);", region.group(1), re.S)
    if not made:
        raise SystemExit(f"{WHERE}: no `}} else {{ ... }}` branch followed by a `return`; "
                         "redraw book/diagrams/23e_tangent_frame.py")
    e1, e2 = (Vec(*(b - a for a, b in zip(P[0], P[i]))) for i in (1, 2))
    duv1, duv2 = (Vec(*(b - a for a, b in zip(UV[0], UV[i]))) for i in (1, 2))
    scope = dict(GLSL, world=Varying(e1, e2), uv=Varying(duv1, duv2), n=Vec(*NORMAL))
    for statement in statements(made.group(1)) + statements(made.group(2)):
        if "draw." in statement:  # the push constants' factors: 1 in this example
            continue
        try:
            exec(statement, {}, scope)
        except Exception as error:  # noqa: BLE001  (any failure is one line for the build)
            raise SystemExit(f"{WHERE}: book/diagrams/23e_tangent_frame.py cannot run `{statement}` "
                             f"({error}); redraw the figure") from None
    result = eval(made.group(3), {}, scope)
    return e1, e2, duv1, duv2, scope["t"], scope["b"], scope["m"], result


# ---- drawing --------------------------------------------------------------------------

def view(p, ox, oy, k):
    """A point of the plane z = 0 (and above it) on the page: x to the right, y going
    back (up and a little to the left), z straight up: the plane drawn as a floor."""
    x, y, z = p
    return ox + k * (x - 0.3 * y), oy - k * (0.5 * y + z)


def fmt(v):
    return "(" + ", ".join(f"{c:.2f}".replace("-0.00", "0.00") for c in v.c) + ")"


def arrow(s, a, b, colour, width=2.0, dash=None):
    s.line(a[0], a[1], b[0], b[1], stroke=colour, width=width, arrow="end", dash=dash)


def position_panel(s, x, y, w, e1, e2):
    s.text(x, y, "1. The triangle in position space", size=13, bold=True)
    k = w / 5.2
    ox, oy = x + 0.5 * k, y + 30 + 1.6 * k
    pts = [view(p, ox, oy, k) for p in P]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    arrow(s, pts[0], pts[1], BLUE)
    arrow(s, pts[0], pts[2], ORANGE)
    for i, ((px, py), (dx, dy)) in enumerate(zip(pts, [(-6, 18), (6, 4), (0, -8)])):
        s.text(px + dx, py + dy, f"P_{{{i}}}", size=12, anchor="end" if i == 0 else "start")
    m1 = view([(a + b) / 2 for a, b in zip(P[0], P[1])], ox, oy, k)
    m2 = view([(a + b) / 2 for a, b in zip(P[0], P[2])], ox, oy, k)
    s.text(m1[0] + 4, m1[1] + 18, "e_{1}", size=13, fill=BLUE, bold=True)
    s.text(m2[0] - 8, m2[1], "e_{2}", size=13, fill=ORANGE, bold=True, anchor="end")
    ty = oy + 46
    s.lines(x, ty, [f"e_{{1}} = P_{{1}} \u2212 P_{{0}} = {fmt(e1)}",
                    f"e_{{2}} = P_{{2}} \u2212 P_{{0}} = {fmt(e2)}",
                    "(in the plane z = 0, drawn as a floor)"], size=12)
    return ty + 3 * 12 * 1.3


def uv_panel(s, x, y, w, duv1, duv2):
    s.text(x, y, "2. The same triangle in UV space", size=13, bold=True)
    side = min(w - 90, 200)
    left, top = x + 26, y + 22
    s.rect(left, top, side, side, fill="#ffffff", stroke=GREY, width=1)
    for f in (0.25, 0.5, 0.75):
        s.line(left + f * side, top, left + f * side, top + side, stroke="#e6eaef", width=1)
        s.line(left, top + f * side, left + side, top + f * side, stroke="#e6eaef", width=1)
    s.text(left - 4, top + 4, "0", size=11, anchor="end", fill=MUTED)
    arrow(s, (left, top - 8), (left + side, top - 8), MUTED, width=1)
    s.text(left + side + 4, top - 4, "u", size=12, fill=MUTED, italic=True)
    arrow(s, (left - 12, top), (left - 12, top + side), MUTED, width=1)
    s.text(left - 16, top + side + 2, "v", size=12, fill=MUTED, italic=True, anchor="end")
    pts = [(left + u * side, top + v * side) for u, v in UV]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    arrow(s, pts[0], pts[1], BLUE)
    arrow(s, pts[0], pts[2], ORANGE)
    for i, (px, py) in enumerate(pts):
        s.text(px + (8 if i else -4), py + (14 if i == 0 else 4), f"uv_{{{i}}}", size=12,
               anchor="end" if i == 0 else "start")
    tx = left + side + 12
    s.lines(tx, top + 40, ["v grows", "down the", "image"], size=11.5, fill=MUTED)
    ty = top + side + 24
    s.lines(x, ty, [f"(du_{{1}}, dv_{{1}}) = uv_{{1}} \u2212 uv_{{0}} = {fmt(duv1)}",
                    f"(du_{{2}}, dv_{{2}}) = uv_{{2}} \u2212 uv_{{0}} = {fmt(duv2)}"], size=12)
    return ty + 2 * 12 * 1.3


def frame_panel(s, x, y, w, t, b, m, result, text_at=None):
    """The frame on the triangle; its numbers below it, or at text_at (x, y) beside it."""
    s.text(x, y, "3. The frame, and one texel in it", size=13, bold=True)
    k = w / 5.2
    ox, oy = x + 0.5 * k, y + 30 + 2.6 * k
    pts = [view(p, ox, oy, k) for p in P]
    s.polygon(pts, fill=GREY_FILL, stroke=GREY, width=1.2)
    centre = tuple(sum(c) / 3 for c in zip(*P))
    o = view(centre, ox, oy, k)
    L = 1.8  # the drawn length of a unit vector, in world units

    def tip(v):
        return view(tuple(c + L * d for c, d in zip(centre, v.c)), ox, oy, k)

    nvec = Vec(*NORMAL)
    arrow(s, o, tip(t), RED, width=2.4)
    arrow(s, o, tip(b), GREEN, width=2.4)
    arrow(s, o, tip(nvec), BLUE, width=2.4)
    # The texel's direction: x along T, then y along B, then z along N, dashed.
    along_t = tip(t * m.x)
    along_tb = tip(t * m.x + b * m.y)
    s.polyline([o, along_t, along_tb, tip(t * m.x + b * m.y + nvec * m.z)], stroke=MUTED, width=1,
               dash="3 3")
    arrow(s, o, tip(result), PURPLE, width=2.6)
    for v, name, colour, dx, dy in ((t, "T", RED, 6, 12), (b, "B", GREEN, -6, -4),
                                    (nvec, "N", BLUE, -8, 0), (result, "n'", PURPLE, 6, -2)):
        px, py = tip(v)
        s.text(px + dx, py + dy, name, size=13, bold=True, fill=colour, anchor="end" if dx < 0 else "start")
    tx, ty = text_at or (x, oy + 34)
    rows = [(f"T = {fmt(t)}: where u grows", RED),
            (f"B = {fmt(b)}: where v falls (image up)", GREEN),
            (f"N = {fmt(nvec)}", BLUE),
            (f"texel RGB {TEXEL} \u00d7 2/255 \u2212 1", INK),
            (f"  = (x, y, z) = {fmt(m.xyz)}", INK),
            ("n' = normalize(x T + y B + z N)", PURPLE),
            (f"   = {fmt(result)}", PURPLE)]
    for i, (row, colour) in enumerate(rows):
        s.text(tx, ty + i * 12 * 1.3, row, size=12, fill=colour)
    return max(ty + len(rows) * 12 * 1.3, oy + 20)


def main() -> None:
    e1, e2, duv1, duv2, t, b, m, result = shader_frame()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23e: the tangent frame made from a triangle's edges and its texture coordinates"
    desc = (f"A triangle with corners P0, P1, P2 in the plane z = 0; its edges e1 = {fmt(e1)} and "
            f"e2 = {fmt(e2)}. The same triangle in UV space, v down the image: its edges' (du, dv) are "
            f"{fmt(duv1)} and {fmt(duv2)}. From them the shader's lines make T = {fmt(t)}, the direction "
            f"in which u grows, and B = {fmt(b)}, the direction in which v falls; N is (0, 0, 1). A "
            f"normal-map texel of RGB {TEXEL} is (x, y, z) = {fmt(m.xyz)}, and x T + y B + z N, "
            f"normalised, is {fmt(result)}: a normal leaning along T and B.")
    foot = ["Every number is computed by the lines of surface.glsl's normal map,",
            "with dFdx and dFdy standing for the steps along e1 and e2."]
    if narrow:
        w = 370
        s = Svg(400, 2000, title, desc)
        s.text(15, 24, "The tangent frame from edges and UVs", size=14, bold=True)
        y = position_panel(s, 15, 52, w, e1, e2)
        y = uv_panel(s, 15, y + 30, w, duv1, duv2)
        y = frame_panel(s, 15, y + 30, w, t, b, m, result)
        s.lines(15, y + 16, ["Every number is computed by the lines of", "surface.glsl's normal map, with dFdx and",
                             "dFdy standing for the steps along e1 and e2."], size=11.5, fill=MUTED)
        s.height = y + 16 + 3 * 11.5 * 1.3 + 4
    else:
        w = 340
        s = Svg(760, 900, title, desc)
        s.text(20, 26, "The tangent frame, made from a triangle's edges and its UVs", size=15, bold=True)
        y = max(position_panel(s, 20, 60, w, e1, e2), uv_panel(s, 400, 60, w, duv1, duv2))
        y = frame_panel(s, 20, y + 40, w, t, b, m, result, text_at=(400, y + 40 + 80))
        s.lines(20, y + 24, foot, size=12, fill=MUTED)
        s.height = y + 24 + 2 * 12 * 1.3
    s.write()


if __name__ == "__main__":
    main()
