"""Chapter 21b: one frame's two renderings into one image, in recording order.

Chapter 21's own rendering draws into its multisampled colour image (colour_,
loadOp CLEAR, storeOp DONT_CARE) and, at vkCmdEndRendering, resolves each
pixel's samples into the frame's target. Then the runner's barrier, then the
overlay's rendering into that same target with loadOp LOAD (storeOp STORE),
blending the panel over the picture it kept; then the barrier to
PRESENT_SRC_KHR, the submit and the present. Drawn for a window whose swapchain
is _SRGB (the frame goes straight into the swapchain image); a note says what
changes where the runner draws into its own image and copies it.

Every call, layout, stage, access and op the figure names is read, in order,
from common/frame/src/runner.cpp (record, draw_frame), runner.hpp
(drawn_by_colour_output, the default target_after), chapter 21's main.cpp
(record), common/frame/src/overlay.cpp (record) and common/resources/src/
rendering.cpp (begin_colour_rendering): a call that vanishes or moves stops the
book's build.

Wide: the steps in a column on the left, and beside them the two images'
layouts, step by step. With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it,
for phones) the tracks are left out and each step names its layouts itself,
380 units wide.
"""

import os
from pathlib import Path

from golden import GOLDEN, enlarged, read_png
from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, Svg, text_width)

ROOT = Path(__file__).resolve().parents[2]
RUNNER = ROOT / "common" / "frame" / "src" / "runner.cpp"
RUNNER_HPP = ROOT / "common" / "frame" / "include" / "vkt" / "frame" / "runner.hpp"
CHAPTER = ROOT / "chapters" / "21_multisampling" / "main.cpp"
OVERLAY = ROOT / "common" / "frame" / "src" / "overlay.cpp"
DEPTH = ROOT / "common" / "resources" / "src" / "depth.cpp"
RENDERING = ROOT / "common" / "resources" / "src" / "rendering.cpp"


def stop(path: Path, what: str) -> None:
    raise SystemExit(f"{path.relative_to(ROOT)}: {what}; redraw book/diagrams/21b_two_renderings.py")


def folded(path: Path) -> str:
    return " ".join(path.read_text(encoding="utf-8").split())


def in_order(path: Path, needles: list) -> None:
    """Each needle (whitespace folded) occurs in path, after the one before it."""
    text, at, before = folded(path), 0, None
    for needle in needles:
        needle = " ".join(needle.split())
        found = text.find(needle, at)
        if found < 0:
            stop(path, f"'{needle[:70]}' is not there after '{before[:50]}'" if before
                 else f"'{needle[:70]}' is not there")
        at, before = found + len(needle), needle


