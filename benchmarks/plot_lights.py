#!/usr/bin/env python3
"""A log-log line chart of scripts/bench-lights.sh --tiled output (its Markdown
table rows), as a PNG, with the Python standard library only (zlib and struct
write the PNG), in the manner of plot_physics.py.

    scripts/bench-lights.sh build/release/bin/16_deferred --tiled build/release/bin/17_tiled_deferred \
        > benchmarks/results/17_tiled_deferred-DEVICE.md
    python3 benchmarks/plot_lights.py benchmarks/results/17_tiled_deferred-DEVICE.md book/images/17_tiled_deferred_bench.png

x: lights; y: GPU milliseconds per frame (sum of the passes' medians).
Lines: forward (red), deferred (orange), tiled fragment (blue), tiled compute
(cyan); a cell "n/a" leaves its point out. Dashed grey lines mark 16.7 ms and
6.9 ms (the frame budgets of 60 and 144 frames a second) where they fall
inside the chart. Grid lines at powers of ten (time) and at each light count;
no text (the book page says what the axes are), so no font is needed.
"""
import math
import struct
import sys
import zlib

W, H, MARGIN = 640, 400, 40
# (column of the table, colour): forward, deferred, tiled fragment, tiled compute
SERIES = [(3, (200, 40, 30)), (4, (240, 150, 20)), (6, (30, 80, 200)), (8, (20, 170, 190))]
BUDGETS = [16.7, 6.9]


def png(pixels):
    rows = b"".join(b"\0" + bytes(pixels[y * W * 3:(y + 1) * W * 3]) for y in range(H))
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                struct.pack(">I", zlib.crc32(kind + data)))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def number(cell):
    try:
        return float(cell.replace(",", ""))
    except ValueError:
        return None


def read_rows(source):
    rows = []
    for line in open(source):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) < 9 or number(cells[2]) is None:
            continue  # the header, the separator, anything else
        rows.append([number(c) for c in cells])
    return sorted(rows, key=lambda r: r[2])


def main(source, target):
    rows = read_rows(source)
    if not rows:
        sys.exit(f"plot_lights.py: no table rows in {source}")
    xs = [r[2] for r in rows]
    values = [r[col] for r in rows for col, _ in SERIES if r[col]]
    x0, x1 = math.log10(min(xs)), math.log10(max(xs))
    if x1 == x0:
        x1 = x0 + 1
    y0, y1 = math.floor(math.log10(min(values))), math.ceil(math.log10(max(values)))
    if y1 == y0:
        y1 = y0 + 1
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

    def line(a, b, colour, radius=0, dash=0):
        steps = int(max(abs(b[0] - a[0]), abs(b[1] - a[1]))) + 1
        for i in range(steps + 1):
            if dash and (i // dash) % 2:
                continue
            t = i / steps
            dot(a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, colour, radius)

    grey = (215, 215, 215)
    for p in range(y0, y1 + 1):  # decades of milliseconds
        line(to_screen(xs[0], 10 ** p), to_screen(xs[-1], 10 ** p), grey)
    for x in xs:  # each light count
        line(to_screen(x, 10 ** y0), to_screen(x, 10 ** y1), grey)
    for budget in BUDGETS:
        if 10 ** y0 < budget < 10 ** y1:
            line(to_screen(xs[0], budget), to_screen(xs[-1], budget), (120, 120, 120), 0, 6)
    line((MARGIN, H - MARGIN), (W - MARGIN, H - MARGIN), (0, 0, 0))
    line((MARGIN, MARGIN), (MARGIN, H - MARGIN), (0, 0, 0))
    for col, colour in SERIES:
        points = [to_screen(r[2], r[col]) for r in rows if r[col]]
        for a, b in zip(points, points[1:]):
            line(a, b, colour, 1)
        for p in points:
            dot(p[0], p[1], colour, 3)
    with open(target, "wb") as out:
        out.write(png(pixels))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit("usage: plot_lights.py TABLE.md OUT.png")
    main(sys.argv[1], sys.argv[2])
