"""Chapter 23c at a glance: the sky cube made at start-up, the three images
the split sum computes from it (irradiance, prefiltered specular, the BRDF
table) and the three reads a pixel makes of them.

The sizes, level counts, sample counts and the format are read from
chapters/23_materials/environment.hpp (book/source_constants.py), and the
script checks that environment.hpp still gives level 0 of the prefiltered
cube one sample and that scene_ibl.frag still reads the three images as
drawn, so the figure cannot drift from the code.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three stages are drawn one above the other, 380 units wide.
"""

import os
import re
import sys
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, PURPLE_FILL, Svg)

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
    size = 11 if narrow else 12.5
    lead = size * 1.35
    small = 11  # the reads' column, which holds the longest lines
    steps = [round(k / (SPEC_LEVELS - 1), 2) for k in range(SPEC_LEVELS)]
    s = Svg(380 if narrow else 960, 100, "Chapter 23c: the sky, the three images made from it, three reads a pixel",
            f"Once, at start-up, in compute: sky.comp makes a sky cube of {SKY} by {SKY} texels a face, "
            f"and downsample.comp its {SKY_LEVELS} mip levels. From it irradiance.comp makes the irradiance "
            f"cube, {IRR} by {IRR} a face, one level, {IRR_SAMPLES} samples a texel, and prefilter.comp the "
            f"prefiltered specular cube, {SPEC} by {SPEC} a face, {SPEC_LEVELS} levels, one per roughness "
            f"step from 0 to 1, {SPEC_SAMPLES} samples a texel but 1 at level 0, a mirror. brdf_lut.comp makes the BRDF table, {LUT} by {LUT}, from no sky at all. "
            f"All are {fmt}. Every pixel of scene_ibl.frag then reads the table at (n·v, roughness) for "
            "A and B, S = F0 A + B; the irradiance at n, times the diffuse colour and 1 − S; and the "
            "prefiltered cube in the mirror direction at level roughness × "
            f"{SPEC_LEVELS - 1}, times S; the sum is the ambient light.")

    def card(x, y, w, head, lines, fill, stroke):
        """A box: a bold heading, then lines (`code` in monospace); its bottom."""
        h = (len(lines) + 1) * lead + 10
        s.rect(x, y, w, h, fill=fill, stroke=stroke, rx=6, width=1.3)
        ty = y + 5 + size
        s.text(x + 9, ty, head, size=size, bold=not head.startswith("`"))
        for line in lines:
            ty += lead
            s.text(x + 9, ty, line, size=size, fill=INK)
        return y + h

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
    reads = [
        ("the table", "`texture(brdf_lut, (n·v, roughness))`", "gives A, B: S = F0 A + B"),
        ("irradiance", "`texture(irradiance_map, n)`", "× diffuse colour × (1 − S)"),
        ("prefiltered", "`textureLod(specular_map, r, level)`",
         f"r = reflect(−v, n), level = roughness × {SPEC_LEVELS - 1}"),
    ]
    head_once = f"Once, at start-up, in compute: all {fmt}"
    head_pixel = "Every pixel: three reads"

    if not narrow:
        s.text(20, 26, head_once, size=size + 1.5, bold=True, fill=ORANGE)
        sky_bottom = card(20, 60, 250, "sky cube", sky_lines, ORANGE_FILL, ORANGE)
        x, w = 320, 300
        y0 = 40
        irr_bottom = card(x, y0, w, "irradiance cube", irr_lines, BLUE_FILL, BLUE)
        spec_top = irr_bottom + 14
        spec_bottom = card(x, spec_top, w, "prefiltered specular cube", spec_lines, PURPLE_FILL, PURPLE)
        lut_top = spec_bottom + 14
        lut_bottom = card(x, lut_top, w, "BRDF table", lut_lines, GREY_FILL, GREY)
        # The sky feeds the two cubes (irradiance.comp, prefilter.comp).
        sx = 270
        s.path(f"M{sx},{(60 + sky_bottom) / 2 - 10} C{sx + 25},{(60 + sky_bottom) / 2 - 10} {x - 25},"
               f"{(y0 + irr_bottom) / 2} {x - 2},{(y0 + irr_bottom) / 2}", stroke=BLUE, width=1.5, arrow="end")
        s.path(f"M{sx},{(60 + sky_bottom) / 2 + 10} C{sx + 25},{(60 + sky_bottom) / 2 + 10} {x - 25},"
               f"{(spec_top + spec_bottom) / 2} {x - 2},{(spec_top + spec_bottom) / 2}", stroke=PURPLE,
               width=1.5, arrow="end")
        s.text(20, sky_bottom + 22, "`irradiance.comp` and `prefilter.comp`", size=size, fill=MUTED)
        s.text(20, sky_bottom + 22 + lead, "read the sky; `brdf_lut.comp` reads", size=size, fill=MUTED)
        s.text(20, sky_bottom + 22 + 2 * lead, "nothing: the table fits any sky.", size=size, fill=MUTED)
        # Right: the reads, each beside its image.
        rx, rw = 680, 270
        s.text(rx, 26, head_pixel, size=size + 1.5, bold=True, fill=GREEN)
        tops = [lut_top, y0, spec_top]
        bottoms = [lut_bottom, irr_bottom, spec_bottom]
        colours = [GREY, BLUE, PURPLE]
        for (name, call, use), top, bottom, colour in zip(reads, tops, bottoms, colours):
            mid = (top + bottom) / 2
            s.line(x + w, mid, rx - 2, mid, stroke=colour, width=1.5, arrow="end")
            s.rect(rx, mid - 1.5 * lead, rw, 3 * lead, fill=GREEN_FILL, stroke=GREEN, rx=6, width=1.2)
            s.text(rx + 8, mid - 0.25 * lead, call, size=small)
            s.text(rx + 8, mid + 0.8 * lead, use, size=small)
        bottom = max(lut_bottom, sky_bottom + 22 + 2 * lead)
        s.box(rx, bottom + 20, rw, 2 * lead + 10,
              ["ambient = irradiance × diffuse × (1 − S)", "+ prefiltered × S"], fill=GREEN_FILL,
              stroke=GREEN, size=small)
        s.line(rx + rw / 2, (lut_top + lut_bottom) / 2 + 1.5 * lead, rx + rw / 2, bottom + 18, stroke=GREEN,
               width=1.3, arrow="end")
        s.text(rx + rw / 2 + 8, bottom + 12, "the three, summed", size=small, fill=MUTED)
        s.height = bottom + 20 + 2 * lead + 10 + 12
    else:
        x, w = 10, 360
        y = 22
        first, _, rest = head_once.partition(": ")
        s.text(x, y, first + ":", size=size + 1.5, bold=True, fill=ORANGE)
        y += (size + 1.5) * 1.3
        s.text(x, y, rest, size=size + 1.5, bold=True, fill=ORANGE)
        y = card(x, y + 10, w, "sky cube", sky_lines, ORANGE_FILL, ORANGE)
        s.line(x + w / 2, y, x + w / 2, y + 16, stroke=ORANGE, width=1.3, arrow="end")
        s.text(x + w / 2 + 8, y + 12, "read by the two cubes' shaders", size=size, fill=MUTED)
        y = card(x, y + 18, w, "irradiance cube (irradiance.comp)", irr_lines, BLUE_FILL, BLUE)
        y = card(x, y + 10, w, "prefiltered specular cube (prefilter.comp)", spec_lines, PURPLE_FILL, PURPLE)
        y = card(x, y + 10, w, "BRDF table (brdf_lut.comp)", lut_lines, GREY_FILL, GREY)
        s.text(x, y + 36, head_pixel, size=size + 1.5, bold=True, fill=GREEN)
        y += 46
        for name, call, use in reads:
            y = card(x, y, w, call, [use], GREEN_FILL, GREEN) + 8
        s.box(x, y + 4, w, 2 * lead + 10, ["ambient = irradiance × diffuse × (1 − S)", "+ prefiltered × S"],
              fill=GREEN_FILL, stroke=GREEN, size=size)
        s.height = y + 4 + 2 * lead + 10 + 12
    s.write()


if __name__ == "__main__":
    main()
