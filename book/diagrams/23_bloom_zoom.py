"""Chapter 23d: one highlight with and without bloom, enlarged.

Drawn from two reviewed test pictures, both --sky uniform, headless at
320x240 after 10 frames: tests/golden/23_materials_uniform.png (no bloom)
and tests/golden/23_materials_bloom.png (--bloom 0.3). The same crop of
each, around the smooth gold sphere at the bottom left, whose highlight is
the brightest radiance in the frame; every pixel enlarged 6 times, so that
the halo, a few pixels wide at this size, can be seen.
"""

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP_W, CROP_H, ZOOM = 36, 156, 48, 48, 6
COLUMNS = [("23_materials_uniform.png", "--bloom 0"), ("23_materials_bloom.png", "--bloom 0.3")]
X0, Y0, GAP = 20, 50, 30


def main() -> None:
    w, h = CROP_W * ZOOM, CROP_H * ZOOM
    s = Svg(X0 * 2 + 2 * w + GAP, Y0 + h + 60, "Chapter 23d: a highlight without and with bloom, enlarged 6 times",
            "The same 48 by 48 pixels of two test pictures under the uniform sky, around the smooth gold "
            "sphere at the bottom left of the grid, each pixel enlarged 6 times. Left, without bloom: a "
            "dark sphere with a small white highlight, its edge sharp against the dark blue sky. Right, "
            "with --bloom 0.3: the same highlight wrapped in a warm glow that lights the dark sphere "
            "around it and spills over its edge into the sky.")
    for c, (name, flag) in enumerate(COLUMNS):
        x = X0 + c * (w + GAP)
        s.text(x + w / 2, 30, flag, size=14, anchor="middle", bold=True, mono=True)
        enlarged(s, read_png(GOLDEN / name), LEFT, TOP, CROP_W, CROP_H, x, Y0, ZOOM)
    s.text(X0, Y0 + h + 30, f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 "
           "picture (--sky uniform), each pixel enlarged 6 times", size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
