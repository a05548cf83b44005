"""Chapter 28b: the culled view with marks on it, computed from the chapter's camera.

The picture is the reviewed test picture tests/golden/28_gpu_culling_task_culled.png
(--headless --frames 10 --size 320x240 --instances 4096 --path task --view culled),
drawn from the second camera. Over it, three marks placed by projecting the
scene's own numbers through that camera, so they stand where the chapter puts
things and move if its sources do:

- the first camera: its eye, and the foot of a line straight down to the floor;
- the edges of the first camera's frustum on the floor: where its left, right
  and bottom planes cut the floor (y = 0);
- the nearest wall in front of the first camera: the top edge of its back face.

The numbers are read from chapters/28_gpu_culling/scene.hpp (camera(): the eye,
the gaze, the turn with time, the second camera's offsets, the field of view;
kSpacing, kWallEvery and the walls' size) and from the runner's fixed time step
(common/frame/src/harness.cpp): the picture is frame 9, t = 9/60 s. A line the
script expects and does not find stops the book's build.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the picture
is enlarged 1.25 times instead of 2, in 400 units.
"""

import math
import os
import re
import sys
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import INK, MUTED, Svg, text_width

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "book"))
from source_constants import constant  # noqa: E402  (book/, above this folder)

SCENE = ROOT / "chapters" / "28_gpu_culling" / "scene.hpp"
HARNESS = ROOT / "common" / "frame" / "src" / "harness.cpp"
PICTURE = "28_gpu_culling_task_culled.png"
INSTANCES, FRAMES = 4096, 10  # the test's --instances and --frames
NUM = r"(-?[0-9]+(?:\.[0-9]+)?)f?"


def found(path: Path, pattern: str) -> tuple:
    """The numbers of the one line of path that matches pattern (a regex with groups)."""
    match = re.search(pattern, path.read_text(encoding="utf-8"))
    if not match:
        raise SystemExit(f"{path.relative_to(ROOT)}: no line matches {pattern!r}; "
                         "redraw book/diagrams/28b_culled_marks.py")
    return tuple(float(g) for g in match.groups())


SPACING = float(constant(SCENE, "kSpacing"))
WALL_EVERY = int(constant(SCENE, "kWallEvery"))
YAW0, YAW_RATE = found(SCENE, rf"const float yaw = {NUM} \+ {NUM} \* float\(time\);")
EYE_X, EYE_Y, EYE_Z = found(SCENE, rf"glm::vec3 eye\({NUM} \* kSpacing, {NUM}, {NUM} \* side\);")
(GAZE_Y,) = found(SCENE, rf"glm::vec3 ahead\(std::sin\(yaw\), {NUM}, -std::cos\(yaw\)\);")
(TARGET,) = found(SCENE, rf"const glm::vec3 target = eye \+ {NUM} \* flat;")
UP, RIGHT, AHEAD = found(SCENE, rf"eye \+= glm::vec3\(0, {NUM}, 0\) \+ {NUM} \* right \+ {NUM} \* flat;")
(FOV,) = found(SCENE, rf"vulkan_perspective\(glm::radians\({NUM}\), aspect")
WALL_W, WALL_H, WALL_D = found(SCENE, rf"o\.scale = glm::vec4\({NUM}, {NUM}, {NUM}, 0\.0f\);")
STEP_NUM, STEP_DEN = found(HARNESS, rf"fixed_time_step = {NUM} / {NUM};")


def sub(a, b): return tuple(x - y for x, y in zip(a, b))
def add(a, b): return tuple(x + y for x, y in zip(a, b))
def scale(k, a): return tuple(k * x for x in a)
def dot(a, b): return sum(x * y for x, y in zip(a, b))
def cross(a, b): return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])
def unit(a): return scale(1 / math.sqrt(dot(a, a)), a)


class Camera:
    """glm::lookAt with +y up and vulkan_perspective (y flipped), as scene.hpp builds them."""

    def __init__(self, eye, ahead, width, height):
        self.eye, self.width, self.height = eye, width, height
        self.forward = unit(ahead)
        self.right = unit(cross(self.forward, (0, 1, 0)))
        self.up = cross(self.right, self.forward)
        self.tan = math.tan(math.radians(FOV) / 2)
        self.aspect = width / height

    def pixel(self, p):
        """Where the world point p lands in the picture, in pixels (x right, y down)."""
        d = sub(p, self.eye)
        z = dot(d, self.forward)
        x = dot(d, self.right) / (z * self.tan * self.aspect)
        y = dot(d, self.up) / (z * self.tan)
        return ((x + 1) / 2 * self.width, (1 - y) / 2 * self.height)

    def segment(self, p, q):
        """The world segment p-q in the picture, in pixels: cut at 1 m before the eye
        first (a point behind the camera has no place), then at the picture's edges."""
        dp, dq = dot(sub(p, self.eye), self.forward) - 1, dot(sub(q, self.eye), self.forward) - 1
        if dp < 0 and dq < 0:
            return None
        if dp < 0 or dq < 0:
            cut = add(p, scale(dp / (dp - dq), sub(q, p)))
            p, q = (cut, q) if dp < 0 else (p, cut)
        return clip(self.pixel(p), self.pixel(q), self.width, self.height)

    def ray(self, nx, ny):
        """The direction through normalised screen point (nx right, ny up)."""
        return add(add(self.forward, scale(nx * self.tan * self.aspect, self.right)),
                   scale(ny * self.tan, self.up))


