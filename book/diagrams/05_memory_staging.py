"""Chapter 05: memory heaps and types, and the staging upload.

The heaps and types are what chapter 05 prints on an NVIDIA H100 and on
lavapipe (book/05_vertex_buffers.md quotes both); the upload is
chapters/05_vertex_buffers/main.cpp [upload]: a HOST_VISIBLE | HOST_COHERENT
staging buffer, a DEVICE_LOCAL buffer, vkCmdCopyBuffer, a barrier to the
vertex input stage, a fence wait.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
content is drawn 400 units wide: the heaps one above the other, the bus between.
"""

import os

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, Svg)

W, H = 1000, 668


def memory_type(s, x, y, w, number, flags, note=None, highlight=None, buffer=None):
    fill, stroke = highlight if highlight else ("#ffffff", GREY)
    h = 72 if buffer else (50 if note else 36)
    s.rect(x, y, w, h, fill=fill, stroke=stroke, rx=5, width=1.3 if highlight else 1)
    s.text(x + 10, y + 22, f"type {number}", size=12.5, bold=True)
    s.text(x + 68, y + 22, flags, size=10.5, mono=True)
    if note:
        s.text(x + 68, y + 39, note, size=11, fill=MUTED, italic=True)
    if buffer:
        box = (x + w - 150, y + 34, 140, 30)
        s.box(*box, buffer, fill="#ffffff", stroke=stroke, size=11.5, width=1.8)
        return box
    return None


def narrow_type(s, x, y, w, number, flags, note=None, highlight=None):
    fill, stroke = highlight if highlight else ("#ffffff", GREY)
    lines = [flags] if isinstance(flags, str) else flags
    h = 24 + 15 * len(lines) + (15 if note else 0)
    s.rect(x, y, w, h, fill=fill, stroke=stroke, rx=5, width=1.3 if highlight else 1)
    s.text(x + 10, y + 19, f"type {number}", size=12.5, bold=True)
    s.lines(x + 68, y + 19, lines, size=11, mono=True, leading=1.35)
    if note:
        s.text(x + 68, y + 19 + 15 * len(lines), note, size=11, fill=MUTED, italic=True)
    return h


