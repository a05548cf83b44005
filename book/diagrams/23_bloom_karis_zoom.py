"""Chapter 23d: the smooth gold sphere's two highlights, bloomed with the plain mean and with Karis's average.

Drawn from two reviewed test pictures, both --sky uniform --bloom 0.3, headless at
320x240 after 10 frames: tests/golden/23_materials_bloom.png (the first halving a
plain mean, --bloom-average box) and tests/golden/23_materials_bloom_karis.png
(--bloom-average karis). The same 36 by 32 pixels of each, around the two
highlights of the smooth gold sphere at the bottom left; every pixel enlarged 5
times, so that the square the plain mean makes of the small highlight can be seen.
"""

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

LEFT, TOP, CROP_W, CROP_H, ZOOM = 48, 166, 36, 32, 5
COLUMNS = [("23_materials_bloom.png", "box (the mean)"), ("23_materials_bloom_karis.png", "karis")]
X0, Y0, GAP = 10, 50, 20


def main() -> None:
    w, h = CROP_W * ZOOM, CROP_H * ZOOM
    s = Svg(X0 * 2 + 2 * w + GAP, Y0 + h + 62,
            "Chapter 23d: two highlights bloomed with the plain mean and with Karis's average",
            "The same 36 by 32 pixels of two test pictures with --bloom 0.3 under the uniform sky, "
            "around the two highlights of the smooth gold sphere at the bottom left, each pixel "
            "enlarged 5 times. Left, the first halving a plain mean: the large highlight sits in a "
            "wide bright glow and the small one, a few pixels, in a bright square of glow. Right, "
            "Karis's average: both highlights keep only a faint glow, and the square is gone.")
    for c, (name, label) in enumerate(COLUMNS):
        x = X0 + c * (w + GAP)
        s.text(x + w / 2, 22, "--bloom-average", size=13.5, anchor="middle", mono=True, fill=MUTED)
        s.text(x + w / 2, 40, label, size=15, anchor="middle", bold=True, mono=True)
        enlarged(s, read_png(GOLDEN / name), LEFT, TOP, CROP_W, CROP_H, x, Y0, ZOOM)
    s.text(X0, Y0 + h + 26, f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the "
           "320x240 picture,", size=13.5, fill=MUTED)
    s.text(X0, Y0 + h + 46, "--bloom 0.3, each pixel enlarged 5 times", size=13.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
