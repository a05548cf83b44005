"""Chapter 28b: the task payload, one packed word per mesh workgroup launched.

Top: one 32-bit launch word, the instance in the high 32 - kMeshletBits bits
and the meshlet in the low kMeshletBits (shaders/28_gpu_culling/task_data.glsl,
instances.task: `(i << kMeshletBits) | (mesh.first_meshlet + m)`), with the
bits of an example word. Below: one task workgroup of kTaskGroup invocations,
one instance each; those that keep their instance append one word per meshlet
of its mesh to the payload (room for kTaskGroup * kMostMeshlets words), and
EmitMeshTasksEXT launches one mesh workgroup per word. The constants are read
from task_data.glsl; which instances are kept and how many meshlets their
meshes have are an example, as drawn.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
content is drawn 400 units wide: narrower cells, the text in short lines.
"""

import os
import sys
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, PURPLE_FILL, RED, Svg)

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

TASK_DATA = Path(__file__).resolve().parents[2] / "shaders" / "28_gpu_culling" / "task_data.glsl"
GROUP = int(constant(TASK_DATA, "kTaskGroup"))
MOST = int(constant(TASK_DATA, "kMostMeshlets"))
BITS = int(constant(TASK_DATA, "kMeshletBits"))

# The example: the invocations that keep their instance, with their mesh's first
# meshlet and meshlet count, in the order their atomicAdd on `launches` landed.
INSTANCE, MESHLET = 37, 5  # the example word
KEPT = [(0, 4, 3), (5, 0, 4), (6, 7, 2), (20, 4, 3)]  # (invocation, first_meshlet, count)
COLOURS = [(BLUE, BLUE_FILL), (GREEN, GREEN_FILL), (ORANGE, ORANGE_FILL), (PURPLE, PURPLE_FILL)]

