"""Chapter 03: four frames of the runner's loop over time, two in flight.

What it shows is common/frame/src/runner.cpp (draw_frame): per frame slot a
fence `done` and a semaphore `image_acquired`; per swapchain image a semaphore
`ready_to_present`; the CPU waits for the slot's fence (the frame two back),
acquires, records, submits (waiting for image_acquired at the COPY stage,
signalling ready_to_present[image] and done[slot]) and presents.
"""

from svg import BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, MUTED, PURPLE, RED, Svg, text_width

W, H = 1000, 496
LEFT, RIGHT = 112, 986           # the lanes' time axis, in pixels
CPU_Y, GPU_Y, PE_Y = 84, 210, 336  # the top of each lane
LANE_H = 40
# Durations in pixels: the GPU (a frame in 310) is slower than the CPU (226),
# so from frame 2 on the CPU waits for the fence of the frame two back.
ACQUIRE, RECORD, SUBMIT, PRESENT = 52, 66, 50, 58
DRAW, COPY = 262, 48

SLOT_STROKE = (BLUE, GREEN)
SLOT_FILL = (BLUE_FILL, GREEN_FILL)


def main() -> None:
    s = Svg(W, H, "Chapter 03: the frame loop with two frames in flight",
            "Four frames over time on three lanes: the CPU, the GPU queue and the presentation "
            "engine. The CPU waits for a slot's fence before reusing it, the GPU waits for "
            "image_acquired before the copy into the swapchain image and signals ready_to_present "
            "for presentation and done for the CPU.")

    s.text(10, 26, "The runner's loop over time: two frames in flight (and here three swapchain images)", size=15,
           bold=True)
    for y, name, sub in ((CPU_Y, "CPU", "the runner"), (GPU_Y, "GPU queue", "submissions"),
                         (PE_Y, "Presentation", "engine")):
        s.rect(LEFT - 6, y - 8, RIGHT - LEFT + 10, LANE_H + 16, fill="#fafbfc", stroke="#e4e8ec", rx=6)
        s.text(10, y + 17, name, size=14, bold=True)
        s.text(10, y + 34, sub, size=11.5, fill=MUTED)

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
        copy = (draw[1], draw[1] + COPY)
        gpu_free = copy[1]
        fence_time[slot] = copy[1]
        frames.append(dict(f=f, slot=slot, image=image, wait=(cpu_start, wait_end), acquire=acquire,
                           record=record, submit=submit, present=present, draw=draw, copy=copy))
        cpu_start = present[1]

    def block(span, y, label, slot, size=11.5):
        x0, x1 = span[0], min(span[1], RIGHT)
        if x0 >= RIGHT:
            return
        s.rect(x0, y, x1 - x0, LANE_H, fill=SLOT_FILL[slot], stroke=SLOT_STROKE[slot], rx=4, width=1.2)
        if span[1] > RIGHT:
            label = "..."
        s.text((x0 + x1) / 2, y + LANE_H / 2 + 4, label, size=size, anchor="middle")

    # The presentation lane first: what is on screen (the arrows go over it).
    for i, fr in enumerate(frames):
        t = fr["copy"][1]
        if t >= RIGHT:
            continue
        nxt = frames[i + 1]["copy"][1] if i + 1 < len(frames) else RIGHT
        x1 = min(nxt, RIGHT)
        s.rect(t, PE_Y, x1 - t, LANE_H, fill=GREY_FILL, stroke=GREY, rx=4)
        s.text((t + x1) / 2, PE_Y + 25, f"image {fr['image']} on screen" if x1 - t > 150 else
               f"image {fr['image']}", size=11.5, anchor="middle")

    # The CPU lane.
    for fr in frames:
        slot = fr["slot"]
        w0, w1 = fr["wait"]
        if w1 - w0 > 1:
            s.rect(w0, CPU_Y + 8, w1 - w0, LANE_H - 16, fill="#ffffff", stroke=RED, rx=3, dash="3 2")
            if w1 - w0 > 36:
                s.text((w0 + w1) / 2, CPU_Y + LANE_H / 2 + 4, "wait", size=11, anchor="middle", fill=RED)
        block(fr["acquire"], CPU_Y, "acquire", slot, size=11)
        block(fr["record"], CPU_Y, f"record {fr['f']}", slot)
        block(fr["submit"], CPU_Y, "submit", slot, size=11)
        block(fr["present"], CPU_Y, "present", slot, size=11)
        label = f"frame {fr['f']}: slot {slot}, image {fr['image']}"
        if fr["acquire"][0] + text_width(label, 11.5, bold=True) > W - 4:
            label = f"frame {fr['f']}"
        s.text(fr["acquire"][0] + 1, CPU_Y - 14, label, size=11.5, fill=SLOT_STROKE[slot], bold=True)

    # The GPU lane: the chapter's commands into the runner's own target, then
    # the copy into the swapchain image, the one step that waits for image_acquired.
    for fr in frames:
        block(fr["draw"], GPU_Y, f"frame {fr['f']}: the chapter draws", fr["slot"])
        block(fr["copy"], GPU_Y, "copy", fr["slot"], size=11)

    # vkQueueSubmit2: CPU -> GPU.
    for fr in frames:
        t0, t1 = (fr["submit"][0] + fr["submit"][1]) / 2, fr["draw"][0] + 30
        if t1 < RIGHT:
            s.polyline([(t0, CPU_Y + LANE_H), (t0, CPU_Y + LANE_H + 30), (t1, GPU_Y - 30), (t1, GPU_Y)],
                       stroke=GREY, width=1.2, arrow="end")

    # image_acquired[slot]: the presentation engine signals it once the image
    # is free (here at once: nothing is on screen yet), the copy waits for it.
    for fr in frames:
        t_sig, t_copy = fr["acquire"][1] - 4, fr["copy"][0] + 12
        if t_copy >= RIGHT:
            continue
        level = PE_Y - 16 - 12 * fr["slot"]
        s.polyline([(t_sig, PE_Y + 8), (t_sig, level), (t_copy, level), (t_copy, GPU_Y + LANE_H)],
                   stroke=PURPLE, width=1.3, arrow="end")
        s.circle(t_sig, PE_Y + 8, 3.5, fill=PURPLE, stroke=PURPLE)
        if fr["f"] == 0:
            s.text(t_sig + 6, PE_Y + 26, "image_acquired[0]", size=11, fill=PURPLE, mono=True)

    # ready_to_present[image]: the submission signals it, the present waits for
    # it, and the image goes on screen. done[slot]: the fence the CPU waits on
    # before it reuses the slot, two frames later.
    for fr in frames:
        t = fr["copy"][1]
        if t >= RIGHT:
            continue
        s.line(t - 4, GPU_Y + LANE_H, t - 4, PE_Y, stroke=PURPLE, width=1.6, arrow="end")
        s.line(t + 4, GPU_Y, t + 4, CPU_Y + LANE_H, stroke=RED, width=1.6, arrow="end")
        s.text(t + 9, GPU_Y - 40, f"done[{fr['slot']}]", size=11, fill=RED, mono=True)
        if fr["f"] == 0:
            s.text(t + 2, PE_Y - 44, f"ready_to_present[{fr['image']}]", size=11, fill=PURPLE, mono=True)

    # The time axis and the legend.
    s.line(LEFT, H - 90, RIGHT, H - 90, stroke=MUTED, width=1.2, arrow="end")
    s.text(RIGHT, H - 74, "time", size=12, anchor="end", fill=MUTED)
    ly = H - 46
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
    s.write()


if __name__ == "__main__":
    main()
