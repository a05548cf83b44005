#!/usr/bin/env python3
"""A log-log line chart of physics_bench's output, as a PNG, with the Python
standard library only (zlib and struct write the PNG).

    build/release/bin/physics_bench > benchmarks/results/physics.jsonl
    python3 benchmarks/plot_physics.py benchmarks/results/physics.jsonl book/images/14_physics_bench.png

Lines: the whole step with brute force (red) and with sort-and-sweep (blue),
and the broad phase alone, brute force (orange) and sort-and-sweep (cyan).
Grid lines at powers of ten (time) and at each box count; no text (the book
page says what the axes are), so no font is needed.
"""
import json
import math
import struct
import sys
import zlib

W, H, MARGIN = 640, 400, 40
SERIES = [("step_brute_force_ms", (200, 40, 30)), ("step_sweep_ms", (30, 80, 200)),
          ("pairs_brute_force_ms", (240, 150, 20)), ("pairs_sweep_ms", (20, 170, 190))]


def png(pixels):
    rows = b"".join(b"\0" + bytes(pixels[y * W * 3:(y + 1) * W * 3]) for y in range(H))
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                struct.pack(">I", zlib.crc32(kind + data)))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def main(source, target):
    rows = [json.loads(line) for line in open(source) if line.strip()]
    xs = [r["boxes"] for r in rows]
    values = [r[key] for r in rows for key, _ in SERIES]
    x0, x1 = math.log10(min(xs)), math.log10(max(xs))
    y0, y1 = math.floor(math.log10(min(values))), math.ceil(math.log10(max(values)))
    pixels = bytearray([255] * (W * H * 3))

    def to_screen(x, y):
        sx = MARGIN + (math.log10(x) - x0) / (x1 - x0) * (W - 2 * MARGIN)
        sy = H - MARGIN - (math.log10(y) - y0) / (y1 - y0) * (H - 2 * MARGIN)
        return sx, sy

    def dot(x, y, colour, radius=0):
        for dy in range(-radius, radius + 1):
            for dx in range(-radius, radius + 1):
                px, py = int(round(x)) + dx, int(round(y)) + dy
                if 0 <= px < W and 0 <= py < H:
                    pixels[(py * W + px) * 3:(py * W + px) * 3 + 3] = bytes(colour)

    def line(a, b, colour, radius=0):
        steps = int(max(abs(b[0] - a[0]), abs(b[1] - a[1]))) + 1
        for i in range(steps + 1):
            t = i / steps
            dot(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, colour, radius)

    grey = (215, 215, 215)
    for p in range(y0, y1 + 1):  # decades of milliseconds
        line(to_screen(xs[0], 10 ** p), to_screen(xs[-1], 10 ** p), grey)
    for x in xs:  # each box count
        line(to_screen(x, 10 ** y0), to_screen(x, 10 ** y1), grey)
    line((MARGIN, H - MARGIN), (W - MARGIN, H - MARGIN), (0, 0, 0))
    line((MARGIN, MARGIN), (MARGIN, H - MARGIN), (0, 0, 0))
    for key, colour in SERIES:
        points = [to_screen(r["boxes"], r[key]) for r in rows]
        for a, b in zip(points, points[1:]):
            line(a, b, colour, 1)
        for p in points:
            dot(p[0], p[1], colour, 3)
    with open(target, "wb") as out:
        out.write(png(pixels))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_physics.py RESULTS.jsonl OUT.png")
    main(sys.argv[1], sys.argv[2])
