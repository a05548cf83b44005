"""Chapter 23b: the same HDR picture at three exposures, side by side.

Drawn from three reviewed test pictures made with the same flags but the
exposure, headless at 320x240 after 10 frames, through the ACES curve:
tests/golden/23_materials_exposure_minus_2.png (--sky uniform --exposure -2),
tests/golden/23_materials_uniform.png (--sky uniform, 0 EV) and
tests/golden/23_materials_exposure_plus_2.png (--sky uniform --exposure 2).
The exposure multiplies the radiance by 2^EV before the curve, so each step
of 2 EV is four times the light. Under each picture, read from it when the
book is built: the sky's corner pixel, and how many pixels have a channel at
255, in all and row by row (plastic at the top to gold at the bottom).

book/23b_hdr.md says where those pixels go from 0 EV to +2 EV; the phrases
it must say are computed here from the same pictures (quoted()), and the
build stops if the page says otherwise. `python3 23b_exposure_strip.py
--numbers` prints them.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three pictures are stacked, 400 units wide.
"""

import os
import sys
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, Svg

W, H = 320, 240
COLUMNS = [("23_materials_exposure_minus_2.png", "--exposure -2", "× 1/4"),
           ("23_materials_uniform.png", "--exposure 0", "× 1"),
           ("23_materials_exposure_plus_2.png", "--exposure 2", "× 4")]
ROWS, SPHERE_COLUMNS = 4, 5  # chapters/23_materials/grid.hpp: metallic down, roughness across
PAGE = Path(__file__).resolve().parents[1] / "23b_hdr.md"


def at_255(p) -> bool:
    """A pixel with at least one channel at 255."""
    return 255 in p


def bands(flags: list[bool], count: int, name: str, what: str) -> list[tuple[int, int]]:
    """The runs of True in flags (rows or columns that show a sphere), which must be count."""
    runs, start = [], None
    for i, flag in enumerate(flags + [False]):
        if flag and start is None:
            start = i
        elif not flag and start is not None:
            runs.append((start, i))
            start = None
    if len(runs) != count:
        raise SystemExit(f"tests/golden/{name}: {len(runs)} {what} of spheres, not {count}; "
                         "redraw book/diagrams/23b_exposure_strip.py")
    return runs


def grid_cells(pixels, name: str) -> list[list[int]]:
    """Pixels at 255 in each sphere's cell, [row][column]; a sphere is what differs from the
    sky in the picture's corner."""
    sky = pixels[0][0]
    shows = [[sum(abs(a - b) for a, b in zip(p, sky)) > 6 for p in row] for row in pixels]
    rows = bands([any(row) for row in shows], ROWS, name, "rows")
    columns = bands([any(row[x] for row in shows) for x in range(W)], SPHERE_COLUMNS, name, "columns")
    return [[sum(at_255(p) for row in pixels[y0:y1] for p in row[x0:x1]) for x0, x1 in columns]
            for y0, y1 in rows]


def pictures() -> list[tuple[list, list[list[int]]]]:
    out = []
    for name, _, _ in COLUMNS:
        pixels = read_png(GOLDEN / name)
        if len(pixels) != H or len(pixels[0]) != W:
            raise SystemExit(f"tests/golden/{name}: {len(pixels[0])}x{len(pixels)}, not {W}x{H}; "
                             "redraw book/diagrams/23b_exposure_strip.py")
        out.append((pixels, grid_cells(pixels, name)))
    total = [sum(at_255(p) for row in pixels for p in row) for pixels, _ in out]
    inside = [sum(map(sum, cells)) for _, cells in out]
    if total != inside:  # every pixel at 255 lies on a sphere, none in the sky
        raise SystemExit(f"book/diagrams/23b_exposure_strip.py: {total} pixels at 255, {inside} on the spheres")
    return out


def listed(numbers: list) -> str:
    """'1, 9, 16 and 23'."""
    words = [f"{n:g}" for n in numbers]
    return ", ".join(words[:-1]) + " and " + words[-1]


def quoted() -> dict[str, str]:
    """The phrases book/23b_hdr.md must say about 0 EV against +2 EV, computed here."""
    (_, _), (_, zero), (_, plus) = pictures()
    rows0, rows2 = [sum(r) for r in zero], [sum(r) for r in plus]
    t0, t2 = sum(rows0), sum(rows2)
    return {
        f"from {t0} to {t2}, {t2 / t0:.1f} times": "the pixels at 255 in all",
        f"from {listed(rows0)} to {listed(rows2)}": "the pixels at 255 row by row",
    }


def check_page() -> None:
    """The page's numbers, as this script computes them; a page that disagrees stops the build."""
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    for phrase, what in quoted().items():
        if phrase not in text:
            sys.exit(f"book/23b_hdr.md: {what}: the page should say '{phrase}' "
                     "(book/diagrams/23b_exposure_strip.py computes it from the golden images)")


def main() -> None:
    check_page()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    shown = pictures()
    title = "Chapter 23b: the uniform sky's grid at -2, 0 and +2 EV, through the ACES curve"
    description = ("Three test pictures of the sphere grid under the uniform sky, the same but for the "
                   "exposure. At -2 EV (radiance times 1/4) the picture is dark, the sky near black and "
                   "the highlights small. At 0 EV it is the chapter's picture. At +2 EV (times 4) the "
                   "plastic is pale cream, the sky a light blue-grey and the metal rows' highlights "
                   "several times larger, yet every sphere is still shaded: the curve's shoulder rolls "
                   "the bright values off instead of cutting them. Under each picture, its sky pixel and "
                   "its pixels with a channel at 255, in all and row by row from plastic to gold.")
    size, top, step, under = 13.5, 30, 0, 64
    if narrow:
        width, x0, step = 400, 40, H + 46 + under
        s = Svg(width, top + 2 * step + H + under + 44, title, description)
    else:
        gap, x0 = 20, 10
        width = 2 * x0 + 3 * W + 2 * gap
        s = Svg(width, top + H + under + 26, title, description)
    for i, ((pixels, cells), (_, flag, factor)) in enumerate(zip(shown, COLUMNS)):
        x, y = (x0, top + i * step) if narrow else (x0 + i * (W + gap), top)
        s.text(x + W / 2, y - 10, f"{flag}  ({factor})", size=size + 0.5, anchor="middle", bold=True,
               mono=True)
        enlarged(s, pixels, 0, 0, W, H, x, y, 1)
        rows = [sum(r) for r in cells]
        s.text(x + W / 2, y + H + 20, f"sky {pixels[0][0]}", size=size, anchor="middle", fill=MUTED)
        s.text(x + W / 2, y + H + 40, f"{sum(rows)} pixels at 255, by row:", size=size, anchor="middle",
               fill=MUTED)
        s.text(x + W / 2, y + H + 60, "  ".join(str(n) for n in rows), size=size, anchor="middle",
               fill=MUTED, bold=True)
    foot = top + (2 * step if narrow else 0) + H + under + 16
    key = ["rows, top to bottom: metallic 0 (plastic),", "1/3, 2/3 and 1 (gold)"]
    if narrow:
        s.lines(x0, foot, key, size=size, fill=MUTED)
    else:
        s.text(x0, foot, " ".join(key), size=size, fill=MUTED)
    s.write()


if __name__ == "__main__":
    if sys.argv[1:] == ["--numbers"]:
        for phrase in quoted():
            print(phrase)
    else:
        main()
