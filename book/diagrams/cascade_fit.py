"""Chapter 22's cascades, computed as chapters/22_shadows/cascades.hpp computes them.

Shared by 22_cascades.py and 22_acne.py, so that the two diagrams and the
page quote one width for a near-cascade texel. The camera is the chapter's
(eye (0, 3, 8) looking along (0, -0.25, -1), 50 degrees high, 4:3 as at the
default 800x600 and the tests' 320x240, near 0.1, far 60), three cascades
split by the practical scheme with lambda 0.6, the light along
(-0.6, -1, -0.45). The map's size is read from main.cpp (shadow_size).
"""

import math
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

MAIN_CPP = Path(__file__).resolve().parents[2] / "chapters" / "22_shadows" / "main.cpp"
MAP_SIZE = int(constant(MAIN_CPP, "shadow_size"))
EYE = (0.0, 3.0, 8.0)
LIGHT = (-0.6, -1.0, -0.45)
FOV_Y, ASPECT = math.radians(50), 4 / 3
NEAR, FAR, LAMBDA, COUNT = 0.1, 60.0, 0.6, 3


def add(a, b):
    return tuple(x + y for x, y in zip(a, b))


def mul(k, a):
    return tuple(k * x for x in a)


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def unit(a):
    return mul(1 / math.sqrt(dot(a, a)), a)


def splits():
    """cascade_splits(NEAR, FAR, COUNT, LAMBDA)."""
    out = []
    for i in range(COUNT + 1):
        t = i / COUNT
        out.append(LAMBDA * NEAR * (FAR / NEAR) ** t + (1 - LAMBDA) * (NEAR + (FAR - NEAR) * t))
    return out


def slice_corners(d0, d1):
    """The eight corners of the camera's view between d0 and d1, as slice_corners() makes them."""
    forward = unit((0.0, -0.25, -1.0))
    up = unit(cross(cross(forward, (0, 1, 0)), forward))
    right = unit(cross(forward, up))
    corners = []
    for d in (d0, d1):
        h = d * math.tan(FOV_Y / 2)
        w = h * ASPECT
        for sy in (-1, 1):
            for sx in (-1, 1):
                corners.append(add(add(add(EYE, mul(d, forward)), mul(sx * w, right)), mul(sy * h, up)))
    return corners


def sphere(i):
    """Cascade i's bounding sphere: its centre and radius, as light_from_world() finds them."""
    corners = slice_corners(*splits()[i:i + 2])
    centre = mul(1 / 8, tuple(map(sum, zip(*corners))))
    return corners, centre, max(math.dist(p, centre) for p in corners)


def box_side(i):
    """The side of cascade i's light box: the sphere and half a texel more each way (2 * half)."""
    return 2 * sphere(i)[2] * MAP_SIZE / (MAP_SIZE - 1)


def texel(i):
    """The width of one texel of cascade i's map."""
    return box_side(i) / MAP_SIZE


# The floor's depth from the light per unit across the map: the light, (-0.6, -1, -0.45) / 1.25,
# meets the floor's normal at cos 0.8 and sin 0.6, a slope of 0.6 / 0.8.
FLOOR_SLOPE = 0.75


def one_cascade_radius():
    """The radius of the sphere round the whole view, which --cascades 1 fits its box around."""
    corners = slice_corners(NEAR, FAR)
    centre = mul(1 / 8, tuple(map(sum, zip(*corners))))
    return max(math.dist(p, centre) for p in corners)


def one_cascade_box_side():
    """The side of the light box with --cascades 1: one sphere round the whole view."""
    corners = slice_corners(NEAR, FAR)
    centre = mul(1 / 8, tuple(map(sum, zip(*corners))))
    return 2 * max(math.dist(p, centre) for p in corners) * MAP_SIZE / (MAP_SIZE - 1)


def one_cascade_centre():
    """The centre of the sphere round the whole view: on the line of sight, halfway out."""
    corners = slice_corners(NEAR, FAR)
    return mul(1 / 8, tuple(map(sum, zip(*corners))))


def check_page() -> None:
    """book/22_shadows.md and book/22b_cascades.md quote these numbers in their prose; a page
    that no longer agrees with the arithmetic stops the diagram, and so the book's build,
    with one line."""
    book = Path(__file__).resolve().parents[1]
    quoted = {
        "22_shadows.md": {
            f"a texel is {texel(0):.4f} units wide": "the near cascade's texel",
            f"the box is {box_side(0):.2f} units across": "the near cascade's box",
            f"floor falls about {FLOOR_SLOPE * texel(0):.4f} units": "the floor's fall across a texel",
            f"{4 * FLOOR_SLOPE * texel(0):.3f} units in the near cascade": "the slope bias 4",
            f"with one map, {one_cascade_box_side():.0f} units across": "--cascades 1's box",
            f"the one map's texels are {one_cascade_box_side() / box_side(0):.0f} times as wide as the near "
            "cascade's": "--cascades 1's texel against the near cascade's",
            f"sphere is {one_cascade_radius():.1f} units in radius": "--cascades 1's sphere",
            f"{math.dist(one_cascade_centre(), EYE):.2f} units from the eye": "--cascades 1's sphere's centre",
            f"centre is at y = \u2212{-one_cascade_centre()[1]:.1f}, {-one_cascade_centre()[1]:.1f} units "
            "below the floor": "--cascades 1's sphere's centre",
            f"with one map {one_cascade_box_side():.0f} units across, and a depth": "--cascades 1's box",
            f"`half`, half the box's side, is the sphere's radius, {one_cascade_radius():.1f} units":
                "--cascades 1's half side",
            f"moved by less than a texel, {one_cascade_box_side() / MAP_SIZE:.2f} units here":
                "--cascades 1's texel",
        },
        "22b_cascades.md": {
            f"A texel is now about {one_cascade_box_side() / MAP_SIZE:.2f} units wide (a box "
            f"{one_cascade_box_side():.0f} units across)": "--cascades 1's texel and box",
            f"boundaries fall at {splits()[1]:.1f} and {splits()[2]:.1f}": "the splits",
            f"The square around the far slice is {box_side(2):.0f} units wide, over six times the "
            f"near one's {box_side(0):.0f}": "the far and near boxes",
        },
    }
    for name, phrases in quoted.items():
        text = " ".join((book / name).read_text(encoding="utf-8").split())
        for phrase, what in phrases.items():
            if phrase not in text:
                sys.exit(f"book/{name}: {what}: the page should say '{phrase}' "
                         "(book/diagrams/cascade_fit.py computes it as cascades.hpp does)")
