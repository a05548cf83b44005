"""Chapter 29: the two queues over three frames, and what orders them.

From chapters/29_async_compute/main.cpp: record(N) submits scene N + 1 to the
graphics queue, then bloom N + 1 to the compute queue (waiting for scene N + 1
on the scenes timeline), then the runner submits tone map N (waiting for bloom
N on the blooms timeline, signalling frame N on the frames timeline).
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, ORANGE, ORANGE_FILL, Svg)

W, H = 1000, 400


def main() -> None:
    s = Svg(W, H, "Chapter 29: the graphics and the compute queue over three frames",
            "Two lanes of time. The graphics queue runs scene 2, tone map 1, scene 3, tone map 2, "
            "scene 4, tone map 3. The compute queue runs bloom 2 after scene 2, bloom 3 after "
            "scene 3, bloom 4 after scene 4, each while the graphics queue draws the tone map of "
            "the frame before and the next scene. Arrows: each bloom waits for its scene on the "
            "scenes timeline (release and acquire of the HDR image), each tone map waits for its "
            "bloom on the blooms timeline (release and acquire of the HDR image and the bloom "
            "chain). Below, the host waits on the frames timeline before it reuses a slot.")
    s.text(20, 28, "--queues async: frames 1 to 3 (record(N) submits scene N + 1, bloom N + 1, tone map N)",
           size=15, bold=True)
    gy, cy, h = 70, 190, 48
    s.text(20, gy + 30, "graphics queue", size=13, bold=True, fill=BLUE)
    s.text(20, cy + 30, "compute queue", size=13, bold=True, fill=GREEN)
    x0, scene_w, tone_w, bloom_w, gap = 150, 150, 70, 170, 8
    scenes, tones = {}, {}
    x = x0
    for n in (2, 3, 4):
        scenes[n] = x
        s.box(x, gy, scene_w, h, [f"scene {n}", "lamps.frag \u2192 HDR"], fill=BLUE_FILL, stroke=BLUE,
              size=12.5)
        x += scene_w + gap
        tones[n - 1] = x
        s.box(x, gy, tone_w, h, ["tone", f"map {n - 1}"], fill=ORANGE_FILL, stroke=ORANGE, size=12.5)
        x += tone_w + gap
    for n in (2, 3, 4):
        bx = scenes[n] + scene_w + 12
        s.box(bx, cy, bloom_w, h, [f"bloom {n}", "down 6 levels, up 5"], fill=GREEN_FILL,
              stroke=GREEN, size=12.5)
        # scene n -> bloom n: scenes timeline
        s.line(scenes[n] + scene_w - 10, gy + h, bx + 10, cy, stroke=INK, width=1.3, arrow="end")
        if n in tones:
            s.line(bx + bloom_w - 10, cy, tones[n] + tone_w / 2, gy + h, stroke=INK, width=1.3,
                   dash="5 3", arrow="end")
    s.text(20, cy + h + 40, "solid: the bloom waits for its scene (scenes timeline); the HDR image is "
           "released by the graphics family, acquired by the compute family.", size=12.5)
    s.text(20, cy + h + 62, "dashed: the tone map waits for its bloom (blooms timeline); the HDR image "
           "and the chain are released by compute, acquired by graphics.", size=12.5)
    s.text(20, cy + h + 84, "The bloom of N + 1 runs beside tone map N and scene N + 2: the overlap "
           "the chapter measures.", size=12.5)
    s.text(20, cy + h + 114, "Host: before slot s is used again, vkWaitSemaphores(frames timeline \u2265 "
           "the value of the frame that last showed it). No fence.", size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
