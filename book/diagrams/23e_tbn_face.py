"""Chapter 23e: one normal-map texel turned into a direction on one face of the cube.

The test model's cube (scripts/make_pbr_cubes.py's cube(), the left cube, which
has TANGENT) seen from its upper right front, its +x face carrying the normal
map. On that face, at one texel of a stud's slope: T (where u grows, the file's
TANGENT), B (up the image, where v falls: cross(N, T) times TANGENT's w) and N
(out of the face), and the texel's (x, y, z) turned into x T + y B + z N.

Nothing is typed: the face's corners, texture coordinates, normal and tangent
come from the script that writes the model, the texel is read out of
assets/gltf/pbr_cubes.gltf (23e_texture_maps.py reads its images), and T, B and
the normal are computed by the lines of shaders/23_materials/surface.glsl
themselves (tangent_frame.file_frame runs the TANGENT branch and the texel's
lines). This is the plain change of basis; 23g's figures are about the frame
made without TANGENT and about its sign.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
panels stand one above the other, 400 units wide.
"""

from __future__ import annotations

import base64
import importlib
import importlib.util
import math
import os
from pathlib import Path

from golden import enlarged, png_bytes
from svg import BLUE, GREEN, GREY, GREY_FILL, INK, MUTED, PURPLE, RED, Svg, text_width
from tangent_frame import Vec, dot, file_frame

WHO = "book/diagrams/23e_tbn_face.py"
ROOT = Path(__file__).resolve().parents[2]
FACE = 0  # cube()'s first face: the one whose normal is +x
AT = (12, 36)  # the texel (column, row) of the normal map: the upper right slope of a stud
STUDS = 4  # studs per side of the map (make_pbr_cubes.bump's default)


