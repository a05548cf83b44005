"""Chapter 28: one frame of two-phase occlusion culling, and what each pass reads and writes.

The passes as chapter 28's record() issues them with --cull occlusion: cull 1
(early), draw 1, the depth pyramid, cull 2 (late), draw 2; the buffers are
main.cpp's (three lists of commands, the counts, one visibility word per
instance).
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, PURPLE_FILL, Svg)

W, H = 1000, 470


def main() -> None:
    s = Svg(W, H, "Chapter 28: one frame of two-phase occlusion culling",
            "Five passes in one command buffer. Cull 1, a compute pass, appends a draw command for "
            "every instance that was seen last frame and is in the frustum. Draw 1 clears colour "
            "and depth and draws the floor and that list with vkCmdDrawIndexedIndirectCount. The "
            "pyramid pass reduces the depth buffer to a mip chain of minimum (farthest) depths. "
            "Cull 2 tests every instance in the frustum against the pyramid, writes whether it is "
            "seen into the visibility buffer, and appends those seen now but not drawn early. "
            "Draw 2 loads colour and depth and draws that list.")
    s.text(20, 28, "One frame, --cull occlusion: the CPU records the same five passes every frame",
           size=15, bold=True)
    passes = [
        ("cull 1 (compute)", ["in the frustum and", "visible[i] = 1?", "\u2192 early list"], ORANGE_FILL, ORANGE),
        ("draw 1", ["clear; floor +", "DrawIndexedIndirect-", "Count(early list)"], BLUE_FILL, BLUE),
        ("pyramid (compute)", ["depth \u2192 level 0,", "each level the min", "of 2 x 2 below"], PURPLE_FILL, PURPLE),
        ("cull 2 (compute)", ["in the frustum and", "not behind the pyramid?", "visible[i] := that"], ORANGE_FILL, ORANGE),
        ("draw 2", ["load; DrawIndexed-", "IndirectCount(late", "list: seen, not early)"], BLUE_FILL, BLUE),
    ]
    x, y, w, h, gap = 20, 60, 172, 110, 20
    for i, (name, rows, fill, stroke) in enumerate(passes):
        bx = x + i * (w + gap)
        s.box(bx, y, w, h, [], fill=fill, stroke=stroke)
        s.text(bx + w / 2, y + 24, name, size=13.5, bold=True, anchor="middle", fill=stroke)
        for r, row in enumerate(rows):
            s.text(bx + w / 2, y + 50 + r * 19, row, size=12.5, anchor="middle")
        if i + 1 < len(passes):
            s.line(bx + w, y + h / 2, bx + w + gap, y + h / 2, stroke=INK, width=1.6, arrow="end")

    # What they share.
    by = 240
    s.text(20, by, "In memory", size=15, bold=True)
    buffers = [
        ("draw lists", ["3 x N VkDrawIndexed-", "IndirectCommand: early,", "late, culled (--view)"]),
        ("counts", ["8 words: the 3 list", "lengths (the draw counts),", "in frustum, occluded"]),
        ("visible", ["1 word per instance:", "seen by the last cull 2", "(kept across frames)"]),
        ("depth pyramid", ["R32_SFLOAT mips, level 0", "half the depth buffer", "(power of two), to 1 x 1"]),
    ]
    bw = 228
    for i, (name, rows) in enumerate(buffers):
        bx = 20 + i * (bw + 16)
        s.box(bx, by + 14, bw, 96, [], fill=GREEN_FILL, stroke=GREEN)
        s.text(bx + bw / 2, by + 36, name, size=13.5, bold=True, anchor="middle", fill=GREEN)
        for r, row in enumerate(rows):
            s.text(bx + bw / 2, by + 60 + r * 18, row, size=12.5, anchor="middle")
    notes = [
        "Depth is reversed (1 near, 0 far): the farthest depth over a rectangle is its min, which the",
        "pyramid keeps. A box is hidden when its nearest corner's depth is less than that min.",
        "The first frame sees nothing in cull 1 (visible[] all 0): it draws everything visible in draw 2.",
    ]
    for i, note in enumerate(notes):
        s.text(20, by + 140 + i * 22, note, size=12.5, fill=MUTED if i == 2 else INK)
    s.write()


if __name__ == "__main__":
    main()
