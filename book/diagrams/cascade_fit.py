"""Chapter 22's cascades, computed as chapters/22_shadows/cascades.hpp computes them.

Shared by 22_cascades.py, 22_light_box.py, 22b_snap.py and 22_acne.py, so that the diagrams and the
pages quote one width for a texel: of the near cascade, or of the one map of --cascades 1. The camera is the chapter's
(eye (0, 3, 8) looking along (0, -0.25, -1), 50 degrees high, 4:3 as at the
default 800x600 and the tests' 320x240, near 0.1, far 60), three cascades
split by the practical scheme with lambda 0.6, the light along
(-0.6, -1, -0.45), each box reaching BEHIND units further towards the light (main.cpp passes
40.0f to light_from_world). The map's size is read from main.cpp (shadow_size).
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
BEHIND = 40.0


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


def one_map_texel():
    """The width of one texel of the one map of --cascades 1."""
    return one_cascade_box_side() / MAP_SIZE


def one_map_depth():
    """The depth of the light box with --cascades 1: twice the sphere's radius and BEHIND."""
    return 2 * one_cascade_radius() + BEHIND


def one_map_constant_bias(steps=4):
    """How far depthBiasConstantFactor `steps` moves a depth in the one map, in units, at least
    and at most: everything the camera sees lies at depths from 1 - 2 * radius / depth to 1,
    where a D32_SFLOAT step is 2^(e - 23), e = -2 below 0.5 and -1 above."""
    assert 0.25 <= 1 - 2 * one_cascade_radius() / one_map_depth() < 0.5
    return steps * 2.0 ** -25 * one_map_depth(), steps * 2.0 ** -24 * one_map_depth()


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
            f"a texel is {one_map_texel():.3f} units wide (the box, {one_cascade_box_side():.0f} units "
            f"across, over {MAP_SIZE} texels)": "the one map's texel",
            f"floor falls about {FLOOR_SLOPE * one_map_texel():.4f} units": "the floor's fall across a texel",
            f"4 \u00d7 {FLOOR_SLOPE * one_map_texel():.4f} = {4 * FLOOR_SLOPE * one_map_texel():.3f} units in "
            "the one map": "the slope bias 4",
            f"every step lies {4 * FLOOR_SLOPE * one_map_texel():.3f} units deeper": "the acne figure's alt text",
            f"box {one_map_depth():.0f} units deep (2 \u00d7 {one_cascade_radius():.1f} + {BEHIND:.0f}), at "
            f"depths between about {1 - 2 * one_cascade_radius() / one_map_depth():.1f} and 1":
                "the one map's depth range",
            f"moves a depth by {one_map_constant_bias()[0] * 1e5:.0f} to {one_map_constant_bias()[1] * 1e5:.0f} "
            "\u00d7 10\u207b\u2075 units": "the constant term",
            f"The slope term's {4 * FLOOR_SLOPE * one_map_texel():.3f} units is over "
            f"{int(4 * FLOOR_SLOPE * one_map_texel() / one_map_constant_bias()[1]) // 1000 * 1000:,} times more":
                "the slope term against the constant",
            f"with one map, {one_cascade_box_side():.0f} units across": "--cascades 1's box",
            f"bounding sphere, radius {one_cascade_radius():.1f}; around that the dashed orange square of "
            f"the light's box, {one_cascade_box_side():.0f} units a side": "22_light_box's alt text",
            f"the same box, {one_cascade_box_side():.0f} units across and {one_map_depth():.0f} deep, its top "
            f"{BEHIND:.0f} units empty above the sphere and the other {2 * one_cascade_radius():.1f} through "
            "it": "22_light_box's alt text",
            f"line of sight, {math.dist(one_cascade_centre(), EYE):.2f} units from the eye and "
            f"{-one_cascade_centre()[1]:.1f} units below the floor": "22_light_box's alt text",
        },
        "22b_cascades.md": {
            f"near cascade a texel is {texel(0):.4f} units, the near square's {box_side(0):.2f} units "
            f"over {MAP_SIZE}": "the near cascade's texel",
            f"the one map's texels are {one_cascade_box_side() / box_side(0):.0f} times as wide as the near "
            "cascade's": "--cascades 1's texel against the near cascade's",
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
