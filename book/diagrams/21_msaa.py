"""Chapter 21: one pixel through multisampling, and the attachments that hold it.

The sample positions are Vulkan's standard 4-sample locations
(VkPhysicalDeviceLimits::standardSampleLocations): (0.375, 0.125),
(0.875, 0.375), (0.125, 0.625), (0.625, 0.875) of the pixel.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
figure is 400 units wide: the three steps stacked, each pixel with its words
beside it, and the attachments in one column, the resolve pointing down.
"""

import os

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, Svg)

W, H = 1000, 480
SAMPLES = [(0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875)]
SPOKE = "#fff6da"  # the chapter's spoke colour, stored
BACK = "#272738"   # the clear colour, stored
# An edge through the pixel: the triangle covers what lies below the line
# from (0, 0.95) to (1, 0.2), which takes samples 2 and 4 (of 1..4).
EDGE = ((0.0, 0.95), (1.0, 0.2))


def covered(x: float, y: float) -> bool:
    (x0, y0), (x1, y1) = EDGE
    return y > y0 + (y1 - y0) * (x - x0)


def pixel(s: Svg, x: float, y: float, size: float, show_edge: bool, filled: bool) -> None:
    s.rect(x, y, size, size, fill=BACK, stroke=INK, width=1.4)
    if show_edge:
        (x0, y0), (x1, y1) = EDGE
        s.polygon([(x + x0 * size, y + y0 * size), (x + x1 * size, y + y1 * size),
                   (x + size, y + size), (x, y + size)], fill=SPOKE, stroke="none", opacity=0.35)
        s.line(x + x0 * size, y + y0 * size, x + x1 * size, y + y1 * size, stroke=ORANGE, width=2)
    for i, (sx, sy) in enumerate(SAMPLES):
        inside = covered(sx, sy)
        fill = (SPOKE if inside else BACK) if filled else ("#ffffff" if inside else "none")
        s.circle(x + sx * size, y + sy * size, 9, fill=fill, stroke=BLUE if inside else GREY, width=2)
        # The number beside its point, on the side away from the pixel's nearer edge.
        right = sx < 0.75
        s.text(x + sx * size + (13 if right else -13), y + sy * size + 4, str(i + 1), size=11,
               fill="#ffffff", anchor="start" if right else "end")


TITLE = "Chapter 21: one pixel through multisampling, and the attachments that hold it"
DESCRIPTION = ("Top: a triangle's edge crosses one pixel; of its four sample points two are covered and "
               "pass the depth test. The fragment shader runs once for the pixel and its colour is stored "
               "in the two covered samples. When rendering ends the four samples are averaged into the "
               "single-sample target: half spoke, half background. Bottom: the multisampled colour and "
               "depth images are the chapter's own and transient; only the resolved target is kept.")
# The average of two spoke samples and two background samples, in linear light
# (what an sRGB resolve averages), stored sRGB-encoded again.
RESOLVED = "#bdb6a4"
COLOUR_BOX = ["colour: 4 samples per pixel", "ours, transient; storeOp DONT_CARE"]
DEPTH_BOX = ["depth: 4 samples per pixel", "ours, transient; storeOp DONT_CARE"]
TARGET_BOX = ["the frame's target: 1 sample per pixel", "resolveImageView; presented or read back"]
KEPT_BOX = ["nothing of the samples is kept: a tiling GPU", "may hold them on chip (LAZILY_ALLOCATED)"]


def steps(s: Svg, places, size: float) -> None:
    """The pixel of each step at its place (x, y)."""
    pixel(s, *places[0], size, show_edge=True, filled=False)
    pixel(s, *places[1], size, show_edge=False, filled=True)
    s.rect(*places[2], size, size, fill=RESOLVED, stroke=INK, width=1.4)