def check_sources() -> None:
    in_order(RUNNER, [
        # draw_frame: the acquire, the recording, the submit, the present.
        "vkAcquireNextImageKHR(", "slot.image_acquired", "record(slot, image_index, frame);",
        ".semaphore = slot.image_acquired, .stageMask = acquire_wait_stage(),",
        ".semaphore = swapchain_->ready_to_present(image_index),",
        "vkQueueSubmit2(", "VkResult result = vkQueuePresentKHR(device_.queue(), &present);",
        # record: the barrier before the chapter, the chapter, the overlay, the present barrier.
        "image_barrier( cmd, frame.target, VK_IMAGE_LAYOUT_UNDEFINED, frame.target_layout, "
        "frame.target_ready, VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "
        "VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT);",
        "renderer_->record(frame);",
        "TargetWrite last = renderer_->target_after(frame);",
        "leave(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, "
        "VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);",
        "overlay_->record(cmd, frame.slot, frame.target_view, frame.extent);",
        "last = drawn_by_colour_output;",
        "if (!straight) leave(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL",
        "vkCmdCopyImage(",
        "image_barrier(cmd, image, layout, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, stage, access, "
        "VK_PIPELINE_STAGE_2_NONE, VK_ACCESS_2_NONE);",
        # Drawn straight into the swapchain image: the stage waited at and first written.
        "return drawn_into() ? VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT : VK_PIPELINE_STAGE_2_COPY_BIT;",
        "return drawn_into() ? VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT : VK_PIPELINE_STAGE_2_NONE;",
    ])
    in_order(RUNNER_HPP, [
        "drawn_by_colour_output{VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, "
        "VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT};",
        "virtual TargetWrite target_after(const Frame&) const { return drawn_by_colour_output; }",
    ])
    if "target_after" in folded(CHAPTER):
        stop(CHAPTER, "chapter 21 now says its own target_after (the figure has the runner's default)")
    in_order(CHAPTER, ['.name = "--samples",', '.default_value = "4"'])
    in_order(DEPTH, ["void begin_depth_frame(", "VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL,"])
    in_order(CHAPTER, [
        "void record(const vkt::Frame& frame) override {",
        "vkt::begin_depth_frame(frame.cmd, depth_.image);",
        "frame.cmd, colour_.image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,",
        ".imageView = msaa ? VkImageView(colour_.view) : frame.target_view,",
        ".resolveMode = msaa ? VK_RESOLVE_MODE_AVERAGE_BIT : VK_RESOLVE_MODE_NONE,",
        ".resolveImageView = msaa ? frame.target_view : VK_NULL_HANDLE,",
        ".resolveImageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,",
        ".loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR,",
        ".storeOp = msaa ? VK_ATTACHMENT_STORE_OP_DONT_CARE : VK_ATTACHMENT_STORE_OP_STORE,",
        "vkCmdBeginRendering(frame.cmd, &rendering);",
        "vkCmdDrawIndexed(frame.cmd, wheel_indices_,",
        "vkCmdDrawIndexed(frame.cmd, index_count_ - wheel_indices_,",
        "vkCmdEndRendering(frame.cmd);",
    ])
    in_order(OVERLAY, [
        ".alpha_blend = true",
        "SlotBuffers& buffers = slots_[slot]; upload(buffers,",
        "begin_colour_rendering(cmd, target, extent, VK_ATTACHMENT_LOAD_OP_LOAD);",
        "vkCmdDrawIndexed(cmd, draw.ElemCount,",
        "vkCmdEndRendering(cmd);",
    ])
    in_order(RENDERING, [
        "void begin_colour_rendering(", ".imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL,",
        ".loadOp = load,", ".storeOp = VK_ATTACHMENT_STORE_OP_STORE,", "vkCmdBeginRendering(cmd, &rendering);",
    ])


# The picture after R2, the overlay's rendering: the overlay test's, 640x480, shrunk five times.
PICTURE = "21_multisampling_overlay.png"
PICTURE_W, PICTURE_H, SHRINK = 640, 480, 5


def picture():
    pixels = read_png(GOLDEN / PICTURE)
    if (len(pixels[0]), len(pixels)) != (PICTURE_W, PICTURE_H):
        stop(GOLDEN / PICTURE, f"is not {PICTURE_W}x{PICTURE_H}")
    return pixels


def shrunk(s: Svg, pixels, x: float, y: float) -> None:
    """The picture, each SHRINK x SHRINK block averaged to one pixel, in a thin frame."""
    rows = []
    for by in range(0, PICTURE_H, SHRINK):
        row = []
        for bx in range(0, PICTURE_W, SHRINK):
            block = [pixels[by + j][bx + i] for j in range(SHRINK) for i in range(SHRINK)]
            row.append(tuple(round(sum(p[c] for p in block) / len(block)) for c in range(3)))
        rows.append(row)
    enlarged(s, rows, 0, 0, len(rows[0]), len(rows), x, y, 1)


# Layout -> (fill, stroke), as chapter 03's and 04's barrier figures colour them.
LAYOUTS = {
    "UNDEFINED": (GREY_FILL, GREY),
    "COLOR_ATTACHMENT_OPTIMAL": (BLUE_FILL, BLUE),
    "PRESENT_SRC_KHR": (PURPLE_FILL, PURPLE),
}

