#!/usr/bin/env python3
"""Writes the tutorial's textures into assets/textures/ (chapter 09).

checker.png, 256x256 RGB: an 8x8 checkerboard of 32-texel cells, light grey
cells alternating with saturated ones (red, green, blue, amber, a colour per
2x2 block of cells), every cell framed by a thin dark line. The lines and the
sharp cell edges are the high frequencies that alias (shimmer, moire) when a
texture is minified without mip maps; the coloured cells make it easy to see
which mip level is in use.

Only Python's standard library: the PNG is written with zlib and struct. The
output is the same byte for byte on every run (no timestamps, fixed zlib
level), so the committed file can be checked against the script.

    python3 scripts/make_textures.py            # writes assets/textures/checker.png
    python3 scripts/make_textures.py --check    # exit 1 if the file differs
"""

import pathlib
import struct
import sys
import zlib

SIZE = 256
CELL = 32
LINE = 2  # the dark frame of every cell, in texels
LIGHT = (230, 230, 222)
FRAME = (24, 24, 32)
PALETTE = [(200, 40, 40), (40, 160, 60), (40, 80, 200), (230, 160, 30)]


def texel(x, y):
    cx, cy = x // CELL, y // CELL
    ix, iy = x % CELL, y % CELL
    if ix < LINE or iy < LINE:
        return FRAME
    if (cx + cy) % 2 == 0:
        return LIGHT
    return PALETTE[(cx // 2 + 2 * (cy // 2)) % 4]


def png_chunk(kind, data):
    body = kind + data
    return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)


def png_rgb(width, height, pixel):
    rows = bytearray()
    for y in range(height):
        rows.append(0)  # filter type 0: the row as it is
        for x in range(width):
            rows.extend(pixel(x, y))
    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", header)
            + png_chunk(b"IDAT", zlib.compress(bytes(rows), 9)) + png_chunk(b"IEND", b""))


def main():
    out = pathlib.Path(__file__).resolve().parent.parent / "assets" / "textures" / "checker.png"
    data = png_rgb(SIZE, SIZE, texel)
    if "--check" in sys.argv[1:]:
        if not out.exists() or out.read_bytes() != data:
            print(f"{out} differs from what scripts/make_textures.py writes", file=sys.stderr)
            return 1
        print(f"{out} is up to date")
        return 0
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_bytes(data)
    print(f"wrote {out} ({len(data)} bytes)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
