"""Chapter 16: the G-buffer, 16 bytes per pixel, and what each channel holds.

From chapters/16_deferred/main.cpp [formats] and the shared shaders:
shaders/common/deferred/gbuffer.frag writes base_colour = (albedo, 1),
normal = oct_encode(world normal), params = (specular, shininess / 255, 0, 0);
lighting.frag reads them with texelFetch and rebuilds the position from depth
through frame.inverse_view_proj.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
content is drawn 400 units wide: one image to a row, the text in short lines.
"""

import os

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, RED, Svg)

W, H = 1000, 580
CELL, X0, Y0, CELL_H = 56, 52, 130, 54

TARGETS = [
    ("base colour", "R8G8B8A8_SRGB", "location 0", BLUE_FILL, BLUE,
     [("R", "albedo\nred"), ("G", "albedo\ngreen"), ("B", "albedo\nblue"), ("A", "1.0,\nunused")]),
    ("normal", "R16G16_SNORM", "location 1", GREEN_FILL, GREEN,
     [("x (16 bits)", "octahedral\ne.x in [\u22121, 1]"), None, ("y (16 bits)", "octahedral\ne.y in [\u22121, 1]"), None]),
    ("material", "R8G8B8A8_UNORM", "location 2", ORANGE_FILL, ORANGE,
     [("R", "specular"), ("G", "shininess\n/ 255"), ("B", "0,\nspare"), ("A", "0,\nspare")]),
    ("depth", "D32_SFLOAT", "depth attachment", PURPLE_FILL, PURPLE,
     [("depth (32-bit float)", "0 at the near plane,\n1 at the far plane"), None, None, None]),
]


def narrow() -> None:
    """The phone layout: 400 wide, every text at least 11 units."""
    nw, cell, cell_h, x0 = 400, 88, 46, 24
    rows = 4 * 132
    h = 98 + rows + 392
    s = Svg(nw, h, "Chapter 16: the G-buffer, byte by byte",
            "One pixel of the G-buffer is 16 bytes in four images: base colour R8G8B8A8_SRGB (albedo, "
            "alpha unused), normal R16G16_SNORM (the octahedral encoding's two numbers), material "
            "R8G8B8A8_UNORM (specular, shininess / 255, two spare bytes) and depth D32_SFLOAT, from "
            "which pass 2 rebuilds the position.")
    s.lines(16, 26, ["One pixel of the G-buffer:", "16 bytes in four images"], size=15, bold=True)
    s.lines(16, 68, ["pass 1 (gbuffer.frag) writes them, pass 2", "(lighting.frag) reads each with texelFetch"],
            size=11.5, fill=MUTED)
    y = 118
    for t, (name, fmt, where, fill, stroke, channels) in enumerate(TARGETS):
        s.text(x0, y, name, size=13.5, bold=True, fill=stroke)
        s.text(nw - 16, y, where, size=11.5, anchor="end", fill=MUTED)
        s.text(x0, y + 17, fmt, size=11.5, mono=True)
        top = y + 26
        k = 0
        while k < 4:
            span = 1
            while k + span < 4 and channels[k + span] is None:
                span += 1
            label, meaning = channels[k]
            cx = x0 + k * cell
            s.rect(cx, top, span * cell, cell_h, fill=fill, stroke=stroke, width=1.4)
            s.text(cx + span * cell / 2, top + 20, label, size=12, anchor="middle", bold=True)
            if span == 1:
                s.text(cx + cell / 2, top + 37, "8 bits", size=11, anchor="middle", fill=MUTED)
            s.lines(cx + span * cell / 2, top + cell_h + 15, meaning.split("\n"), size=11, leading=1.2,
                    anchor="middle")
            k += span
        for b in range(1, 4):
            s.line(x0 + b * cell, top + cell_h - 6, x0 + b * cell, top + cell_h, stroke=stroke, width=1)
        s.text(x0 + 4 * cell, top - 4, f"bytes {t * 4}..{t * 4 + 3}", size=11, anchor="end", fill=MUTED)
        y += 132
    y += 4
    s.text(16, y, "What each part stores, and why", size=14, bold=True)
    s.lines(16, y + 22, [
        "**base colour**: linear albedo in; the _SRGB format",
        "encodes on write, decodes on read.",
        "**normal**: a unit vector has two degrees of freedom;",
        "oct_encode folds it onto |x| + |y| + |z| = 1, so two",
        "16-bit numbers cover every direction (about 0.006\u00b0).",
        "**material**: specular in [0, 1] and shininess / 255",
        "(the lighting pass rounds it back: round(g \u00d7 255)).",
        "**depth**: the depth test needs it anyway; sampled",
        "afterwards it gives back the world position:",
    ], size=11.5, leading=1.45)
    fy = y + 22 + 9 * 11.5 * 1.45 - 4
    s.rect(16, fy, nw - 32, 42, fill=GREY_FILL, stroke=GREY, rx=4)
    s.lines(26, fy + 17, ["position = inverse_view_proj \u00d7", "  (ndc.xy, depth, 1), divided by w"], size=11,
            mono=True, leading=1.35)
    py = fy + 56
    s.rect(16, py, nw - 32, 84, fill="#ffffff", stroke=RED, rx=6, dash="5 3")
    s.text(28, py + 20, "not stored: the position", size=12.5, bold=True, fill=RED)
    s.lines(28, py + 39, ["an R32G32B32A32_SFLOAT target would add 16", "bytes a pixel, doubling the G-buffer; depth",
                          "and the pixel's coordinates give it back."], size=11.5, leading=1.3)
    sy = py + 104
    s.lines(16, sy, ["One G-buffer serves both frames in flight:", "barriers order the passes. 16 bytes a pixel,",
                     "written once and read once, every frame:"], size=11.5, leading=1.4)
    s.lines(16, sy + 52, ["14.1 MiB at 1280\u00d7720, 31.6 MiB at 1920\u00d71080,", "126.6 MiB at 3840\u00d72160"],
            size=11, mono=True, leading=1.4)
    s.height = sy + 52 + 11 * 1.4 + 16  # the last line's baseline, and a margin
    s.write()


