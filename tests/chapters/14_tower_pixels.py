#!/usr/bin/env python3
"""Chapter 14's tower, worked out from the scene and the camera alone.

    python3 tests/chapters/14_tower_pixels.py

Prints the pixels tests/chapters/14_physics.cmake checks: where the middle of
a tower box's +x and +z faces lands in the 320x240 picture, and the colour
that face must have there, if the tower stands where it was built.
  - the scene: 1,000 falling boxes (so a floor of half width 20.32,
    physics_scene.cpp's add_falling_boxes), then add_stacks' tower of 20
    boxes 0.6 x 0.5 x 0.6 m at x = 5 - 20.32, z = 0, box i centred at
    y = 0.25 + 0.5 i; body index 2 + 1000 + 55 + i (the floor, the ramp, the
    falling boxes and the pyramid come first);
  - the camera: chapters/14_physics/main.cpp's look-at and 45 degree
    perspective, eye distance 1.7 x the heaps' extent;
  - the colour: box_colour's palette and scale, linear, times the fragment
    shader's 0.25 + 0.75 max(n . l, 0) for l = normalize(0.4, 1, 0.3),
    encoded to sRGB as the target stores it.
A tower that sank, leaned or fell, a wrong instance colour, a face lit by the
wrong normal, or a camera off by a pixel each change these.
"""
import math

W, H = 320, 240


def scene():
    count, spacing, clusters = 1000, 1.6, 4
    share = (count + clusters - 1) // clusters
    side, room = 1, 2
    while room < share:
        side += 1
        room += 2 * side * side
    width = spacing * side
    extent = 0.6 * width + 0.5 * width
    return count, extent, extent + 8.0  # falling boxes, extent, floor half width


def normalize(v):
    n = math.sqrt(sum(c * c for c in v))
    return [c / n for c in v]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def pixel_of(p, extent):
    d = 1.7 * extent
    eye, target = [0.45 * d, 0.8 * d, 1.3 * d], [0.0, 0.0, -0.1 * d]
    forward = normalize([t - e for t, e in zip(target, eye)])
    side = normalize(cross(forward, [0.0, 1.0, 0.0]))
    up = cross(side, forward)
    q = [a - e for a, e in zip(p, eye)]
    depth = dot(q, forward)
    focal = 1.0 / math.tan(math.radians(45.0) / 2)
    x = focal / (W / H) * dot(q, side) / depth
    y = focal * dot(q, up) / depth
    return (x + 1) / 2 * W, (1 - y) / 2 * H  # Vulkan's +y is down the screen


def box_colour(index):
    palette = [0xC03020, 0x2060C0, 0x30A040, 0xD0A020, 0x8040B0, 0x20A0A0]
    h = (index * 2654435761) & 0xFFFFFFFF
    rgb, scale = palette[(h >> 16) % 6], 160 + (h >> 8) % 96
    return [((rgb >> (16 - shift)) & 0xFF) * scale // 255 for shift in (0, 8, 16)]


def srgb(linear):
    c = 12.92 * linear if linear <= 0.0031308 else 1.055 * linear ** (1 / 2.4) - 0.055
    return round(255 * c)


def main():
    count, extent, floor = scene()
    to_light = normalize([0.4, 1.0, 0.3])
    x0, first = 5.0 - floor, 2 + count + 55
    for i in (4, 16):
        y = 0.25 + 0.5 * i
        for normal, centre in (([1, 0, 0], [x0 + 0.3, y, 0.0]), ([0, 0, 1], [x0, y, 0.3])):
            px, py = pixel_of(centre, extent)
            light = 0.25 + 0.75 * max(dot(normal, to_light), 0.0)
            r, g, b = (srgb(c / 255 * light) for c in box_colour(first + i))
            print(f"box {i}, face {normal}: pixel {px:.2f},{py:.2f} -> "
                  f"{int(px)},{int(py)},{r},{g},{b}")


if __name__ == "__main__":
    main()
