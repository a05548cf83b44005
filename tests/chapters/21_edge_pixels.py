#!/usr/bin/env python3
"""Chapter 21's blended pixels, worked out from the geometry alone.

    python3 tests/chapters/21_edge_pixels.py

The numbers tests/chapters/21_multisampling.cmake allows around: for each
pixel of a test rectangle, how many of Vulkan's standard 4x sample positions
are covered. A pixel with one to three covered samples resolves to a blend.
  - the spokes: build_scene's twelve quads (chapters/21_multisampling/main.cpp),
    turned as the chapter turns them at frame 9 (t = 9/60 s), through
    clip_from_world at 320x240, in the rectangle x 10..59, y 100..139;
  - the stripes with sample shading: the fragment shader's formula
    (shaders/21_multisampling/scene.frag) at each sample position, in the
    rectangle x 250..284, y 90..129, which the striped quad covers whole.
"""
import math

WIDTH, HEIGHT = 320, 240
SAMPLES = ((0.375, 0.125), (0.875, 0.375), (0.125, 0.625), (0.625, 0.875))


def spoke_quads(frame):
    angle = 0.13 + 0.3 * frame / 60.0
    c, s = math.cos(angle), math.sin(angle)
    sx, sy, cx, cy = 0.75, -1.0, -0.62, 0.02  # 320x240: aspect 4/3, scale_y 1

    def to_pixels(p):
        xc = sx * (c * p[0] - s * p[1] + cx)
        yc = sy * (s * p[0] + c * p[1] + cy)
        return ((xc + 1) / 2 * WIDTH, (yc + 1) / 2 * HEIGHT)

    quads = []
    for k in range(12):
        a = 2 * math.pi * k / 12
        along, across = (math.cos(a), math.sin(a)), (-math.sin(a), math.cos(a))
        corners = []
        for r, h in ((0.06, -1), (0.78, -1), (0.78, 1), (0.06, 1)):
            corners.append(to_pixels((r * along[0] + h * 0.009 * across[0],
                                      r * along[1] + h * 0.009 * across[1])))
        quads.append(corners)
    return quads


def inside(quad, x, y):
    side = 0
    for i in range(4):
        (x0, y0), (x1, y1) = quad[i], quad[(i + 1) % 4]
        cross = (x1 - x0) * (y - y0) - (y1 - y0) * (x - x0)
        if cross == 0:
            continue
        if side == 0:
            side = 1 if cross > 0 else -1
        elif (cross > 0) != (side > 0):
            return False
    return True


def blended(rect, covered):
    x0, y0, w, h = rect
    counts = [0] * 5
    for y in range(y0, y0 + h):
        for x in range(x0, x0 + w):
            counts[sum(1 for ox, oy in SAMPLES if covered(x + ox, y + oy))] += 1
    return counts


def main():
    quads = spoke_quads(9)
    spokes = blended((10, 100, 50, 40), lambda x, y: any(inside(q, x, y) for q in quads))
    print(f"spokes, frame 9: {sum(spokes[1:4])} blended, {spokes[4]} covered, {spokes[0]} empty")

    def light(x, y):
        a = (x * 0.92 + y * 0.39) / 2.5
        return a - math.floor(a) <= 0.5  # step(fract(across), 0.5)

    stripes = blended((250, 90, 35, 40), light)
    print(f"stripes, sample shading: {sum(stripes[1:4])} blended of {sum(stripes)}")


if __name__ == "__main__":
    main()
