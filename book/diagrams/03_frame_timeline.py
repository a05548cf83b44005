"""Chapter 03: four frames of its loop over time, two in flight, both ways.

What it shows is chapters/03_swapchain/main.cpp (draw_frame), which the runner
(common/frame/src/runner.cpp) repeats for chapters 04 on: per frame slot a
fence `done` and a semaphore `image_acquired`; per swapchain image a semaphore
`ready_to_present`; the CPU waits for the slot's fence (the frame two back),
acquires, records, submits (signalling ready_to_present[image] and done[slot])
and presents. The submission waits for image_acquired at the stage of its first
write to the swapchain image: CLEAR where chapter 03 clears straight into it
(an _SRGB surface; the runner's chapters draw there, at COLOR_ATTACHMENT_OUTPUT),
COPY where our own image is copied into it (a _UNORM surface, or
--copy-to-swapchain). The two timelines
share the time axis: the CPU's work is the same, the GPU's differs by the copy.
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, GRID, MUTED, PURPLE, RED, Svg,
                 text_width)

LEFT, RIGHT = 112, 986  # the lanes' time axis, in pixels
LANE_H, GAP = 34, 60    # a lane's height, the room between two lanes
HEAD = 72                             # a timeline's heading, above its CPU lane
PANEL_H = HEAD + 3 * LANE_H + 2 * GAP + 8  # a timeline with its heading
TOP, SEP = 40, 26                     # the first timeline's top, the room between the two
AXIS_Y = TOP + 2 * PANEL_H + SEP + 12  # the time axis, below both
W, H = 1000, AXIS_Y + 76
# Durations in pixels: the GPU (a frame in 262, 310 with the copy) is slower
# than the CPU (226), so from frame 2 on the CPU waits for the fence of the
# frame two back.
ACQUIRE, RECORD, SUBMIT, PRESENT = 52, 66, 50, 58
DRAW, COPY = 262, 48

SLOT_STROKE = (BLUE, GREEN)
SLOT_FILL = (BLUE_FILL, GREEN_FILL)


def schedule(direct: bool) -> list[dict]:
    """Four frames: when each step of the CPU and the GPU runs."""
    cpu_start, gpu_free = float(LEFT), float(LEFT)
    fence_time = {0: float(LEFT), 1: float(LEFT)}  # created signalled
    frames = []
    for f in range(4):
        slot, image = f % 2, f % 3
        wait_end = max(cpu_start, fence_time[slot])
        acquire = (wait_end, wait_end + ACQUIRE)
        record = (acquire[1], acquire[1] + RECORD)
        submit = (record[1], record[1] + SUBMIT)
        present = (submit[1], submit[1] + PRESENT)
        gpu_begin = max(submit[1], gpu_free)
        draw = (gpu_begin, gpu_begin + DRAW)
        copy = None if direct else (draw[1], draw[1] + COPY)
        end = draw[1] if direct else copy[1]
        gpu_free = fence_time[slot] = end
        frames.append(dict(f=f, slot=slot, image=image, wait=(cpu_start, wait_end), acquire=acquire,
                           record=record, submit=submit, present=present, draw=draw, copy=copy, end=end))
        cpu_start = present[1]
    return frames


def timeline(s: Svg, top: float, direct: bool) -> None:
    """One timeline of three lanes, its heading's top at `top`."""
    cpu_y = top + HEAD
    gpu_y = cpu_y + LANE_H + GAP
    pe_y = gpu_y + LANE_H + GAP
    frames = schedule(direct)

    if direct:
        title = "Cleared straight into the swapchain image (an _SRGB surface, usually a window)"
        sub = "The clear is the first write to the image: it waits for " \
              "`image_acquired`, at `CLEAR`."
    else:
        title = "Through our own image (a _UNORM surface, or --copy-to-swapchain)"
        sub = "The clear goes into our own image; only the copy writes to the swapchain image, so " \
              "the wait is at `COPY`."
    s.text(10, top + 16, title, size=13.5, bold=True)
    s.text(10, top + 34, sub, size=12, fill=MUTED)
    assert 10 + max(text_width(title, 13.5, bold=True), text_width(sub, 12)) < W - 10, "a heading is too long"

    for y, name, sub_name in ((cpu_y, "CPU", "the loop"), (gpu_y, "GPU queue", "submissions"),
                              (pe_y, "Presentation", "engine")):
        s.rect(LEFT - 6, y - 7, RIGHT - LEFT + 10, LANE_H + 14, fill="#fafbfc", stroke="#e4e8ec", rx=6)
        s.text(10, y + 14, name, size=14, bold=True)
        s.text(10, y + 30, sub_name, size=11.5, fill=MUTED)

    def block(span, y, label, slot, size=11.5):
        x0, x1 = span[0], min(span[1], RIGHT)
        if x0 >= RIGHT:
            return
        s.rect(x0, y, x1 - x0, LANE_H, fill=SLOT_FILL[slot], stroke=SLOT_STROKE[slot], rx=4, width=1.2)
        if span[1] > RIGHT or text_width(label, size) > x1 - x0 - 6:
            label = "..."
        s.text((x0 + x1) / 2, y + LANE_H / 2 + 4, label, size=size, anchor="middle")

    # The presentation lane first: what is on screen (the arrows go over it).
    for i, fr in enumerate(frames):
        t = fr["end"]
        if t >= RIGHT:
            continue
        nxt = frames[i + 1]["end"] if i + 1 < len(frames) else RIGHT
        x1 = min(nxt, RIGHT)
        s.rect(t, pe_y, x1 - t, LANE_H, fill=GREY_FILL, stroke=GREY, rx=4)
        s.text((t + x1) / 2, pe_y + LANE_H / 2 + 4,
               f"image {fr['image']} on screen" if x1 - t > 150 else f"image {fr['image']}", size=11.5,
               anchor="middle")

    # The CPU lane.
    for fr in frames:
        slot = fr["slot"]
        w0, w1 = fr["wait"]
        if w1 - w0 > 1:
            s.rect(w0, cpu_y + 7, w1 - w0, LANE_H - 14, fill="#ffffff", stroke=RED, rx=3, dash="3 2")
            if w1 - w0 > 36:
                s.text((w0 + w1) / 2, cpu_y + LANE_H / 2 + 4, "wait", size=11, anchor="middle", fill=RED)
        block(fr["acquire"], cpu_y, "acquire", slot, size=11)
        block(fr["record"], cpu_y, f"record {fr['f']}", slot)
        block(fr["submit"], cpu_y, "submit", slot, size=11)
        block(fr["present"], cpu_y, "present", slot, size=11)
        label = f"frame {fr['f']}: slot {slot}, image {fr['image']}"
        if fr["acquire"][0] + text_width(label, 11.5, bold=True) > W - 4:
            label = f"frame {fr['f']}"
        s.text(fr["acquire"][0] + 1, cpu_y - 12, label, size=11.5, fill=SLOT_STROKE[slot], bold=True)

    # The GPU lane: the clear, into the swapchain image itself or into our own
    # image and then the copy.
    for fr in frames:
        where = f"image {fr['image']}" if direct else "our own image"
        block(fr["draw"], gpu_y, f"frame {fr['f']}: the clear of {where}", fr["slot"])
        if not direct:
            block(fr["copy"], gpu_y, "copy", fr["slot"], size=11)

    # vkQueueSubmit2: CPU -> GPU.
    for fr in frames:
        t0, t1 = (fr["submit"][0] + fr["submit"][1]) / 2, fr["draw"][0] + 30
        if t1 < RIGHT:
            s.polyline([(t0, cpu_y + LANE_H), (t0, cpu_y + LANE_H + 22), (t1, gpu_y - 22), (t1, gpu_y)],
                       stroke=GREY, width=1.2, arrow="end")

    # image_acquired[slot]: the presentation engine signals it once the image
    # is free (here at once: nothing is on screen yet); the first write to the
    # image waits for it.
    for fr in frames:
        t_sig = fr["acquire"][1] - 4
        # The first write to the swapchain image waits: the clear straight in,
        # or the copy.
        t_wait = fr["draw"][0] + 12 if direct else fr["copy"][0] + 12
        if t_wait >= RIGHT:
            continue
        level = pe_y - 16 - 12 * fr["slot"]
        s.polyline([(t_sig, pe_y + 7), (t_sig, level), (t_wait, level), (t_wait, gpu_y + LANE_H)],
                   stroke=PURPLE, width=1.3, arrow="end")
        s.circle(t_sig, pe_y + 7, 3.5, fill=PURPLE, stroke=PURPLE)
        if fr["f"] == 0:
            stage = "CLEAR" if direct else "COPY"
            s.text(t_sig + 6, pe_y + 22, f"`image_acquired[0]`, waited for at `{stage}`", size=11,
                   fill=PURPLE)

    # ready_to_present[image]: the submission signals it, the present waits for
    # it, and the image goes on screen. done[slot]: the fence the CPU waits on
    # before it reuses the slot, two frames later.
    for fr in frames:
        t = fr["end"]
        if t >= RIGHT:
            continue
        s.line(t - 4, gpu_y + LANE_H, t - 4, pe_y, stroke=PURPLE, width=1.6, arrow="end")
        s.line(t + 4, gpu_y, t + 4, cpu_y + LANE_H, stroke=RED, width=1.6, arrow="end")
        s.text(t + 9, gpu_y - 30, f"done[{fr['slot']}]", size=11, fill=RED, mono=True)
        if fr["f"] == 0:  # beside its arrow, on the side where no other arrow crosses
            s.text(t - 10 if direct else t + 2, pe_y - 40, f"ready_to_present[{fr['image']}]", size=11,
                   fill=PURPLE, mono=True, anchor="end" if direct else "start")


