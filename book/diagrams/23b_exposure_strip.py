"""Chapter 23b: the same HDR picture at three exposures, and why the HDR image holds floats.

Drawn from three reviewed test pictures made with the same flags but the
exposure, headless at 320x240 after 10 frames, through the ACES curve:
tests/golden/23_materials_exposure_minus_2.png (--sky uniform --exposure -2),
tests/golden/23_materials_uniform.png (--sky uniform, 0 EV) and
tests/golden/23_materials_exposure_plus_2.png (--sky uniform --exposure 2).
The exposure multiplies the radiance by 2^EV before the curve, so each step
of 2 EV is four times the light. Under each picture, read from it when the
book is built: the sky's corner pixel, and how many pixels have a channel at
255. The row-by-row counts (plastic at the top to gold at the bottom) are not
drawn; the page quotes them under the strip.

Below them, one square of the -2 EV picture (boxed on it), around the bottom
row's second sphere, enlarged: as the chapter makes it, from the float HDR
image, and from book/images/23b_unorm_exposure_minus_2.png, the same command
with the scene pass's output clamped to 0..1 and rounded to 8 bits, as an
R8G8B8A8_UNORM target stores it (book/images/23b_unorm_exposure_minus_2.txt
says how it was made). Under each square, read from the pictures when the book
is built: its brightest pixel and how many pixels of the square have exactly
that colour.

book/23b_hdr.md says where the pixels at 255 go from 0 EV to +2 EV and quotes
the squares' brightest pixels; the phrases it must say are computed here from
the same pictures (quoted()), and the build stops if the page says otherwise.
The page also says that the 8-bit square's flat disc is the same set of pixels
as the pure white disc in tests/golden/23_materials_clamp.png (23b_clamp_aces.py's
square, the same place at 0 EV cut at 1); same_disc() checks that it is.
`python3 23b_exposure_strip.py --numbers` prints them.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three pictures are stacked, 400 units wide, and the two squares sit side by
side under them, enlarged 4 times instead of 6.
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
# The square enlarged under the strip (23b_clamp_aces.py's): the bottom row's second sphere.
LEFT, TOP, CROP_W, CROP_H = 92, 164, 44, 44
SQUARES = [(GOLDEN / "23_materials_exposure_minus_2.png", "float (the chapter's)"),
           (PAGE.parent / "images" / "23b_unorm_exposure_minus_2.png", "8-bit (R8G8B8A8_UNORM)")]


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


def brightest(pixels) -> tuple[tuple[int, int, int], int]:
    """The square's brightest pixel (largest channel sum) and how many pixels share its colour."""
    square = [p for row in pixels[TOP:TOP + CROP_H] for p in row[LEFT:LEFT + CROP_W]]
    top = max(square, key=sum)
    return top, square.count(top)


def squares() -> list[tuple[list, tuple[int, int, int], int]]:
    """Each square's picture, its brightest pixel and how many pixels have that colour."""
    out = []
    for path, _ in SQUARES:
        pixels = read_png(path)
        if len(pixels) != H or len(pixels[0]) != W:
            raise SystemExit(f"{path.name}: {len(pixels[0])}x{len(pixels)}, not {W}x{H}; "
                             "redraw book/diagrams/23b_exposure_strip.py")
        out.append((pixels, *brightest(pixels)))
    return out


def same_disc(flat_pixels, flat) -> int:
    """The 8-bit square's pixels of its brightest colour must be exactly the clamped picture's pure
    white pixels in the same square: both store every channel that reaches 1 as 1. Their count."""
    def where(pixels, colour):
        return {(x, y) for y in range(TOP, TOP + CROP_H) for x in range(LEFT, LEFT + CROP_W)
                if pixels[y][x] == colour}
    grey = where(flat_pixels, flat)
    white = where(read_png(GOLDEN / "23_materials_clamp.png"), (255, 255, 255))
    if grey != white:
        raise SystemExit(f"book/diagrams/23b_exposure_strip.py: the 8-bit square's flat disc ({len(grey)} "
                         f"pixels) is not the clamped picture's white disc ({len(white)} pixels); "
                         "book/23b_hdr.md says they are the same pixels")
    return len(grey)


def quoted() -> dict[str, str]:
    """The phrases book/23b_hdr.md must say, computed here: 0 EV against +2 EV, and the squares."""
    (_, minus), (_, zero), (_, plus) = pictures()
    rows0, rows2 = [sum(r) for r in zero], [sum(r) for r in plus]
    tm, t0, t2 = sum(map(sum, minus)), sum(rows0), sum(rows2)
    (_, lit, _), (flat_pixels, flat, flat_count) = squares()
    disc = same_disc(flat_pixels, flat)
    return {
        f"| ACES, -2 EV | {tm:,} |": "the table's pixels at 255 at -2 EV",
        f"| ACES, 0 EV | {t0:,} |": "the table's pixels at 255 at 0 EV",
        f"| ACES, +2 EV | {t2:,} |": "the table's pixels at 255 at +2 EV",
        f"the count grows {t2 / t0:.1f} times": "the pixels at 255, 0 EV against +2 EV",
        f"from {listed(rows0)} to {listed(rows2)}": "the pixels at 255 row by row",
        f"the brightest pixel {lit}": "the float square's brightest pixel",
        f"{flat_count} pixels of one colour, {flat}": "the 8-bit square's flat disc",
        f"the same {disc} pixels that [the 8-bit square]": "the 8-bit and the clamped discs, one set",
    }


