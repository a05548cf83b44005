"""Chapter 29: a queue-family ownership transfer, the HDR image from the
graphics family to the compute family, as a release and an acquire barrier.

The fields are those chapters/29_async_compute/main.cpp passes to
ch29::ownership_barrier (queues.hpp) in draw_ahead when the two families
differ: the release at the end of the scene's command buffer on the graphics
queue, the acquire at the start of the bloom's on the compute queue, and the
scenes timeline (scene_done_) between the two submits. The script checks that
main.cpp still makes those calls, so the figure cannot drift from the code.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
queues are drawn one above the other, 420 units wide.
"""

import os
import re
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, INK, MUTED, PURPLE, PURPLE_FILL, RED, Svg)

MAIN_CPP = Path(__file__).resolve().parents[2] / "chapters" / "29_async_compute" / "main.cpp"

# What main.cpp must say (whitespace folded) for the figure to be right.
RELEASE_CALL = ("ch29::ownership_barrier( scene, hdr_[s].image, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, "
                "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, graphics_family_, handover ? compute_family_ : "
                "graphics_family_, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "
                "VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, handover ? VK_PIPELINE_STAGE_2_NONE")
RELEASE_ACCESS = "handover ? 0 : VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);"
SCENE_SUBMIT = "ch29::submit(gpu_.queue, scene, VK_NULL_HANDLE, 0, VK_PIPELINE_STAGE_2_NONE, scene_done_, ++scenes_);"
ACQUIRE_CALL = ("ch29::ownership_barrier(cmd, hdr_[s].image, 1, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, "
                "VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, graphics_family_, compute_family_, "
                "VK_PIPELINE_STAGE_2_NONE, 0, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "
                "VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);")
BLOOM_SUBMIT = ("ch29::submit(compute_queue_, cmd, scene_done_, scenes_, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, "
                "bloom_done_, bloom_value_[s]);")


def check_source() -> None:
    code = " ".join(MAIN_CPP.read_text(encoding="utf-8").split())
    code = code.replace("( ", "(")
    for want in (RELEASE_CALL, RELEASE_ACCESS, SCENE_SUBMIT, ACQUIRE_CALL, BLOOM_SUBMIT):
        if " ".join(want.split()).replace("( ", "(") not in code:
            raise SystemExit(f"chapters/29_async_compute/main.cpp: no longer says `{want[:60]}...`; "
                             "redraw book/diagrams/29_ownership_transfer.py")


# (field, release value, release ignored, acquire value, acquire ignored, must match)
FIELDS = [
    ("srcStageMask", "COLOR_ATTACHMENT_OUTPUT_BIT", False, "NONE", True, False),
    ("srcAccessMask", "COLOR_ATTACHMENT_WRITE_BIT", False, "0", True, False),
    ("dstStageMask", "NONE", True, "COMPUTE_SHADER_BIT", False, False),
    ("dstAccessMask", "0", True, "SHADER_SAMPLED_READ_BIT", False, False),
    ("oldLayout", "COLOR_ATTACHMENT_OPTIMAL", False, "COLOR_ATTACHMENT_OPTIMAL", False, True),
    ("newLayout", "SHADER_READ_ONLY_OPTIMAL", False, "SHADER_READ_ONLY_OPTIMAL", False, True),
    ("srcQueueFamilyIndex", "graphics_family_", False, "graphics_family_", False, True),
    ("dstQueueFamilyIndex", "compute_family_", False, "compute_family_", False, True),
    ("image, range", "hdr_[s].image, 1 level", False, "hdr_[s].image, 1 level", False, True),
]
COL_W = 390
ROW = 21
SIZE = 11.5


def half(s: Svg, x: float, y: float, acquire: bool) -> float:
    """One queue's side: what comes before, the barrier's fields, what comes after.
    Returns the y below it."""
    colour, fill = (GREEN, GREEN_FILL) if acquire else (BLUE, BLUE_FILL)
    queue = "compute queue (compute_family_)" if acquire else "graphics queue (graphics_family_)"
    s.text(x, y, queue, size=13, bold=True, fill=colour)
    y += 12
    if acquire:
        s.box(x, y, COL_W, 44, ["vkQueueSubmit2 of the bloom's command buffer:",
                                "waits scene_done_ \u2265 scenes_ at COMPUTE_SHADER"],
              fill=PURPLE_FILL, stroke=PURPLE, size=SIZE)
    else:
        s.box(x, y, COL_W, 30, "the scene's command buffer: draw_scene writes the HDR image",
              fill=fill, stroke=colour, size=SIZE)
    y += (44 if acquire else 30) + 10
    title = ("acquire: the first barrier of the bloom's commands" if acquire
             else "release: the last barrier of the scene's commands")
    top = y
    s.text(x + 8, y + 16, title, size=12, bold=True, fill=colour)
    y += 26
    for name, rv, ri, av, ai, match in FIELDS:
        value, ignored = (av, ai) if acquire else (rv, ri)
        if match:
            s.rect(x + 4, y, COL_W - 8, ROW, fill=PURPLE_FILL, stroke="none", width=0)
        s.text(x + 10, y + 15, name, size=SIZE, mono=True, fill=MUTED if ignored else INK)
        s.text(x + 160, y + 15, value + ("  ignored" if ignored else ""), size=SIZE, mono=True,
               fill=MUTED if ignored else (INK if match else colour), bold=not ignored and not match)
        y += ROW
    s.rect(x, top, COL_W, y - top + 6, fill="none", stroke=colour, width=1.6, rx=6)
    y += 16
    if acquire:
        s.box(x, y, COL_W, 30, "the bloom's first dispatch samples the HDR image", fill=fill, stroke=colour,
              size=SIZE)
        y += 30
    else:
        s.box(x, y, COL_W, 44, ["vkQueueSubmit2 of the scene's command buffer:", "signals scene_done_ = ++scenes_"],
              fill=PURPLE_FILL, stroke=PURPLE, size=SIZE)
        y += 44
    return y


