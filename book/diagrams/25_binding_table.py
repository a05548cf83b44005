"""Chapter 25: the shader binding table, laid out by the device's alignments.

The layout is computed here with the same rules as
chapters/25_ray_tracing/main.cpp's create_binding_table (a record is the
handle rounded up to shaderGroupHandleAlignment, each table starts at a
multiple of shaderGroupBaseAlignment, the ray-generation table's stride is
its size), for two devices: lavapipe (handle 32 bytes, handle alignment 16,
base alignment 32, what the chapter prints there) and a device with 32, 32
and 64 (NVIDIA's drivers report these). Bytes to scale, 5 px each.
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, Svg)

W, H = 1000, 560
PX = 5.0  # pixels per byte


def align_up(size: int, alignment: int) -> int:
    return (size + alignment - 1) // alignment * alignment


def layout(handle: int, handle_alignment: int, base: int) -> dict:
    record = align_up(handle, handle_alignment)
    raygen_size = align_up(record, base)
    miss_offset, miss_size = raygen_size, align_up(2 * record, base)
    hit_offset, hit_size = miss_offset + miss_size, record
    return {"handle": handle, "record": record, "base": base, "handle_alignment": handle_alignment,
            "regions": [("ray generation", 0, raygen_size, raygen_size, 1, ORANGE, ORANGE_FILL),
                        ("miss", miss_offset, record, miss_size, 2, BLUE, BLUE_FILL),
                        ("hit", hit_offset, record, hit_size, 1, GREEN, GREEN_FILL)],
            "total": hit_offset + hit_size}


def draw_table(s: Svg, x0: float, y: float, title: str, t: dict) -> None:
    s.text(x0, y - 54, title, size=14, bold=True)
    s.text(x0, y - 31, f"shaderGroupHandleSize {t['handle']}, shaderGroupHandleAlignment "
           f"{t['handle_alignment']}, shaderGroupBaseAlignment {t['base']}: records of "
           f"{t['record']} bytes, {t['total']} bytes in all", size=12.5, fill=MUTED)
    names = {"ray generation": ["raygen"], "miss": ["sky", "shadow"], "hit": ["closest hit"]}
    # Padding first (the whole table's width), then each record over it.
    s.rect(x0, y, t["total"] * PX, 40, fill=GREY_FILL, stroke=GREY)
    for name, offset, stride, size, count, stroke, fill in t["regions"]:
        for i in range(count):
            rx = x0 + (offset + i * stride) * PX
            s.rect(rx, y, t["handle"] * PX, 40, fill=fill, stroke=stroke, width=1.4)
            s.text(rx + t["handle"] * PX / 2, y + 16, names[name][i], size=13, anchor="middle")
            s.text(rx + t["handle"] * PX / 2, y + 33, f"handle {t['handle']} B", size=12.5,
                   anchor="middle", fill=MUTED)
        # The region the trace call is given: where it starts, its stride, its size.
        s.brace(x0 + offset * PX, x0 + (offset + size) * PX, y + 48, stroke=stroke)
        s.text(x0 + (offset + size / 2) * PX, y + 72, name, size=13, anchor="middle", fill=stroke,
               bold=True)
        s.text(x0 + (offset + size / 2) * PX, y + 90, f"+{offset}, stride {stride}, size {size}",
               size=12.5, anchor="middle", mono=True)
    # The base alignment's multiples: where a table may start.
    for b in range(0, t["total"] + 1, t["base"]):
        s.line(x0 + b * PX, y - 8, x0 + b * PX, y, stroke=INK, width=1.2)
        s.text(x0 + b * PX, y - 11, str(b), size=12.5, anchor="middle", fill=MUTED)


def main() -> None:
    s = Svg(W, H, "Chapter 25: the shader binding table on two devices",
            "The four shader group handles (ray generation, the sky miss, the shadow miss, the hit "
            "group) copied into one buffer. Each record is a handle rounded up to the handle "
            "alignment; each of the three tables starts at a multiple of the base alignment, with "
            "padding before it where needed. On lavapipe (32, 16, 32) the table is 128 bytes with no "
            "padding; on a device with 32, 32 and 64 the ray-generation table is padded to 64 bytes "
            "and the miss table to 64, 160 bytes in all.")
    s.text(20, 28, "vkGetRayTracingShaderGroupHandlesKHR: 4 handles, one per shader group, "
           "copied to their records", size=14, bold=True)
    s.text(20, 48, "grey: padding, never read.  Ticks: multiples of shaderGroupBaseAlignment, "
           "where a table may start (the buffer's address rounded up to one first).", size=12.5,
           fill=MUTED)
    draw_table(s, 40, 140, "lavapipe", layout(32, 16, 32))
    draw_table(s, 40, 360, "a device with 32, 32 and 64 (NVIDIA's drivers report these)",
               layout(32, 32, 64))
    s.lines(20, 520, ["vkCmdTraceRaysKHR(cmd, &raygen, &miss, &hit, &callable, width, height, 1) is "
                      "given the three regions (and an empty one for callables).",
                      "A ray's miss index picks a record of the miss table; its hit group offset, "
                      "plus the instance's, one of the hit table."], size=12.5, leading=1.4)
    s.write()


if __name__ == "__main__":
    main()
