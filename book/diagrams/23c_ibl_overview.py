"""Chapter 23c at a glance: the sky cube made at start-up, the three images
the split sum computes from it (irradiance, prefiltered specular, the BRDF
table) and the three reads a pixel makes of them.

The sizes, level counts, sample counts and the format are read from
chapters/23_materials/environment.hpp (book/source_constants.py), and the
script checks that environment.hpp still gives level 0 of the prefiltered
cube one sample and that scene_ibl.frag still reads the three images as
drawn, so the figure cannot drift from the code.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three stages are drawn one above the other, 340 units wide; each
layout is drawn at about the width it is shown, so its type reads at that size.
"""

import os
import re
import sys
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, PURPLE_FILL, Svg, text_width)

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ROOT = Path(__file__).resolve().parents[2]
ENVIRONMENT_HPP = ROOT / "chapters" / "23_materials" / "environment.hpp"
SCENE_IBL = ROOT / "shaders" / "23_materials" / "scene_ibl.frag"


def number(name: str) -> int:
    return int(constant(ENVIRONMENT_HPP, name))


SKY, SKY_LEVELS = number("sky_size"), number("sky_levels")
IRR, IRR_SAMPLES = number("irradiance_size"), number("irradiance_samples")
SPEC, SPEC_LEVELS, SPEC_SAMPLES = number("specular_size"), number("specular_levels"), number("specular_samples")
LUT, LUT_SAMPLES = number("lut_size"), number("lut_samples")

# The three reads, as scene_ibl.frag says them (whitespace folded).
READS = [
    "vec2 ab = texture(brdf_lut, vec2(n_dot_v, m.roughness)).rg;",
    "vec3 specular_share = f0_of(m) * ab.x + ab.y;",
    "texture(irradiance_map, n).rgb * diffuse_of(m) * (1.0 - specular_share);",
    "float level = m.roughness * float(textureQueryLevels(specular_map) - 1);",
    "textureLod(specular_map, reflect(-v, n), level).rgb * specular_share;",
]

# The prefilter's sample count: one for level 0, the mirror, whose half vectors are all n.
MIRROR_SAMPLES = "push.samples = level == 0 ? 1 : specular_samples;"


def check_sources() -> str:
    """The image format's name (environment.hpp); exits if scene_ibl.frag no longer reads as drawn."""
    code = " ".join(SCENE_IBL.read_text(encoding="utf-8").split())
    for want in READS:
        if want not in code:
            raise SystemExit(f"shaders/23_materials/scene_ibl.frag: no longer says `{want[:60]}`; "
                             "redraw book/diagrams/23c_ibl_overview.py")
    env = " ".join(ENVIRONMENT_HPP.read_text(encoding="utf-8").split())
    if MIRROR_SAMPLES not in env:
        raise SystemExit(f"chapters/23_materials/environment.hpp: no longer says `{MIRROR_SAMPLES}`; "
                         "redraw book/diagrams/23c_ibl_overview.py")
    found = re.search(r"VkFormat format = VK_FORMAT_([A-Z0-9_]+);", ENVIRONMENT_HPP.read_text(encoding="utf-8"))
    if not found:
        raise SystemExit("chapters/23_materials/environment.hpp: no `VkFormat format = VK_FORMAT_...;`; "
                         "redraw book/diagrams/23c_ibl_overview.py")
    return found.group(1)


def sizes(top: int, levels: int) -> str:
    return f"{top}, {top >> 1}, .. {top >> (levels - 1)}"


