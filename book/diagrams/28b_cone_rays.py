"""Chapter 28b: why the cone test is made from the eye's position, not along the view.

A cut through the eye, seen from above. The rays from the eye fan out to the
screen's side edges, each FIELD_SIDE degrees off the forward axis, where
FIELD_SIDE = atan(tan(fov / 2) * 16 / 9): the vertical field of view is read
from chapters/28_gpu_culling/scene.hpp (its vulkan_perspective call), the
aspect is the 1920x1080 picture the page names. A meshlet stands on the right
edge's ray, its normals within CONE_HALF degrees of an axis turned CONE_TURN
degrees from the forward axis, towards the middle of the screen.

The orthographic test compares the axis with the forward axis (CONE_TURN
degrees, under 90 - CONE_HALF: it culls the meshlet); the perspective test
compares it with the real ray (CONE_TURN + FIELD_SIDE degrees, over 90: every
triangle faces the eye, and it keeps the meshlet). The angles are computed
here; book/28b_task_path.md quotes them, and a page that no longer says them
stops the book's build (`python3 28b_cone_rays.py --numbers` prints them).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the text
stands below the drawing, 400 units wide.
"""

import math
import os
import re
import sys
from pathlib import Path

from svg import GREEN, GREEN_FILL, GREY, INK, MUTED, ORANGE, ORANGE_FILL, RED, Svg

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "chapters" / "28_gpu_culling" / "scene.hpp"
PAGE = ROOT / "book" / "28b_task_path.md"
WIDTH, HEIGHT = 1920, 1080  # the picture the page names
CONE_TURN = 70.0  # the meshlet's cone axis, from the forward axis towards the screen's middle
CONE_HALF = 10.0  # the cone's half-angle


def field_of_view() -> float:
    """The vertical field of view of chapter 28's camera, in degrees."""
    text = SCENE.read_text(encoding="utf-8")
    found = re.findall(r"vulkan_perspective\(glm::radians\(([0-9.]+)f?\)", text)
    if len(found) != 1:
        sys.exit("chapters/28_gpu_culling/scene.hpp: no single vulkan_perspective(glm::radians(...)) call; "
                 "redraw book/diagrams/28b_cone_rays.py")
    return float(found[0])


def angles() -> dict:
    fov = field_of_view()
    half = math.tan(math.radians(fov / 2))
    side = math.degrees(math.atan(half * WIDTH / HEIGHT))
    corner = math.degrees(math.atan(half * math.hypot(WIDTH, HEIGHT) / HEIGHT))
    return {"fov": fov, "top": fov / 2, "side": side, "corner": corner, "ray": CONE_TURN + side}


def quoted() -> list:
    """What book/28b_task_path.md must say, computed here."""
    a = angles()
    return [f"vertical field of view of {a['fov']:g} degrees",
            f"{a['top']:g} degrees off the forward axis",
            f"{WIDTH}x{HEIGHT}",
            f"{a['side']:.1f} degrees off it",
            f"in a corner {a['corner']:.1f} degrees",
            f"by up to {a['corner']:.1f} degrees",
            f"{CONE_HALF:g} degrees of an axis turned {CONE_TURN:g} degrees",
            f"{a['ray']:.1f} degrees from the axis"]


def check_page() -> None:
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    for phrase in quoted():
        if phrase not in text:
            sys.exit(f"book/28b_task_path.md: the page should say '{phrase}' "
                     "(book/diagrams/28b_cone_rays.py computes it)")


def point(origin, length, degrees):
    """The point LENGTH from ORIGIN at DEGREES (counter-clockwise from +x, y up on screen)."""
    return (origin[0] + length * math.cos(math.radians(degrees)),
            origin[1] - length * math.sin(math.radians(degrees)))