def on_floor(eye, d):
    return add(eye, scale(-eye[1] / d[1], d))


def cameras(width, height):
    """The first camera and the second (--view culled's) at frame FRAMES - 1."""
    side = SPACING * math.ceil(math.sqrt(INSTANCES))
    yaw = YAW0 + YAW_RATE * (FRAMES - 1) * STEP_NUM / STEP_DEN
    eye = (EYE_X * SPACING, EYE_Y, EYE_Z * side)
    ahead = (math.sin(yaw), GAZE_Y, -math.cos(yaw))
    flat, right = (ahead[0], 0.0, ahead[2]), (-ahead[2], 0.0, ahead[0])
    target = add(eye, scale(TARGET, flat))
    eye2 = add(add(add(eye, (0.0, UP, 0.0)), scale(RIGHT, right)), scale(AHEAD, flat))
    return Camera(eye, ahead, width, height), Camera(eye2, sub((target[0], 0.0, target[2]), eye2),
                                                     width, height)


def nearest_wall(first):
    """The z of the nearest wall row in front of the first camera (a row of walls runs
    along x), the eye's distance from the row's middle plane, and half the field."""
    side = math.ceil(math.sqrt(INSTANCES))
    half = 0.5 * SPACING * side
    rows = [SPACING * (row + 0.5) - half for row in range(0, side, WALL_EVERY)]
    in_front = [(z, abs(z - first.eye[2])) for z in rows if (z - first.eye[2]) * first.forward[2] > 0]
    z, distance = min(in_front, key=lambda row: row[1])
    return z, distance, half


def clip(p, q, width, height):
    """The part of segment p-q inside the picture (Liang and Barsky's clipping), or None."""
    t0, t1 = 0.0, 1.0
    dx, dy = q[0] - p[0], q[1] - p[1]
    for den, num in ((-dx, p[0]), (dx, width - p[0]), (-dy, p[1]), (dy, height - p[1])):
        if den == 0:
            if num < 0:
                return None
        elif den < 0:
            t0 = max(t0, num / den)
        else:
            t1 = min(t1, num / den)
    if t0 > t1:
        return None
    return (p[0] + t0 * dx, p[1] + t0 * dy), (p[0] + t1 * dx, p[1] + t1 * dy)


def floor_edge(first, second, nx, width, height):
    """One side edge of the first camera's frustum on the floor, in the second camera's
    picture: from the corner of its near edge outwards, as far as the field goes."""
    near = on_floor(first.eye, first.ray(nx, -1.0))
    along = unit(sub(on_floor(first.eye, first.ray(nx, -0.5)), near))
    _, _, half = nearest_wall(first)
    far, step = near, 0.5
    while abs(far[0]) < half + SPACING and abs(far[2]) < half + SPACING:
        far = add(far, scale(step, along))
    return second.segment(near, far)


def halo_line(s, p, q, x0, y0, zoom, dash=None):
    """A mark line, dark on a white halo so that it reads on magenta, yellow and grey."""
    a, b = (x0 + p[0] * zoom, y0 + p[1] * zoom), (x0 + q[0] * zoom, y0 + q[1] * zoom)
    s.line(*a, *b, stroke="#ffffff", width=4.2)
    s.line(*a, *b, stroke=INK, width=1.8, dash=dash)


