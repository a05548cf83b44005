"""Chapter 21b: what Dear ImGui hands over each frame (ImDrawData, its
ImDrawLists, their ImDrawCmds) and what the overlay records from it: the
upload into this frame's slot buffers, a rendering with LOAD_OP_LOAD over the
finished frame, and per command a scissor from its ClipRect and one
vkCmdDrawIndexed.

Every name is one that common/frame/src/overlay.cpp uses; the script checks
that the file still says the lines the figure draws, so the two cannot drift.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
columns are drawn one above the other, 380 units wide.
"""

import os
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, MUTED, ORANGE, ORANGE_FILL,
                 Svg)

OVERLAY_CPP = Path(__file__).resolve().parents[2] / "common" / "frame" / "src" / "overlay.cpp"

# What overlay.cpp must say (whitespace folded) for the figure to be right.
CODE = [
    "const ImDrawData* data = ImGui::GetDrawData();",
    "for (int i = 0; i < data->CmdListsCount; ++i) {",
    "const ImDrawList* list = data->CmdLists[i];",
    "std::memcpy(vertex, list->VtxBuffer.Data,",
    "std::memcpy(index, list->IdxBuffer.Data,",
    "SlotBuffers& buffers = slots_[slot];",
    "begin_colour_rendering(cmd, target, extent, VK_ATTACHMENT_LOAD_OP_LOAD);",
    "vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);",
    "const Push push{{2.0f / data->DisplaySize.x, 2.0f / data->DisplaySize.y},",
    "for (const ImDrawCmd& draw : list->CmdBuffer) {",
    "const float x0 = std::max(draw.ClipRect.x - data->DisplayPos.x, 0.0f);",
    "const float x1 = std::min(draw.ClipRect.z - data->DisplayPos.x, float(extent.width));",
    "vkCmdSetScissor(cmd, 0, 1, &scissor);",
    "vkCmdDrawIndexed(cmd, draw.ElemCount, 1, first_index + draw.IdxOffset, "
    "first_vertex + int32_t(draw.VtxOffset), 0);",
    "first_index += uint32_t(list->IdxBuffer.Size);",
    "first_vertex += list->VtxBuffer.Size;",
    "vkCmdEndRendering(cmd);",
]


def check_source() -> None:
    code = " ".join(OVERLAY_CPP.read_text(encoding="utf-8").split())
    for want in CODE:
        if " ".join(want.split()) not in code:
            raise SystemExit(f"common/frame/src/overlay.cpp: no longer says `{want[:60]}`; "
                             "redraw book/diagrams/21b_overlay_data.py")