def main() -> None:
    if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow":
        narrow()
        return
    s = Svg(W, H, "Chapter 16: the G-buffer, byte by byte",
            "One pixel of the G-buffer is 16 bytes in four images: base colour R8G8B8A8_SRGB (albedo, "
            "alpha unused), normal R16G16_SNORM (the octahedral encoding's two numbers), material "
            "R8G8B8A8_UNORM (specular, shininess / 255, two spare bytes) and depth D32_SFLOAT, from "
            "which pass 2 rebuilds the position.")

    s.text(20, 30, "One pixel of the G-buffer: 16 bytes in four images", size=15, bold=True)
    s.text(20, 50, "pass 1 (gbuffer.frag) writes them, pass 2 (lighting.frag) reads each back with texelFetch",
           size=12, fill=MUTED)

    targets = TARGETS
    for t, (name, fmt, where, fill, stroke, channels) in enumerate(targets):
        gx = X0 + t * 4 * CELL + t * 8
        gw = 4 * CELL
        s.text(gx + gw / 2, Y0 - 44, name, size=13.5, anchor="middle", bold=True, fill=stroke)
        s.text(gx + gw / 2, Y0 - 28, fmt, size=11, anchor="middle", mono=True)
        s.text(gx + gw / 2, Y0 - 12, where, size=11, anchor="middle", fill=MUTED)
        k = 0
        while k < 4:
            channel = channels[k]
            span = 1
            while k + span < 4 and channels[k + span] is None:
                span += 1
            cx = gx + k * CELL
            s.rect(cx, Y0, span * CELL, CELL_H, fill=fill, stroke=stroke, width=1.4)
            label, meaning = channel
            s.text(cx + span * CELL / 2, Y0 + 22, label, size=11.5 if span == 1 else 11.5, anchor="middle",
                   bold=True)
            if span == 1:
                s.text(cx + CELL / 2, Y0 + 40, "8 bits", size=10, anchor="middle", fill=MUTED)
            s.lines(cx + span * CELL / 2, Y0 + CELL_H + 17, meaning.split("\n"), size=10.5, leading=1.25, anchor="middle")
            k += span
        # Byte ticks under each byte.
        for b in range(4):
            s.text(gx + b * CELL + CELL / 2, Y0 + CELL_H + 56, f"byte {t * 4 + b}", size=9.5, anchor="middle",
                   fill=MUTED)
            if b:
                s.line(gx + b * CELL, Y0 + CELL_H - 6, gx + b * CELL, Y0 + CELL_H, stroke=stroke, width=1)

    # What the numbers mean.
    y = Y0 + CELL_H + 92
    s.text(20, y, "What each part stores, and why in that format", size=14, bold=True)
    s.lines(20, y + 24, [
        "**base colour**: linear albedo in, the _SRGB format encodes on write and decodes on read: 8 bits where the eye sees them.",
        "**normal**: a unit vector has two degrees of freedom. oct_encode projects it onto |x| + |y| + |z| = 1 and folds",
        "      the lower half over the upper, so two 16-bit numbers in [\u22121, 1] cover every direction (about 0.006\u00b0 of error).",
        "**material**: specular in [0, 1], and shininess / 255 (the lighting pass rounds shininess back: round(g \u00d7 255)).",
        "**depth**: the depth test needs it anyway; sampled afterwards it gives back the world position:",
    ], size=12, leading=1.5)
    s.rect(40, y + 108, 640, 30, fill=GREY_FILL, stroke=GREY, rx=4)
    s.text(52, y + 128, "position = inverse_view_proj \u00d7 (ndc.xy, depth, 1), divided by w", size=12, mono=True)

    # The position that is not stored.
    px, py = 700, H - 112
    s.rect(px, py, 280, 100, fill="#ffffff", stroke=RED, rx=6, dash="5 3")
    s.text(px + 12, py + 22, "not stored: the position", size=12.5, bold=True, fill=RED)
    s.lines(px + 12, py + 42, ["an R32G32B32A32_SFLOAT target would", "add 16 bytes a pixel, doubling the",
                               "G-buffer; depth and the pixel's", "coordinates give it back."],
            size=11.5, leading=1.3)

    # Sizes.
    s.text(20, H - 46, "16 bytes a pixel, written once by pass 1 and read once by pass 2, every frame:",
           size=12.5, bold=True)
    s.text(20, H - 24, "14.1 MiB at 1280\u00d7720, 31.6 MiB at 1920\u00d71080, 126.6 MiB at 3840\u00d72160",
           size=12.5, mono=True)
    s.text(20, H - 70, "One G-buffer serves both frames in flight: barriers order the passes.", size=12)
    s.write()


if __name__ == "__main__":
    main()
