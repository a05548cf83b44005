"""Chapter 28b: the task payload, two words per mesh workgroup launched.

Top: one 32-bit launch word, the instance in the high 32 - kMeshletBits bits
and the meshlet in the low kMeshletBits (shaders/28_gpu_culling/task_data.glsl,
instances.task: `(i << kMeshletBits) | m`, m an index into the list of all
meshlets), with the bits of an example word. Below: one task workgroup of
kTaskGroup invocations, one instance each; for each meshlet of a kept instance
an invocation takes the next slot k = atomicAdd(launches, 1) and writes
payload.launch[k]; payload.why[k], the payload's second array, is written and
read only in --view culled's pass. EmitMeshTasksEXT launches one mesh workgroup
per slot. The constants and the payload's arrays (their names and count) are
read from task_data.glsl; which instances are kept, how many meshlets their
meshes have and the order the atomics gave are an example, as drawn.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
content is drawn 400 units wide: narrower cells, the text in short lines.
"""

import os
import re
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
# The payload's arrays, `uint NAME[kTaskGroup * kMostMeshlets];` each, in order.
_PAYLOAD = re.search(r"struct Payload\s*\{(.*?)\};", TASK_DATA.read_text(encoding="utf-8"), re.S)
ARRAYS = re.findall(r"^\s*uint\s+(\w+)\[kTaskGroup \* kMostMeshlets\];", _PAYLOAD.group(1), re.M)
if ARRAYS != ["launch", "why"] or len(re.findall(r";", re.sub(r"//.*", "", _PAYLOAD.group(1)))) != 2:
    sys.exit(f"{TASK_DATA.name}: struct Payload is not launch[] and why[] any more: redraw 28b_task_payload")
ROOM = GROUP * MOST
BYTES = len(ARRAYS) * 4  # per launch slot

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
    s = Svg(width, H, "Chapter 28b: the task payload, launch[] and why[], one slot per mesh workgroup",
            f"Top: a 32-bit launch word; its high {32 - BITS} bits hold the instance, its low {BITS} "
            f"bits the meshlet; instance {INSTANCE} and meshlet {MESHLET} make {word:,}. "
            f"Below: one task workgroup of {GROUP} invocations, one instance each; four keep their "
            f"instance and write one launch word per meshlet of its mesh, each in the next free slot, "
            f"{launches} of the {ROOM} the payload has room for. The payload's second array, why[], "
            f"is left unwritten: only --view culled's pass uses it. Each slot takes {BYTES} bytes, "
            f"{ROOM * BYTES:,} in all. EmitMeshTasksEXT({launches}, 1, 1) launches {launches} mesh "
            f"workgroups, the k-th reading slot k.")
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
        caption = [f"payload.launch[{GROUP} \u00d7 {MOST} = {ROOM}]: each meshlet",
                   "of a kept instance takes the next slot,",
                   "k = atomicAdd(launches, 1); a word shown as",
                   "its invocation (top) and meshlet (bottom)"]
    else:
        caption = [f"payload.launch[{GROUP} \u00d7 {MOST} = {ROOM}]: each meshlet of a kept instance takes the "
                   "next slot,",
                   "k = atomicAdd(launches, 1); each word shown as its invocation (top) and its meshlet (bottom)"]
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
    # The second array, why[], in the row below: unwritten by the frame's passes.
    wy, wh = py + 34, 20
    for k in range(launches):
        x = x0 + k * pw
        s.rect(x, wy, pw, wh, fill=GREY_FILL, stroke=GREY, width=0.8, dash="3 2")
        s.text(x + pw / 2, wy + 14, "\u2013", size=small, anchor="middle", fill=MUTED)
    if not narrow:
        s.text(x0 - 6, py + 22, "launch", size=small, anchor="end", fill=MUTED, mono=True)
        s.text(x0 - 6, wy + 14, "why", size=small, anchor="end", fill=MUTED, mono=True)
    rest = x0 + at * pw
    end = width - 16 if narrow else x0 + 32 * cell
    s.rect(rest, py, end - rest, 34 + wh, fill="#ffffff", stroke=GREY, width=1, dash="4 3")
    if narrow:
        s.text(rest + 3, py + 22, "\u2026", size=small, fill=MUTED)
    else:
        s.lines(rest + 8, py + 18, ["unused slots,", f"up to {ROOM - 1}"], size=small, fill=MUTED,
                leading=1.3)
    # The mesh workgroups.
    my = wy + wh + 32
    for k in range(launches):
        x = x0 + k * pw
        s.line(x + pw / 2, wy + wh + 1, x + pw / 2, my - 1, stroke=GREY, width=1.1, arrow="end")
        s.rect(x + 3, my, pw - 6, 30, fill="#ffffff", stroke=INK, width=1.2, rx=4)
        s.text(x + pw / 2, my + 20, str(k), size=12 if not narrow else small, anchor="middle")
    if narrow:
        s.text(x0, my + 48, "mesh workgroups", size=body, fill=INK)
        s.text(end, my + 48, f"unused slots, up to {ROOM - 1}", size=small, fill=MUTED, anchor="end")
        my += 20
    else:
        s.text(x0 + launches * pw + 8, my + 20, "mesh workgroups", size=body, fill=INK)
    my += 30
    if narrow:
        s.lines(16, my + 28, [f"EmitMeshTasksEXT(launches = {launches}, 1, 1):", "one mesh workgroup per slot"],
                size=body, bold=True)
        my += 16
        text = ["mesh workgroup k reads payload.launch[k]",
                "(gl_WorkGroupID.x = k), unpacks the instance and",
                "the meshlet, and writes that meshlet's triangles,",
                "placed by that instance's transform. At most",
                f"{GROUP} \u00d7 {MOST} = {ROOM} mesh workgroups per task",
                "workgroup; a culled instance launches none.",
                "",
                "payload.why[k], the lower row: which test culled",
                "launch k. Only --view culled's extra pass writes",
                "and reads it; the frame's passes leave it unset.",
                f"{len(ARRAYS)} arrays \u00d7 4 bytes = {BYTES} bytes a slot,",
                f"{ROOM} slots = {ROOM * BYTES:,} bytes of payload."]
        note = ["Which instances are kept, their meshlet counts", "and the slots' order: an example, as drawn."]
        tx = 16
    else:
        s.text(x0, my + 28, f"EmitMeshTasksEXT(launches = {launches}, 1, 1): one mesh workgroup per slot",
               size=body, bold=True)
        text = [f"mesh workgroup k reads payload.launch[gl_WorkGroupID.x = k], unpacks the instance and the meshlet,",
                f"and writes that meshlet's triangles, placed by that instance's transform. At most {GROUP} \u00d7 "
                f"{MOST} = {ROOM}",
                "mesh workgroups per task workgroup; a culled instance launches none.",
                "",
                "payload.why[k], the lower row: which test culled launch k. Only --view culled's extra pass",
                "writes and reads it; the frame's passes leave it unset. "
                f"{len(ARRAYS)} arrays \u00d7 4 bytes = {BYTES} bytes a slot,",
                f"{ROOM} slots = {ROOM * BYTES:,} bytes of payload."]
        note = ["Which instances are kept, their meshlet counts and the slots' order: an example, as drawn."]
        tx = x0
    s.lines(tx, my + 56, text, size=body)
    ny = my + 56 + len(text) * body * 1.3 + 14
    s.lines(tx, ny, note, size=12 if not narrow else small, fill=RED)
    s.height = ny + len(note) * 15 + 12
    s.write()


if __name__ == "__main__":
    main()