def main() -> None:
    fmt = check_sources()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    # The wide layout is drawn at about the size it is shown in a page (some 800 px),
    # the narrow one at about a phone's column (some 350 px), so the type below is
    # about the size a reader sees.
    size = 12.5 if narrow else 14
    head_size = size + 1.5
    lead = size * 1.35
    steps = [round(k / (SPEC_LEVELS - 1), 2) for k in range(SPEC_LEVELS)]
    width = 340 if narrow else 800
    s = Svg(width, 100, "Chapter 23c: the sky, the three images made from it, three reads a pixel",
            f"Once, at start-up, in compute: sky.comp makes a sky cube of {SKY} by {SKY} texels a face, "
            f"and downsample.comp its {SKY_LEVELS} mip levels. From it irradiance.comp makes the irradiance "
            f"cube, {IRR} by {IRR} a face, one level, {IRR_SAMPLES} samples a texel, and prefilter.comp the "
            f"prefiltered specular cube, {SPEC} by {SPEC} a face, {SPEC_LEVELS} levels, one per roughness "
            f"step from 0 to 1, {SPEC_SAMPLES} samples a texel but 1 at level 0, a mirror. brdf_lut.comp makes the BRDF table, {LUT} by {LUT}, from no sky at all. "
            f"All are {fmt}. Every pixel of scene_ibl.frag then reads the table at (n·v, roughness) for "
            "A and B, S = F0 A + B; the irradiance at n, times the diffuse colour and 1 − S; and the "
            "prefiltered cube in the mirror direction at level roughness × "
            f"{SPEC_LEVELS - 1}, times S; the sum is the ambient light.")

    def fits(label, w, bold=False):
        """Stops the build if a line would run out of its room."""
        if text_width(label, size, bold) > w:
            raise SystemExit(f"book/diagrams/23c_ibl_overview.py: `{label}` is wider than {w:.0f}")

    def card(x, y, w, head, lines, fill, stroke):
        """A box: a bold heading, then lines (`code` in monospace); its bottom."""
        h = (len(lines) + 1) * lead + 10
        s.rect(x, y, w, h, fill=fill, stroke=stroke, rx=6, width=1.3)
        ty = y + 5 + size
        bold = not head.startswith("`")
        fits(head, w - 18, bold)
        s.text(x + 9, ty, head, size=size, bold=bold)
        for line in lines:
            ty += lead
            fits(line, w - 18)
            s.text(x + 9, ty, line, size=size, fill=INK)
        return y + h

    def header(x, y, label, colour):
        if text_width(label, head_size, True) > width - x - 8:
            raise SystemExit(f"book/diagrams/23c_ibl_overview.py: `{label}` is too wide")
        s.text(x, y, label, size=head_size, bold=True, fill=colour)

    sky_lines = [f"{SKY} × {SKY} a face, 6 faces", f"{SKY_LEVELS} levels: {sizes(SKY, SKY_LEVELS)}",
                 "`sky.comp`: level 0, its formula", "`downsample.comp`: each next level"]
    irr_lines = [f"{IRR} × {IRR} a face, 1 level", f"{IRR_SAMPLES} cosine samples a texel",
                 "cosine-weighted mean over n's hemisphere"]
    spec_lines = [f"{SPEC} × {SPEC} a face, {SPEC_LEVELS} levels: {sizes(SPEC, SPEC_LEVELS)}",
                  "roughness " + ", ".join(f"{r:g}" for r in steps),
                  f"{SPEC_SAMPLES} samples a texel at levels 1 to {SPEC_LEVELS - 1};",
                  "level 0, a mirror: 1 sample a texel"]
    lut_lines = [f"{LUT} × {LUT}, 2D, 1 level: (A, B)", "at (n·v, roughness)",
                 f"{LUT_SAMPLES} samples; reads no sky"]
    # Each image beside the read a pixel makes of it.
    rows = [
        ("irradiance cube (`irradiance.comp`)", irr_lines, BLUE_FILL, BLUE,
         "`texture(irradiance_map, n)`", ["× diffuse colour × (1 − S)"]),
        ("prefiltered specular cube (`prefilter.comp`)", spec_lines, PURPLE_FILL, PURPLE,
         "`textureLod(specular_map, r, level)`",
         [f"r = reflect(−v, n), level = roughness × {SPEC_LEVELS - 1}", "× S"]),
        ("BRDF table (`brdf_lut.comp`)", lut_lines, GREY_FILL, GREY,
         "`texture(brdf_lut, (n·v, roughness))`", ["gives A, B: S = F0 A + B"]),
    ]
    sum_lines = ["ambient = irradiance × diffuse × (1 − S)", "+ prefiltered × S"]
    once_first, once_rest = "Once, at start-up, in compute:", f"all {fmt}"
    head_pixel = "Every pixel: three reads"

    if not narrow:
        lx, rx, w = 16, 424, 360
        header(lx, 26, f"{once_first} {once_rest}", ORANGE)
        sky_bottom = card(lx, 40, w, "sky cube", sky_lines, ORANGE_FILL, ORANGE)
        note = ["`irradiance.comp` and `prefilter.comp`", "read the sky; `brdf_lut.comp` reads",
                "nothing: the table fits any sky."]
        for i, line in enumerate(note):
            fits(line, width - rx - 10)
            s.text(rx, 40 + size + 8 + i * lead, line, size=size, fill=MUTED)
        s.line(lx + w / 2, sky_bottom, lx + w / 2, sky_bottom + 26, stroke=ORANGE, width=1.3, arrow="end")
        y = sky_bottom + 30
        header(rx, y + 4, head_pixel, GREEN)
        y += 16
        read_bottom = y
        for head, lines, fill, stroke, call, use in rows:
            bottom = card(lx, y, w, head, lines, fill, stroke)
            mid = (y + bottom) / 2
            read_h = (len(use) + 1) * lead + 10
            read_top = max(mid - read_h / 2, read_bottom + 10)
            read_bottom = card(rx, read_top, w, call, use, GREEN_FILL, GREEN)
            s.line(lx + w, (read_top + read_bottom) / 2, rx - 2, (read_top + read_bottom) / 2,
                   stroke=stroke, width=1.5, arrow="end")
            y = bottom + 14
        s.line(rx + w / 2, read_bottom, rx + w / 2, read_bottom + 20, stroke=GREEN, width=1.3, arrow="end")
        s.text(rx + w / 2 + 8, read_bottom + 15, "the three, summed", size=size, fill=MUTED)
        sum_top = read_bottom + 22
        for line in sum_lines:
            fits(line, w - 16)
        s.box(rx, sum_top, w, 2 * lead + 10, sum_lines, fill=GREEN_FILL, stroke=GREEN, size=size)
        s.height = max(y, sum_top + 2 * lead + 10) + 12
    else:
        x, w = 8, width - 16
        y = 20
        header(x, y, once_first, ORANGE)
        y += head_size * 1.3
        header(x, y, once_rest, ORANGE)
        y = card(x, y + 10, w, "sky cube", sky_lines, ORANGE_FILL, ORANGE)
        s.line(x + 30, y, x + 30, y + 18, stroke=ORANGE, width=1.3, arrow="end")
        fits("read by the two cubes' shaders", w - 48)
        s.text(x + 40, y + 14, "read by the two cubes' shaders", size=size, fill=MUTED)
        y += 20
        for head, lines, fill, stroke, _, _ in rows:
            y = card(x, y, w, head, lines, fill, stroke) + 10
        header(x, y + 24, head_pixel, GREEN)
        y += 36
        for _, _, _, _, call, use in rows:
            y = card(x, y, w, call, use, GREEN_FILL, GREEN) + 8
        for line in sum_lines:
            fits(line, w - 16)
        s.box(x, y + 4, w, 2 * lead + 10, sum_lines, fill=GREEN_FILL, stroke=GREEN, size=size)
        s.height = y + 4 + 2 * lead + 10 + 12
    s.write()


if __name__ == "__main__":
    main()