def model_script():
    spec = importlib.util.spec_from_file_location("make_pbr_cubes", ROOT / "scripts" / "make_pbr_cubes.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def face():
    """The face's four corners, their (u, v), its normal and its TANGENT (xyz, w)."""
    pos, nrm, uv, tan, _ = model_script().cube()
    corners = range(4 * FACE, 4 * FACE + 4)
    return [pos[i] for i in corners], [uv[i] for i in corners], nrm[4 * FACE], tan[4 * FACE]


def on_face(corners, uvs, u, v):
    """The point of the face at (u, v): the face is a square, its (u, v) affine on it."""
    (p0, p1, p3), (a, b, d) = (corners[0], corners[1], corners[3]), (uvs[0], uvs[1], uvs[3])
    # p = p0 + s (p1 - p0) + r (p3 - p0), with (u, v) = a + s (b - a) + r (d - a)
    m = ((b[0] - a[0], d[0] - a[0]), (b[1] - a[1], d[1] - a[1]))
    det = m[0][0] * m[1][1] - m[0][1] * m[1][0]
    du, dv = u - a[0], v - a[1]
    s = (du * m[1][1] - dv * m[0][1]) / det
    r = (m[0][0] * dv - m[1][0] * du) / det
    return tuple(p0[i] + s * (p1[i] - p0[i]) + r * (p3[i] - p0[i]) for i in range(3))


# An orthographic view from the cube's upper right front.
EYE = Vec(1.0, 0.4, 0.6)


def camera():
    d = EYE * (1 / math.sqrt(dot(EYE, EYE)))
    right = Vec(d.z, 0.0, -d.x)
    right = right * (1 / math.sqrt(dot(right, right)))
    up = Vec(d.y * right.z - d.z * right.y, d.z * right.x - d.x * right.z, d.x * right.y - d.y * right.x)
    return d, right, up


def fmt(v, digits=2):
    return "(" + ", ".join(f"{c:.{digits}f}".replace("-0.00", "0.00").replace("-", "\u2212")
                           for c in v.c) + ")"


def num(c):
    return f"{c:.2f}".replace("-", "\u2212")


def arrow(s, a, b, colour, width=2.4):
    s.line(a[0], a[1], b[0], b[1], stroke=colour, width=width, arrow="end")


def face_panel(s, x, y, w, corners, uvs, normal, tex, t, b, m, result):
    """The cube with the normal map on its +x face and the frame at the texel; returns
    the panel's bottom."""
    s.text(x, y, "2. On the cube's +x face: T, B, N and n'", size=13, bold=True)
    _, right, up = camera()
    size = len(tex)
    centre = on_face(corners, uvs, (AT[0] + 0.5) / size, (AT[1] + 0.5) / size)
    L = 0.6  # the drawn length of a unit vector, in the cube's units (its side is 1)
    n = Vec(*normal)

    def flat(p):
        p = Vec(*p)
        return dot(p, right), -dot(p, up)

    def at(v):
        return tuple(c + L * d for c, d in zip(centre, v.c))

    # Fit the cube and the arrows' tips into the panel's width, 24 units spare each side.
    cube = [(sx * 0.5, sy * 0.5, sz * 0.5) for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)]
    seen = [flat(p) for p in cube + [at(v) for v in (t, b, n, result)]]
    x0, x1 = min(p[0] for p in seen), max(p[0] for p in seen)
    y0, y1 = min(p[1] for p in seen), max(p[1] for p in seen)
    k = (w - 48) / (x1 - x0)
    top = y + 34

    def page(p):
        fx, fy = flat(p)
        return x + 24 + k * (fx - x0), top + k * (fy - y0)

    # The cube's two other faces turned towards the eye (+y, +z), plain.
    for face_normal in ((0, 1, 0), (0, 0, 1)):
        a = [i for i in range(3) if face_normal[i] == 0]
        quad = []
        for su, sv in ((-1, -1), (1, -1), (1, 1), (-1, 1)):
            p = [0.5 * c for c in face_normal]
            p[a[0]], p[a[1]] = 0.5 * su, 0.5 * sv
            quad.append(page(p))
        s.polygon(quad, fill=GREY_FILL, stroke=GREY, width=1.2)
    # The +x face, the normal map on it (faded, so that the arrows stand out): texel
    # (px, py) is at (u, v) = (px, py) / 64.
    o = page(on_face(corners, uvs, 0, 0))
    eu = [c - d for c, d in zip(page(on_face(corners, uvs, 1 / size, 0)), o)]
    ev = [c - d for c, d in zip(page(on_face(corners, uvs, 0, 1 / size)), o)]
    data = base64.b64encode(png_bytes(tex)).decode("ascii")
    s.add(f'<image x="0" y="0" width="{size}" height="{size}" preserveAspectRatio="none" '
          f'image-rendering="pixelated" style="image-rendering: pixelated" opacity="0.6" '
          f'transform="matrix({eu[0]:.4f} {eu[1]:.4f} {ev[0]:.4f} {ev[1]:.4f} {o[0]:.2f} {o[1]:.2f})" '
          f'href="data:image/png;base64,{data}"/>')
    s.polygon([page(c) for c in corners], stroke=INK, width=1.2)
    # u along the face's top edge, v down its front edge.
    top_left, top_right = page(on_face(corners, uvs, 0, 0)), page(on_face(corners, uvs, 1, 0))
    bottom_left = page(on_face(corners, uvs, 0, 1))
    s.line(top_left[0], top_left[1] - 9, top_right[0], top_right[1] - 9, stroke=MUTED, width=1, arrow="end")
    s.text(top_right[0] + 4, top_right[1] - 10, "u", size=12, italic=True, fill=MUTED)
    s.line(top_left[0] - 7, top_left[1] + 4, bottom_left[0] - 7, bottom_left[1], stroke=MUTED, width=1,
           arrow="end")
    s.text(bottom_left[0] - 11, (top_left[1] + bottom_left[1]) / 2 + 4, "v", size=12, italic=True, fill=MUTED,
           anchor="end")
    # The texel, outlined, and the frame at its middle.
    u0, v0 = AT[0] / size, AT[1] / size
    cell = [page(on_face(corners, uvs, u0 + du / size, v0 + dv / size))
            for du, dv in ((0, 0), (1, 0), (1, 1), (0, 1))]
    s.polygon(cell, stroke=INK, width=1.6)
    start = page(centre)

    def tip(v):
        return page(at(v))

    s.polyline([start, tip(t * m.x), tip(t * m.x + b * m.y), tip(t * m.x + b * m.y + n * m.z)],
               stroke=INK, width=1.2, dash="4 3")
    for v, name, colour, width in ((t, "T", RED, 2.6), (b, "B", GREEN, 2.6), (n, "N", BLUE, 2.6),
                                   (result, "n'", PURPLE, 3.0)):
        end = tip(v)
        s.line(start[0], start[1], end[0], end[1], stroke="#ffffff", width=width + 3)
        arrow(s, start, end, colour, width)
        dx, dy = end[0] - start[0], end[1] - start[1]
        r = math.hypot(dx, dy)
        lx, ly = end[0] + 11 * dx / r, end[1] + 11 * dy / r + 5
        s.text(lx, ly, name, size=14, bold=True, fill=colour,
               anchor="start" if dx > 4 else "end" if dx < -4 else "middle")
    return top + k * (y1 - y0) + 14