# The steps, in recording order: (kind, title, who, lines). kind: barrier,
# rendering or queue. A line is (head, code, remark): a bold word, monospace
# code, a grey remark, any of them empty.
STEPS = [
    ("barrier", "B1  barrier: the target, for drawing", "the runner", [
        ("layout", "UNDEFINED →", ""),
        ("", "COLOR_ATTACHMENT_OPTIMAL", ""),
        ("", "", "after the submit's wait for image_acquired, at"),
        ("", "", "the same stage, COLOR_ATTACHMENT_OUTPUT")]),
    ("barrier", "B2  barriers: the chapter's own images", "chapter 21", [
        ("colour_", "UNDEFINED → COLOR_ATTACHMENT_OPTIMAL", ""),
        ("depth_", "UNDEFINED → DEPTH_ATTACHMENT_OPTIMAL", ""),
        ("", "", "last frame's samples thrown away")]),
    ("rendering", "R1  rendering: the wheel and the quads", "chapter 21's record()", [
        ("colour_", "loadOp CLEAR, storeOp DONT_CARE", ""),
        ("depth_", "loadOp CLEAR, storeOp DONT_CARE", ""),
        ("resolve", "VK_RESOLVE_MODE_AVERAGE_BIT", ""),
        ("", "", "into resolveImageView: the swapchain image"),
        ("draws", "vkCmdDrawIndexed × 2", "4 samples a pixel"),
        ("end", "vkCmdEndRendering", "the resolve: each pixel's"),
        ("", "", "samples averaged into the target")]),
    ("barrier", "B3  barrier: the resolve done and visible", "the runner", [
        ("layout", "COLOR_ATTACHMENT_OPTIMAL", "unchanged"),
        ("before", "COLOR_ATTACHMENT_OUTPUT", ""),
        ("", "COLOR_ATTACHMENT_WRITE", ""),
        ("after", "COLOR_ATTACHMENT_OUTPUT", ""),
        ("", "COLOR_ATTACHMENT_READ | WRITE", ""),
        ("", "", "before: the write the chapter's target_after names")]),
    ("rendering", "R2  rendering: the panel", "Overlay::record", [
        ("target", "", "the same swapchain image"),
        ("ops", "loadOp LOAD, storeOp STORE", ""),
        ("", "", "LOAD keeps the chapter's picture under the panel"),
        ("draws", "vkCmdDrawIndexed", "per ImDrawCmd, blended:"),
        ("", "", "each pixel mixed with the one loaded below it"),
        ("end", "vkCmdEndRendering", "")]),
    ("barrier", "B4  barrier: to the presentation engine", "the runner", [
        ("layout", "COLOR_ATTACHMENT_OPTIMAL →", ""),
        ("", "PRESENT_SRC_KHR", ""),
        ("before", "COLOR_ATTACHMENT_OUTPUT", ""),
        ("", "COLOR_ATTACHMENT_WRITE", ""),
        ("after", "NONE, NONE", "the semaphore orders the present")]),
    ("queue", "submit, then present", "the runner", [
        ("", "vkQueueSubmit2", "waits for image_acquired,"),
        ("", "", "signals ready_to_present"),
        ("", "vkQueuePresentKHR", "waits for ready_to_present")]),
]
STYLE = {"barrier": (PURPLE_FILL, PURPLE), "rendering": (BLUE_FILL, BLUE), "queue": (GREEN_FILL, GREEN)}


