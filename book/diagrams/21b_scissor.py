"""Chapter 21b: one draw command's scissor, and a glyph it cuts.

The target (the frame the overlay draws over), the panel in its top left
corner, and one ImDrawCmd's ClipRect: the panel's inner rectangle. Minus
DisplayPos ((0, 0): one window, one target) and clamped to the target, it is
the VkRect2D the overlay gives vkCmdSetScissor. A line of text runs past the
clip's right edge; one glyph, one quad of two triangles that Dear ImGui emits
whole, straddles the edge, and the scissor test discards the part of it
outside. A schematic: the sizes are not the panel's.

Every name is one that common/frame/src/overlay.cpp uses; the script checks
that the file still says the lines the figure draws, so the two cannot drift.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
steps go under the picture, 400 units wide.
"""

import os
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, RED,
                 RED_FILL, Svg, text_width)

OVERLAY_CPP = Path(__file__).resolve().parents[2] / "common" / "frame" / "src" / "overlay.cpp"

# What overlay.cpp must say (whitespace folded) for the figure to be right.
CODE = [
    "for (const ImDrawCmd& draw : list->CmdBuffer) {",
    "const float x0 = std::max(draw.ClipRect.x - data->DisplayPos.x, 0.0f);",
    "const float y0 = std::max(draw.ClipRect.y - data->DisplayPos.y, 0.0f);",
    "const float x1 = std::min(draw.ClipRect.z - data->DisplayPos.x, float(extent.width));",
    "const float y1 = std::min(draw.ClipRect.w - data->DisplayPos.y, float(extent.height));",
    "if (draw.UserCallback || x1 <= x0 || y1 <= y0) continue;",
    "const VkRect2D scissor{{int32_t(x0), int32_t(y0)}, {uint32_t(x1 - x0), uint32_t(y1 - y0)}};",
    "vkCmdSetScissor(cmd, 0, 1, &scissor);",
    "vkCmdDrawIndexed(cmd, draw.ElemCount, 1,",
]

TEXT = "Sample shading"
CUT = 10  # the glyph the clip's right edge goes through: the "d"


def check_source() -> None:
    code = " ".join(OVERLAY_CPP.read_text(encoding="utf-8").split())
    for want in CODE:
        if " ".join(want.split()) not in code:
            raise SystemExit(f"common/frame/src/overlay.cpp: no longer says `{want[:60]}`; "
                             "redraw book/diagrams/21b_scissor.py")


