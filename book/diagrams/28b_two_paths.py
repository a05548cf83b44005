"""Chapter 28b: the indirect path and the task path side by side, one frame of --cull occlusion.

Left, --path indirect (chapter 28's core, main.cpp's record()): cull 1 (cull.comp,
phase 0) appends a VkDrawIndexedIndirectCommand per kept instance to a list and
counts it; draw 1 is vkCmdDrawIndexedIndirectCount over that list (draw.vert,
draw.frag); the pyramid pass (pyramid.comp) reduces the depth; cull 2 (phase 1)
tests against the pyramid and writes visible[]; draw 2 draws the late list.
Right, --path task (task_path.hpp): no cull passes; each draw is one
vkCmdDrawMeshTasksEXT whose task shader (instances.task) makes the same
cull_instance test, then cull_meshlet for each meshlet, writes payload.launch[]
and calls EmitMeshTasksEXT; the mesh shader (instances.mesh) reads its slot.
The pyramid pass is the same for both. Every name drawn is checked against the
sources below: the build stops if one of them no longer says it.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the same
two columns are drawn 400 units wide, every text at least 11 units.
"""

import os
import sys
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, PURPLE_FILL, Svg)

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ROOT = Path(__file__).resolve().parents[2]
CH, SH = ROOT / "chapters" / "28_gpu_culling", ROOT / "shaders" / "28_gpu_culling"
GROUP = int(constant(SH / "task_data.glsl", "kTaskGroup"))
MOST = int(constant(SH / "task_data.glsl", "kMostMeshlets"))
CULL_GROUP = int(constant(CH / "main.cpp", "kCullGroup"))

# What the figure names, and where the sources say it (whitespace ignored).
NAMES = {
    CH / "main.cpp": ["cull(frame.cmd, push);", "vkCmdDrawIndexedIndirectCount(", "pyramid_->build(frame.cmd);",
                      "push.phase = 1;", "if (!task_) {", "task_->draw(frame.cmd, push);"],
    CH / "task_path.hpp": ['"instances.task"', '"instances.mesh"', '"draw.frag"', "vkCmdDrawMeshTasksEXT",
                           "dispatch_count(push.instance_count, kTaskGroup)"],
    CH / "draw_pass.hpp": ['"draw.vert"', '"draw.frag"'],
    CH / "pyramid.hpp": ['"pyramid.comp"'],
    SH / "cull.comp": ["uint list = cull_instance(i);", "atomicAdd(counts[list], 1);",
                       "draws[list * push.instance_count + slot] ="],
    SH / "instance_cull.glsl": ["visible[i] != 0", "visible[i] = seen ? 1 : 0;", "occluded(corners)"],
    SH / "instances.task": ["uint list = cull_instance(i);", "cull_meshlet(o, meshlets[m]",
                            "payload.launch[atomicAdd(launches, 1)]", "EmitMeshTasksEXT(launches, 1, 1);",
                            "taskPayloadSharedEXT Payload payload;"],
    SH / "instances.mesh": ["payload.launch[gl_WorkGroupID.x]"],
    SH / "meshlet_cull.glsl": ["occluded(corners)"],
}


def check_sources() -> None:
    for path, wants in NAMES.items():
        code = "".join(path.read_text(encoding="utf-8").split())
        for want in wants:
            if "".join(want.split()) not in code:
                sys.exit(f"{path.relative_to(ROOT)}: no longer says `{want}`; redraw book/diagrams/28b_two_paths.py")


