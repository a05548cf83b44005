"""Chapters 03 and 04: the barriers of one frame, in recording order.

The runner's barriers are common/frame/src/runner.cpp [frame-barriers]
(numbered as the book's list numbers them); a and b are chapter 03's own
(chapters/03_swapchain/main.cpp [to-transfer] and [to-attachment]); chapter 04
clears with loadOp CLEAR instead and needs none.
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, Svg)

W, H = 1000, 596
TARGET_Y, SWAP_Y, TRACK_H = 100, 290, 30

LAYOUT_STYLE = {
    "UNDEFINED": (GREY_FILL, GREY),
    "COLOR_ATTACHMENT_OPTIMAL": (BLUE_FILL, BLUE),
    "TRANSFER_DST_OPTIMAL": (GREEN_FILL, GREEN),
    "TRANSFER_SRC_OPTIMAL": (ORANGE_FILL, ORANGE),
    "PRESENT_SRC_KHR": (PURPLE_FILL, PURPLE),
}

X1, XA, XB, X3, X4, X5A, X5B, X6 = 150, 236, 396, 500, 596, 618, 720, 760
START, END = 40, 984


def main() -> None:
    s = Svg(W, H, "Chapters 03 and 04: the barriers of a frame",
            "One frame's command buffer from left to right: the layouts of the runner's own target "
            "and of the acquired swapchain image, and each barrier's stages and accesses before "
            "and after.")

    s.text(START, 28, "One frame's command buffer, in recording order", size=15, bold=True)
    s.line(START, 44, END, 44, stroke=MUTED, arrow="end")

    def segment(x0, x1, y, layout, label=None, dash=None):
        fill, stroke = LAYOUT_STYLE[layout]
        s.rect(x0, y, x1 - x0, TRACK_H, fill=fill, stroke=stroke, width=1.2, dash=dash)
        text = label if label is not None else layout
        s.text((x0 + x1) / 2, y + TRACK_H / 2 + 4, text, size=10.5, anchor="middle", mono=True)

    # Our target.
    s.text(START, TARGET_Y - 38, "the runner's own target (one image, shared by both slots)", size=12.5,
           bold=True)
    segment(START, X1, TARGET_Y, "UNDEFINED", "UNDEFINED")
    segment(X1, XA, TARGET_Y, "COLOR_ATTACHMENT_OPTIMAL", "COLOR_ATT.")
    segment(XA, XB, TARGET_Y, "TRANSFER_DST_OPTIMAL", "TRANSFER_DST (03)")
    segment(XB, X3, TARGET_Y, "COLOR_ATTACHMENT_OPTIMAL", "COLOR_ATT.")
    segment(X3, X5B, TARGET_Y, "TRANSFER_SRC_OPTIMAL", "TRANSFER_SRC")

    # The chapter's part, between barriers 1 and 3.
    bx0, bx1, by = X1 + 4, X3 - 4, TARGET_Y + TRACK_H + 10
    s.rect(bx0, by, bx1 - bx0, 92, fill="#ffffff", stroke=GREY, rx=5, dash="4 3")
    s.text((bx0 + bx1) / 2, by + 17, "2  the chapter records", size=11.5, anchor="middle", bold=True)
    s.lines(bx0 + 10, by + 34, ["03: a, vkCmdClearColorImage, b", "    a, b: COLOR_ATTACHMENT_OUTPUT",
                                "          \u21c4 CLEAR stage",
                                "04: loadOp CLEAR, draw: no barrier"], size=10.5, leading=1.25, mono=True)

    # The swapchain image.
    s.text(START, SWAP_Y - 38, "the acquired swapchain image", size=12.5, bold=True)
    s.rect(START, SWAP_Y, X4 - START, TRACK_H, fill="#ffffff", stroke=GREY, dash="4 3")
    s.text((START + X4) / 2, SWAP_Y + TRACK_H / 2 + 4,
           "may still be read by the presentation engine until image_acquired", size=10.5,
           anchor="middle", fill=MUTED)
    segment(X4, X6, SWAP_Y, "TRANSFER_DST_OPTIMAL", "TRANSFER_DST")
    segment(X6, END - 70, SWAP_Y, "PRESENT_SRC_KHR", "PRESENT_SRC_KHR")
    s.text(END - 70, SWAP_Y + TRACK_H + 18, "then vkQueuePresentKHR,", size=10.5, anchor="end",
           fill=PURPLE)
    s.text(END - 70, SWAP_Y + TRACK_H + 32, "after the submission signals ready_to_present", size=10.5,
           anchor="end", fill=PURPLE)

    # The semaphore wait that holds back the COPY stage.
    s.polyline([(X4 - 110, SWAP_Y + TRACK_H + 26), (X4 - 8, SWAP_Y + TRACK_H + 26), (X4 - 8, SWAP_Y + TRACK_H + 4)],
               stroke=PURPLE, width=1.5, arrow="end")
    s.text(X4 - 112, SWAP_Y + TRACK_H + 30, "the submission waits for image_acquired at COPY", size=10.5,
           anchor="end", fill=PURPLE)

    # Step 5, the copy.
    s.line((X5A + X5B) / 2, TARGET_Y + TRACK_H, (X5A + X5B) / 2, SWAP_Y, stroke=INK, width=2, arrow="end")
    s.text((X5A + X5B) / 2 + 6, SWAP_Y - 60, "5  vkCmdCopyImage", size=11.5, bold=True)

    # The barrier lines.
    def barrier(x, y0, y1, name, minor=False):
        s.line(x, y0 - 8, x, y1 + 8, stroke=INK if not minor else MUTED, width=2.4 if not minor else 1.4)
        s.circle(x, y0 - 20, 10, fill=INK if not minor else "#ffffff", stroke=INK if not minor else MUTED)
        s.text(x, y0 - 16, name, size=11.5, anchor="middle", fill="#ffffff" if not minor else MUTED,
               bold=True)

    barrier(X1, TARGET_Y, TARGET_Y + TRACK_H, "1")
    barrier(XA, TARGET_Y, TARGET_Y + TRACK_H, "a", minor=True)
    barrier(XB, TARGET_Y, TARGET_Y + TRACK_H, "b", minor=True)
    barrier(X3, TARGET_Y, TARGET_Y + TRACK_H, "3")
    barrier(X4, SWAP_Y, SWAP_Y + TRACK_H, "4")
    barrier(X6, SWAP_Y, SWAP_Y + TRACK_H, "6")

    # The callouts: stage and access before (src) and after (dst).
    callouts = [
        (X1, TARGET_Y, "1", "target", "UNDEFINED", "COLOR_ATTACHMENT_OPTIMAL",
         ("COPY", "NONE"), ("COLOR_ATTACHMENT_OUTPUT", "COLOR_ATTACHMENT_WRITE|READ"),
         "after the last frame's copy read it"),
        (X3, TARGET_Y, "3", "target", "COLOR_ATTACHMENT_OPTIMAL", "TRANSFER_SRC_OPTIMAL",
         ("COLOR_ATTACHMENT_OUTPUT", "COLOR_ATTACHMENT_WRITE"), ("COPY", "TRANSFER_READ"),
         "the drawing is done and visible"),
        (X4, SWAP_Y, "4", "swapchain image", "UNDEFINED", "TRANSFER_DST_OPTIMAL",
         ("COPY", "NONE"), ("COPY", "TRANSFER_WRITE"),
         "after the semaphore wait at COPY"),
        (X6, SWAP_Y, "6", "swapchain image", "TRANSFER_DST_OPTIMAL", "PRESENT_SRC_KHR",
         ("COPY", "TRANSFER_WRITE"), ("NONE", "NONE"),
         "the semaphore orders the present"),
    ]
    box_w, box_h, top = 232, 168, 398
    for i, (x, y, name, image, old, new, src, dst, why) in enumerate(callouts):
        bx = START + i * (box_w + 6)
        s.rect(bx, top, box_w, box_h, fill="#fbfcfd", stroke=GREY, rx=6)
        s.circle(bx + 16, top + 17, 9, fill=INK, stroke=INK)
        s.text(bx + 16, top + 21, name, size=11, anchor="middle", fill="#ffffff", bold=True)
        s.text(bx + 32, top + 22, image, size=12.5, bold=True)
        fill, stroke = LAYOUT_STYLE[old]
        s.text(bx + 10, top + 44, old, size=10.5, mono=True, fill=stroke if old != "UNDEFINED" else GREY)
        fill, stroke = LAYOUT_STYLE[new]
        s.text(bx + 10, top + 58, "\u2192 " + new, size=10.5, mono=True, fill=stroke)
        s.text(bx + 10, top + 80, "before", size=10.5, fill=MUTED)
        s.lines(bx + 58, top + 80, list(src), size=10.5, leading=1.25, mono=True)
        s.text(bx + 10, top + 114, "after", size=10.5, fill=MUTED)
        s.lines(bx + 58, top + 114, list(dst), size=10.5, leading=1.25, mono=True)
        s.text(bx + 10, top + 154, why, size=11, fill=INK, italic=True)

    s.text(START, H - 12, "Stage names drop VK_PIPELINE_STAGE_2_, accesses VK_ACCESS_2_ and layouts "
           "VK_IMAGE_LAYOUT_; the first line of 'before' and 'after' is the stage, the second the access.",
           size=10.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
