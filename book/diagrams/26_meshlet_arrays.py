"""Chapter 26: one meshlet's two arrays, as the remap step fills them.

A small example meshlet of two triangles, (17, 42, 18) and (18, 42, 43) in the
model's indices. The remap gives each new model vertex the next local number
(17 -> 0, 42 -> 1, 18 -> 2, 43 -> 3): meshlet_vertices[] holds the model's
indices, one uint each; meshlet_triangles[] holds one uint per triangle, three
8-bit local numbers packed in its low three bytes. The sizes (64 vertices,
124 triangles, 8 bits) and the names are read from the sources below: the build
stops if one of them no longer says it.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the figure
is drawn 400 units wide, every text at least 11 units.
"""

import os
import sys
from pathlib import Path

from svg import BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, Svg

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ROOT = Path(__file__).resolve().parents[2]
BUILDER = ROOT / "common" / "scene" / "include" / "vkt" / "scene" / "meshlets.hpp"
CHAPTER = ROOT / "chapters" / "26_mesh_shaders" / "meshlets.hpp"
MESH = ROOT / "shaders" / "26_mesh_shaders" / "meshlets.mesh"
DATA = ROOT / "shaders" / "26_mesh_shaders" / "meshlet_data.glsl"
MOST_VERTICES = int(constant(CHAPTER, "kMeshVertices"))
MOST_TRIANGLES = int(constant(CHAPTER, "kMeshTriangles"))

# What the figure names, and where the sources say it (whitespace ignored).
NAMES = {
    BUILDER: ["std::vector<uint32_t> vertices;", "std::vector<uint32_t> triangles;",
              "local[v] = int32_t(m.vertex_count++);", "packed |= uint32_t(local[v]) << (8 * k);",
              "uint32_t vertex_offset = 0, vertex_count = 0;",
              "uint32_t triangle_offset = 0, triangle_count = 0;"],
    MESH: [f"max_vertices = {MOST_VERTICES}, max_primitives = {MOST_TRIANGLES}",
           "vertices[meshlet_vertices[m.vertex_offset + i]]",
           "meshlet_triangles[m.triangle_offset + i]",
           "uvec3(packed & 0xFFu, (packed >> 8) & 0xFFu, (packed >> 16) & 0xFFu)"],
    DATA: ["uint meshlet_vertices[];", "uint meshlet_triangles[];", "Vertex vertices[];"],
}

TRIANGLES = [(17, 42, 18), (18, 42, 43)]


def check_sources() -> None:
    for path, wants in NAMES.items():
        code = "".join(path.read_text(encoding="utf-8").split())
        for want in wants:
            if "".join(want.split()) not in code:
                sys.exit(f"{path.relative_to(ROOT)}: no longer says `{want}`; "
                         "redraw book/diagrams/26_meshlet_arrays.py")


def remap() -> tuple[list[int], list[tuple[int, ...]]]:
    """The builder's remap step, on the example: model vertices, local triangles."""
    order, local = [], {}
    for triangle in TRIANGLES:
        for v in triangle:
            if v not in local:
                local[v] = len(order)
                order.append(v)
    return order, [tuple(local[v] for v in t) for t in TRIANGLES]


