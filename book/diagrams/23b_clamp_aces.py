"""Chapter 23b: the same picture cut at 1 and through the ACES curve, whole and one highlight enlarged.

Drawn from two reviewed test pictures made with the same flags but the curve,
headless at 320x240 after 10 frames: tests/golden/23_materials_clamp.png
(--sky uniform --tone-map clamp) and tests/golden/23_materials_uniform.png
(--sky uniform, ACES by default). Each is shown whole, a picture pixel to a
unit, and under it the same square of it enlarged (nearest neighbour, through
golden.enlarged): around the bottom row's second sphere (metal, roughness
0.325), whose two highlights show the difference most clearly: cut at 1, a
flat white disc with a hard edge, ringed in yellow; through ACES, a white
centre that fades out. The square is boxed on the whole picture. Over each
picture and under each square, read from the pictures when the book is built,
how many pixels have a channel at 255; book/23b_hdr.md quotes all four counts in its table
and the clamped disc's pure white pixels, and the build stops if the page says
otherwise (quoted()).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
whole pictures are stacked, 400 units wide, and the two squares sit side by
side under them, enlarged 4 times instead of 7.
"""

import os
import sys
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

W, H = 320, 240
LEFT, TOP, CROP_W, CROP_H = 92, 164, 44, 44  # the square, in the 320x240 picture
COLUMNS = [("23_materials_clamp.png", "--tone-map clamp", "cut at 1"),
           ("23_materials_uniform.png", "--tone-map aces", "the default")]
PAGE = Path(__file__).resolve().parents[1] / "23b_hdr.md"
BOX = "#ffffff"


def saturated(pixels, left=0, top=0, width=W, height=H) -> int:
    """Pixels (of the picture, or of a crop of it) with at least one channel at 255."""
    return sum(255 in p for row in pixels[top:top + height] for p in row[left:left + width])


def pictures() -> list:
    out = []
    for name, _, _ in COLUMNS:
        pixels = read_png(GOLDEN / name)
        if len(pixels) != H or len(pixels[0]) != W:
            raise SystemExit(f"tests/golden/{name}: {len(pixels[0])}x{len(pixels)}, not {W}x{H}; "
                             "redraw book/diagrams/23b_clamp_aces.py")
        out.append(pixels)
    return out


def white(pixels) -> int:
    """Pixels of the square that are pure white, (255, 255, 255)."""
    return sum(p == (255, 255, 255) for row in pixels[TOP:TOP + CROP_H] for p in row[LEFT:LEFT + CROP_W])


def quoted(whole: list[int], square: list[int], disc: int) -> dict[str, str]:
    """The phrases book/23b_hdr.md must say, computed here."""
    clamp, aces = whole
    clamp_sq, aces_sq = square
    return {f"a flat disc of {disc} pixels of pure white": "the clamped highlight's flat disc",
            f"| ACES, 0 EV | {aces:,} |": "the table's pixels at 255 through ACES",
            f"| Clamp, 0 EV | {clamp:,} |": "the table's pixels at 255 cut at 1",
            f"| ACES, 0 EV, the boxed square | {aces_sq:,} |": "the table's square through ACES",
            f"| Clamp, 0 EV, the boxed square | {clamp_sq:,} |": "the table's square cut at 1"}


def check_page(whole: list[int], square: list[int], disc: int) -> None:
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    for phrase, what in quoted(whole, square, disc).items():
        if phrase not in text:
            sys.exit(f"book/23b_hdr.md: {what}: the page should say '{phrase}' "
                     "(book/diagrams/23b_clamp_aces.py counts them in the golden images)")


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    shown = pictures()
    whole = [saturated(p) for p in shown]
    square = [saturated(p, LEFT, TOP, CROP_W, CROP_H) for p in shown]
    check_page(whole, square, white(shown[0]))
    zoom = 4 if narrow else 7
    zw, zh = CROP_W * zoom, CROP_H * zoom
    title = ("Chapter 23b: the uniform sky's grid cut at 1 and through the ACES curve, "
             "and one highlight enlarged")
    description = (f"Two test pictures of the sphere grid under the uniform sky at exposure 0, the same "
                   f"size, and under them the same {CROP_W} by {CROP_H} pixel square of each, around the "
                   f"second sphere of the bottom row (metal, fairly smooth), enlarged {zoom} times. Cut at 1 "
                   "(left, above on a phone): the plastic a strong yellow-orange, the highlights larger flat "
                   "yellow-white blots, the rough gold at the bottom right darker, the sky a greyer blue; "
                   "enlarged, the large highlight is a flat white disc with a hard edge, ringed in yellow. "
                   "Through ACES (right, below): pale cream plastic, small white highlights, a dark blue "
                   "sky; enlarged, both highlights are white at the centre and fade smoothly into the gold. "
                   "Over each picture and under each square, how many pixels have a channel at 255.")
    size, top = 13.5, 46  # two lines above each picture: its flags and its count
    if narrow:
        x0, step = 40, top + H + 24
        zoom_top = 2 * step + 12
        height = zoom_top + zh + 66
        width = 400
    else:
        x0, gap = 10, 30
        zoom_top = top + H + 50
        height = zoom_top + zh + 64
        width = 2 * x0 + 2 * W + gap
    s = Svg(width, height, title, description)
    for i, (pixels, (_, flag, note), count, count_sq) in enumerate(zip(shown, COLUMNS, whole, square)):
        x, y = (x0, top + i * step) if narrow else (x0 + i * (W + gap), top)
        s.text(x + W / 2, y - 26, f"{flag} ({note})", size=size + 0.5, anchor="middle", bold=True, mono=True)
        s.text(x + W / 2, y - 8, f"{count:,} pixels at 255", size=size, anchor="middle", fill=MUTED)
        enlarged(s, pixels, 0, 0, W, H, x, y, 1)
        s.rect(x + LEFT - 1, y + TOP - 1, CROP_W + 2, CROP_H + 2, stroke=BOX, width=1.5)
        if narrow:
            zx, label = 16 + i * (zw + 16), flag
        else:
            zx, label = x + (W - zw) / 2, None
            # From the box on the picture to its enlargement below.
            s.line(x + LEFT - 1, y + TOP + CROP_H + 1, zx, zoom_top, stroke=MUTED, width=1, dash="4 3")
            s.line(x + LEFT + CROP_W + 1, y + TOP + CROP_H + 1, zx + zw, zoom_top, stroke=MUTED, width=1,
                   dash="4 3")
        if label:
            s.text(zx + zw / 2, zoom_top - 10, label, size=size, anchor="middle", bold=True, mono=True)
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, zx, zoom_top, zoom)
        under = f"{count_sq} pixels at 255" if narrow else f"{count_sq} pixels of the square at 255"
        s.text(zx + zw / 2, zoom_top + zh + 20, under, size=size, anchor="middle", fill=MUTED)
    where = f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1}"
    if narrow:
        s.lines(16, zoom_top + zh + 42, [f"the boxed square, enlarged {zoom} times:", where + " of each picture"],
                size=size, fill=MUTED)
    else:
        s.text(width / 2, zoom_top + zh + 46, f"the boxed square, {where}, enlarged {zoom} times", size=size,
               anchor="middle", fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
