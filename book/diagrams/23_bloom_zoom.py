"""Chapter 23d: one highlight with and without bloom, enlarged.

Drawn from two reviewed test pictures, both --sky uniform, headless at
320x240 after 10 frames: tests/golden/23_materials_uniform.png (no bloom)
and tests/golden/23_materials_bloom.png (--bloom 0.3). The same crop of
each, around the smooth gold sphere at the bottom left, whose highlight is
the brightest radiance in the frame; every pixel enlarged 6 times, so that
the halo, a few pixels wide at this size, can be seen.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
crops stand one above the other, 400 units wide, at the same enlargement.
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP_W, CROP_H, ZOOM = 36, 156, 48, 48, 6
COLUMNS = [("23_materials_uniform.png", "--bloom 0"), ("23_materials_bloom.png", "--bloom 0.3")]
X0, Y0, GAP = 20, 50, 30


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    w, h = CROP_W * ZOOM, CROP_H * ZOOM
    title = "Chapter 23d: a highlight without and with bloom, enlarged 6 times"
    description = ("The same 48 by 48 pixels of two test pictures under the uniform sky, around the smooth gold "
                   "sphere at the bottom left of the grid, each pixel enlarged 6 times. " +
                   ("Top" if narrow else "Left") + ", without bloom: a dark sphere with a small white highlight, "
                   "its edge sharp against the dark blue sky. " + ("Bottom" if narrow else "Right") +
                   ", with --bloom 0.3: the same highlight wrapped in a warm glow that lights the dark sphere "
                   "around it and spills over its edge into the sky.")
    where = f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 picture"
    if narrow:
        width, x = 400, (400 - w) / 2
        s = Svg(width, 2 * (h + 40) + 40, title, description)
        for c, (name, flag) in enumerate(COLUMNS):
            y = 30 + c * (h + 40)
            s.text(width / 2, y - 8, flag, size=14, anchor="middle", bold=True, mono=True)
            enlarged(s, read_png(GOLDEN / name), LEFT, TOP, CROP_W, CROP_H, x, y, ZOOM)
        y = 30 + 2 * (h + 40) - 14
        s.text(x, y, where + ",", size=12, fill=MUTED)
        s.text(x, y + 17, "--sky uniform, each pixel enlarged 6 times", size=12, fill=MUTED)
        s.write()
        return
    s = Svg(X0 * 2 + 2 * w + GAP, Y0 + h + 60, title, description)
    for c, (name, flag) in enumerate(COLUMNS):
        x = X0 + c * (w + GAP)
        s.text(x + w / 2, 30, flag, size=14, anchor="middle", bold=True, mono=True)
        enlarged(s, read_png(GOLDEN / name), LEFT, TOP, CROP_W, CROP_H, x, Y0, ZOOM)
    s.text(X0, Y0 + h + 30, where + " (--sky uniform), each pixel enlarged 6 times", size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