def texel_panel(s, x, y, tex, zoom):
    """The stud's cell of the map, enlarged, the texel outlined; returns (right, bottom)."""
    s.text(x, y, "1. One texel of the normal map", size=13, bold=True)
    cell = len(tex) // STUDS
    left, top = AT[0] // cell * cell, AT[1] // cell * cell
    ox, oy = x + 14, y + 26
    enlarged(s, tex, left, top, cell, cell, ox, oy, zoom)
    s.rect(ox + (AT[0] - left) * zoom, oy + (AT[1] - top) * zoom, zoom, zoom, stroke=INK, width=2.2)
    s.line(ox, oy + cell * zoom + 10, ox + cell * zoom, oy + cell * zoom + 10, stroke=MUTED, width=1,
           arrow="end")
    s.text(ox + cell * zoom + 4, oy + cell * zoom + 14, "u", size=12, italic=True, fill=MUTED)
    s.line(ox - 8, oy, ox - 8, oy + cell * zoom, stroke=MUTED, width=1, arrow="end")
    s.text(ox - 10, oy + cell * zoom + 14, "v", size=12, italic=True, fill=MUTED, anchor="end")
    return ox + cell * zoom, oy + cell * zoom + 14, (left, top, cell)


def whole(v):
    """A vector of whole numbers as such, (0, 0, −1); else two decimals."""
    if all(abs(c - round(c)) < 1e-9 for c in v.c):
        return "(" + ", ".join(f"{round(c):d}".replace("-", "−") for c in v.c) + ")"
    return fmt(v)


def rows(rgb, t, b, n, m, total, result, w):
    """The figure's numbers: the texel, then the frame and the change of basis."""
    texel = [(f"texel ({AT[0]}, {AT[1]}), RGB {rgb}", INK),
             ("× 2/255 − 1: (x, y, z) =", INK),
             (f"  {fmt(m.xyz, 3)}", INK)]
    frame = [(f"T = {whole(t)}: the file's TANGENT,", RED), ("  where u grows", RED),
             (f"B = w N × T = {whole(b)} (w = {w:+g}),", GREEN), ("  up the image, where v falls", GREEN),
             (f"N = {whole(n)}: out of the face", BLUE),
             ("x T + y B + z N =", PURPLE), (f"  {fmt(total, 3)}", PURPLE),
             (f"n' = normalize(that) = {fmt(result, 3)}", PURPLE)]
    return texel, frame


