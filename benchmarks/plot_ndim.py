#!/usr/bin/env python3
"""Median frame time against n for chapters 18, 19 and 20 (one n-cube and 250
n-cubes at 1920x1080), from the raw output of their benchmark scripts, as a
PNG written with the Python standard library only (zlib and struct), in the
manner of plot_lights.py.

    python3 benchmarks/plot_ndim.py book/images/20_ndim_compute_bench.png \\
        benchmarks/results/2026-11-23-18_ndim_cpu-lavapipe.txt \\
        benchmarks/results/2026-11-23-19_ndim_gpu-lavapipe.txt \\
        benchmarks/results/2026-11-23-20_ndim_compute-lavapipe.txt

Each run in the input is a line "# CHAPTER --scene S --dim N [...]" followed
by the runner's JSON line. x: n (4, 8, 12, linear); y: the median frame time
(cpu_frame_ms, the runner's clock around a whole frame) in milliseconds, log
scale. Lines: chapter 18 (red), 19 (green), 20 with graphics lines (orange),
20 with the compute rasteriser (blue); thick for 250 n-cubes, thin with
hollow points for one. Runs with other options (18's --matrix, 19's
--edge-order) are left out.
Grid lines at powers of ten and at each n; no text (the book page says what
the axes are), so no font is needed.
"""
import json
import math
import struct
import sys
import zlib

W, H, MARGIN = 640, 400, 40
COLOURS = {"18": (200, 40, 30), "19": (40, 160, 60), "20 graphics": (240, 150, 20),
           "20 compute": (30, 80, 200)}


def png(pixels):
    rows = b"".join(b"\0" + bytes(pixels[y * W * 3:(y + 1) * W * 3]) for y in range(H))
    chunk = lambda kind, data: (struct.pack(">I", len(data)) + kind + data +
                                struct.pack(">I", zlib.crc32(kind + data)))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(rows, 9)) + chunk(b"IEND", b""))


def read_runs(sources):
    """{(series, scene): {n: median ms}} from the scripts' raw output."""
    runs, header = {}, None
    for source in sources:
        for line in open(source):
            if line.startswith("# "):
                header = line[2:].split()
                continue
            if not line.startswith("{") or not header:
                continue
            args, header = header, None
            chapter = args[0][:2]
            options = {a for a in args[1:] if a.startswith("--")}
            if chapter not in ("18", "19", "20") or "--dim" not in args or \
                    options - {"--scene", "--dim", "--raster", "--frames"}:
                continue  # the empty frame, the default scene, other options
            scene, n = args[args.index("--scene") + 1], int(args[args.index("--dim") + 1])
            series = chapter
            if chapter == "20":
                series += " " + args[args.index("--raster") + 1]
            runs.setdefault((series, scene), {})[n] = json.loads(line)["cpu_frame_ms"]["median"]
    return runs


def main(target, sources):
    runs = read_runs(sources)
    if not runs:
        sys.exit("plot_ndim.py: no runs found")
    values = [ms for points in runs.values() for ms in points.values()]
    y0, y1 = math.floor(math.log10(min(values))), math.ceil(math.log10(max(values)))
    x0, x1 = 4, 12
    pixels = bytearray([255] * (W * H * 3))

    def to_screen(n, ms):
        return (MARGIN + (n - x0) / (x1 - x0) * (W - 2 * MARGIN),
                H - MARGIN - (math.log10(ms) - y0) / (y1 - y0) * (H - 2 * MARGIN))

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
    for p in range(y0, y1 + 1):
        line(to_screen(x0, 10 ** p), to_screen(x1, 10 ** p), grey)
    for n in (4, 8, 12):
        line(to_screen(n, 10 ** y0), to_screen(n, 10 ** y1), grey)
    line((MARGIN, H - MARGIN), (W - MARGIN, H - MARGIN), (0, 0, 0))
    line((MARGIN, MARGIN), (MARGIN, H - MARGIN), (0, 0, 0))
    for (series, scene), points in sorted(runs.items()):
        if series not in COLOURS or scene not in ("cube", "many"):
            continue
        colour, many = COLOURS[series], scene == "many"
        xy = [to_screen(n, points[n]) for n in sorted(points)]
        for a, b in zip(xy, xy[1:]):
            line(a, b, colour, 1 if many else 0)
        for x, y in xy:
            dot(x, y, colour, 4)
            if not many:
                dot(x, y, (255, 255, 255), 2)
    with open(target, "wb") as out:
        out.write(png(pixels))


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit("usage: plot_ndim.py OUT.png RESULTS.txt...")
    main(sys.argv[1], sys.argv[2:])
