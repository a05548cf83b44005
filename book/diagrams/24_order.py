"""Chapter 24: the order of operations, once before the first frame and every frame.

Left (on a phone: first), what runs once: the four bottom levels are sized,
given buffers, created, built in one command and asked their compacted sizes;
the compacting copy, page 24b's, is dashed. Right (on a phone: below), what
every frame records: the instances written, the top level built between two
barriers, and the draws whose fragment shader traces the shadow rays.

Each step is named by the call it is, and the script reads those calls from
the chapter's sources: the KHR names from acceleration.hpp's loads, and the
order from bottom_level.hpp, acceleration.hpp, main.cpp's record and
top_level.hpp. A call that vanishes or moves stops the book's build.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
columns are stacked, 400 units wide.
"""

import os
import re
from pathlib import Path

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, PURPLE_FILL, Svg)

ROOT = Path(__file__).resolve().parents[2]
CHAPTER = ROOT / "chapters" / "24_ray_queries"
FRAG = ROOT / "shaders" / "24_ray_queries" / "scene.frag"


def stop(where: str, what: str) -> None:
    raise SystemExit(f"{where}: {what}; redraw book/diagrams/24_order.py")


def loaded_functions() -> dict:
    """member of RayFunctions -> the Vulkan command it is loaded as."""
    text = (CHAPTER / "acceleration.hpp").read_text(encoding="utf-8")
    found = dict(re.findall(r'load\(device, (\w+), "(vk\w+)"\)', text))
    if not found:
        stop("chapters/24_ray_queries/acceleration.hpp", "no extension command is loaded")
    return found


def in_order(path: Path, needles: list) -> None:
    """Each needle occurs in path, after the one before it."""
    text = path.read_text(encoding="utf-8")
    at, before = 0, None
    for needle in needles:
        found = text.find(needle, at)
        if found < 0:
            stop(str(path.relative_to(ROOT)),
                 f"'{needle}' is not there after '{before}'" if before else f"'{needle}' is not there")
        at, before = found + len(needle), needle


def calls() -> tuple:
    fn = loaded_functions()

    def name(member: str) -> str:
        if member not in fn:
            stop("chapters/24_ray_queries/acceleration.hpp", f"RayFunctions no longer loads {member}")
        return fn[member]

    in_order(CHAPTER / "bottom_level.hpp",
             ["inline void write_compacted_sizes(", "after_builds(cmd);", "vkCmdResetQueryPool(",
              "ray.cmd_write_properties(", "ray.build_sizes(",
              "AccelerationStructure(gpu, ray, VK_ACCELERATION_STRUCTURE_TYPE_BOTTOM",
              "create_address_buffer(", "ray.cmd_build(", "write_compacted_sizes(cmd, ray, built, pool);",
              "vkGetQueryPoolResults(", "after_builds(cmd);", "ray.cmd_copy("])
    in_order(CHAPTER / "acceleration.hpp",
             ["vkGetBufferDeviceAddress(", "storage_ = create_address_buffer(", "ray.create(",
              "ray.address("])
    in_order(CHAPTER / "main.cpp",
             ["top_->write_instances(", "vkCmdPipelineBarrier2(cmd, &wait_before);",
              "top_->record(cmd", "vkCmdPipelineBarrier2(cmd, &wait_after);", "vkCmdDrawIndexed("])
    in_order(CHAPTER / "top_level.hpp",
             ["void write_instances(", "VkAccelerationStructureInstanceKHR", "void record(",
              "ray_.cmd_build(cmd, 1"])
    in_order(FRAG, ["rayQueryInitializeEXT(", "rayQueryProceedEXT("])

    once = [
        (name("build_sizes"), ["each structure's size, and its scratch size"], BLUE_FILL, BLUE, None),
        ("vkGetBufferDeviceAddress", ["a storage buffer per structure and one", "scratch buffer, reached by address"],
         GREY_FILL, GREY, None),
        (name("create"), ["a handle over its storage buffer, then", f"its address ({name('address')})"],
         BLUE_FILL, BLUE, None),
        (name("cmd_build"), ["the four bottom levels, in one command"], BLUE_FILL, BLUE, None),
        ("vkCmdPipelineBarrier2", ["the builds' writes before the query reads"], PURPLE_FILL, PURPLE, None),
        (name("cmd_write_properties"), ["each compacted size into a query pool,", "read back with vkGetQueryPoolResults"],
         BLUE_FILL, BLUE, None),
        (name("cmd_copy"), ["page 24b: each copied into a structure", "of exactly that size"], GREY_FILL, GREY,
         "5 4"),
    ]
    frame = [
        ("write_instances (the CPU)", ["a VkAccelerationStructureInstanceKHR per", "object, into this frame's buffer"],
         ORANGE_FILL, ORANGE, None),
        ("vkCmdPipelineBarrier2", ["last frame's ray queries and build are done"], PURPLE_FILL, PURPLE, None),
        (name("cmd_build"), ["the top level: UPDATE (a refit) or BUILD"], BLUE_FILL, BLUE, None),
        ("vkCmdPipelineBarrier2", ["the build's writes before the fragment", "shader's reads"], PURPLE_FILL,
         PURPLE, None),
        ("vkCmdDrawIndexed → rayQueryInitializeEXT", ["each lit fragment of scene.frag traces", "its shadow ray"],
         GREEN_FILL, GREEN, None),
    ]
    return once, frame