LEGEND = [
    "bold: the half that counts here; grey: ignored (NONE, 0)",
    "shaded: must be the same in both barriers",
    "values without their VK_PIPELINE_STAGE_2_, VK_ACCESS_2_ and",
    "VK_IMAGE_LAYOUT_ prefixes; the layout changes once, between the two",
]
LEGEND_NARROW = [
    "bold: the half that counts here;",
    "grey: ignored (NONE, 0)",
    "shaded: must be the same in both barriers",
    "values without their VK_PIPELINE_STAGE_2_,",
    "VK_ACCESS_2_ and VK_IMAGE_LAYOUT_ prefixes;",
    "the layout changes once, between the two",
]


def main() -> None:
    check_source()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    title = "Chapter 29: handing the HDR image from the graphics family to the compute family"
    desc = ("Two barriers with the same image, layouts (COLOR_ATTACHMENT_OPTIMAL to SHADER_READ_ONLY_OPTIMAL) "
            "and families (srcQueueFamilyIndex graphics_family_, dstQueueFamilyIndex compute_family_). The "
            "release, last in the scene's command buffer on the graphics queue, sets the source half: "
            "COLOR_ATTACHMENT_OUTPUT and COLOR_ATTACHMENT_WRITE; its destination half, NONE and 0, is "
            "ignored. That submit signals the scenes timeline. The bloom's submit on the compute queue waits "
            "for it at the compute shader, and its first barrier, the acquire, sets the destination half: "
            "COMPUTE_SHADER and SHADER_SAMPLED_READ; its source half, NONE and 0, is ignored.")
    if narrow:
        w = COL_W + 30
        s = Svg(w, 1000, title, desc)
        s.lines(15, 24, ["An ownership transfer: release, then", "acquire"], size=14, bold=True)
        s.text(15, 62, "ch29::ownership_barrier, as draw_ahead calls it", size=12, fill=MUTED)
        y = half(s, 15, 92, acquire=False)
        s.line(15 + COL_W / 2, y, 15 + COL_W / 2, y + 46, stroke=PURPLE, width=2, arrow="end")
        s.text(15 + COL_W / 2 + 10, y + 22, "scenes timeline", size=12, fill=PURPLE, bold=True)
        s.text(15 + COL_W / 2 + 10, y + 38, "(semaphore scene_done_)", size=12, fill=PURPLE)
        y = half(s, 15, y + 70, acquire=True)
        s.lines(15, y + 28, LEGEND_NARROW, size=SIZE, fill=MUTED)
        s.height = y + 28 + len(LEGEND_NARROW) * SIZE * 1.3 + 8
    else:
        lx, rx = 20, 20 + COL_W + 50
        s = Svg(rx + COL_W + 20, 1000, title, desc)
        s.text(20, 28, "An ownership transfer: a release on one queue, an acquire on the other",
               size=14, bold=True)
        s.text(20, 48, "ch29::ownership_barrier, as draw_ahead calls it for the HDR image (time runs down)",
               size=12, fill=MUTED)
        left = half(s, lx, 80, acquire=False)
        right_top = left - 20
        s.path(f"M{lx + COL_W:.1f},{left - 22:.1f} C{lx + COL_W + 40:.1f},{left - 22:.1f} "
               f"{rx - 40:.1f},{right_top + 34:.1f} {rx:.1f},{right_top + 34:.1f}", stroke=PURPLE, width=2,
               arrow="end")
        s.lines(lx + COL_W - 120, left + 26, ["scenes timeline", "(semaphore scene_done_)"], size=12,
                fill=PURPLE, bold=False)
        right = half(s, rx, right_top, acquire=True)
        s.lines(lx, left + 80, LEGEND, size=SIZE, fill=MUTED)
        s.height = max(right, left + 80 + 4 * SIZE * 1.3) + 16
    s.write()


if __name__ == "__main__":
    main()
