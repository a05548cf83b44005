"""The tests' reviewed pictures (tests/golden/*.png), read for the book's figures.

A figure that shows part of a chapter's picture enlarged reads the golden
image here when the book is built, so it always shows what the tests check.
PNGs are decoded and encoded with zlib (8-bit RGB or RGBA, not interlaced:
what vkt::write_png writes): the standard library only, like svg.py.
"""

import base64
import struct
import zlib
from pathlib import Path

from svg import INK

GOLDEN = Path(__file__).resolve().parents[2] / "tests" / "golden"


def read_png(path: Path) -> list[list[tuple[int, int, int]]]:
    """The pixels of an 8-bit RGB or RGBA PNG, rows of (r, g, b)."""
    data = path.read_bytes()
    if data[:8] != b"\x89PNG\r\n\x1a\n":
        raise SystemExit(f"{path}: not a PNG file")
    pos, idat = 8, b""
    width = height = channels = 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour_type, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour_type not in (2, 6) or interlace:
                raise SystemExit(f"{path}: only 8-bit RGB or RGBA, not interlaced")
            channels = 3 if colour_type == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride = zlib.decompress(idat), width * channels
    rows, previous = [], bytearray(stride)
    for y in range(height):
        start = y * (stride + 1)
        kind, line = raw[start], bytearray(raw[start + 1:start + 1 + stride])
        for i in range(stride):  # undo the row's filter (PNG specification, section 9)
            a = line[i - channels] if i >= channels else 0
            b = previous[i]
            c = previous[i - channels] if i >= channels else 0
            if kind == 1:
                line[i] = (line[i] + a) & 255
            elif kind == 2:
                line[i] = (line[i] + b) & 255
            elif kind == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append([tuple(line[x * channels:x * channels + 3]) for x in range(width)])
        previous = line
    return rows


def png_bytes(rows: list[list[tuple[int, int, int]]]) -> bytes:
    """An 8-bit RGB PNG of rows of (r, g, b), every row unfiltered."""
    height, width = len(rows), len(rows[0])
    raw = b"".join(b"\0" + bytes(c for pixel in row for c in pixel) for row in rows)

    def chunk(kind: bytes, body: bytes) -> bytes:
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def enlarged(s, pixels, left: int, top: int, width: int, height: int, x: float, y: float,
             zoom: float) -> None:
    """The crop (left, top, width, height) of a picture drawn at (x, y), every pixel a
    square zoom units wide (pixelated, not smoothed), in a thin frame. The crop travels
    inside the SVG as a PNG: the figure needs no file beside it."""
    crop = [row[left:left + width] for row in pixels[top:top + height]]
    data = base64.b64encode(png_bytes(crop)).decode("ascii")
    s.add(f'<image x="{x:g}" y="{y:g}" width="{width * zoom:g}" height="{height * zoom:g}" '
          f'preserveAspectRatio="none" image-rendering="pixelated" style="image-rendering: pixelated" '
          f'href="data:image/png;base64,{data}"/>')
    s.rect(x, y, width * zoom, height * zoom, stroke=INK, width=1)
