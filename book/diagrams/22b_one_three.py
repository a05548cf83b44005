"""Chapter 22b: one cascade against three, the front of the scene enlarged.

Drawn from the chapter's two reviewed test pictures, headless at 320x240 after
10 frames: tests/golden/22_shadows_one_cascade.png (the default, one cascade) and
tests/golden/22_shadows.png (--cascades 3). The same crop of
each, the left front pillar's foot, the sphere, the torus and the start of the
right front pillar's shadow, is enlarged (nearest neighbour, through
golden.enlarged), so the figure always shows what the tests check: with one
map, the shadows' stepped edges and the grey blocks on the sphere's and the
torus's lit sides; with three, smooth edges and clean lit sides.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
crops are stacked, 400 units wide, instead of side by side.
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg, wrap

LEFT, TOP, CROP_W, CROP_H = 0, 106, 232, 108  # the crop, in the 320x240 pictures
COLUMNS = [("22_shadows_one_cascade.png", "One cascade: the default",
            "Stepped shadow edges under the sphere and beside the pillar; grey blocks on the "
            "sphere's and the torus's lit sides."),
           ("22_shadows.png", "Three cascades: --cascades 3",
            "The same shadows with smooth edges; the sphere and the torus clean on their lit sides.")]
TITLE = "Chapter 22b: the front of the scene with one cascade and with three, enlarged"
DESCRIPTION = ("The same crop of the chapter's two test pictures at 320x240, pixels 0 to 231 across and "
               "106 to 213 down: the left front pillar's foot, the blue sphere, the green torus and "
               "the start of the right front pillar's shadow. With one cascade the sphere's shadow and "
               "the pillar's have stepped edges, and the sphere and the torus carry blocky grey "
               "patches on their lit sides; with three cascades the shadows' edges are smooth and the "
               "lit sides clean.")
WHERE = f"pixels x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 picture"


def wide(pictures) -> Svg:
    zoom, gap, x0 = 1.6, 20, 16  # about 800 units: a wide column shows it at its own size
    s = Svg(x0 * 2 + 2 * CROP_W * zoom + gap, 100, TITLE, DESCRIPTION)
    y, most = 56, 1
    for c, (pixels, (_, title, note)) in enumerate(zip(pictures, COLUMNS)):
        x = x0 + c * (CROP_W * zoom + gap)
        s.text(x, 28, title, size=14, bold=True)
        s.text(x, 46, WHERE, size=12, fill=MUTED)
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, x, y, zoom)
        lines = wrap(note, CROP_W * zoom, 13)
        s.lines(x, y + CROP_H * zoom + 22, lines, size=13)
        most = max(most, len(lines))
    s.height = y + CROP_H * zoom + 22 + (most - 1) * 13 * 1.3 + 10
    return s


def narrow(pictures) -> Svg:
    x, width = 20, 360
    zoom = width / CROP_W
    s = Svg(400, 100, TITLE, DESCRIPTION.replace("With one cascade", "Above, one cascade:")
            .replace("with three cascades", "below, three cascades:"))
    y = 26
    for pixels, (_, title, note) in zip(pictures, COLUMNS):
        s.text(x, y, title, size=14, bold=True)
        s.text(x, y + 18, WHERE, size=12, fill=MUTED)
        y += 28
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, x, y, zoom)
        y += CROP_H * zoom + 20
        lines = wrap(note, width, 13)
        s.lines(x, y, lines, size=13)
        y += len(lines) * 13 * 1.3 + 24
    s.height = y - 20
    return s


def main() -> None:
    pictures = [read_png(GOLDEN / name) for name, _, _ in COLUMNS]
    s = narrow(pictures) if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide(pictures)
    s.write()


if __name__ == "__main__":
    main()