def column(s: Svg, x: float, y: float, w: float, title: str, note: str, steps: list, size: float,
           mono_size: float) -> float:
    lead = size * 1.35
    s.text(x, y + size + 1.5, title, size=size + 1.5, bold=True)
    s.text(x, y + size + 1.5 + lead, note, size=size, fill=MUTED)
    y += size + 1.5 + lead + 12
    for i, (head, lines, fill, stroke, dash) in enumerate(steps):
        h = mono_size + 10 + len(lines) * lead + 4
        s.rect(x, y, w, h, fill=fill, stroke=stroke, rx=6, width=1.3, dash=dash)
        s.text(x + 9, y + 5 + mono_size, head, size=mono_size, bold=True, mono=True)
        for k, line in enumerate(lines):
            s.text(x + 9, y + 5 + mono_size + (k + 1) * lead, line, size=size,
                   fill=MUTED if dash else INK)
        y += h
        if i < len(steps) - 1:
            s.line(x + w / 2, y, x + w / 2, y + 14, stroke=GREY, width=1.3, arrow="end")
            y += 14
    return y


def main() -> None:
    once, frame = calls()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 11 if narrow else 12.5
    mono_size = 10.5 if narrow else 12
    W = 400 if narrow else 960
    steps_text = "; ".join(head for head, *_ in once)
    frame_text = "; ".join(head for head, *_ in frame)
    s = Svg(W, 100, "Chapter 24: the order of operations, once and every frame",
            f"Once, before the first frame, for the four bottom levels: {steps_text} (the last one "
            f"dashed: page 24b's compacting copy). Every frame: {frame_text}.")
    if narrow:
        y = column(s, 10, 8, 380, "Once, before the first frame",
                   "the four bottom levels (the top level is sized and created once too)",
                   once, size, mono_size)
        y = column(s, 10, y + 24, 380, "Every frame", "the top level, then the draws", frame,
                   size, mono_size)
    else:
        y1 = column(s, 12, 8, 456, "Once, before the first frame",
                   "the four bottom levels (the top level is sized and created once too)",
                    once, size, mono_size)
        y2 = column(s, 492, 8, 456, "Every frame", "the top level, then the draws", frame,
                    size, mono_size)
        # The bottom levels' addresses are what the instances point at.
        s.text(492, y2 + 30, "Each instance holds a bottom level's address:", size=size, fill=MUTED)
        s.text(492, y2 + 30 + size * 1.35, "the bottom levels never change, the instances do.",
               size=size, fill=MUTED)
        y = max(y1, y2 + 30 + size * 1.35)
    s.height = y + 12
    s.write()


if __name__ == "__main__":
    main()
