"""Chapter 23b: the same picture through the ACES curve and cut at 1, at one size.

Drawn from two reviewed test pictures made with the same flags but the curve,
headless at 320x240 after 10 frames: tests/golden/23_materials_uniform.png
(--sky uniform, ACES by default) and tests/golden/23_materials_clamp.png
(--sky uniform --tone-map clamp), each shown whole and at the same size, a
picture pixel to a unit. Under each, read from it when the book is built, how
many pixels have a channel at 255; book/23b_hdr.md quotes both counts, and the
build stops if the page says otherwise (quoted()).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
pictures are stacked, 400 units wide, each still 320 units wide.
"""

import os
import sys
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

W, H = 320, 240
COLUMNS = [("23_materials_uniform.png", "--tone-map aces", "(the default)"),
           ("23_materials_clamp.png", "--tone-map clamp", "(cut at 1)")]
PAGE = Path(__file__).resolve().parents[1] / "23b_hdr.md"


def saturated(pixels) -> int:
    """Pixels with at least one channel at 255."""
    return sum(255 in p for row in pixels for p in row)


def pictures() -> list:
    out = []
    for name, _, _ in COLUMNS:
        pixels = read_png(GOLDEN / name)
        if len(pixels) != H or len(pixels[0]) != W:
            raise SystemExit(f"tests/golden/{name}: {len(pixels[0])}x{len(pixels)}, not {W}x{H}; "
                             "redraw book/diagrams/23b_clamp_aces.py")
        out.append(pixels)
    return out


def quoted(counts: list[int]) -> dict[str, str]:
    """The phrase book/23b_hdr.md must say, computed here."""
    aces, clamp = counts
    return {f"{clamp:,} pixels have a channel at 255 with clamp, against {aces:,} with ACES":
            "the pixels at 255 through each curve"}


def check_page(counts: list[int]) -> None:
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    for phrase, what in quoted(counts).items():
        if phrase not in text:
            sys.exit(f"book/23b_hdr.md: {what}: the page should say '{phrase}' "
                     "(book/diagrams/23b_clamp_aces.py counts them in the golden images)")


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    shown = pictures()
    counts = [saturated(p) for p in shown]
    check_page(counts)
    title = "Chapter 23b: the uniform sky's grid through the ACES curve and cut at 1"
    description = ("Two test pictures of the sphere grid under the uniform sky at exposure 0, the same "
                   "size. Left (above on a phone), through ACES: pale cream plastic at the top, gold at "
                   "the bottom, small white highlights, a dark blue sky. Right (below), cut at 1: the "
                   "plastic a stronger yellow-orange, the highlights larger flat yellow-white blots, the "
                   "rough gold at the bottom right darker, the sky a greyer blue. Under each, how many "
                   "pixels have a channel at 255.")
    size, top, under = 13.5, 30, 30
    if narrow:
        width, x0, step = 400, 40, top + H + under
        s = Svg(width, step + top + H + under, title, description)
    else:
        gap, x0 = 30, 10
        width, step = 2 * x0 + 2 * W + gap, 0
        s = Svg(width, top + H + under, title, description)
    for i, (pixels, (_, flag, note), count) in enumerate(zip(shown, COLUMNS, counts)):
        x, y = (x0, top + i * step) if narrow else (x0 + i * (W + gap), top)
        s.text(x + W / 2, y - 10, f"{flag} {note}", size=size + 0.5, anchor="middle", bold=True, mono=True)
        enlarged(s, pixels, 0, 0, W, H, x, y, 1)
        s.text(x + W / 2, y + H + 20, f"{count:,} pixels at 255", size=size, anchor="middle", fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
