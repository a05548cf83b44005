"""Chapter 23b: the same HDR picture at three exposures, side by side.

Drawn from three reviewed test pictures made with the same flags but the
exposure, headless at 320x240 after 10 frames, through the ACES curve:
tests/golden/23_materials_exposure_minus_2.png (--sky uniform --exposure -2),
tests/golden/23_materials_uniform.png (--sky uniform, 0 EV) and
tests/golden/23_materials_exposure_plus_2.png (--sky uniform --exposure 2).
The exposure multiplies the radiance by 2^EV before the curve, so each step
of 2 EV is four times the light. Under each picture, read from it when the
book is built: the sky's corner pixel and how many pixels have a channel at
255.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three pictures are stacked, 400 units wide.
"""

import os

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

W, H = 320, 240
COLUMNS = [("23_materials_exposure_minus_2.png", "--exposure -2", "× 1/4"),
           ("23_materials_uniform.png", "--exposure 0", "× 1"),
           ("23_materials_exposure_plus_2.png", "--exposure 2", "× 4")]


def saturated(pixels) -> int:
    """Pixels with at least one channel at 255."""
    return sum(255 in p for row in pixels for p in row)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    pictures = [(read_png(GOLDEN / name), flag, factor) for name, flag, factor in COLUMNS]
    for (pixels, flag, _), (name, _, _) in zip(pictures, COLUMNS):
        if len(pixels) != H or len(pixels[0]) != W:
            raise SystemExit(f"tests/golden/{name}: {len(pixels[0])}x{len(pixels)}, not {W}x{H}; "
                             "redraw book/diagrams/23b_exposure_strip.py")
    title = "Chapter 23b: the uniform sky's grid at -2, 0 and +2 EV, through the ACES curve"
    description = ("Three test pictures of the sphere grid under the uniform sky, the same but for the "
                   "exposure. At -2 EV (radiance times 1/4) the picture is dark, the sky near black and "
                   "the highlights small. At 0 EV it is the chapter's picture. At +2 EV (times 4) the "
                   "plastic is pale cream, the sky a light blue-grey and the highlights larger, yet "
                   "still shaded: the curve's shoulder rolls the bright values off instead of cutting "
                   "them.")
    size, top, step = 13.5, 30, 0
    if narrow:
        width, x0, step = 400, 40, H + 84
        s = Svg(width, top + 2 * step + H + 34, title, description)
    else:
        gap, x0 = 20, 10
        width = 2 * x0 + 3 * W + 2 * gap
        s = Svg(width, top + H + 34, title, description)
    for i, (pixels, flag, factor) in enumerate(pictures):
        x, y = (x0, top + i * step) if narrow else (x0 + i * (W + gap), top)
        s.text(x + W / 2, y - 10, f"{flag}  ({factor})", size=size + 0.5, anchor="middle", bold=True,
               mono=True)
        enlarged(s, pixels, 0, 0, W, H, x, y, 1)
        sky = pixels[0][0]
        s.text(x + W / 2, y + H + 20, f"sky {sky}, {saturated(pixels)} pixels at 255", size=size,
               anchor="middle", fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
