"""Chapter 23c: the one-time command buffer that makes the image-based light,
in recording order, numbered as the page numbers it.

1. Four image barriers, UNDEFINED to GENERAL.
2. The sky's levels: sky.comp writes level 0, downsample.comp each next level
   from the one above, with a memory barrier after every level (storage write,
   then the next dispatch's sampled read; the layout stays GENERAL).
3. irradiance.comp, prefilter.comp once per specular level, brdf_lut.comp: no
   barrier between them, since they read only the finished sky (or nothing)
   and each writes its own image.
4. Four image barriers, GENERAL to SHADER_READ_ONLY_OPTIMAL, for the
   fragment shader's sampled reads.

The sizes and level counts come from chapters/23_materials/environment.hpp
(book/source_constants.py), and the script checks that precompute() still
records these steps in this order, so the figure cannot drift from the code.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three dispatches of step 3 are stacked and the figure is 380 units wide.
"""

import os
import re
import sys
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE, PURPLE_FILL,
                 Svg, wrap)

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ROOT = Path(__file__).resolve().parents[2]
ENVIRONMENT_HPP = ROOT / "chapters" / "23_materials" / "environment.hpp"


def number(name: str) -> int:
    return int(constant(ENVIRONMENT_HPP, name))


SKY, SKY_LEVELS = number("sky_size"), number("sky_levels")
IRR = number("irradiance_size")
SPEC, SPEC_LEVELS = number("specular_size"), number("specular_levels")
LUT = number("lut_size")

# precompute()'s steps, in the order the figure draws them (whitespace folded).
ORDER = [
    "VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_GENERAL, VK_PIPELINE_STAGE_2_NONE, 0, "
    "VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT",
    "vkt::memory_barrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, "
    "VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);",
    "dispatch(cmd, 0, VK_NULL_HANDLE, sky_.level[0], push, sky_size, 6);",
    "for (uint32_t level = 1; level < sky_levels; ++level) { written(); "
    "dispatch(cmd, 1, sky_.level[level - 1], sky_.level[level], push, sky_size >> level, 6); } written(); }",
    "dispatch(cmd, 2, sky_.image.view, irradiance_.level[0], push, irradiance_size, 6);",
    "for (uint32_t level = 0; level < specular_levels; ++level) {",
    "dispatch(cmd, 3, sky_.image.view, specular_.level[level], push, specular_size >> level, 6);",
    "dispatch(cmd, 4, VK_NULL_HANDLE, lut_.view, push, lut_size, 1);",
    "VK_IMAGE_LAYOUT_GENERAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "
    "VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT, "
    "VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);",
]
# The pipelines' indices, as dispatch() takes them.
PIPELINES = '{"sky.comp", "downsample.comp", "irradiance.comp", "prefilter.comp", "brdf_lut.comp"}'


def check_order() -> None:
    code = " ".join(ENVIRONMENT_HPP.read_text(encoding="utf-8").split())
    body = code[code.index("void precompute("):]
    at = 0
    for want in ORDER:
        found = body.find(want, at)
        if found < 0:
            raise SystemExit(f"chapters/23_materials/environment.hpp: precompute() no longer says "
                             f"`{want[:70]}` in this order; redraw book/diagrams/23c_precompute_timeline.py")
        at = found + len(want)
    if PIPELINES not in code:
        raise SystemExit("chapters/23_materials/environment.hpp: the compute pipelines changed order; "
                         "redraw book/diagrams/23c_precompute_timeline.py")
    if len(re.findall(r"written\(\);", body)) != 2:
        raise SystemExit("chapters/23_materials/environment.hpp: precompute() has more or fewer "
                         "written() barriers; redraw book/diagrams/23c_precompute_timeline.py")


