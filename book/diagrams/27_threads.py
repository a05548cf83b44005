"""Chapter 27: one frame recorded by four threads, and the command pools they own.

Numbers from chapter 27: 4,097 objects (64 x 64 and the floor) split into four
consecutive shares (first_[t] = 4097 * t / 4), two frames in flight, so
2 x 4 = 8 command pools.
"""

from svg import (BLUE, BLUE_FILL, GREY, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE,
                 PURPLE_FILL, Svg)

W, H = 1000, 580
THREADS = 4
OBJECTS = 4097
SLOTS = 2


def main() -> None:
    s = Svg(W, H, "Chapter 27: one frame recorded by four threads into secondary command buffers",
            "Top: Workers::run wakes three worker threads; thread 0 is the caller. Each thread "
            "resets its own command pool for this frame slot and records its share of the 4,097 "
            "objects into its own secondary command buffer. After the join, the primary command "
            "buffer begins rendering with SECONDARY_COMMAND_BUFFERS and executes the four "
            "secondaries in thread order, then is submitted. Bottom: the eight pools, one per "
            "thread per frame slot; a thread uses only its own column, and a slot's row only after "
            "that slot's fence has signalled.")
    first = [OBJECTS * t // THREADS for t in range(THREADS + 1)]

    s.text(20, 28, "One frame, --threads 4 (frame slot 1)", size=15, bold=True)
    top, lane = 56, 62
    fork_x, join_x = 150, 640
    s.line(fork_x, top - 8, fork_x, top + THREADS * lane - 10, stroke=INK, width=2)
    s.text(fork_x, top + THREADS * lane + 8, "fork: run(job)", size=12.5, anchor="middle", mono=True)
    s.line(join_x, top - 8, join_x, top + THREADS * lane - 10, stroke=INK, width=2)
    s.text(join_x, top + THREADS * lane + 8, "join: run returns", size=12.5, anchor="middle")
    for t in range(THREADS):
        y = top + t * lane
        who = "thread 0 (caller)" if t == 0 else f"worker thread {t}"
        s.box(20, y, 118, 40, [who], fill="#ffffff", stroke=INK, size=12.5)
        s.line(138, y + 20, fork_x + 10, y + 20, stroke=INK, width=1.4, arrow="end")
        s.box(fork_x + 10, y, 150, 40, ["vkResetCommandPool", f"pools_[{THREADS + t}]"], fill=PURPLE_FILL,
              stroke=PURPLE, size=12.5, mono=False)
        s.line(fork_x + 160, y + 20, fork_x + 176, y + 20, stroke=INK, width=1.4, arrow="end")
        s.box(fork_x + 176, y, 300, 40,
              [f"secondary {t}: bind, viewport,", f"objects {first[t]}..{first[t + 1] - 1}: push + draw"],
              fill=ORANGE_FILL, stroke=ORANGE, size=12.5)
        s.line(fork_x + 476, y + 20, join_x, y + 20, stroke=INK, width=1.4, arrow="end")

    # The primary, after the join.
    px, pw = 670, 310
    s.box(px, top, pw, THREADS * lane - 22, [], fill=BLUE_FILL, stroke=BLUE)
    s.text(px + pw / 2, top + 22, "the frame's primary command buffer", size=13, bold=True,
           anchor="middle", fill=BLUE)
    rows = ["vkCmdBeginRendering(", "  flags = SECONDARY_COMMAND_BUFFERS)", "vkCmdExecuteCommands(4,",
            "  secondary 0, 1, 2, 3)", "vkCmdEndRendering", "\u2192 vkQueueSubmit2"]
    for i, row in enumerate(rows):
        s.text(px + 14, top + 50 + i * 27, row, size=12.5, mono=True)

    s.text(20, top + THREADS * lane + 40,
           "In thread order, so the GPU sees the draws 0 .. 4096 in the same order at every N: "
           "the same picture, to the bit.", size=12.5)

    # The pools: one per thread per frame slot.
    gy = top + THREADS * lane + 80
    s.text(20, gy, f"The {SLOTS * THREADS} command pools: one per thread per frame slot (pools_[slot * 4 + t])", size=15, bold=True)
    cx, cw, ch = 150, 150, 40
    for t in range(THREADS):
        s.text(cx + t * (cw + 12) + cw / 2, gy + 28, f"thread {t}", size=12.5, anchor="middle", fill=MUTED)
    for slot in range(SLOTS):
        y = gy + 40 + slot * (ch + 12)
        s.text(cx - 12, y + 25, f"slot {slot}", size=12.5, anchor="end", fill=MUTED)
        for t in range(THREADS):
            current = slot == 1
            s.box(cx + t * (cw + 12), y, cw, ch, [f"pools_[{slot * THREADS + t}]"],
                  fill=PURPLE_FILL if current else "#ffffff", stroke=PURPLE if current else GREY,
                  size=12.5, dash=None if current else "4 3")
    ny = gy + 40 + SLOTS * (ch + 12) + 18
    s.text(20, ny, "A pool is externally synchronised: one thread at a time. Column t is thread t's alone;",
           size=12.5)
    s.text(20, ny + 20, "row 0 (dashed) may still be on the GPU, and is reset only after slot 0's fence has "
           "signalled.", size=12.5)
    s.write()


if __name__ == "__main__":
    main()
