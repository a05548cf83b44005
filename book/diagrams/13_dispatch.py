"""Chapter 13: workgroups, invocations, and a dispatch split by the device's limits.

Numbers from common/resources/include/vkt/resources/compute.hpp
(dispatch_count, max_items_per_dispatch, split_dispatch), chapter 13's
workgroups of 256 and 32-byte particles, and lavapipe's limits
(maxComputeWorkGroupCount[0] = 65,535, maxStorageBufferRange = 2^27).

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
content is drawn 400 units wide: workgroups and chunks two to a row, the text in
short lines.
"""

import os

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, RED, RED_FILL, Svg)

W, H = 1000, 620
GROUP = 256


def narrow() -> None:
    """The phone layout: 400 wide, every text at least 11 units."""
    nw = 400
    s = Svg(nw, 1000, "Chapter 13: workgroups, invocations and a dispatch split by the device's limits",
            "Top: 1,000 particles need 4 workgroups of 256 invocations; the last 24 invocations have "
            "no particle and return. Bottom: 16,777,216 particles on lavapipe exceed both limits of "
            "one dispatch, so they are split into 4 chunks of 4,194,304, each with its own descriptor "
            "window and its own dispatch of 16,384 workgroups.")
    s.lines(16, 26, ["vkCmdDispatch(cmd, 4, 1, 1) for 1,000", "particles: dispatch_count(1000, 256) = 4"],
            size=14, bold=True, leading=1.35)
    y0, gw, gh, gap = 74, 180, 56, 8
    for g in range(4):
        gx, gy = 16 + (g % 2) * (gw + gap), y0 + (g // 2) * (gh + gap)
        s.rect(gx, gy, gw, gh, fill=BLUE_FILL, stroke=BLUE, width=1.6)
        s.text(gx + gw / 2, gy + 22, f"workgroup {g}", size=13, anchor="middle", bold=True)
        s.text(gx + gw / 2, gy + 41, f"invocations {g * GROUP}..{g * GROUP + 255}", size=11.5, anchor="middle",
               fill=MUTED)
        if g == 3:  # its last 24 invocations have no particle
            idle = gw * 24 / GROUP
            s.rect(gx + gw - idle, gy, idle, gh, fill=RED_FILL, stroke=RED, width=1.4)
    y = y0 + 2 * (gh + gap) + 14
    s.lines(16, y, ["invocations 1000..1023 (red): no particle, they", "return"], size=11.5, fill=RED)
    s.lines(16, y + 38, ["gl_GlobalInvocationID.x: one invocation per", "particle; a workgroup runs whole, so:"],
            size=11.5, fill=MUTED)
    s.text(16, y + 76, "if (index >= push.count) return;", size=12, mono=True)

    by = y + 118
    s.lines(16, by, ["16,777,216 particles on lavapipe: 512 MiB,", "more than one dispatch may cover"], size=14,
            bold=True, leading=1.35)
    s.lines(16, by + 46, [
        "maxComputeWorkGroupCount[0] = 65,535 groups:",
        "  65,535 \u00d7 256 = 16,776,960 particles",
        "  (too many groups by 1: 65,536 needed)",
        "maxStorageBufferRange = 134,217,728 B (128 MiB):",
        "  128 MiB / 32 B = 4,194,304 particles",
        "  (the smaller limit: it decides)",
        "max_items_per_dispatch = the smaller, in whole",
        "workgroups (offsets keep the storage alignment)",
        "= **4,194,304**; split_dispatch gives 4 chunks:",
    ], size=11.5, leading=1.45)
    cy = by + 46 + 9 * 11.5 * 1.45 + 10
    s.text(16, cy, "the one storage buffer (M = 1,048,576 particles)", size=11.5, fill=MUTED)
    cw, ch = 180, 200
    for k in range(4):
        cx, ky = 16 + (k % 2) * (cw + gap), cy + 10 + (k // 2) * (ch + gap)
        s.rect(cx, ky, cw, 48, fill=ORANGE_FILL if k % 2 == 0 else "#fff6ec", stroke=ORANGE, width=1.6)
        s.text(cx + cw / 2, ky + 20, f"particles {k * 4}M..{k * 4 + 4}M", size=12, anchor="middle", bold=True)
        s.text(cx + cw / 2, ky + 38, f"bytes {k * 128}..{(k + 1) * 128} MiB", size=11.5, anchor="middle",
               fill=MUTED)
        s.rect(cx, ky + 56, cw, ch - 64, fill="#ffffff", stroke=GREY, rx=6)
        s.text(cx + 10, ky + 76, f"descriptor set {k}", size=12, bold=True, fill=PURPLE)
        s.lines(cx + 10, ky + 93, [f"offset {k * 128} MiB,", "range 128 MiB"], size=11, mono=True)
        s.text(cx + 10, ky + 128, "push constants", size=12, bold=True, fill=GREEN)
        s.lines(cx + 10, ky + 145, [f"first {k * 4194304:,}", "count 4,194,304"], size=11, mono=True)
        s.text(cx + 10, ky + 183, "vkCmdDispatch(16384,1,1)", size=11, mono=True, fill=BLUE)
    ty = cy + 10 + 2 * (ch + gap) + 14
    s.lines(16, ty, ["Each chunk's shader indexes from 0 within its", "window; 'first' feeds the hash of the first",
                     "state. --dispatch-max N forces the split at any", "count."], size=11.5, leading=1.4)
    s.height = ty + 3 * 11.5 * 1.4 + 18
    s.write()


def main() -> None:
    if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow":
        narrow()
        return
    s = Svg(W, H, "Chapter 13: workgroups, invocations and a dispatch split by the device's limits",
            "Top: 1,000 particles need 4 workgroups of 256 invocations; the last 24 invocations have "
            "no particle and return. Bottom: 16,777,216 particles on lavapipe exceed both limits of "
            "one dispatch, so they are split into 4 chunks of 4,194,304, each with its own descriptor "
            "window and its own dispatch of 16,384 workgroups.")

    # ---- Top: one dispatch of 4 workgroups ------------------------------------------------
    s.text(20, 30, "vkCmdDispatch(cmd, 4, 1, 1) for 1,000 particles: dispatch_count(1000, 256) = 4",
           size=14, bold=True)
    x0, y0, bar_w, bar_h = 20, 64, 960, 64
    per = bar_w / 1024
    for g in range(4):
        gx = x0 + g * GROUP * per
        s.rect(gx, y0, GROUP * per, bar_h, fill=BLUE_FILL, stroke=BLUE, width=1.6)
        # A few invocations drawn as ticks: one tick per 8 invocations.
        for k in range(0, GROUP, 8):
            s.line(gx + k * per, y0 + bar_h - 12, gx + k * per, y0 + bar_h, stroke=BLUE, width=0.6)
        s.text(gx + GROUP * per / 2, y0 + 24, f"workgroup {g}", size=13, anchor="middle", bold=True)
        s.text(gx + GROUP * per / 2, y0 + 42, f"invocations {g * GROUP}..{g * GROUP + 255}", size=11.5,
               anchor="middle", fill=MUTED)
    idle_x = x0 + 1000 * per
    s.rect(idle_x, y0, 24 * per, bar_h, fill=RED_FILL, stroke=RED, width=1.4)
    s.line(idle_x, y0 - 8, idle_x, y0 + bar_h + 8, stroke=RED, width=1.6)
    s.text(idle_x - 4, y0 + bar_h + 22, "invocations 1000..1023: no particle, they return",
           size=11.5, anchor="end", fill=RED)
    s.text(x0, y0 + bar_h + 22, "gl_GlobalInvocationID.x: one invocation per particle", size=11.5, fill=MUTED)
    s.text(x0, y0 + bar_h + 44, "if (index >= push.count) return;", size=12, mono=True)
    s.text(x0 + 262, y0 + bar_h + 44, "a workgroup runs whole, so the shader checks its index against the count",
           size=11.5, fill=MUTED)

    # ---- Bottom: a split by the limits ---------------------------------------------------
    by = 236
    s.text(20, by, "16,777,216 particles on lavapipe: 512 MiB, more than one dispatch may cover", size=14,
           bold=True)
    s.lines(20, by + 26, [
        "maxComputeWorkGroupCount[0] = 65,535 groups:  65,535 \u00d7 256 = 16,776,960 particles",
        "maxStorageBufferRange = 2^{27} B = 128 MiB:  128 MiB / 32 B = 4,194,304 particles",
        "max_items_per_dispatch = the smaller, in whole workgroups (and offsets that keep",
        "minStorageBufferOffsetAlignment) = **4,194,304**; split_dispatch gives 4 chunks:",
    ], size=12, leading=1.5)
    s.text(W - 20, by + 26, "too many groups by 1: 65,536 needed", size=11.5, anchor="end", fill=RED)
    s.text(W - 20, by + 44, "the binding limit is the smaller: it decides", size=11.5, anchor="end", fill=ORANGE)

    cy, ch = by + 120, 58
    cw = 960 / 4
    for k in range(4):
        cx = 20 + k * cw
        s.rect(cx, cy, cw, ch, fill=ORANGE_FILL if k % 2 == 0 else "#fff6ec", stroke=ORANGE, width=1.6)
        s.text(cx + cw / 2, cy + 24, f"particles {k * 4}M..{k * 4 + 4}M", size=12.5, anchor="middle", bold=True)
        s.text(cx + cw / 2, cy + 42, f"bytes {k * 128}..{(k + 1) * 128} MiB", size=11.5, anchor="middle",
               fill=MUTED)
    s.text(20, cy - 8, "the one storage buffer (M = 1,048,576 particles)", size=11.5, fill=MUTED)

    # Each chunk's descriptor and dispatch.
    dy = cy + ch + 18
    for k in range(4):
        cx = 20 + k * cw
        s.brace(cx + 4, cx + cw - 4, dy - 12, depth=7)
        s.rect(cx + 8, dy + 4, cw - 16, 122, fill="#ffffff", stroke=GREY, rx=6)
        s.text(cx + 18, dy + 24, f"descriptor set {k}", size=12, bold=True, fill=PURPLE)
        s.text(cx + 18, dy + 42, f"offset {k * 128} MiB, range 128 MiB", size=11, mono=True)
        s.text(cx + 18, dy + 64, "push constants", size=12, bold=True, fill=GREEN)
        s.text(cx + 18, dy + 82, f"first {k * 4194304:,}", size=11, mono=True)
        s.text(cx + 18, dy + 97, "count 4,194,304", size=11, mono=True)
        s.text(cx + 18, dy + 117, "vkCmdDispatch(16384, 1, 1)", size=11, mono=True, fill=BLUE)
    s.text(20, H - 14, "Each chunk's shader indexes from 0 within its window; 'first' feeds the hash of the "
           "first state. --dispatch-max N forces the split at any count.", size=11.5, fill=INK)
    s.write()


if __name__ == "__main__":
    main()
