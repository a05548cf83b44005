"""Chapter 23g's tangent frame, computed by the lines of the shader itself.

Shared by the figures of 23g (23g_*.py). shader_frame() reads
shaders/23_materials/surface.glsl's [normal-map] region: the branch that makes
the frame from dFdx and dFdy (the `} else {` one), then the lines that read the
normal map's texel and turn it into the world. It runs them, statement by
statement, on small vector types that behave like GLSL's (vec2, vec3, mat3, dot,
cross, normalize, inversesqrt, sign ...), with dFdx and dFdy standing for a
triangle's two edges and their (du, dv): the formula needs only two steps across
the triangle. So a figure drawn with these numbers cannot disagree with the
shader; a line this cannot run stops the book's build with one line naming it.
Before each figure the same lines also run on Vulkan's own steps (one pixel
right, one down the window, on a face towards the eye): unless T then points
where u grows and B where v falls, the build stops. file_frame() runs the other
branch, the frame from a file's TANGENT, and the same texel lines (page 23e's
figure of one face).
"""

from __future__ import annotations

import math
import re
from pathlib import Path

SHADER = Path(__file__).resolve().parents[2] / "shaders" / "23_materials" / "surface.glsl"
WHERE = "shaders/23_materials/surface.glsl [normal-map]"

# GLSL's vectors, enough of them to run the shader's lines.


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
    "normal_map": None,
}


def statements(code: str) -> list[str]:
    """The shader's statements, comments dropped, one declaration per name."""
    code = re.sub(r"//[^\n]*", "", code)
    # GLSL's `a < b ? x : y` (plain operands only) as Python's `(x if a < b else y)`.
    code = re.sub(r"([\w.]+ [<>=!]=? [\w.]+) \? ([-\w.]+) : ([-\w.]+)", r"(\2 if \1 else \3)", code)
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


def check_vulkan_steps(who):
    """The shader's lines on a face seen as Vulkan sees it: the face in z = 0, N = +z
    towards the eye, dFdx one pixel right (+x) and dFdy one pixel down the window (-y:
    Vulkan's window y runs down), the texture upright on it (u grows right, v down). T
    must point where u grows (+x) and B where v falls (+y); a frame made by OpenGL's
    formula without det's sign comes out turned half round here."""
    t, b = _run(((0, 0, 0), (1, 0, 0), (0, -1, 0)), ((0, 0), (1, 0), (0, 1)), (0, 0, 1),
                (128, 128, 255), who)[4:6]
    if not (t.x > 0.99 and b.y > 0.99):
        raise SystemExit(f"{WHERE}: on Vulkan's pixel steps (right, down, a front face) the made "
                         f"frame has T = {t.c}, B = {b.c}, not (1, 0, 0), (0, 1, 0): T must "
                         f"point where u grows; fix the shader before drawing {who}")


def shader_frame(p, uv, normal, texel, who):
    check_vulkan_steps(who)
    return _run(p, uv, normal, texel, who)


def _run(p, uv, normal, texel, who, keep_sign=True):
    """Runs the shader's own lines on one triangle (corners p, texture coordinates uv,
    normal), dFdx and dFdy standing for its edges from corner 0 to corners 1 and 2, and
    texel, the normal map's RGB (0..255): e1, e2, their (du, dv), T, B, the texel's m and
    the normal it gives. who: the diagram, named in a failure. keep_sign=False runs them
    with det_sign set to 1 (OpenGL's formula as it is: page 23g's figure)."""
    text = SHADER.read_text(encoding="utf-8")
    region = re.search(r"// \[normal-map\]\n(.*?)// \[/normal-map\]", text, re.S)
    made = region and re.search(r"\} else \{\n(.*?)\n    \}\n(.*?)return (.*?);", region.group(1), re.S)
    if not made:
        raise SystemExit(f"{WHERE}: no `}} else {{ ... }}` branch followed by a `return`; "
                         f"redraw {who}")
    e1, e2 = (Vec(*(b - a for a, b in zip(p[0], p[i]))) for i in (1, 2))
    duv1, duv2 = (Vec(*(b - a for a, b in zip(uv[0], uv[i]))) for i in (1, 2))
    scope = dict(GLSL, world=Varying(e1, e2), uv=Varying(duv1, duv2), n=Vec(*normal),
                 texture=lambda sampler, at: Vec(*(c / 255 for c in texel), 1.0))
    lines = statements(made.group(1)) + statements(made.group(2))
    if not keep_sign:
        lines = ["det_sign = 1.0" if line.startswith("det_sign =") else line for line in lines]
    run_statements(lines, scope, who)
    result = eval(made.group(3), {}, scope)
    return e1, e2, duv1, duv2, scope["t"], scope["b"], scope["m"], result


def run_statements(lines, scope, who):
    """Runs the shader's statements one by one in `scope`, skipping those that read the
    push constants' factors (draw.*: 1 in these examples); a failure stops the build
    naming the diagram and the statement."""
    for statement in lines:
        if "draw." in statement:
            continue
        try:
            exec(statement, {}, scope)
        except Exception as error:  # noqa: BLE001  (any failure is one line for the build)
            raise SystemExit(f"{WHERE}: {who} cannot run `{statement}` "
                             f"({error}); redraw the figure") from None


def file_frame(normal, tangent, texel, who):
    """Runs the shader's other branch, the frame from the file's TANGENT (xyz and its
    w, +1 or -1), then the lines that read the normal map's texel (RGB, 0..255) and
    turn it into the world, for one point with that normal: T, B, the texel's m and
    the normal it gives. who: the diagram, named in a failure."""
    text = SHADER.read_text(encoding="utf-8")
    region = re.search(r"// \[normal-map\]\n(.*?)// \[/normal-map\]", text, re.S)
    found = region and re.search(r"\{\n    (vec3 n = .*?;)\n.*?if \(world_tangent\.w != 0\.0\) \{\n(.*?)\n"
                                 r"    \} else \{\n.*?\n    \}\n(.*?)return (.*?);", region.group(1), re.S)
    if not found:
        raise SystemExit(f"{WHERE}: no `vec3 n = ...`, then `if (world_tangent.w != 0.0) {{ ... }} "
                         f"else {{ ... }}` followed by a `return`; redraw {who}")
    scope = dict(GLSL, world_normal=Vec(*normal), world_tangent=Vec(*tangent), uv=None,
                 texture=lambda sampler, at: Vec(*(c / 255 for c in texel), 1.0))
    run_statements(statements(found.group(1)) + statements(found.group(2)) + statements(found.group(3)),
                   scope, who)
    result = eval(found.group(4), {}, scope)
    return scope["t"], scope["b"], scope["m"], result