W, H = 760, 650


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    launches = sum(count for _, _, count in KEPT)
    word = INSTANCE << BITS | MESHLET
    # Sizes: the wide layout, or the phone's (every text at least 11 units).
    cell, pw, x0, small, body = (11, 28, 24, 11, 12) if narrow else (20, 40, 60, 11.5, 12.5)
    mono = 11 if narrow else 12
    width = 400 if narrow else W
    s = Svg(width, H, "Chapter 28b: the task payload, one packed word per mesh workgroup",
            f"Top: a 32-bit launch word; its high {32 - BITS} bits hold the instance, its low {BITS} "
            f"bits the meshlet; instance {INSTANCE} and meshlet {MESHLET} make {word:,}. "
            f"Below: one task workgroup of {GROUP} invocations, one instance each; four keep their "
            f"instance and append one word per meshlet of its mesh to the payload, {launches} words of "
            f"the {GROUP * MOST} it has room for; EmitMeshTasksEXT({launches}, 1, 1) launches "
            f"{launches} mesh workgroups, the k-th reading word k.")
    y = 28
    if narrow:
        s.lines(16, y, ["One launch word: the instance and the", "meshlet in 32 bits"], size=14, bold=True)
        y += 18
    else:
        s.text(20, y, "One launch word: the instance and the meshlet in 32 bits", size=14, bold=True)
    y0 = y + 44
    for b in range(32):
        bit = 31 - b
        high = bit >= BITS
        x = x0 + b * cell
        s.rect(x, y0, cell, 28, fill=BLUE_FILL if high else ORANGE_FILL, stroke=BLUE if high else ORANGE,
               width=1)
        s.text(x + cell / 2, y0 + 19, str(word >> bit & 1), size=mono, anchor="middle", mono=True)
        if bit in (31, BITS, BITS - 1, 0):
            s.text(x + cell / 2 + (3 if bit == BITS - 1 and narrow else 0) - (3 if bit == BITS and narrow else 0),
                   y0 - 8, str(bit), size=small, anchor="middle", fill=MUTED)
    split = x0 + (32 - BITS) * cell
    if not narrow:
        s.text(x0 - 8, y0 - 8, "bit", size=12, anchor="end", fill=MUTED)
    s.brace(x0, split - 2, y0 + 34)
    s.brace(split + 2, x0 + 32 * cell, y0 + 34)
    if narrow:
        instance = [f"instance i: {32 - BITS} bits,", f"0 .. {(1 << (32 - BITS)) - 1:,}; here {INSTANCE}"]
        meshlet = [f"meshlet: {BITS} bits,", f"0 .. {(1 << BITS) - 1:,}; here {MESHLET}"]
    else:
        instance = [f"instance i: {32 - BITS} bits, 0 .. {(1 << (32 - BITS)) - 1:,}", f"here {INSTANCE}"]
        meshlet = [f"meshlet: {BITS} bits, 0 .. {(1 << BITS) - 1:,}", f"here {MESHLET}"]
    s.lines((x0 + split) / 2, y0 + 62, instance, size=body, anchor="middle", fill=BLUE)
    s.lines((split + x0 + 32 * cell) / 2, y0 + 62, meshlet, size=body, anchor="middle", fill=ORANGE)
    if narrow:
        code = [f"task: launch = (i << {BITS})", "            | (mesh.first_meshlet + m)",
                f"      = {INSTANCE} \u00d7 {1 << BITS:,} + {MESHLET} = {word:,}",
                f"mesh: instance = launch >> {BITS}", f"      meshlet = launch & {(1 << BITS) - 1}"]
    else:
        code = [f"task:  launch = (i << {BITS}) | (mesh.first_meshlet + m)"
                f"  = {INSTANCE} \u00d7 {1 << BITS:,} + {MESHLET} = {word:,}",
                f"mesh:  instance = launch >> {BITS};  meshlet = launch & {(1 << BITS) - 1}"]
    s.lines(x0 if not narrow else 16, y0 + 118, code, size=mono, mono=True, leading=1.55)

    # ---- One task workgroup ----------------------------------------------------------------
    ty = y0 + 118 + len(code) * mono * 1.55 + 36
    if narrow:
        s.lines(16, ty, [f"One task workgroup: {GROUP} invocations,", "one instance each, fill the payload"],
                size=14, bold=True)
        ty += 18
        caption = [f"invocation 0 .. {GROUP - 1}: instance {GROUP}w + invocation;",
                   "coloured: kept (the number: its mesh's",
                   "meshlets), grey: culled"]
    else:
        s.text(20, ty, f"One task workgroup: {GROUP} invocations, one instance each, fill the payload",
               size=14, bold=True)
        caption = [f"invocation 0 .. {GROUP - 1}: instance {GROUP}w + invocation; "
                   "coloured: kept (the number: its mesh's meshlets), grey: culled"]
    s.lines(x0 if not narrow else 16, ty + 32, caption, size=12 if not narrow else small, fill=MUTED)
    iy = ty + 32 + (len(caption) - 1) * 15 + 10
    kept = {inv: k for k, (inv, _, _) in enumerate(KEPT)}
    for inv in range(GROUP):
        x = x0 + inv * cell
        if inv in kept:
            stroke, fill = COLOURS[kept[inv]]
        else:
            stroke, fill = GREY, GREY_FILL
        s.rect(x, iy, cell, 26, fill=fill, stroke=stroke, width=1.6 if inv in kept else 0.8)
        if inv in kept:
            s.text(x + cell / 2, iy + 18, str(KEPT[kept[inv]][2]), size=mono, anchor="middle", bold=True,
                   fill=stroke)
    # The payload: the words written, then the room left.
    if narrow:
        caption = [f"payload.launch[{GROUP} \u00d7 {MOST} = {GROUP * MOST}]: a kept instance",
                   "appends one word per meshlet at",
                   "atomicAdd(launches, count); each word shown",
                   "as its invocation (top) and its meshlet (bottom)"]
    else:
        caption = [f"payload.launch[{GROUP} \u00d7 {MOST} = {GROUP * MOST}]: a kept instance appends one word "
                   "per meshlet at atomicAdd(launches, count);",
                   "each word shown as its invocation (top) and its meshlet (bottom), packed as above"]
    cy = iy + 80
    s.lines(x0 if not narrow else 16, cy, caption, size=12 if not narrow else small, fill=MUTED)
    py = cy + len(caption) * 15 + 6
    at = 0
    for k, (inv, first, count) in enumerate(KEPT):
        stroke, fill = COLOURS[k]
        s.line(x0 + inv * cell + cell / 2, iy + 26, x0 + at * pw + 6, cy - 18, stroke=stroke, width=1.3,
               arrow="end")
        for m in range(count):
            x = x0 + (at + m) * pw
            s.rect(x, py, pw, 34, fill=fill, stroke=stroke, width=1.4)
            s.text(x + pw / 2, py + 14, f"{inv}", size=small, anchor="middle", fill=stroke)
            s.text(x + pw / 2, py + 28, f"m{first + m}", size=small, anchor="middle", fill=INK)
        at += count
    rest = x0 + at * pw
    end = width - 16 if narrow else x0 + 32 * cell
    s.rect(rest, py, end - rest, 34, fill="#ffffff", stroke=GREY, width=1, dash="4 3")
    if narrow:
        s.text(rest + 3, py + 22, "\u2026", size=small, fill=MUTED)
    else:
        s.lines(rest + 8, py + 14, ["unused, up to", f"launch[{GROUP * MOST - 1}]"], size=small, fill=MUTED,
                leading=1.2)
    # The mesh workgroups.
    my = py + 62
    for k in range(launches):
        x = x0 + k * pw
        s.line(x + pw / 2, py + 35, x + pw / 2, my - 1, stroke=GREY, width=1.1, arrow="end")
        s.rect(x + 3, my, pw - 6, 30, fill="#ffffff", stroke=INK, width=1.2, rx=4)
        s.text(x + pw / 2, my + 20, str(k), size=12 if not narrow else small, anchor="middle")
    if narrow:
        s.text(x0, my + 48, "mesh workgroups", size=body, fill=INK)
        s.text(end, my + 48, f"unused, up to launch[{GROUP * MOST - 1}]", size=small, fill=MUTED,
               anchor="end")
        my += 20
    else:
        s.text(x0 + launches * pw + 8, my + 20, "mesh workgroups", size=body, fill=INK)
    my += 30
    if narrow:
        s.lines(16, my + 28, [f"EmitMeshTasksEXT(launches = {launches}, 1, 1):", "one mesh workgroup per word"],
                size=body, bold=True)
        my += 16
        text = ["mesh workgroup k reads payload.launch[k]",
                "(gl_WorkGroupID.x = k), unpacks the instance and",
                "the meshlet, and writes that meshlet's triangles,",
                "placed by that instance's transform. At most",
                f"{GROUP} \u00d7 {MOST} = {GROUP * MOST} mesh workgroups per task",
                "workgroup; a culled instance launches none."]
        note = ["Which instances are kept and their meshlet", "counts: an example, as drawn."]
        tx = 16
    else:
        s.text(x0, my + 28, f"EmitMeshTasksEXT(launches = {launches}, 1, 1): one mesh workgroup per word",
               size=body, bold=True)
        text = [f"mesh workgroup k reads payload.launch[gl_WorkGroupID.x = k], unpacks the instance and the meshlet,",
                f"and writes that meshlet's triangles, placed by that instance's transform. At most {GROUP} \u00d7 "
                f"{MOST} = {GROUP * MOST}",
                "mesh workgroups per task workgroup; a culled instance launches none."]
        note = ["Which instances are kept and their meshlet counts: an example, as drawn."]
        tx = x0
    s.lines(tx, my + 56, text, size=body)
    ny = my + 56 + len(text) * body * 1.3 + 14
    s.lines(tx, ny, note, size=12 if not narrow else small, fill=RED)
    s.height = ny + len(note) * 15 + 12
    s.write()


if __name__ == "__main__":
    main()