def column(s, x, y, lines, size, room, leading=1.35):
    for i, (row, colour) in enumerate(lines):
        if text_width(row, size) > room:
            raise SystemExit(f"{WHO}: '{row}' is wider than its column")
        s.text(x, y + i * size * leading, row, size=size, fill=colour)
    return y + len(lines) * size * leading


def main() -> None:
    corners, uvs, normal, tangent = face()
    tex = importlib.import_module("23e_texture_maps").maps()[0]["normal"]
    rgb = tex[AT[1]][AT[0]]
    if rgb == (128, 128, 255):
        raise SystemExit(f"{WHO}: texel {AT} of the normal map is flat; pick one on a stud's slope")
    t, b, m, result = file_frame(normal, tangent, rgb, WHO)
    n = Vec(*normal)
    total = t * m.x + b * m.y + n * m.z
    texel, frame = rows(rgb, t, b, n, m, total, result, tangent[3])
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 23e: one normal-map texel turned into a direction on one face of the cube"
    desc = (f"Left, the cell of one stud in the test model's normal map, enlarged, with texel "
            f"({AT[0]}, {AT[1]}) outlined on the stud's {'right' if m.x > 0 else 'left'} "
            f"{'upper' if m.y > 0 else 'lower'} slope: RGB {rgb}, which is (x, y, z) = {fmt(m.xyz, 3)}. "
            f"Right, the cube seen from its upper right front, its +x face carrying the normal map, and "
            f"at that texel three arrows: T = {whole(t)} (red, where u grows along the face), "
            f"B = {whole(b)} (green, up the face, where v falls) and N = {whole(n)} (blue, out of the "
            f"face). A dashed path goes x along T (under T's arrow), then y along B and z along N, to "
            f"the tip of a purple arrow, n' = {fmt(result, 3)}, which leans from N towards T and B.")
    foot = ["In the cube's own axes; the node's turn carries T, B, N and n' into the world alike.",
            "Every number is computed: the texel read from assets/gltf/pbr_cubes.gltf, the frame",
            "and n' by the lines of surface.glsl for a face with the file's TANGENT."]
    if narrow:
        s = Svg(400, 2000, title, desc)
        s.text(12, 24, "A normal-map texel on one face", size=14, bold=True)
        right, bottom, _ = texel_panel(s, 12, 54, tex, 7)
        beside = [(f"texel ({AT[0]}, {AT[1]})", INK), (f"RGB {rgb}", INK), ("× 2/255 − 1:", INK),
                  (f"x = {m.x:.3f}", INK), (f"y = {m.y:.3f}", INK), (f"z = {m.z:.3f}", INK)]
        column(s, right + 18, 54 + 42, beside, 12, 400 - right - 24)
        y = face_panel(s, 12, bottom + 36, 376, corners, uvs, normal, tex, t, b, m, result)
        y = column(s, 12, y + 10, frame, 12, 376)
        narrow_foot = ["In the cube's own axes: the node's turn carries", "T, B, N and n' into the world alike.",
                       "Every number is computed: the texel read from", "the model, the frame and n' by the lines",
                       "of surface.glsl (its TANGENT branch)."]
        y = column(s, 12, y + 14, [(row, MUTED) for row in narrow_foot], 11.5, 376, 1.3)
        s.height = y + 4
    else:
        s = Svg(780, 2000, title, desc)
        s.text(20, 26, "A normal-map texel turned into a direction on one face of the cube", size=15,
               bold=True)
        _, bottom, _ = texel_panel(s, 20, 60, tex, 9)
        y_left = column(s, 20, bottom + 28, texel, 12.5, 300)
        y_left = column(s, 20, y_left + 14, frame, 12.5, 300)
        y = face_panel(s, 330, 60, 430, corners, uvs, normal, tex, t, b, m, result)
        y = max(y, y_left) + 12
        y = column(s, 20, y, [(row, MUTED) for row in foot], 12, 740, 1.3)
        s.height = y + 4
    s.write()


if __name__ == "__main__":
    main()