# Each row: (label, left boxes, right boxes); a box is (colour, fill, title, lines, dashed).
# None in place of the left and right lists: one box across both columns.
def rows() -> list:
    cull = (ORANGE, ORANGE_FILL)
    draw = (BLUE, BLUE_FILL)
    none = (GREY, GREY_FILL)
    return [
        ("cull 1", [(*cull, "cull 1: cull.comp (compute)",
                     [f"one invocation per instance,", f"{CULL_GROUP} a workgroup: cull_instance(i),",
                      "phase 0: in the frustum and", "visible[i] (seen last frame)?",
                      "kept: atomicAdd(counts[list], 1)", "and one VkDrawIndexedIndirect-",
                      "Command into the early list"], False)],
         [(*none, "no cull pass",
           ["draw 1's task shader makes", "the same test, as it draws"], True)]),
        ("draw 1", [(*draw, "draw 1: clear, then",
                     ["vkCmdDrawIndexed-", "IndirectCount(early list,", "counts[early]): each command",
                      "one instance, draw.vert,", "then draw.frag"], False)],
         [(*draw, "draw 1: clear, then",
           ["vkCmdDrawMeshTasksEXT(", f"\u2308N / {GROUP}\u2309, 1, 1)"], False),
          (*cull, "instances.task",
           [f"{GROUP} instances a workgroup:", "cull_instance(i), phase 0;", "kept: cull_meshlet for each",
            "meshlet; kept: one slot", "payload.launch[k]; then", "EmitMeshTasksEXT(launches,", "1, 1)"], False),
          (*draw, "instances.mesh",
           ["mesh workgroup k reads", "payload.launch[", "gl_WorkGroupID.x]: one", "meshlet, then draw.frag"],
           False)]),
        ("pyramid", None, None),
        ("cull 2", [(*cull, "cull 2: cull.comp, phase 1",
                     ["in the frustum and not", "occluded(corners) by the", "pyramid? visible[i] := that;",
                      "seen, not drawn early:", "into the late list"], False)],
         [(*none, "no cull pass",
           ["draw 2's task shader makes", "the same test, as it draws"], True)]),
        ("draw 2", [(*draw, "draw 2: load, then",
                     ["vkCmdDrawIndexed-", "IndirectCount(late list,", "counts[late])"], False)],
         [(*draw, "draw 2: load, then",
           ["vkCmdDrawMeshTasksEXT", "again; instances.task, phase 1,", "tests instances and meshlets",
            "against the pyramid, sets", "visible[i]; instances.mesh", "draws what it launches"], False)]),
    ]