def main() -> None:
    check_source()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 11 if narrow else 12.5
    lead = size * 1.35
    if narrow:
        left, right, col_w, W = 10, 10, 360, 380
    else:
        left, right, col_w, W = 20, 500, 440, 960
    s = Svg(W, 100, "Chapter 21b: what Dear ImGui hands over, and what the overlay draws with it",
            "Left, what ImGui::GetDrawData() returns after ImGui::Render(): an ImDrawData with "
            "DisplayPos, DisplaySize and CmdLists, each an ImDrawList with a VtxBuffer of ImDrawVert "
            "(pos, uv, col), an IdxBuffer of ImDrawIdx and a CmdBuffer of ImDrawCmd, each command a "
            "ClipRect, a TextureId and an ElemCount, IdxOffset and VtxOffset. Right, what "
            "Overlay::record does with it each frame: copies every list's vertices and indices one "
            "after the other into this frame's slot buffers, begins a rendering with "
            "VK_ATTACHMENT_LOAD_OP_LOAD over the finished frame, and for every command sets the "
            "scissor to its ClipRect minus DisplayPos, clamped to the target, and draws its indices "
            "with vkCmdDrawIndexed.")

    def code_line(x, y, label):
        """Code in monospace; after a `~`, a remark in grey."""
        code, _, note = label.partition("~")
        code = code.rstrip()
        if code:
            s.text(x, y, code, size=size, mono=True)
        if note:
            s.text(x + (0.602 * size * (len(code) + 1) if code else 0), y, note.strip(), size=size,
                   fill=MUTED)

    def lines_box(x, y, w, labels, fill, stroke, head=None, extra=0):
        """A box of left-aligned lines, a bold heading first, `extra` room below them; its bottom."""
        h = (len(labels) + (1 if head else 0)) * lead + 12 + extra
        s.rect(x, y, w, h, fill=fill, stroke=stroke, rx=6, width=1.3)
        ty = y + 6 + size
        if head:
            s.text(x + 9, ty, head, size=size, bold=True)
            ty += lead
        for label in labels:
            code_line(x + 9, ty, label)
            ty += lead
        return y + h - extra

    # ---- left: what Dear ImGui hands over --------------------------------------------
    y = 22 if narrow else 28
    s.text(left, y, "What Dear ImGui hands over", size=size + 1.5, bold=True, fill=ORANGE)
    y += 10
    y = lines_box(left, y, col_w, ["DisplayPos, DisplaySize", "CmdLists[0 .. CmdListsCount − 1]"],
                  ORANGE_FILL, ORANGE, head="ImGui::GetDrawData(): ImDrawData")
    # Two lists, the second drawn behind the first.
    list_x, list_w = left + 14, col_w - 14
    s.line(left + 8, y, left + 8, y + 20, stroke=ORANGE, width=1.3, arrow="end")
    y += 20
    s.rect(list_x + 8, y - 6, list_w - 8, 10, fill=ORANGE_FILL, stroke=ORANGE, rx=4)
    list_top = y
    s.add("")  # the list's white card goes here, once its height is known
    card_at = len(s.items) - 1
    ty = y + 6 + size
    s.text(list_x + 9, ty, "CmdLists[i]: ImDrawList", size=size, bold=True)
    ty += lead
    s.text(list_x + 9, ty, "VtxBuffer: ImDrawVert (pos, uv, col) ×n", size=size, mono=True)
    strip_x, strip_w = list_x + 9, list_w - 18
    vtx_y = ty + 6
    for k in range(8):
        s.rect(strip_x + k * strip_w / 8, vtx_y, strip_w / 8, 12, fill=ORANGE_FILL, stroke=ORANGE,
               width=0.8)
    ty = vtx_y + 12 + size + 6
    s.text(list_x + 9, ty, "IdxBuffer: ImDrawIdx (3 per triangle)", size=size, mono=True)
    idx_y = ty + 6
    for k in range(12):
        s.rect(strip_x + k * strip_w / 12, idx_y, strip_w / 12, 12, fill=ORANGE_FILL, stroke=ORANGE,
               width=0.8)
    ty = idx_y + 12 + size + 6
    s.text(list_x + 9, ty, "CmdBuffer: ImDrawCmd, one per clip rectangle", size=size, mono=True)
    ty += 8
    cmd_top = ty
    cmd_labels = ["ClipRect (x0, y0, x1, y1)", "TextureId ~ the font: not read",
                  "ElemCount, IdxOffset, VtxOffset"]
    ch = len(cmd_labels) * lead + 10
    s.rect(strip_x + 8, cmd_top - 5, strip_w - 8, ch, fill=GREY_FILL, stroke=GREY, rx=5)
    s.rect(strip_x, cmd_top, strip_w - 8, ch, fill=GREY_FILL, stroke=GREY, rx=5, width=1.2)
    cy = cmd_top + 4 + size
    for label in cmd_labels:
        code_line(strip_x + 8, cy, label)
        cy += lead
    list_h = cmd_top + ch + 10 - list_top
    s.rect(list_x, list_top, list_w, list_h, fill="#ffffff", stroke=ORANGE, rx=6, width=1.3)
    s.items[card_at] = s.items.pop()
    left_bottom = list_top + list_h
    s.text(left, left_bottom + size + 6, "A new command starts only where the clip rectangle",
           size=size, fill=MUTED)
    s.text(left, left_bottom + size + 6 + lead, "(or the texture) changes: a handful per panel.",
           size=size, fill=MUTED)
    left_bottom += size + 6 + lead + 4

    # ---- right: what the overlay records each frame ----------------------------------
    y = left_bottom + 34 if narrow else 28
    s.text(right, y, "Each frame, Overlay::record", size=size + 1.5, bold=True, fill=BLUE)
    y += 10
    y = lines_box(right, y, col_w, ["SlotBuffers& buffers = slots_[slot]", "memcpy each list's VtxBuffer,",
                                    "IdxBuffer, one after the other:"],
                  BLUE_FILL, BLUE, head="1. upload into this frame's slot", extra=2 * (size + 20))
    # The two buffers, list 0 then list 1.
    bx, bw = right + 9, col_w - 18
    for row, (name, split) in enumerate((("buffers.vertices", 0.55), ("buffers.indices", 0.6))):
        by = y + 4 + row * (size + 20)
        s.text(bx, by + size, name, size=size, mono=True)
        sx = bx + 0.602 * size * 17
        sw = bw - 0.602 * size * 17
        s.rect(sx, by + 1, sw * split, 14, fill=ORANGE_FILL, stroke=ORANGE, width=0.9)
        s.rect(sx + sw * split, by + 1, sw * (1 - split) * 0.8, 14, fill=ORANGE_FILL, stroke=ORANGE,
               width=0.9, dash="3 2")
        s.text(sx + 4, by + size, "list 0", size=size, fill=MUTED)
        s.text(sx + sw * split + 4, by + size, "list 1", size=size, fill=MUTED)
    upload_bottom = y + 4 + 2 * (size + 20)
    y = upload_bottom
    s.line(right + col_w / 2, y, right + col_w / 2, y + 16, stroke=BLUE, width=1.3, arrow="end")
    y += 16
    y = lines_box(right, y, col_w, ["begin_colour_rendering(cmd, target,",
                                    "  extent, VK_ATTACHMENT_LOAD_OP_LOAD)",
                                    "~ over the finished frame: keeps its pixels",
                                    "bind pipeline_, set_ (the font); push",
                                    "  scale, translate: pixels to clip space"],
                  BLUE_FILL, BLUE, head="2. begin rendering over the frame")
    s.line(right + col_w / 2, y, right + col_w / 2, y + 16, stroke=BLUE, width=1.3, arrow="end")
    y += 16
    loop_top = y
    y = lines_box(right, y, col_w, ["x0 = max(ClipRect.x − DisplayPos.x, 0)",
                                    "x1 = min(ClipRect.z − DisplayPos.x,",
                                    "         extent.width) ~ y0, y1 alike",
                                    "~ empty: skipped",
                                    "vkCmdSetScissor(x0, y0, x1 − x0, y1 − y0)",
                                    "vkCmdDrawIndexed(ElemCount, 1,",
                                    "  first_index + IdxOffset,",
                                    "  first_vertex + VtxOffset, 0)",
                                    "~ then first_index, first_vertex += the list's",
                                    "~ IdxBuffer.Size, VtxBuffer.Size"],
                  GREEN_FILL, GREEN, head="3. for each list, each ImDrawCmd")
    s.line(right + col_w / 2, y, right + col_w / 2, y + 16, stroke=BLUE, width=1.3, arrow="end")
    y += 16
    y = lines_box(right, y, col_w, ["vkCmdEndRendering(cmd)"], BLUE_FILL, BLUE)
    bottom = max(y, left_bottom)

    # The hand-over: lists into the upload, each command into the loop.
    if not narrow:
        s.line(list_x + list_w, (vtx_y + idx_y) / 2 + 6, right - 2, (vtx_y + idx_y) / 2 + 6, stroke=ORANGE,
               width=1.4, arrow="end")
        s.polyline([(strip_x + strip_w - 8, cmd_top + ch / 2), (right - 16, cmd_top + ch / 2),
                    (right - 16, loop_top + 40), (right - 2, loop_top + 40)], stroke=GREEN, width=1.4,
                   arrow="end")
    s.height = bottom + 12
    s.items = [item for item in s.items if item]
    s.write()


if __name__ == "__main__":
    main()