def main() -> None:
    check_sources()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 10.5 if narrow else 12
    mono = 10.5 if narrow else 11
    lead = size * 1.38
    W = 380 if narrow else 960
    x0, box_w = (8, 364) if narrow else (12, 540)
    s = Svg(W, 100, "Chapter 21b: one frame's two renderings into one image",
            "One frame's command buffer, in recording order, in a window whose swapchain image is "
            "drawn into: B1, the runner's barrier takes the acquired swapchain image from UNDEFINED to "
            "COLOR_ATTACHMENT_OPTIMAL; B2, chapter 21's barriers on its multisampled colour and its depth "
            "image; R1, the chapter's rendering: colour_ with loadOp CLEAR and storeOp DONT_CARE, "
            "resolveMode AVERAGE into the swapchain image at vkCmdEndRendering; B3, the runner's barrier: "
            "the resolve's COLOR_ATTACHMENT_WRITE done and visible to the overlay's "
            "COLOR_ATTACHMENT_READ and WRITE, the layout unchanged; R2, the overlay's rendering, "
            "into the same image with loadOp LOAD and storeOp STORE, the panel blended over the "
            "picture it kept; B4, the barrier to PRESENT_SRC_KHR; then the submit and the present. "
            "Where the runner draws into its own image instead (a _UNORM surface, as headless on "
            "lavapipe), that image is copied into the swapchain image between R2 and B4.")

    y = 8
    s.text(x0, y + size + 2, "One frame's command buffer, in recording order", size=size + 2, bold=True)
    y += size + 2 + lead
    s.text(x0, y, "4 samples (the default), in a window whose _SRGB swapchain", size=size, fill=MUTED)
    y += lead
    s.text(x0, y, "image is drawn into", size=size, fill=MUTED)

    # Beside the steps (wide only): the two images' tracks.
    tracks = [("colour_", "4 samples a pixel", 580), ("the swapchain image", "the frame's target", 770)]
    track_w = 172
    if not narrow:
        for name, sub, tx in tracks:
            s.text(tx, 22, name, size=size + 1, bold=True, mono=name == "colour_")
            s.text(tx, 22 + lead, sub, size=size, fill=MUTED)
    y += 16
    top = y
    places = []  # (top, bottom) of each step's box
    for i, (kind, title, who, lines) in enumerate(STEPS):
        fill, stroke = STYLE[kind]
        # The one who records it beside the title, or under it where there is no room.
        apart = text_width(title, size, bold=True) + text_width(who, size) + 30 > box_w - 18
        rows = len(lines) + (1 if apart else 0)
        h = 6 + size + 4 + rows * lead + 7
        s.rect(x0, y, box_w, h, fill=fill, stroke=stroke, rx=6, width=1.5 if kind == "rendering" else 1.2)
        s.text(x0 + 9, y + 6 + size, title, size=size, bold=True)
        ty = y + 6 + size + 3
        if apart:
            ty += lead
            s.text(x0 + 9, ty, who, size=size, fill=MUTED)
        else:
            s.text(x0 + box_w - 9, y + 6 + size, who, size=size, fill=MUTED, anchor="end")
        tab = x0 + 9 + max([text_width(head, size, bold=True) for head, _, _ in lines if head] or [0])
        tab += 8 if tab > x0 + 9 else 0
        for head, code, note in lines:
            ty += lead
            x = x0 + 9
            if head:
                s.text(x, ty, head, size=size, bold=True)
                x = tab
            elif code:
                x = tab
            if code:
                s.text(x, ty, code, size=mono, mono=True)
                x += text_width(code, mono, mono=True) + 7
            if note:
                s.text(x, ty, note, size=size, fill=MUTED, italic=True)
                x += text_width(note, size)
            assert x <= x0 + box_w - 6, (narrow, head, code, note, x - x0 - box_w)
        places.append((y, y + h))
        y += h
        if i < len(STEPS) - 1:
            s.line(x0 + 30, y, x0 + 30, y + 12, stroke=GREY, width=1.2, arrow="end")
            y += 12
    bottom = y

    if not narrow:
        def segment(tx, y0, y1, layout, label=None, dash=None):
            fill, stroke = LAYOUTS[layout] if layout else ("#ffffff", GREY)
            s.rect(tx, y0, track_w, y1 - y0, fill=fill, stroke=stroke, width=1.1, dash=dash)
            for k, text in enumerate(label or [layout]):
                s.text(tx + track_w / 2, y0 + 16 + k * lead, text, size=mono if not label else size,
                       anchor="middle", mono=not label, fill=INK if not label else MUTED)

        c_x, t_x = tracks[0][2], tracks[1][2]

        def mid(step):
            return (places[step][0] + places[step][1]) / 2
        r1_top, r1_bottom = places[2]
        r2_top, r2_bottom = places[4]
        # colour_: thrown away at B2, in COLOR_ATTACHMENT_OPTIMAL through R1, then dropped.
        segment(c_x, top, mid(1), "UNDEFINED", ["UNDEFINED:", "last frame's samples"])
        segment(c_x, mid(1), r1_bottom, "COLOR_ATTACHMENT_OPTIMAL")
        s.lines(c_x + track_w / 2, r1_top + 30, ["cleared, then the", "draws' samples"], size=size,
                anchor="middle")
        segment(c_x, r1_bottom, bottom, None, ["not stored", "(DONT_CARE)"], dash="4 3")
        # The target: the presentation engine's until B1, then one layout until B4.
        segment(t_x, top, mid(0), None, ["acquired, not", "yet drawn into"], dash="4 3")
        segment(t_x, mid(0), mid(5), "COLOR_ATTACHMENT_OPTIMAL")
        segment(t_x, mid(5), bottom, "PRESENT_SRC_KHR")
        s.lines(t_x + track_w / 2, r1_bottom - 34, ["the chapter's picture,", "resolved at the end"],
                size=size, anchor="middle")
        s.lines(t_x + track_w / 2, mid(3) + 22, ["the resolve now visible", "to R2"], size=size,
                anchor="middle")
        # After rendering 2: what the image holds, the test's picture shrunk five times.
        s.text(t_x + track_w / 2, r2_top + 16, "the panel blended over it:", size=size, anchor="middle")
        thumb_w, thumb_h = PICTURE_W // SHRINK, PICTURE_H // SHRINK
        shrunk(s, picture(), t_x + (track_w - thumb_w) / 2, r2_top + 24)
        # Each barrier, where it falls on the image it changes, with its label from STEPS.
        for step, xs in ((0, [t_x]), (1, [c_x]), (3, [t_x]), (5, [t_x])):
            label = STEPS[step][1].split()[0]
            for tx in xs:
                s.line(tx - 4, mid(step), tx + track_w + 4, mid(step), stroke=PURPLE, width=2)
                s.rect(tx - 25, mid(step) - 8, 22, 16, fill=PURPLE, stroke=PURPLE, rx=8)
                s.text(tx - 14, mid(step) + 3.8, label, size=10.5, anchor="middle", fill="#ffffff",
                       bold=True)
        # The resolve: colour_'s samples averaged into the swapchain image at vkCmdEndRendering.
        ay = r1_bottom - 10
        s.line(c_x + track_w, ay, t_x - 2, ay, stroke=BLUE, width=2, arrow="end")
        s.text((c_x + track_w + t_x) / 2, ay - 6, "resolve", size=size, anchor="middle", fill=BLUE, bold=True)

    # Where the runner draws into its own image: the difference, in a dashed note.
    y = bottom + 14
    note = ["Through the runner's own _SRGB image instead (a _UNORM surface, as headless on",
            "lavapipe): that image is the target of B1 to R2, and between R2 and B4 it is copied into",
            "the swapchain image (chapter 04's figure); the overlay is the same."]
    if narrow:
        note = ["Through the runner's own _SRGB image instead (a",
                "_UNORM surface, as headless on lavapipe): that image",
                "is the target of B1 to R2, and between R2 and B4 it is",
                "copied into the swapchain image (chapter 04's figure)."]
    h = len(note) * lead + 12
    s.rect(x0, y, W - 2 * x0, h, fill="#ffffff", stroke=GREY, rx=6, dash="5 4")
    s.lines(x0 + 9, y + 6 + size, note, size=size, leading=1.38, fill=MUTED)
    s.height = y + h + 8
    s.write()


if __name__ == "__main__":
    main()
