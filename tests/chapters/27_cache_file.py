#!/usr/bin/python3
"""Writes a pipeline cache file that chapter 27 must refuse, for its tests.

    27_cache_file.py corrupt PATH   # text where the header should be
    27_cache_file.py foreign PATH   # a well-formed header of another device

The foreign header names vendor 0x10de (NVIDIA), device 0x2330 and a cache
UUID of sixteen 0xab bytes, followed by 64 bytes of made-up data: lavapipe's
vendor is 0x10005, so every field the chapter checks differs there.
"""

import struct
import sys


def main(argv: list[str]) -> int:
    if len(argv) != 3 or argv[1] not in ("corrupt", "foreign"):
        print("usage: 27_cache_file.py corrupt|foreign PATH", file=sys.stderr)
        return 2
    if argv[1] == "corrupt":
        data = b"this is not a Vulkan pipeline cache, but it is long enough to have a header\n"
    else:
        # VkPipelineCacheHeaderVersionOne: headerSize, headerVersion, vendorID,
        # deviceID (four little-endian uint32), then the 16-byte UUID.
        data = struct.pack("<4I", 32, 1, 0x10DE, 0x2330) + bytes([0xAB] * 16) + bytes(range(64))
    with open(argv[2], "wb") as out:
        out.write(data)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
