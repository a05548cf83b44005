"""Chapter 23e: the five maps switched on in turn.

Drawn from five reviewed test pictures of one cube with TANGENT, headless at
320x240 after 10 frames under the uniform sky: the cube written by
scripts/make_pbr_cubes.py --maps N with only the first N maps (base colour,
metallic-roughness, normal, occlusion, emissive), tests/golden/
23_materials_maps_*.png for N = 1 to 4 and 23_materials_cube.png for all
five. The same 144 x 144 pixels of each (the cube), enlarged twice, in a row,
and under each but the first what changed since the step before: the absolute
difference per channel, times 16.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) each step
is a row, the picture and its change side by side, 400 units wide.
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP = 92, 50, 144  # the cube in the 320x240 picture
GAIN = 16  # the differences, brightened to be seen
STEPS = [("23_materials_maps_1_base.png", "1. base colour"),
         ("23_materials_maps_2_metal_rough.png", "2. + metallic-roughness"),
         ("23_materials_maps_3_normal.png", "3. + normal"),
         ("23_materials_maps_4_occlusion.png", "4. + occlusion"),
         ("23_materials_cube.png", "5. + emissive (all five)")]


def difference(a, b):
    """|a - b| per channel, times GAIN, of two crops: what one step changed."""
    return [[tuple(min(255, abs(p - q) * GAIN) for p, q in zip(x, y)) for x, y in zip(ra, rb)]
            for ra, rb in zip(a, b)]


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    crops = [[row[LEFT:LEFT + CROP] for row in read_png(GOLDEN / name)[TOP:TOP + CROP]]
             for name, _ in STEPS]
    changes = [None] + [difference(crops[i], crops[i - 1]) for i in range(1, len(crops))]
    title = "Chapter 23e: the cube's five maps switched on one at a time"
    description = (
        "Five pictures of the same cube of studs under the uniform sky, each with one more of "
        "glTF's maps, and under each what changed since the one before, the difference times "
        f"{GAIN}. 1, base colour only: a red and cream checker, bright on top and dark in front, "
        "since without a metallic-roughness map glTF makes the surface rough metal. 2, with "
        "metallic-roughness: the checker becomes a bright dielectric on every face and the studs "
        "flat discs of dark polished metal; almost everything changes. 3, with the normal map: the "
        "discs become round raised studs; the change is a bright and a dark edge on each. 4, with "
        "occlusion: a faint darker rim at each stud's foot; the change is a thin ring per stud. 5, "
        "with emissive: a yellow glowing ring in the middle of each face; only the rings change.")
    where = f"x {LEFT}..{LEFT + CROP - 1}, y {TOP}..{TOP + CROP - 1} of each 320x240 picture"
    if narrow:
        zoom, margin, gap, size = 1.25, 14, 12, 12.5
        cell = CROP * zoom
        pitch = cell + 30
        s = Svg(400, 40 + len(STEPS) * pitch + 44, title, description)
        s.text(margin + cell + gap, 26, f"what changed, \u00d7{GAIN}", size=size, fill=MUTED)
        for i, (_, label) in enumerate(STEPS):
            y = 40 + i * pitch + 20
            s.text(margin, y - 7, label, size=size, bold=True)
            enlarged(s, crops[i], 0, 0, CROP, CROP, margin, y, zoom)
            if changes[i]:
                enlarged(s, changes[i], 0, 0, CROP, CROP, margin + cell + gap, y, zoom)
        y = 40 + len(STEPS) * pitch + 10
        s.lines(margin, y, [where + ",", "--sky uniform, enlarged 1.25 times"], size=12, fill=MUTED)
        s.write()
        return
    zoom, margin, gap, size = 2, 20, 20, 20
    cell = CROP * zoom
    s = Svg(2 * margin + len(STEPS) * cell + (len(STEPS) - 1) * gap, 56 + 2 * cell + gap + 50, title,
            description)
    for i, (_, label) in enumerate(STEPS):
        x = margin + i * (cell + gap)
        s.text(x, 40, label, size=size, bold=True)
        enlarged(s, crops[i], 0, 0, CROP, CROP, x, 56, zoom)
        if changes[i]:
            enlarged(s, changes[i], 0, 0, CROP, CROP, x, 56 + cell + gap, zoom)
    s.lines(margin, 56 + cell + gap + 40, ["Below each step:", "what changed since", "the step before,",
                                           f"the difference \u00d7{GAIN}"], size=size, fill=MUTED)
    s.text(margin, 56 + 2 * cell + gap + 36, where + " (--sky uniform), each pixel enlarged twice",
           size=20, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