def wide() -> Svg:
    s = Svg(W, H, TITLE, DESCRIPTION)
    size, top = 150, 58
    columns = [40, 340, 640]
    titles = ["1  rasterise: 4 sample points", "2  shade once, store per sample",
              "3  resolve into the frame's target"]
    notes = [["covered: samples 2 and 4;", "depth is tested at each of them"],
             ["the shader ran once; its colour goes", "to the covered samples only"],
             ["resolveMode AVERAGE: (2 spoke + 2", "background) / 4, in linear light"]]
    for c, x in enumerate(columns):
        s.text(x, 34, titles[c], size=14, bold=True)
        s.lines(x, top + size + 26, notes[c], size=12.5, fill=MUTED)
    steps(s, [(x, top) for x in columns], size)
    for a, b in ((0, 1), (1, 2)):
        s.line(columns[a] + size + 18, top + size / 2, columns[b] - 18, top + size / 2,
               stroke=INK, width=1.6, arrow="end")

    # The attachments of one vkCmdBeginRendering.
    y = 320
    s.text(40, y - 16, "vkCmdBeginRendering: what each attachment is, and what survives it", size=14,
           bold=True)
    s.box(40, y, 300, 62, COLOUR_BOX, fill=BLUE_FILL, stroke=BLUE, bold_first=True)
    s.box(40, y + 80, 300, 62, DEPTH_BOX, fill=GREY_FILL, stroke=GREY, bold_first=True)
    s.box(560, y, 380, 62, TARGET_BOX, fill=GREEN_FILL, stroke=GREEN, bold_first=True)
    s.line(340, y + 31, 560, y + 31, stroke=PURPLE, width=2, arrow="end")
    s.text(450, y + 22, "resolve (AVERAGE)", size=12.5, anchor="middle", fill=PURPLE)
    s.text(450, y + 50, "at vkCmdEndRendering", size=12, anchor="middle", fill=MUTED)
    s.box(560, y + 80, 380, 62, KEPT_BOX, fill=ORANGE_FILL, stroke=ORANGE)
    return s


def narrow() -> Svg:
    """The steps stacked, each pixel with its title and notes at its right; then the
    attachments in one column: depth, colour, the resolve down into the target."""
    s = Svg(400, 100, TITLE, DESCRIPTION)
    size, x, words, step = 120, 20, 162, 160
    titles = [["1  rasterise:", "4 sample points"], ["2  shade once,", "store per sample"],
              ["3  resolve into", "the frame's target"]]
    notes = [["covered: samples 2 and 4;", "depth is tested at", "each of them"],
             ["the shader ran once;", "its colour goes to the", "covered samples only"],
             ["resolveMode AVERAGE:", "(2 spoke + 2 background) / 4,", "in linear light"]]
    tops = [16 + i * step for i in range(3)]
    for i, top in enumerate(tops):
        s.lines(words, top + 16, titles[i], size=13, bold=True)
        s.lines(words, top + 62, notes[i], size=11.5, fill=MUTED)
    steps(s, [(x, top) for top in tops], size)
    for a, b in ((0, 1), (1, 2)):
        s.line(x + size / 2, tops[a] + size + 6, x + size / 2, tops[b] - 6,
               stroke=INK, width=1.6, arrow="end")

    y = tops[2] + size + 36
    s.lines(x, y, ["vkCmdBeginRendering: what each attachment", "is, and what survives it"],
            size=13, bold=True)
    y += 30
    w, h = 360, 52
    s.box(x, y, w, h, DEPTH_BOX, fill=GREY_FILL, stroke=GREY, size=12.5, bold_first=True)
    y += h + 14
    s.box(x, y, w, h, COLOUR_BOX, fill=BLUE_FILL, stroke=BLUE, size=12.5, bold_first=True)
    arrow_x = x + 70
    s.line(arrow_x, y + h, arrow_x, y + h + 58, stroke=PURPLE, width=2, arrow="end")
    s.text(arrow_x + 14, y + h + 26, "resolve (AVERAGE)", size=12.5, fill=PURPLE)
    s.text(arrow_x + 14, y + h + 43, "at vkCmdEndRendering", size=12, fill=MUTED)
    y += h + 58
    s.box(x, y, w, h, TARGET_BOX, fill=GREEN_FILL, stroke=GREEN, size=12.5, bold_first=True)
    y += h + 14
    s.box(x, y, w, h, KEPT_BOX, fill=ORANGE_FILL, stroke=ORANGE, size=12.5)
    s.height = y + h + 10
    return s


def main() -> None:
    s = narrow() if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow" else wide()
    s.write()


if __name__ == "__main__":
    main()