def main() -> None:
    s = Svg(W, H, "Chapter 03: the frame loop with two frames in flight, both ways to the swapchain image",
            "Two timelines of four frames on three lanes each: the CPU, the GPU queue and the "
            "presentation engine. The CPU waits for a slot's fence before reusing it. Cleared straight "
            "into the swapchain image, the clear waits for image_acquired; through "
            "our own image, the copy into the swapchain image waits for it. Either way "
            "the submission signals ready_to_present for presentation and done for the CPU.")

    s.text(10, 24, "Chapter 03's loop over time: two frames in flight (and here three swapchain images)",
           size=15, bold=True)
    timeline(s, TOP, direct=True)
    s.line(10, TOP + PANEL_H + SEP / 2, W - 10, TOP + PANEL_H + SEP / 2, stroke=GRID, width=1)
    timeline(s, TOP + PANEL_H + SEP, direct=False)

    # The time axis, shared by both, and the legend.
    axis_y = AXIS_Y
    s.line(LEFT, axis_y, RIGHT, axis_y, stroke=MUTED, width=1.2, arrow="end")
    s.text(RIGHT, axis_y + 16, "time (the same scale in both)", size=12, anchor="end", fill=MUTED)
    ly = axis_y + 40
    s.rect(LEFT, ly - 12, 16, 14, fill=BLUE_FILL, stroke=BLUE, rx=3)
    s.text(LEFT + 22, ly, "slot 0: frames 0, 2, ...", size=12)
    s.rect(LEFT + 180, ly - 12, 16, 14, fill=GREEN_FILL, stroke=GREEN, rx=3)
    s.text(LEFT + 202, ly, "slot 1: frames 1, 3, ...", size=12)
    s.line(LEFT + 370, ly - 5, LEFT + 400, ly - 5, stroke=GREY, width=1.2, arrow="end")
    s.text(LEFT + 406, ly, "vkQueueSubmit2", size=12, mono=True)
    s.line(LEFT + 530, ly - 5, LEFT + 560, ly - 5, stroke=PURPLE, width=1.6, arrow="end")
    s.text(LEFT + 566, ly, "semaphore: one part of the GPU side tells another", size=12)
    ly += 22
    s.line(LEFT, ly - 5, LEFT + 30, ly - 5, stroke=RED, width=1.6, arrow="end")
    s.text(LEFT + 36, ly, "fence: the GPU tells the CPU", size=12)
    s.rect(LEFT + 250, ly - 12, 30, 14, fill="#ffffff", stroke=RED, rx=3, dash="3 2")
    s.text(LEFT + 286, ly, "vkWaitForFences blocks (here the GPU is the slower)", size=12)
    assert ly + 10 <= H, f"the legend ends at {ly + 10}, the picture at {H}"
    s.write()


if __name__ == "__main__":
    main()