def narrow() -> None:
    """The phone layout: 400 wide, every text at least 11 units."""
    nw = 400
    s = Svg(nw, 1200, "Chapter 05: memory heaps and types, and the staging upload",
            "On an NVIDIA H100: heap 1 is host RAM with memory types 0, 2 and 3, heap 0 is video "
            "memory with types 1 and 4. The CPU writes the vertices into a staging buffer in type 2, "
            "vkCmdCopyBuffer copies them across PCIe into a vertex buffer in type 1, a barrier makes "
            "the copy visible to the vertex input stage. On lavapipe there is one heap and one type.")
    s.lines(16, 26, ["A discrete GPU: NVIDIA H100,", "as chapter 05 prints it"], size=15, bold=True)
    s.box(16, 60, nw - 32, 58, ["CPU", "vkMapMemory, memcpy the vertices,", "vkUnmapMemory (no flush: coherent)"],
          fill="#ffffff", stroke=ORANGE, size=11.5, bold_first=True)
    s.line(nw / 2, 118, nw / 2, 146, stroke=ORANGE, width=2, arrow="end")
    s.text(nw / 2 + 8, 136, "1  write once", size=12, fill=ORANGE, bold=True)
    # Heap 1, host RAM.
    hy, x, w = 150, 16, nw - 32

    def behind(at: int, *args, **kw) -> None:  # a heap's rectangle, under what was drawn since `at`
        s.rect(*args, **kw)
        s.items.insert(at, s.items.pop())
    at = len(s.items)
    s.text(x + 10, hy + 22, "heap 1: host RAM, 96,665 MiB", size=14, bold=True)
    s.text(x + 10, hy + 40, "the CPU's side of the bus", size=11.5, fill=MUTED)
    y = hy + 50
    y += narrow_type(s, x + 10, y, w - 20, 0, "(no flags)") + 6
    y += narrow_type(s, x + 10, y, w - 20, 2, ["HOST_VISIBLE HOST_COHERENT"], "the staging buffer",
                     highlight=(ORANGE_FILL, ORANGE)) + 6
    y += narrow_type(s, x + 10, y, w - 20, 3, ["HOST_VISIBLE HOST_COHERENT", "HOST_CACHED"],
                     "reading back: CPU reads are cached") + 10
    behind(at, x, hy, w, y - hy, fill=ORANGE_FILL, stroke=ORANGE, rx=8, opacity=0.55)
    # The bus and the copy.
    by = y + 8
    s.line(nw / 2, by, nw / 2, by + 62, stroke=INK, width=2.2, arrow="end")
    s.box(24, by + 16, 130, 30, "PCIe bus", fill=GREY_FILL, stroke=GREY, size=12)
    s.lines(nw / 2 + 10, by + 22, ["2  vkCmdCopyBuffer,", "one-time command buffer"], size=12, bold=True)
    # Heap 0, video memory.
    hy = by + 70
    at = len(s.items)
    s.text(x + 10, hy + 22, "heap 0: video memory, 81,559 MiB", size=14, bold=True)
    s.text(x + 10, hy + 40, "DEVICE_LOCAL: the card's own HBM", size=11.5, fill=MUTED)
    y = hy + 50
    y += narrow_type(s, x + 10, y, w - 20, 1, "DEVICE_LOCAL", "vertex and index buffers",
                     highlight=(BLUE_FILL, BLUE)) + 6
    y += narrow_type(s, x + 10, y, w - 20, 4, ["DEVICE_LOCAL HOST_VISIBLE", "HOST_COHERENT"],
                     "video memory the CPU can map (BAR)") + 4
    s.lines(x + 10, y + 14, ["more flags than type 1: a plain DEVICE_LOCAL", "request finds type 1 first"],
            size=11, fill=MUTED, italic=True)
    y += 40
    behind(at, x, hy, w, y - hy, fill=BLUE_FILL, stroke=BLUE, rx=8, opacity=0.55)
    s.line(nw / 2, y, nw / 2, y + 28, stroke=BLUE, width=2, arrow="end")
    s.text(nw / 2 + 8, y + 20, "4  read often", size=12, fill=BLUE, bold=True)
    s.box(16, y + 30, nw - 32, 44, ["GPU", "vertex input reads the vertex buffer, every draw"],
          fill="#ffffff", stroke=BLUE, size=11.5, bold_first=True)
    y += 104
    s.lines(16, y, [
        "**1** Staging: HOST_VISIBLE | HOST_COHERENT,",
        "usage TRANSFER_SRC; mapped, memcpy, unmapped.",
        "**2** The copy into a DEVICE_LOCAL buffer, usage",
        "VERTEX_BUFFER (or INDEX_BUFFER) | TRANSFER_DST.",
        "**3** A barrier: COPY / TRANSFER_WRITE before,",
        "VERTEX_INPUT / VERTEX_ATTRIBUTE_READ | INDEX_READ",
        "after; submit, wait for the fence, destroy staging.",
        "**4** Every draw then reads video memory, not host",
        "RAM across the bus.",
        "A request takes the first type that memoryTypeBits",
        "allows with every wanted flag; the list puts types",
        "with fewer flags first.",
    ], size=11.5, leading=1.45)
    ly = y + 12 * 11.5 * 1.45 + 4
    s.rect(16, ly, nw - 32, 92, fill=GREEN_FILL, stroke=GREEN, rx=8)
    s.lines(28, ly + 22, ["lavapipe (a CPU that plays GPU): heap 0,", "the machine's RAM, and one memory type"],
            size=12, bold=True, leading=1.35)
    s.lines(28, ly + 60, ["type 0: DEVICE_LOCAL HOST_VISIBLE HOST_COHERENT", "HOST_CACHED. Both requests find it; the copy",
                          "still runs."], size=11, leading=1.3)
    s.height = ly + 92 + 16
    s.write()