def main() -> None:
    check_order()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    W = 380 if narrow else 860
    size = 11 if narrow else 14
    small = 10.5 if narrow else 13
    lead = size * 1.35
    rail = 22          # the numbered rail's x
    x0 = 44            # the steps' left edge
    right = W - 8
    width = right - x0
    sky_sizes = [SKY >> k for k in range(SKY_LEVELS)]
    spec_sizes = [SPEC >> k for k in range(SPEC_LEVELS)]
    s = Svg(W, 100, "Chapter 23c: the one-time command buffer that makes the image-based light",
            "Four numbered steps, top to bottom, in recording order. 1: four image barriers, UNDEFINED to "
            f"GENERAL. 2: the sky's {SKY_LEVELS} levels, {SKY} down to {sky_sizes[-1]}, level 0 by sky.comp and "
            "each next one by downsample.comp from the one above, with a memory barrier after every level, "
            "compute storage write to compute sampled read, the layout staying GENERAL. 3: irradiance.comp, "
            f"prefilter.comp once for each of {SPEC_LEVELS} levels, and brdf_lut.comp, with no barrier between "
            "them, since each reads only the finished sky, or nothing, and writes its own image. 4: four image "
            "barriers, GENERAL to SHADER_READ_ONLY_OPTIMAL, compute storage write to fragment sampled read.")

    y = 24
    s.text(8, y, "One command buffer, recorded and submitted once", size=size + 1.5, bold=True)
    y += 14
    tops: list[float] = []

    def step_number(top: float) -> None:
        tops.append(top)
        s.circle(rail, top + 11, 10, fill="#ffffff", stroke=INK, width=1.3)
        s.text(rail, top + 15.5, str(len(tops)), size=size + 1, anchor="middle", bold=True)

    def notes(x: float, y: float, w: float, text: str, fill=MUTED, sz=None, bold=False) -> float:
        sz = sz or small
        for line in wrap(text, w, sz, bold):
            y += sz * 1.35
            s.text(x, y, line, size=sz, fill=fill, bold=bold)
        return y

    def heading(top: float, text: str, fill: str) -> float:
        """A step's number and its bold heading, wrapped; the heading's last baseline."""
        step_number(top)
        return notes(x0, top + 15 - size * 1.35, width, text, fill=fill, sz=size, bold=True)

    def layout_barrier(top: float, old: str, new: str, before: str, after: str) -> float:
        y = heading(top, f"image barrier × 4: {old} → {new}", PURPLE)
        return notes(x0, y, width, f"sky, irradiance, specular, table; {before} → {after}")

    # 1. The layouts for compute.
    y = layout_barrier(y + 8, "UNDEFINED", "GENERAL", "before: nothing", "after: compute's storage writes")

    # 2. The sky's levels, each followed by a memory barrier.
    top = y + 20
    row = heading(top, f"the sky's {SKY_LEVELS} levels, one after another", ORANGE) + 11
    bar = 5 if narrow else 7
    gap = 3 if narrow else 8
    cell = (width - SKY_LEVELS * (bar + 2 * gap)) / SKY_LEVELS
    box_h = 2 * lead + 6
    x = x0
    for k, n in enumerate(sky_sizes):
        s.box(x, row, cell, box_h, [f"L{k}", f"{n}²"], fill=ORANGE_FILL, stroke=ORANGE, size=small)
        x += cell + gap
        s.rect(x, row - 3, bar, box_h + 6, fill=PURPLE, stroke=PURPLE, width=0.8, rx=1)
        x += bar + gap
    y = row + box_h + 4
    y = notes(x0, y, width, f"L0: `sky.comp`, its formula. L1 to L{SKY_LEVELS - 1}: `downsample.comp`, each "
              "from the level above, so each must wait for that level's writes.", fill=INK)
    s.rect(x0, y + 7, bar, 12, fill=PURPLE, stroke=PURPLE, width=0.8, rx=1)
    y = notes(x0 + bar + 6, y, width - bar - 6, "memory barrier: compute storage write → compute sampled "
              "read; the layout stays GENERAL", fill=PURPLE)

    # 3. The three images: no barriers between them.
    top = y + 20
    y = heading(top, "the three images: no barrier between them", BLUE) + 11
    cards = [
        ("`irradiance.comp`", [f"irradiance: {IRR}² × 6 faces", "1 dispatch, reads the sky"], BLUE_FILL, BLUE),
        ("`prefilter.comp`", [f"specular L0 to L{SPEC_LEVELS - 1}: {spec_sizes[0]}² to {spec_sizes[-1]}²",
                              f"{SPEC_LEVELS} dispatches, each reads the sky"], PURPLE_FILL, PURPLE),
        ("`brdf_lut.comp`", [f"table: {LUT}², 1 layer", "1 dispatch, reads nothing"], GREY_FILL, GREY),
    ]
    card_h = 3 * lead + 8
    if narrow:
        for head, body, fill, stroke in cards:
            s.box(x0, y, width, card_h, [head] + body, fill=fill, stroke=stroke, size=small)
            y += card_h + 6
        y -= 6
    else:
        cw = (width - 2 * 12) / 3
        for i, (head, body, fill, stroke) in enumerate(cards):
            s.box(x0 + i * (cw + 12), y, cw, card_h, [head] + body, fill=fill, stroke=stroke, size=small)
        y += card_h
    y = notes(x0, y, width, "Each reads only the sky, finished behind the last barrier of step 2, or nothing, "
              "and writes an image (or level) of its own: none reads another's writes, so the GPU may run "
              "them in any order, or at once.", fill=INK)

    # 4. The layouts for the scene's fragment shader.
    y = layout_barrier(y + 20, "GENERAL", "SHADER_READ_ONLY_OPTIMAL", "compute's storage writes",
                       "the fragment shader's sampled reads")
    y = notes(x0, y + 4, width, "Then the buffer ends, is submitted, and the CPU waits on its fence before "
              "the first frame.", fill=INK)

    # The rail joining the numbers.
    for a, b in zip(tops, tops[1:]):
        s.line(rail, a + 22, rail, b - 1, stroke=MUTED, width=1.2, arrow="end")
    s.height = y + 14
    s.write()


if __name__ == "__main__":
    main()