def main() -> None:
    check_source()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 11 if narrow else 12.5
    lead = size * 1.35
    f = 0.66 if narrow else 1.0  # the picture's scale
    W = 400 if narrow else 960
    s = Svg(W, 100, "Chapter 21b: one draw command's scissor, and a glyph it cuts",
            "The target, the panel in its top left corner, and one ImDrawCmd's ClipRect, the "
            "panel's inner rectangle, drawn dashed in green. Minus DisplayPos, (0, 0) here, and "
            "clamped to the target, it becomes the VkRect2D scissor: offset (x0, y0), extent "
            "(x1 − x0, y1 − y0). The text 'Sample shading' runs past the clip's right edge: the "
            "glyph 'd' is one quad of two triangles, emitted whole, half inside; the scissor test "
            "discards its pixels right of the edge, shaded red, and only the left half is drawn.")

    # ---- the picture: target, panel, clip rectangle, glyphs ---------------------------
    ox, oy = 14, 46  # the target's top left corner on the page
    tw, th = 560 * f, 330 * f

    def at(x, y):
        return ox + x * f, oy + y * f

    s.text(ox, 20, "The target: extent.width × extent.height pixels", size=size + 1.5, bold=True)
    s.text(ox, 20 + lead, "(Dear ImGui's display = the target: DisplayPos (0, 0))", size=size,
           fill=MUTED)
    s.rect(ox, oy, tw, th, fill=GREY_FILL, stroke=GREY, width=1.3)
    # The chapter's picture under the panel: a few spokes.
    cx, cy = at(470, 250)
    for k in range(7):
        ex, ey = at(470 - 420 + 70 * k, 0)
        s.line(cx, cy, ex, ey + 2, stroke="#c9cfd6", width=2.5 * f)
    s.text(ox + 4, oy + size + 2, "(0, 0)", size=size, fill=MUTED)
    s.text(ox + tw - 6, oy + th - 8, "the chapter's picture, kept by LOAD", size=size, anchor="end",
           fill=MUTED)

    # The panel: a window with its title bar.
    px, py = at(30, 40)
    pw, ph = 330 * f, 220 * f
    s.rect(px, py, pw, ph, fill="#dde6f3", stroke=BLUE, width=1.3, rx=3)
    s.rect(px, py, pw, 26 * f + 4, fill=BLUE_FILL, stroke=BLUE, width=1.3, rx=3)
    s.text(px + 8, py + 26 * f / 2 + 2 + size * 0.35, "Settings", size=size, bold=True)

    # The clip rectangle: the panel's inner part.
    bx, by = at(38, 76)
    base_x, base_y = at(48, 150)
    glyph = 40 * f
    x_at = [base_x]
    for c in TEXT:
        x_at.append(x_at[-1] + text_width(c, glyph))
    clip_x1 = (x_at[CUT] + x_at[CUT + 1]) / 2
    clip_y1 = py + ph - 8 * f
    s.rect(bx, by, clip_x1 - bx, clip_y1 - by, stroke=GREEN, width=2, dash="7 4")

    # The glyphs Dear ImGui emits: those that reach inside the clip (the "ing" past it
    # would lie wholly outside), each a quad; the cut one in orange, its outer part red.
    top, bottom = base_y - 0.95 * glyph, base_y + 0.25 * glyph
    for i, c in enumerate(TEXT[:CUT + 1]):
        if c == " ":
            continue
        x0, x1 = x_at[i], x_at[i + 1]
        if i == CUT:
            s.rect(clip_x1, top, x1 - clip_x1, bottom - top, fill=RED_FILL, stroke=RED, width=1.2,
                   dash="4 3")
            s.rect(x0, top, x1 - x0, bottom - top, stroke=ORANGE, width=1.5)
            s.line(x0, bottom, x1, top, stroke=ORANGE, width=1.0)
        else:
            s.rect(x0, top, x1 - x0, bottom - top, stroke="#a8b3bf", width=0.8)
    s.add('<clipPath id="scissor21b"><rect x="{:.1f}" y="{:.1f}" width="{:.1f}" height="{:.1f}"/>'
          '</clipPath>'.format(bx, by, clip_x1 - bx, clip_y1 - by))
    s.add(f'<g opacity="0.3">')
    s.text(x_at[CUT], base_y, TEXT[CUT], size=glyph, fill=INK)
    s.add("</g>")
    s.add('<g clip-path="url(#scissor21b)">')
    s.text(base_x, base_y, TEXT[:CUT + 1], size=glyph, fill=INK)
    s.add("</g>")

    # Corner labels and the scissor's extent.
    s.circle(bx, by, 3, fill=GREEN, stroke=GREEN)
    s.circle(clip_x1, clip_y1, 3, fill=GREEN, stroke=GREEN)
    s.line(ox + 2, oy + 2, bx - 3, by - 3, stroke=GREEN, width=1.1, dash="3 3", arrow="end")
    s.text(bx + 6, by + size + 3, "(x0, y0): offset", size=size, fill=GREEN, bold=True)
    s.text(clip_x1 - 6, clip_y1 - 6, "(x1, y1)", size=size, fill=GREEN, bold=True, anchor="end")
    ey = clip_y1 + 16 * f + 6
    s.line(bx, ey, clip_x1, ey, stroke=GREEN, width=1.2, arrow="both")
    s.text((bx + clip_x1) / 2, ey + size + 4, "extent.width = x1 − x0", size=size, fill=GREEN,
           anchor="middle")
    # Callouts: the quad, the discarded part.
    qx = (x_at[CUT] + x_at[CUT + 1]) / 2
    if narrow:
        # No room beside the panel: a key under the picture.
        ky = oy + th + lead + 8
        s.rect(ox, ky - size, 16, size + 2, fill=RED_FILL, stroke=RED, dash="4 3")
        s.text(ox + 22, ky, "discarded by the scissor: the quad's", size=size, fill=RED, bold=True)
        s.text(ox + 22, ky + lead, "pixels right of x1", size=size, fill=RED)
        ky += 2 * lead + 6
        s.rect(ox, ky - size, 16, size + 2, stroke=ORANGE, width=1.5)
        s.text(ox + 22, ky, "one glyph: one quad (two triangles),", size=size, fill=ORANGE, bold=True)
        s.text(ox + 22, ky + lead, "emitted whole by Dear ImGui", size=size, fill=ORANGE)
        key_bottom = ky + lead
    else:
        lx = px + pw + 20
        s.line(x_at[CUT + 1] + 2, (top + bottom) / 2, lx - 4, top - 10, stroke=RED, width=1.1)
        s.text(lx, top - 14, "discarded by the scissor:", size=size, fill=RED, bold=True)
        s.text(lx, top - 14 + lead, "the quad's pixels right of x1", size=size, fill=RED)
        s.line(qx, bottom + 1, lx - 4, bottom + 40, stroke=ORANGE, width=1.1)
        s.text(lx, bottom + 36, "one glyph: one quad", size=size, fill=ORANGE, bold=True)
        s.text(lx, bottom + 36 + lead, "(two triangles), emitted", size=size, fill=ORANGE)
        s.text(lx, bottom + 36 + 2 * lead, "whole by Dear ImGui", size=size, fill=ORANGE)
        key_bottom = 0
    pic_bottom = max(oy + th, ey + size + 8, key_bottom)

    # ---- the steps: ClipRect to VkRect2D ----------------------------------------------
    if narrow:
        sx, sy, sw = 10, pic_bottom + 22, 380
    else:
        sx, sy, sw = 604, 28, 342
    steps = [
        ("ImDrawCmd draw: draw.ClipRect", ["x0, y0, x1, y1 (display pixels)"], GREY_FILL, GREY),
        ("− data->DisplayPos", ["(0, 0) here: one window, so", "display pixels = target pixels"],
         GREY_FILL, GREY),
        ("clamped to the target", ["x0, y0 ≥ 0; x1 ≤ extent.width,", "y1 ≤ extent.height",
                                   "empty (x1 ≤ x0 or y1 ≤ y0): skipped"], GREY_FILL, GREY),
        ("VkRect2D scissor", ["offset {x0, y0}", "extent {x1 − x0, y1 − y0}"], GREEN_FILL, GREEN),
        ("vkCmdSetScissor(cmd, 0, 1, &scissor)", ["then vkCmdDrawIndexed: each pixel",
                                                  "outside the scissor is discarded"],
         GREEN_FILL, GREEN),
    ]
    y = sy
    for i, (head, lines, fill, stroke) in enumerate(steps):
        h = (len(lines) + 1) * lead + 10
        s.rect(sx, y, sw, h, fill=fill, stroke=stroke, rx=6, width=1.3)
        s.text(sx + 9, y + 5 + size, head, size=size, bold=True, mono=True)
        for k, line in enumerate(lines):
            s.text(sx + 9, y + 5 + size + (k + 1) * lead, line, size=size, fill=INK if k < 2 else MUTED)
        y += h
        if i < len(steps) - 1:
            s.line(sx + sw / 2, y, sx + sw / 2, y + 14, stroke=GREY, width=1.3, arrow="end")
            y += 14
    s.height = max(y, pic_bottom) + 12
    s.write()


if __name__ == "__main__":
    main()