def label(s, x, y, lines, size, anchor="start"):
    """Text on a white card, its first baseline at y, kept inside the figure."""
    w = max(text_width(t, size) for t in lines) + 10
    left = {"start": x - 5, "middle": x - w / 2, "end": x - w + 5}[anchor]
    left = min(max(left, 2), s.width - w - 2)
    s.rect(left, y - size - 2, w, size * 1.3 * len(lines) + 6, fill="#ffffff", stroke=INK,
           width=0.8, rx=3, opacity=0.92)
    s.lines(left + 5, y, lines, size=size)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    pixels = read_png(GOLDEN / PICTURE)
    pw, ph = len(pixels[0]), len(pixels)
    first, second = cameras(pw, ph)
    wall_z, wall_ahead, half = nearest_wall(first)
    zoom, x0, y0, size = (1.25, 0, 8, 11) if narrow else (2, 20, 14, 13.5)
    width = 400 if narrow else 2 * x0 + pw * zoom
    key = ["Lit in their own colours: launched. Magenta: outside the frustum.",
           "Yellow: facing away from the first camera. Red: occluded."]
    where = [f"Marks projected from scene.hpp's camera() at frame {FRAMES - 1} "
             f"(t = {FRAMES - 1}/{STEP_DEN:g} s),", f"{pw}x{ph}, --instances {INSTANCES}, "
             f"each pixel enlarged {zoom:g} times"]
    if narrow:
        key = ["Lit in their own colours: launched.", "Magenta: outside the frustum.",
               "Yellow: facing away from the first camera.", "Red: occluded."]
        where = [f"Marks projected from scene.hpp's camera() at", f"frame {FRAMES - 1} "
                 f"(t = {FRAMES - 1}/{STEP_DEN:g} s), {pw}x{ph}, enlarged {zoom:g} times"]
    lead = size * 1.3
    height = y0 + ph * zoom + 16 + lead * (len(key) + len(where)) + 8
    s = Svg(width, height, "Chapter 28b: the culled view, with the first camera, its frustum's "
            "edges on the floor and the nearest wall marked",
            "The --view culled picture drawn from the second camera, which stands ahead of the first "
            "and above it, looking back. Marks computed from the chapter's camera: the first camera "
            "is a ringed dot in the upper middle of the picture, among the magenta walls behind it, "
            "with a dashed line down to the floor and an arrow along its gaze towards the viewer; "
            "the edges of its view on the floor are two dark lines from a short near edge just "
            "below it, one running to the lower left and one to the right, and the lit shapes fill "
            "the wedge between them while magenta fills the floor outside it; the nearest wall in "
            "front of the first camera is marked along its top edge, where its back shows as a "
            "yellow band running from the bottom left up to the wedge's top, and below it many "
            "shapes, hidden from the first camera by the wall, are red.")
    enlarged(s, pixels, 0, 0, pw, ph, x0, y0, zoom)

    def at(p):
        return x0 + p[0] * zoom, y0 + p[1] * zoom

    # The nearest wall: the top edge of its back face, which the second camera sees.
    back = wall_z - WALL_D / 2
    wall = second.segment((half, WALL_H, back), (-half, WALL_H, back))
    halo_line(s, *wall, x0, y0, zoom, dash="7 4")
    # The frustum's edges on the floor: the near edge, then the two sides.
    bl = second.pixel(on_floor(first.eye, first.ray(-1, -1)))
    br = second.pixel(on_floor(first.eye, first.ray(1, -1)))
    halo_line(s, bl, br, x0, y0, zoom)
    edges = [floor_edge(first, second, nx, pw, ph) for nx in (-1, 1)]
    for edge in edges:
        halo_line(s, *edge, x0, y0, zoom)
    # The first camera: its eye, a line down to the floor, its gaze.
    eye = second.pixel(first.eye)
    foot = second.pixel((first.eye[0], 0.0, first.eye[2]))
    gaze = second.pixel(add(first.eye, scale(6.0, first.forward)))
    halo_line(s, eye, foot, x0, y0, zoom, dash="3 3")
    ex, ey = at(eye)
    s.line(ex, ey, *at(gaze), stroke="#ffffff", width=4.2)
    s.line(ex, ey, *at(gaze), stroke=INK, width=1.8, arrow="end")
    s.circle(ex, ey, 5.5 if not narrow else 4.5, fill=INK, stroke="#ffffff", width=2)

    # Labels, each beside what it names.
    label(s, ex + 12, ey - 8 * zoom, [f"first camera, {EYE_Y:g} m up"], size)
    # The wall's label below its line, on the occluded side, with a leader up to it.
    mx, my = at((wall[0][0] * 0.55 + wall[1][0] * 0.45, wall[0][1] * 0.55 + wall[1][1] * 0.45))
    drop = 26 * zoom
    s.line(mx, my, mx + 10, my + drop - size - 2, stroke=INK, width=1.2)
    label(s, mx + 10, my + drop, ["the nearest wall in front of it,", f"{wall_ahead:.0f} m away: "
                                  "its back is yellow,", "and what it hides is red"], size)
    for (p, q), anchor in zip(edges, ("end", "start")):
        cx, cy = at(q)
        label(s, cx - 8 if anchor == "end" else cx + 8, cy - 10 * zoom, ["frustum's edge"], size, anchor)
    s.lines(x0 if not narrow else 6, y0 + ph * zoom + 16 + size, key + where, size=size - 1,
            fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