def main() -> None:
    check_sources()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size, head = (11, 12) if narrow else (12.5, 14)
    lead = size * 1.3
    width = 400 if narrow else 860
    margin, gap = (6, 8) if narrow else (20, 40)
    col = (width - 2 * margin - gap) / 2
    xs = [margin, margin + col + gap]
    s = Svg(width, 100, "Chapter 28b: one frame of --cull occlusion, the indirect path and the task path",
            "Two columns, the same five steps. Left, --path indirect: cull 1, cull.comp, appends a "
            "draw command for each instance in the frustum and seen last frame and counts it; draw 1 "
            "clears and runs vkCmdDrawIndexedIndirectCount over that early list with draw.vert and "
            "draw.frag; the depth pyramid is built by pyramid.comp; cull 2 tests every instance in "
            "the frustum against the pyramid, writes visible[i] and appends those seen but not drawn "
            "early to the late list; draw 2 loads and draws it. Right, --path task: there are no cull "
            "passes. Each draw is one vkCmdDrawMeshTasksEXT; its task shader, instances.task, makes "
            f"the same test for {GROUP} instances a workgroup, then tests each meshlet of a kept "
            "instance, writes a slot of payload.launch for each one kept and calls EmitMeshTasksEXT; "
            "each mesh workgroup, instances.mesh, reads its slot and draws that meshlet with "
            "draw.frag. The pyramid pass between the draws is the same for both.")
    y = 26
    if narrow:
        s.lines(margin, y, ["One frame of --cull occlusion, the", "two paths side by side"], size=14, bold=True)
        y += 18
    else:
        s.text(margin, y, "One frame of --cull occlusion: the two paths side by side, step by step",
               size=15, bold=True)
    y += 30
    heads = [["--path indirect", "(chapter 28's core)"], ["--path task", "(this page)"]]
    for x, lines in zip(xs, heads):
        s.lines(x + col / 2, y, lines, size=head, bold=True, anchor="middle")
    y += head * 1.3 + 16

    pad_top, pad = head + 14, 8
    overflow = []

    def box_height(lines):
        return pad_top + len(lines) * lead + pad

    def draw_box(x, top, w, colour, fill, title, lines, dashed):
        h = box_height(lines)
        s.rect(x, top, w, h, fill=fill, stroke=colour, width=1.3, rx=6, dash="4 3" if dashed else None)
        s.text(x + w / 2, top + head + 4, title, size=head - 1, bold=True, anchor="middle", fill=colour)
        for i, line in enumerate(lines):
            s.text(x + w / 2, top + pad_top + (i + 0.75) * lead, line, size=size, anchor="middle",
                   fill=MUTED if dashed else INK)
        for text, bold, sz in [(title, True, head - 1)] + [(line, False, size) for line in lines]:
            if s.label_width([text], size=sz, bold=bold) > w - 8:
                overflow.append(f"28b_two_paths: '{text}' does not fit a box {w:.0f} wide")
        return h

    arrow = 22 if not narrow else 18
    bottoms = [None, None]
    for label, left, right in rows():
        if left is None:
            top = y
            for i, x in enumerate(xs):
                s.line(x + col / 2, bottoms[i], x + col / 2, top - 1, stroke=INK, width=1.4, arrow="end")
            lines = (["each level the min of the 2 \u00d7 2", "below; the same pass for both paths"]
                     if narrow else ["each level the minimum (the farthest depth) of the 2 \u00d7 2 below,",
                                     "the same pass for both paths"])
            h = draw_box(margin, top, width - 2 * margin, PURPLE, PURPLE_FILL,
                         "pyramid: pyramid.comp, draw 1's depth \u2192 mips", lines, False)
            bottoms = [top + h, top + h]
            y = top + h + arrow
            continue
        row_bottom = y
        for i, (x, boxes) in enumerate(zip(xs, (left, right))):
            top = y
            if bottoms[i] is not None:
                s.line(x + col / 2, bottoms[i], x + col / 2, top - 1, stroke=INK, width=1.4, arrow="end")
            for k, (colour, fill, title, lines, dashed) in enumerate(boxes):
                inset = 0 if k == 0 else (8 if narrow else 16)
                h = draw_box(x + inset, top, col - inset, colour, fill, title, lines, dashed)
                if k + 1 < len(boxes):
                    s.line(x + inset + 12, top + h, x + inset + 12, top + h + arrow - 1, stroke=INK,
                           width=1.2, arrow="end")
                    top += h + arrow
                else:
                    top += h
            bottoms[i] = top
            row_bottom = max(row_bottom, top)
        y = row_bottom + arrow

    # What each path keeps in memory.
    y += 4
    s.text(margin, y, "In memory", size=head, bold=True)
    y += 10
    mem = [["draws[]: 3 lists of N", "VkDrawIndexedIndirect-", "Command (early, late, culled);",
            "counts[]: their lengths;", "visible[]: 1 word an instance"],
           ["no draw lists; the payload,", f"{GROUP} \u00d7 {MOST} = {GROUP * MOST} slots a task",
            "workgroup, task to mesh;", "counts[] for the report;", "visible[]: 1 word an instance"]]
    h = max(box_height(m) for m in mem)
    for x, lines, title in zip(xs, mem, ["indirect", "task"]):
        draw_box(x, y, col, GREEN, GREEN_FILL, title, lines, False)
    y += h + 18
    note = (["N instances; \u2308N / 32\u2309 task workgroups.", "Names as in the sources; a sketch, not to scale."]
            if narrow else ["N instances, \u2308N / 32\u2309 task workgroups. Names as in chapter 28's sources; "
                            "a sketch, not to scale."])
    note = [n.replace("32", str(GROUP)) for n in note]
    s.lines(margin, y, note, size=size, fill=MUTED)
    s.height = y + len(note) * lead + 8
    if overflow:
        sys.exit("\n".join(overflow))
    s.write()


if __name__ == "__main__":
    main()
