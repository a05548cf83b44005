"""Chapter 07: descriptor set layout, pool, sets, bindings and the dynamic offset.

As chapters/07_uniform_buffers/main.cpp builds them: a set layout with binding
0 (UNIFORM_BUFFER) and binding 1 (UNIFORM_BUFFER_DYNAMIC), a pool with room
for one set per frame in flight, each set pointing at its slot's two buffers,
and two draws that bind the same set with dynamic offsets 0 and stride.
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, Svg)

W, H = 1000, 600


def main() -> None:
    s = Svg(W, H, "Chapter 07: descriptor set layout, pool, sets and the dynamic offset",
            "The set layout describes bindings 0 and 1; the pool holds two sets, one per frame in "
            "flight; each set points binding 0 at its frame's camera buffer and binding 1 at 80 bytes "
            "of its object buffer; two draws bind the same set with dynamic offsets 0 and 128.")

    # The set layout.
    lx, ly, lw = 20, 20, 300
    s.rect(lx, ly, lw, 150, fill=PURPLE_FILL, stroke=PURPLE, rx=8)
    s.text(lx + 12, ly + 24, "VkDescriptorSetLayout", size=13.5, bold=True, mono=True)
    s.text(lx + 12, ly + 42, "what set 0 holds: the shader's view", size=11.5, fill=MUTED)
    s.box(lx + 12, ly + 54, lw - 24, 40, ["binding 0: UNIFORM_BUFFER", "count 1, VERTEX stage"],
          fill="#ffffff", stroke=PURPLE, size=11, mono=True)
    s.box(lx + 12, ly + 100, lw - 24, 40, ["binding 1: UNIFORM_BUFFER_DYNAMIC", "count 1, VERTEX stage"],
          fill="#ffffff", stroke=PURPLE, size=11, mono=True)

    # The GLSL it matches.
    gx, gy = 20, 190
    s.rect(gx, gy, lw, 92, fill=GREY_FILL, stroke=GREY, rx=6)
    s.lines(gx + 10, gy + 20, ["layout(set = 0, binding = 0)", "  uniform FrameUniforms  {view, proj}",
                               "layout(set = 0, binding = 1)", "  uniform ObjectUniforms {world, tint...}"],
            size=10.5, leading=1.55, mono=True)
    s.text(gx + lw / 2, gy + 108, "cube.vert", size=11, anchor="middle", fill=MUTED, mono=True)

    # The pipeline layout names the set layout.
    s.box(20, 330, lw, 46, ["VkPipelineLayout", "set 0: the set layout above"], fill="#ffffff", stroke=INK,
          size=11.5, mono=False, bold_first=True)
    s.line(lx + lw / 2, ly + 150, lx + lw / 2, 190, stroke=PURPLE, width=1.4, dash="4 3")
    s.text(lx + lw / 2 + 6, ly + 164, "matches", size=10.5, fill=PURPLE)

    # The pool and its two sets.
    px, py, pw, ph = 360, 20, 620, 310
    s.rect(px, py, pw, ph, fill="#fbfcfd", stroke=GREY, rx=8)
    s.text(px + 12, py + 24, "VkDescriptorPool", size=13.5, bold=True, mono=True)
    s.text(px + 170, py + 24, "maxSets 2;  UNIFORM_BUFFER 2,  UNIFORM_BUFFER_DYNAMIC 2", size=11, mono=True,
           fill=MUTED)
    s.text(px + 12, py + 42, "destroying the pool frees the sets: sets_ are plain handles", size=11.5,
           fill=MUTED)

    slot_style = [(BLUE_FILL, BLUE), (GREEN_FILL, GREEN)]
    set_boxes = []
    for slot in range(2):
        fill, stroke = slot_style[slot]
        sx, sy, sw, sh = px + 12 + slot * 304, py + 56, 292, 108
        s.rect(sx, sy, sw, sh, fill=fill, stroke=stroke, rx=6)
        s.text(sx + 10, sy + 20, f"VkDescriptorSet sets_[{slot}]", size=12, bold=True, mono=True)
        s.text(sx + sw - 10, sy + 20, f"frame slot {slot}", size=11, anchor="end", fill=stroke)
        s.box(sx + 10, sy + 30, sw - 20, 32, [f"0 \u2192 frame_buffers_[{slot}], 0, 128 B"], fill="#ffffff",
              stroke=stroke, size=10.5, mono=True)
        s.box(sx + 10, sy + 68, sw - 20, 32, [f"1 \u2192 object_buffers_[{slot}], 0, 80 B"], fill="#ffffff",
              stroke=stroke, size=10.5, mono=True)
        set_boxes.append((sx, sy, sw, sh))
    s.text(px + 12, py + 186, "vkAllocateDescriptorSets with the layout, then vkUpdateDescriptorSets:",
           size=11.5)
    s.text(px + 12, py + 202, "each VkWriteDescriptorSet names set, binding, type and buffer, offset, range.",
           size=11.5)

    # Slot 0's buffers.
    bx, by = px + 12, py + 222
    s.text(bx, by + 12, "slot 0's buffers (host-visible, mapped; slot 1 has its own pair)", size=11.5,
           bold=True)
    s.box(bx, by + 22, 150, 46, ["frame_buffers_[0]", "view | proj: 128 B"], fill=ORANGE_FILL, stroke=ORANGE,
          size=10.5, mono=True)
    # The object buffer as a byte strip: two 80-byte blocks, stride 128 (alignment 64).
    ox, oy, scale = bx + 176, by + 34, 1.5  # pixels per byte
    stride, block = 128, 80
    s.text(ox, oy - 6, "object_buffers_[0]", size=10.5, mono=True)
    for i in range(2):
        x0 = ox + i * stride * scale
        s.rect(x0, oy, block * scale, 30, fill=ORANGE_FILL, stroke=ORANGE)
        s.text(x0 + block * scale / 2, oy + 19, f"object {i}: 80 B", size=10.5, anchor="middle")
        s.rect(x0 + block * scale, oy, (stride - block) * scale, 30, fill="#ffffff", stroke=GREY, dash="3 2")
        s.text(x0 + (block + (stride - block) / 2) * scale, oy + 19, "pad", size=10, anchor="middle",
               fill=MUTED)
        s.text(x0, oy + 44, f"{i * stride}", size=10.5, anchor="middle", mono=True)
    s.text(ox + 2 * stride * scale, oy + 44, f"{2 * stride}", size=10.5, anchor="middle", mono=True)

    # The draws: the same set, a different dynamic offset each.
    dy = 372
    draws = [("big cube", 0), ("small cube", stride)]
    for i, (name, offset) in enumerate(draws):
        y = dy + i * 70
        x_arrow = ox + (offset + block / 2) * scale
        width = (x_arrow + 60 - 360) if i == 0 else 620
        s.rect(360, y, width if i == 0 else 620, 56, fill="#ffffff", stroke=INK, rx=6)
        s.text(372, y + 22, f"vkCmdBindDescriptorSets(..., &sets_[slot], 1, &{offset})", size=10.5, mono=True)
        s.text(372, y + 42, f"vkCmdDrawIndexed: the {name}, bytes {offset}..{offset + 79}", size=11.5)
        s.line(x_arrow, y, x_arrow, oy + 30, stroke=BLUE, width=1.6, arrow="end")
        s.text(x_arrow + 6, oy + 60, f"dynamic offset {offset}", size=11, fill=BLUE, mono=True)
    s.text(360, dy + 160, "Each frame binds the same set twice, with a different dynamic offset per draw.",
           size=12.5, bold=True)

    # The notes.
    ny = 420
    s.lines(20, ny, [
        "**stride** = align_up(80, alignment), the alignment",
        "being minUniformBufferOffsetAlignment: 128 at 64",
        "(drawn), 256 at 256, 80 on lavapipe (16).",
        "",
        "**Binding 0** fixes its offset when the set is written.",
        "**Binding 1** fixes buffer and range (80 B); each",
        "vkCmdBindDescriptorSets adds a dynamic offset, so two",
        "draws share one set without rewriting it.",
        "",
        "**One set per frame in flight**: the CPU writes slot 1's",
        "buffers while the GPU may still read slot 0's.",
    ], size=11.5, leading=1.4)
    s.text(360, H - 18, "Names drop VK_DESCRIPTOR_TYPE_ and VK_SHADER_STAGE_; 80 and 128 B are the blocks' std140 sizes.", size=10.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