def check_page() -> None:
    """The page's numbers, as this script computes them; a page that disagrees stops the build."""
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    for phrase, what in quoted().items():
        if phrase not in text:
            sys.exit(f"book/23b_hdr.md: {what}: the page should say '{phrase}' "
                     "(book/diagrams/23b_exposure_strip.py computes it from the pictures)")


def main() -> None:
    check_page()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    shown, crops = pictures(), squares()
    zoom = 4 if narrow else 6
    zw, zh = CROP_W * zoom, CROP_H * zoom
    title = ("Chapter 23b: the uniform sky's grid at -2, 0 and +2 EV through the ACES curve, and one "
             "highlight at -2 EV from a float and an 8-bit HDR image")
    description = ("Three test pictures of the sphere grid under the uniform sky, the same but for the "
                   "exposure. At -2 EV (radiance times 1/4) the picture is dark, the sky near black and "
                   "the highlights small. At 0 EV it is the chapter's picture. At +2 EV (times 4) the "
                   "plastic is pale cream, the sky a light blue-grey and the metal rows' highlights "
                   "several times larger, yet every sphere is still shaded: the curve's shoulder rolls "
                   "the bright values off instead of cutting them. Under each picture, its sky pixel and "
                   "how many of its pixels have a channel at 255. Below, "
                   f"the square boxed on the -2 EV picture, {CROP_W} by {CROP_H} pixels around the second "
                   f"sphere of the bottom row, enlarged {zoom} times, twice. Left, from the 16-bit float "
                   "HDR image: both highlights white at the centre and fading into the gold. Right, from "
                   "an image that stores 0 to 1 in 8 bits: every value above 1 was stored as 1, so the "
                   "large highlight is a flat grey disc and the small one a flat grey patch. Under each "
                   "square, its brightest pixel and how many pixels have that colour.")
    size, top, step, under = 13.5, 30, 0, 44
    if narrow:
        width, x0, step = 400, 40, H + 46 + under
        rule = top + 2 * step + H + under + 14
    else:
        gap, x0 = 20, 10
        width = 2 * x0 + 3 * W + 2 * gap
        rule = top + H + under + 14
    zoom_top = rule + (70 if narrow else 58)
    s = Svg(width, zoom_top + zh + (96 if narrow else 58), title, description)
    for i, ((pixels, cells), (_, flag, factor)) in enumerate(zip(shown, COLUMNS)):
        x, y = (x0, top + i * step) if narrow else (x0 + i * (W + gap), top)
        s.text(x + W / 2, y - 10, f"{flag}  ({factor})", size=size + 0.5, anchor="middle", bold=True,
               mono=True)
        enlarged(s, pixels, 0, 0, W, H, x, y, 1)
        if i == 0:
            s.rect(x + LEFT - 1, y + TOP - 1, CROP_W + 2, CROP_H + 2, stroke="#ffffff", width=1.5)
        s.text(x + W / 2, y + H + 20, f"sky {pixels[0][0]}", size=size, anchor="middle", fill=MUTED)
        s.text(x + W / 2, y + H + 40, f"{sum(map(sum, cells))} pixels at 255", size=size, anchor="middle",
               fill=MUTED)

    # The boxed square of the -2 EV picture, from the float image and from an 8-bit one.
    s.line(x0 if not narrow else 10, rule, width - (x0 if not narrow else 10), rule, stroke=MUTED, width=0.8)
    heading = (["The boxed square at -2 EV, enlarged 4 times,", "had the HDR image been float or 8-bit:"]
               if narrow else
               [f"The boxed square of the -2 EV picture, enlarged {zoom} times, had the HDR image been float "
                "or 8-bit:"])
    s.lines(10 if narrow else x0, rule + 22, heading, size=size + 0.5, bold=True, leading=1.25)
    for c, ((pixels, (r, g, b), count), (_, label)) in enumerate(zip(crops, SQUARES)):
        zx = (16 + c * (zw + 16)) if narrow else (x0 + (W - zw) / 2 + c * (W + gap))
        s.text(zx + zw / 2, zoom_top - 8, label.split(" (")[0] if narrow else label, size=size,
               anchor="middle", bold=True)
        enlarged(s, pixels, LEFT, TOP, CROP_W, CROP_H, zx, zoom_top, zoom)
        caption = [f"brightest ({r}, {g}, {b})", f"× {count}"] if narrow else \
            [f"brightest ({r}, {g}, {b}) × {count}"]
        for i, line in enumerate(caption):
            s.text(zx + zw / 2, zoom_top + zh + 18 + 16 * i, line, size=size, anchor="middle", fill=MUTED)
    where = f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the 320x240 picture"
    if narrow:
        s.lines(16, zoom_top + zh + 58, [where + ",", "--sky uniform --exposure -2"], size=size, fill=MUTED)
    else:
        note = ["8-bit: the scene pass's output", "clamped to 0..1 and rounded to",
                "8 bits, as R8G8B8A8_UNORM", "stores it. Every value above 1",
                "became 1, so × 1/4 only turns", "the flat disc grey.", "",
                f"x {LEFT}..{LEFT + CROP_W - 1}, y {TOP}..{TOP + CROP_H - 1} of the",
                "320x240 picture, --sky uniform", "--exposure -2"]
        s.lines(x0 + 2 * (W + gap) + 10, zoom_top + 14, note, size=size, fill=MUTED)
    s.write()


if __name__ == "__main__":
    if sys.argv[1:] == ["--numbers"]:
        for phrase in quoted():
            print(phrase)
    else:
        main()
