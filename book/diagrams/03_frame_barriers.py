"""Chapter 03's barriers of one frame, in recording order, both ways; and, with
runner=True (04_runner_barriers.py), the runner's, for chapter 04's page.

Chapter 03's are chapters/03_swapchain/main.cpp's record() ([clear], [copy-in],
[to-present]), numbered as the book's list numbers them: its image is cleared
in TRANSFER_DST_OPTIMAL. The runner's (common/frame/src/runner.cpp, record)
hand the chapter its image in COLOR_ATTACHMENT_OPTIMAL; chapter 04 clears with
loadOp CLEAR and draws, with no barrier of its own.

Above, a frame that goes straight into the swapchain image (an _SRGB surface):
barriers 1 and 6 only, both on the swapchain image, the first with the stage
the submission waits at for image_acquired (CLEAR for 03's clear,
COLOR_ATTACHMENT_OUTPUT for the runner's drawing). Below, a frame that goes
into our own image and is copied (a _UNORM surface, or --copy-to-swapchain):
the list's six steps.
"""

import sys

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, GRID, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, Svg, text_width)

TRACK_H = 30
NOTE = TRACK_H + 21  # the first baseline of a note below a track
BOX_W, BOX_H = 232, 146  # a barrier's callout, four to a row

LAYOUT_STYLE = {
    "UNDEFINED": (GREY_FILL, GREY),
    "COLOR_ATTACHMENT_OPTIMAL": (BLUE_FILL, BLUE),
    "TRANSFER_DST_OPTIMAL": (GREEN_FILL, GREEN),
    "TRANSFER_SRC_OPTIMAL": (ORANGE_FILL, ORANGE),
    "PRESENT_SRC_KHR": (PURPLE_FILL, PURPLE),
}

START, END = 40, 984
# Through our target: the barriers' places on the two tracks.
X1, X3, X4, X5A, X5B, X6 = 150, 500, 596, 618, 720, 760
# Straight in: the chapter's part is as wide as below, after a longer wait.
D1 = 330
D6 = D1 + X3 - X1

TOP_A = 54                   # the upper panel: straight into the swapchain image
TRACK_A = TOP_A + 102
CALLOUTS_A = TRACK_A + TRACK_H + 50
TOP_B = CALLOUTS_A + BOX_H + 30  # the lower panel: through our own target
TARGET_Y = TOP_B + 102
SWAP_Y = TARGET_Y + 110
CALLOUTS_B = SWAP_Y + TRACK_H + 52
W, H = 1000, CALLOUTS_B + BOX_H + 34