def main() -> None:
    check_sources()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size, head = (11, 12) if narrow else (12.5, 14)
    lead = size * 1.3
    width = 400 if narrow else 760
    m = 6 if narrow else 20
    order, local_triangles = remap()
    packed = [sum(k << (8 * i) for i, k in enumerate(t)) for t in local_triangles]
    s = Svg(width, 100, "Chapter 26: one meshlet's two arrays, meshlet_vertices and meshlet_triangles",
            f"An example meshlet of two triangles, model vertices 17, 42, 18 and 18, 42, 43. The remap "
            f"numbers each model vertex the first time the meshlet meets it: 17 is local 0, 42 local 1, "
            f"18 local 2, 43 local 3. meshlet_vertices holds 17, 42, 18, 43 from m.vertex_offset on, one "
            f"uint each, pointing into the model's vertices; at most {MOST_VERTICES} a meshlet. "
            f"meshlet_triangles holds one uint per triangle from m.triangle_offset on, its three low "
            f"bytes the local numbers 0, 1, 2 and 2, 1, 3; at most {MOST_TRIANGLES} a meshlet. The mesh "
            f"shader reads vertices[meshlet_vertices[m.vertex_offset + i]] and unpacks the bytes with "
            f"shifts and masks of 0xFF.")

    y = 24
    s.text(m, y, "One meshlet, two triangles: the remap fills two arrays", size=head if narrow else head + 1,
           bold=True)
    y += 22
    cell_w, cell_h = (34, 26) if narrow else (52, 30)
    byte_w, gap = (26, 10) if narrow else (40, 36)
    label_x = m + max(7 * cell_w, 8 * byte_w + gap) + (8 if narrow else 36)
    overflow = []

    def label(top, lines, colour):
        """A row's name and what it holds, to the right of its cells."""
        s.text(label_x, top + size, lines[0], size=size, bold=True, fill=colour)
        s.lines(label_x, top + size + lead, lines[1:], size=size, fill=MUTED)
        for k, line in enumerate(lines):
            if label_x + s.label_width(line, size=size, bold=k == 0) > width - 2:
                overflow.append(f"26_meshlet_arrays: '{line}' runs off the figure")

    def cell(x, top, text, fill, stroke, bold=False, fill_text=INK, w=cell_w):
        s.rect(x, top, w, cell_h, fill=fill, stroke=stroke, width=1.2)
        s.text(x + w / 2, top + cell_h / 2 + size * 0.35, text, size=size, anchor="middle", bold=bold,
               fill=fill_text)

    # ---- Row 1: the model's vertices -------------------------------------------------
    model = ["\u2026", 17, 18, "\u2026", 42, 43, "\u2026"]
    model_x = {}
    for i, v in enumerate(model):
        x = m + i * cell_w
        if isinstance(v, str):
            cell(x, y, v, "#ffffff", GREY, fill_text=MUTED)
        else:
            cell(x, y, f"v{v}", GREY_FILL, GREY)
            model_x[v] = x + cell_w / 2
    label(y - 4, ["vertices[]", "the model's, every vertex", "once (one Vertex each)"] if narrow else
          ["vertices[]", "the model's vertices, each once (one Vertex each)"], INK)
    model_bottom = y + cell_h

    # ---- Row 2: meshlet_vertices ----------------------------------------------------
    y = model_bottom + (50 if narrow else 56)
    cell(m, y, "\u2026", "#ffffff", GREY, fill_text=MUTED)
    vertex_x = []
    for i, v in enumerate(order):
        x = m + (i + 1) * cell_w
        cell(x, y, str(v), BLUE_FILL, BLUE, bold=True)
        s.text(x + cell_w / 2, y + cell_h + lead, str(i), size=size, anchor="middle", fill=BLUE)
        s.line(x + cell_w / 2, y - 1, model_x[v], model_bottom + 1, stroke=BLUE, width=1.2, arrow="end")
        vertex_x.append(x + cell_w / 2)
    cell(m + (len(order) + 1) * cell_w, y, "\u2026", "#ffffff", GREY, fill_text=MUTED)
    s.text(m + cell_w / 2, y + cell_h + lead, "local", size=size, anchor="middle", fill=BLUE)
    label(y - 4, ["meshlet_vertices[]", "one uint each, at most", f"{MOST_VERTICES} a meshlet, from",
                  "m.vertex_offset on"] if narrow else
          ["meshlet_vertices[]", f"one uint each, at most {MOST_VERTICES} a meshlet;",
           f"this one's {len(order)} start at m.vertex_offset"], BLUE)
    local_bottom = y + cell_h + lead + 4

    # ---- Row 3: meshlet_triangles ---------------------------------------------------
    y = local_bottom + (50 if narrow else 56)
    x = m
    for t, (triangle, locals_, word) in enumerate(zip(TRIANGLES, local_triangles, packed)):
        for b in range(4):
            used = b < 3
            cell(x + b * byte_w, y, str(locals_[b]) if used else "0", GREEN_FILL if used else "#ffffff",
                 GREEN if used else GREY, bold=used, fill_text=INK if used else MUTED, w=byte_w)
            if t == 0 and used:
                s.line(x + b * byte_w + byte_w / 2, y - 1, vertex_x[locals_[b]], local_bottom,
                       stroke=GREEN, width=1.1, arrow="end", dash="4 2")
        s.rect(x, y, 4 * byte_w, cell_h, stroke=INK, width=1.4)
        cx = x + 2 * byte_w
        s.text(cx, y + cell_h + lead, f"{triangle[0]}, {triangle[1]}, {triangle[2]}", size=size,
               anchor="middle")
        s.text(cx, y + cell_h + 2 * lead, f"0x{word:08X}", size=size, anchor="middle", mono=True, fill=MUTED)
        x += 4 * byte_w + gap
    label(y - 4, ["meshlet_triangles[]", "one uint a triangle, at", f"most {MOST_TRIANGLES} a meshlet: bits",
                  "0\u20137, 8\u201315, 16\u201323 hold", "three 8-bit local", "numbers"] if narrow else
          ["meshlet_triangles[]", f"one uint a triangle, at most {MOST_TRIANGLES} a meshlet:",
           "bits 0\u20137, 8\u201315, 16\u201323 (left to right) hold",
           "three 8-bit local numbers; bits 24\u201331 are 0"], GREEN)
    y += max(cell_h + 2 * lead, (6 if narrow else 4) * lead) + 8

    # ---- What the mesh shader reads --------------------------------------------------
    y += 14
    s.text(m, y, "The mesh shader (meshlets.mesh) reads them back:", size=size, bold=True)
    y += lead + 2
    code = (["vertices[meshlet_vertices[", "    m.vertex_offset + i]]", "packed = meshlet_triangles[",
             "    m.triangle_offset + i]", "uvec3(packed & 0xFFu,", "      (packed >> 8) & 0xFFu,",
             "      (packed >> 16) & 0xFFu)"] if narrow else
            ["vertices[meshlet_vertices[m.vertex_offset + i]]",
             "packed = meshlet_triangles[m.triangle_offset + i]",
             "uvec3(packed & 0xFFu, (packed >> 8) & 0xFFu, (packed >> 16) & 0xFFu)"])
    s.lines(m + 8, y, code, size=size, mono=True, fill=ORANGE)
    y += (len(code) - 1) * lead + 10
    note = (["Local numbers are 8 bits, so a meshlet could", "name up to 256 vertices; this builder",
             f"stops at {MOST_VERTICES}."] if narrow else
            ["Local numbers are 8 bits, so a meshlet could name up to 256 vertices; "
             f"this builder stops at {MOST_VERTICES}."])
    s.lines(m, y + size, note, size=size, fill=MUTED)
    s.height = y + size + len(note) * lead + 6
    if overflow:
        sys.exit("\n".join(overflow))
    s.write()


if __name__ == "__main__":
    main()