def main() -> None:
    if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow":
        narrow()
        return
    s = Svg(W, H, "Chapter 05: memory heaps and types, and the staging upload",
            "On an NVIDIA H100: heap 1 is host RAM with memory types 0, 2 and 3, heap 0 is video "
            "memory with types 1 and 4. The CPU writes the vertices into a staging buffer in type 2, "
            "vkCmdCopyBuffer copies them across PCIe into a vertex buffer in type 1, a barrier makes "
            "the copy visible to the vertex input stage. On lavapipe there is one heap and one type.")

    s.text(20, 28, "A discrete GPU: NVIDIA H100, as chapter 05 prints it", size=15, bold=True)

    # The two heaps, the bus between them.
    hx1, hx2, hy, hw, hh = 20, 580, 150, 400, 262
    s.rect(hx1, hy, hw, hh, fill=ORANGE_FILL, stroke=ORANGE, rx=8, opacity=0.55)
    s.text(hx1 + 12, hy + 24, "heap 1: host RAM, 96,665 MiB", size=14, bold=True)
    s.text(hx1 + 12, hy + 42, "the machine's memory, the CPU's side of the bus", size=11.5, fill=MUTED)
    s.rect(hx2, hy, hw, hh, fill=BLUE_FILL, stroke=BLUE, rx=8, opacity=0.55)
    s.text(hx2 + 12, hy + 24, "heap 0: video memory, 81,559 MiB", size=14, bold=True)
    s.text(hx2 + 12, hy + 42, "a DEVICE_LOCAL heap: the card's own HBM", size=11.5, fill=MUTED)
    s.rect(hx1 + hw + 30, hy + 112, hx2 - hx1 - hw - 60, 30, fill=GREY_FILL, stroke=GREY, rx=4)
    s.text((hx1 + hw + hx2) / 2, hy + 132, "PCIe bus", size=12, anchor="middle", bold=True)

    ty, tw = hy + 56, hw - 24
    memory_type(s, hx1 + 12, ty, tw, 0, "(no flags)")
    sb = memory_type(s, hx1 + 12, ty + 44, tw, 2, "HOST_VISIBLE HOST_COHERENT", "the staging buffer",
                     highlight=(ORANGE_FILL, ORANGE), buffer="staging buffer")
    memory_type(s, hx1 + 12, ty + 124, tw, 3, "HOST_VISIBLE HOST_COHERENT HOST_CACHED",
                "reading back: CPU reads are cached")
    vb = memory_type(s, hx2 + 12, ty, tw, 1, "DEVICE_LOCAL", "vertex and index buffers",
                     highlight=(BLUE_FILL, BLUE), buffer="vertex buffer")
    memory_type(s, hx2 + 12, ty + 80, tw, 4, "DEVICE_LOCAL HOST_VISIBLE HOST_COHERENT",
                "video memory the CPU can map (the BAR)")
    s.lines(hx2 + 80, ty + 150, ["more flags than type 1: a plain DEVICE_LOCAL", "request finds type 1 first"],
            size=11, fill=MUTED, italic=True)

    # The CPU and the GPU above.
    s.box(hx1 + 100, 52, 300, 62, ["CPU", "vkMapMemory, memcpy the vertices,", "vkUnmapMemory (no flush: coherent)"],
          fill="#ffffff", stroke=ORANGE, size=11.5, bold_first=True)
    s.box(hx2 + 100, 52, 300, 62, ["GPU", "vertex input reads the vertex buffer", "in every frame's draw"],
          fill="#ffffff", stroke=BLUE, size=11.5, bold_first=True)
    s.line(sb[0] + 70, 114, sb[0] + 70, sb[1], stroke=ORANGE, width=2, arrow="end")
    s.text(sb[0] + 76, 136, "1  write once", size=12, fill=ORANGE, bold=True)
    s.line(vb[0] + 70, vb[1], vb[0] + 70, 114, stroke=BLUE, width=2, arrow="end")
    s.text(vb[0] + 76, 136, "4  read often", size=12, fill=BLUE, bold=True)

    # The copy, across the bus.
    s.path(f"M{sb[0] + 140},{sb[1] + 15} C{hx1 + hw + 80},{sb[1] + 15} {hx2 - 80},{vb[1] + 15} "
           f"{vb[0]},{vb[1] + 15}", stroke=INK, width=2.2, arrow="end")
    s.lines((hx1 + hw + hx2) / 2, hy + 70, ["2  vkCmdCopyBuffer", "one-time command", "buffer"], size=12,
            anchor="middle", bold=True)

    # The steps, below the heaps.
    y = hy + hh + 56
    s.lines(20, y, [
        "**1** Staging: HOST_VISIBLE | HOST_COHERENT, usage TRANSFER_SRC; mapped, memcpy, unmapped.",
        "**2** The copy into a DEVICE_LOCAL buffer made with usage VERTEX_BUFFER (or INDEX_BUFFER) | TRANSFER_DST.",
        "**3** A barrier: COPY / TRANSFER_WRITE before, VERTEX_INPUT / VERTEX_ATTRIBUTE_READ | INDEX_READ after;",
        "     then submit, wait for the fence, and destroy the staging buffer.",
        "**4** Every draw after that reads video memory, not host RAM across the bus.",
        "A request takes the first type that memoryTypeBits allows and that has every wanted flag;",
        "the list puts types with fewer flags first.",
    ], size=12.5, leading=1.45)

    # Lavapipe, for contrast.
    lx, ly, lw, lh = 20, H - 70, W - 40, 56
    s.rect(lx, ly, lw, lh, fill=GREEN_FILL, stroke=GREEN, rx=8)
    s.text(lx + 12, ly + 22, "lavapipe (a CPU that plays GPU): heap 0, the machine's RAM, and one memory type",
           size=12.5, bold=True)
    s.text(lx + 12, ly + 42, "type 0: DEVICE_LOCAL HOST_VISIBLE HOST_COHERENT HOST_CACHED. Both requests find it;"
           " the copy still runs.", size=11.5, mono=False)
    s.write()


if __name__ == "__main__":
    main()