def main(runner: bool = False) -> None:
    # What fills the image between barrier 1 and the next: 03's clear, in
    # TRANSFER_DST at the CLEAR stage, or the runner's chapter drawing, in
    # COLOR_ATTACHMENT_OPTIMAL at the colour-output stage.
    if runner:
        work, stage, access = "COLOR_ATTACHMENT_OPTIMAL", "COLOR_ATTACHMENT_OUTPUT", "COLOR_ATTACHMENT_WRITE"
        into, own = "drawn", "the runner's own target"
    else:
        work, stage, access = "TRANSFER_DST_OPTIMAL", "CLEAR", "TRANSFER_WRITE"
        into, own = "cleared", "our own image"
    whose = "The runner's" if runner else "Chapter 03's"
    s = Svg(W, H, f"{whose} barriers of a frame, both ways to the swapchain image",
            f"One frame's command buffer from left to right, twice. {into.capitalize()} straight into the "
            f"swapchain image: two barriers on that image, around the {'chapter' if runner else 'clear'}. "
            f"Through {own}: the layouts of that image and of the acquired swapchain image, four "
            "barriers and the copy. For each barrier, its stages and accesses before and after.")

    s.text(START, 28, f"One frame's command buffer in {'the runner' if runner else 'chapter 03'}, in recording "
           "order: the two ways to the swapchain image",
           size=15, bold=True)
    s.line(START, 44, END, 44, stroke=MUTED, arrow="end")

    def heading(top, title, sub):
        s.text(START, top + 16, title, size=13.5, bold=True)
        s.text(START, top + 34, sub, size=12, fill=MUTED)

    def segment(x0, x1, y, layout, label=None, dash=None):
        fill, stroke = LAYOUT_STYLE[layout]
        s.rect(x0, y, x1 - x0, TRACK_H, fill=fill, stroke=stroke, width=1.2, dash=dash)
        text = label if label is not None else layout
        s.text((x0 + x1) / 2, y + TRACK_H / 2 + 4, text, size=10.5, anchor="middle", mono=True)

    def not_yet_ours(x0, x1, y):
        """The swapchain image before the semaphore wait: the presentation engine's."""
        s.rect(x0, y, x1 - x0, TRACK_H, fill="#ffffff", stroke=GREY, dash="4 3")
        s.text((x0 + x1) / 2, y + TRACK_H / 2 + 4, "may still be read by the presentation engine", size=10.5,
               anchor="middle", fill=MUTED)

    def waits_here(x, y, stage):
        """The semaphore wait that holds back `stage`, and with it the barrier at x."""
        s.polyline([(x - 34, y + TRACK_H + 17), (x - 8, y + TRACK_H + 17), (x - 8, y + TRACK_H + 4)],
                   stroke=PURPLE, width=1.5, arrow="end")
        s.lines(x - 38, y + NOTE, ["the submission waits for image_acquired", f"at {stage}"],
                size=10.5, leading=1.3, anchor="end", fill=PURPLE)

    def presented(x, y):
        s.lines(x, y + NOTE, ["then vkQueuePresentKHR,", "after the submission signals ready_to_present"],
                size=10.5, leading=1.3, anchor="end", fill=PURPLE)

    def barrier(x, y, name, minor=False):
        s.line(x, y - 8, x, y + TRACK_H + 8, stroke=INK if not minor else MUTED, width=2.4 if not minor else 1.4)
        s.circle(x, y - 20, 10, fill=INK if not minor else "#ffffff", stroke=INK if not minor else MUTED)
        s.text(x, y - 16, name, size=11.5, anchor="middle", fill="#ffffff" if not minor else MUTED, bold=True)

    def chapter_segments(x1, y):
        """Between barrier 1 and the next: the clear (03), or what the chapter records (runner)."""
        segment(x1, x1 + X3 - X1, y, work)

    def callout(column, top, name, image, old, new, src, dst, why):
        """A barrier's box: its layouts, and its stage and access before (src) and after (dst)."""
        bx = START + column * (BOX_W + 6)
        s.rect(bx, top, BOX_W, BOX_H, fill="#fbfcfd", stroke=GREY, rx=6)
        s.circle(bx + 16, top + 17, 9, fill=INK, stroke=INK)
        s.text(bx + 16, top + 21, name, size=11, anchor="middle", fill="#ffffff", bold=True)
        s.text(bx + 32, top + 22, image, size=12.5, bold=True)
        s.text(bx + 10, top + 42, old, size=10.5, mono=True,
               fill=LAYOUT_STYLE[old][1] if old != "UNDEFINED" else GREY)
        s.text(bx + 10, top + 56, "\u2192 " + new, size=10.5, mono=True, fill=LAYOUT_STYLE[new][1])
        s.text(bx + 10, top + 76, "before", size=10.5, fill=MUTED)
        s.lines(bx + 58, top + 76, list(src), size=10.5, leading=1.25, mono=True)
        s.text(bx + 10, top + 106, "after", size=10.5, fill=MUTED)
        s.lines(bx + 58, top + 106, list(dst), size=10.5, leading=1.25, mono=True)
        assert text_width(why, 11) < BOX_W - 16, why
        s.text(bx + 10, top + 136, why, size=11, fill=INK, italic=True)

    # ---- Straight into the swapchain image --------------------------------------
    heading(TOP_A, f"{into.capitalize()} straight into the swapchain image (an _SRGB surface, usually a window)",
            "Two barriers, both on the swapchain image: no image of our own, no copy.")
    s.text(START, TRACK_A - 38, "the acquired swapchain image", size=12.5, bold=True)
    not_yet_ours(START, D1, TRACK_A)
    chapter_segments(D1, TRACK_A)
    segment(D6, END - 70, TRACK_A, "PRESENT_SRC_KHR")
    barrier(D1, TRACK_A, "1")
    barrier(D6, TRACK_A, "6")
    waits_here(D1, TRACK_A, stage)
    s.text((D1 + D6) / 2, TRACK_A + NOTE, "2  the chapter records (box below)" if runner else
           "2  vkCmdClearColorImage (box below)", size=11.5, anchor="middle", bold=True)
    presented(END - 70, TRACK_A)

    callout(0, CALLOUTS_A, "1", "swapchain image", "UNDEFINED", work,
            (stage, "NONE"), (stage, "COLOR_ATTACHMENT_WRITE|READ" if runner else access),
            "after the semaphore wait (same stage)")
    callout(3, CALLOUTS_A, "6", "swapchain image", work, "PRESENT_SRC_KHR",
            (stage, access), ("NONE", "NONE"),
            "the semaphore orders the present")
    # The chapter's part, the same either way, in the two columns between.
    bx0, bx1 = START + BOX_W + 6, START + 3 * BOX_W + 12
    s.rect(bx0, CALLOUTS_A, bx1 - bx0, BOX_H, fill="#ffffff", stroke=GREY, rx=6, dash="4 3")
    if runner:
        title = "2  the chapter records (the same either way)"
        what = ["04: loadOp CLEAR, then draw: no barrier of its own",
                "(03 writes its own loop: a clear, in TRANSFER_DST)"]
        note = ["The wait holds back the colour output only: a chapter's vertex",
                "shading or compute may run before the image is free."]
    else:
        title = "2  vkCmdClearColorImage (the same either way)"
        what = ["a transfer command: the image in TRANSFER_DST,",
                "written at the CLEAR stage (TRANSFER_WRITE)"]
        note = ["With --screenshot, before 6: the swapchain image to",
                "TRANSFER_SRC, read back, and from there to PRESENT_SRC."]
    s.text(bx0 + 12, CALLOUTS_A + 22, title, size=12.5, bold=True)
    s.lines(bx0 + 12, CALLOUTS_A + 44, what, size=10.5, leading=1.3, mono=True)
    s.lines(bx0 + 12, CALLOUTS_A + 106, note, size=11, leading=1.3, italic=True)

    s.line(START, TOP_B - 14, END, TOP_B - 14, stroke=GRID, width=1)

    # ---- Through the runner's own target -----------------------------------------
    heading(TOP_B, f"Through {own} (a _UNORM surface, or --copy-to-swapchain)",
            "Six steps: the chapter draws into our target, which the runner copies into the swapchain image."
            if runner else "Six steps: the clear goes into our own _SRGB image, which is copied into the "
            "swapchain image.")
    s.text(START, TARGET_Y - 38, f"{own} (one image, shared by both slots)", size=12.5, bold=True)
    segment(START, X1, TARGET_Y, "UNDEFINED", "UNDEFINED")
    chapter_segments(X1, TARGET_Y)
    segment(X3, X5B, TARGET_Y, "TRANSFER_SRC_OPTIMAL", "TRANSFER_SRC")
    s.text((X1 + X3) / 2, TARGET_Y + NOTE, "2  the chapter records (box above)" if runner else
           "2  the clear (box above)", size=11.5, anchor="middle", bold=True)

    s.text(START, SWAP_Y - 38, "the acquired swapchain image", size=12.5, bold=True)
    not_yet_ours(START, X4, SWAP_Y)
    segment(X4, X6, SWAP_Y, "TRANSFER_DST_OPTIMAL", "TRANSFER_DST")
    segment(X6, END - 70, SWAP_Y, "PRESENT_SRC_KHR")
    waits_here(X4, SWAP_Y, "COPY")
    presented(END - 70, SWAP_Y)

    # Step 5, the copy.
    s.line((X5A + X5B) / 2, TARGET_Y + TRACK_H, (X5A + X5B) / 2, SWAP_Y, stroke=INK, width=2, arrow="end")
    s.text((X5A + X5B) / 2 + 6, SWAP_Y - 44, "5  vkCmdCopyImage", size=11.5, bold=True)

    barrier(X1, TARGET_Y, "1")
    barrier(X3, TARGET_Y, "3")
    barrier(X4, SWAP_Y, "4")
    barrier(X6, SWAP_Y, "6")

    callouts = [
        ("1", "target" if runner else "our image", "UNDEFINED", work,
         ("COPY", "NONE"), (stage, "COLOR_ATTACHMENT_WRITE|READ" if runner else access),
         "after the last frame's copy read it"),
        ("3", "target" if runner else "our image", work, "TRANSFER_SRC_OPTIMAL",
         (stage, access), ("COPY", "TRANSFER_READ"),
         "the drawing is done and visible" if runner else "the clear is done and visible"),
        ("4", "swapchain image", "UNDEFINED", "TRANSFER_DST_OPTIMAL",
         ("COPY", "NONE"), ("COPY", "TRANSFER_WRITE"),
         "after the semaphore wait at COPY"),
        ("6", "swapchain image", "TRANSFER_DST_OPTIMAL", "PRESENT_SRC_KHR",
         ("COPY", "TRANSFER_WRITE"), ("NONE", "NONE"),
         "the semaphore orders the present"),
    ]
    for column, callout_args in enumerate(callouts):
        callout(column, CALLOUTS_B, *callout_args)

    s.text(START, H - 12, "Stage names drop VK_PIPELINE_STAGE_2_, accesses VK_ACCESS_2_ and layouts "
           "VK_IMAGE_LAYOUT_; the first line of 'before' and 'after' is the stage, the second the access.",
           size=10.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main(runner="--runner" in sys.argv)