def draw(s: Svg, eye, scale: float, detail: float, size: float) -> None:
    """The fan of rays, the edge meshlet, its cone and the two verdicts' angles; SCALE sizes
    the fan, DETAIL the meshlet and its angles."""
    a = angles()
    up = 90.0
    right_edge, left_edge = up - a["side"], up + a["side"]
    reach = 300 * scale
    # The forward axis and the fan of rays (short, to leave the meshlet clear).
    s.line(*eye, *point(eye, reach * 1.02, up), stroke=INK, width=1.3, dash="6 4")
    for k in (-2, -1, 1, 2):
        s.line(*eye, *point(eye, reach * 0.55, up + k * a["side"] / 3), stroke=GREY, width=0.8)
    for edge in (right_edge, left_edge):
        s.line(*eye, *point(eye, reach * 1.05, edge), stroke=INK, width=1.6)
    s.circle(*eye, 5, fill=INK, stroke=INK)
    s.text(eye[0], eye[1] + size + 8, "eye", size=size, anchor="middle", bold=True)
    s.text(eye[0] - 6, eye[1] - reach * 1.02 + size, "forward axis", size=size, anchor="end")
    s.arc_arrow(eye[0], eye[1], 46 * scale, up, right_edge, stroke=INK)
    at = point(eye, 46 * scale + 6, (up + right_edge) / 2)
    s.text(at[0] + 2, at[1] - 2, f"{a['side']:.1f}\u00b0", size=size)
    # The edges' names, written along them.
    for edge, name, side, along in ((right_edge, "the screen's edge", 1, 0.4),
                                    (left_edge, "the screen's edge", -1, 0.6)):
        at = point(point(eye, reach * along, edge), size + 7, edge - 90 * side)
        s.text(*at, name, size=size, anchor="middle", rotate=-edge if side > 0 else 180 - edge)

    # The meshlet on the right edge's ray, a short strip facing its cone's axis.
    m = point(eye, 215 * scale, right_edge)
    axis = up + CONE_TURN
    tangent = axis - 90
    strip = [point(point(m, t * detail, tangent), -7 * detail * (t / 26) ** 2, axis) for t in range(-26, 27, 4)]
    cone_end = [point(m, 80 * detail, axis - CONE_HALF), point(m, 80 * detail, axis + CONE_HALF)]
    s.polygon([m, *cone_end], fill=ORANGE_FILL, stroke=ORANGE, width=1.0, opacity=0.8)
    s.line(*m, *point(m, 92 * detail, axis), stroke=ORANGE, width=1.8, arrow="end")
    s.polyline(strip, stroke=INK, width=3.2)
    for t, turn in ((-20, -CONE_HALF), (0, 0), (20, CONE_HALF)):
        foot = point(m, t * detail, tangent)
        s.line(*foot, *point(foot, 22 * detail, axis + turn), stroke=INK, width=1.0, arrow="end")
    axis_end = point(m, 92 * detail, axis)
    s.text(axis_end[0], axis_end[1] - 8, "cone axis", size=size, anchor="middle", fill=ORANGE)

    # The two directions the tests compare the axis with, and their angles.
    s.line(*m, *point(m, 100 * detail, up), stroke=RED, width=1.5, dash="5 3", arrow="end")
    s.arc_arrow(m[0], m[1], 34 * detail, up, axis, stroke=RED)
    at = point(m, 34 * detail + 4, (up + axis) / 2)
    s.text(at[0] - 2, at[1] - 3, f"{CONE_TURN:g}\u00b0", size=size, anchor="end", fill=RED)
    s.line(*m, *point(m, 78 * detail, right_edge), stroke=GREEN, width=1.8, arrow="end")
    s.arc_arrow(m[0], m[1], 56 * detail, right_edge, axis, stroke=GREEN)
    at = point(m, 56 * detail + 5, right_edge + 12)
    s.text(at[0] + 3, at[1], f"{a['ray']:.1f}\u00b0", size=size, fill=GREEN)
    s.text(m[0] + 10 * detail, m[1] + 14 * detail + size, "meshlet", size=size, bold=True)


def legend(s: Svg, x: float, y: float, size: float, lines: list) -> float:
    """Paragraphs of (colour, bold, text) lines; returns the y below them."""
    lead = size * 1.35
    for fill, bold, text in lines:
        if text is None:
            y += lead * 0.6
            continue
        s.text(x, y, text, size=size, fill=fill, bold=bold)
        y += lead
    return y


def main() -> None:
    check_page()
    a = angles()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    description = (f"Seen from above: rays fan out from the eye to the screen's edges, {a['side']:.1f} degrees "
                   f"off the forward axis at the side edge. A meshlet on the right edge's ray has normals within "
                   f"{CONE_HALF:g} degrees of an axis turned {CONE_TURN:g} degrees from the forward axis. The "
                   f"orthographic test measures {CONE_TURN:g} degrees to the forward axis and culls it; along the "
                   f"real ray the axis is {a['ray']:.1f} degrees away, every triangle faces the eye, and the "
                   f"perspective test keeps it.")
    title = "Chapter 28b: the cone test against the forward axis and against the real ray"
    text = [
        (INK, True, "Seen from above: the rays fan out."),
        (INK, False, f"A {a['fov']:g}\u00b0 vertical field in a {WIDTH}x{HEIGHT} picture:"),
        (INK, False, f"the side edges {a['side']:.1f}\u00b0 off the forward axis,"),
        (INK, False, f"a corner {a['corner']:.1f}\u00b0."),
        (None, False, None),
        (INK, False, f"The meshlet's normals lie within {CONE_HALF:g}\u00b0"),
        (INK, False, "of its cone axis."),
        (None, False, None),
        (RED, True, "Orthographic test, against the forward axis:"),
        (RED, False, f"{CONE_TURN:g}\u00b0 from the axis, under 90\u00b0 \u2212 {CONE_HALF:g}\u00b0:"),
        (RED, False, "\u201cfaces away\u201d, culled \u2014 a hole at the edge."),
        (None, False, None),
        (GREEN, True, "Perspective test, against the real ray:"),
        (GREEN, False, f"{a['ray']:.1f}\u00b0 from the axis, over 90\u00b0: every"),
        (GREEN, False, "triangle faces the eye, kept."),
    ]
    if narrow:
        size = 11
        s = Svg(400, 100, title, description)
        draw(s, (175, 296), 0.85, 1.0, size)
        y = legend(s, 10, 350, size, text)
    else:
        size = 12.5
        s = Svg(960, 100, title, description)
        draw(s, (290, 412), 1.25, 1.25, size)
        y = max(legend(s, 630, 70, size, text), 456)
    s.height = y + 6
    s.write()


if __name__ == "__main__":
    if sys.argv[1:] == ["--numbers"]:
        for phrase in quoted():
            print(phrase)
    else:
        main()
