"""Chapter 26: the meshlet pipeline (task -> mesh -> raster) beside the vertex pipeline.

Numbers from chapter 26: the knot's 30,720 triangles cut into 389 meshlets
(at most 64 vertices and 124 triangles), 32 meshlets per task workgroup
(13 workgroups), and the default view's count: 65 meshlets culled, 324 drawn.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
stages stand one above the other, 400 units wide, no text under 11 units.
"""

import os

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, RED, RED_FILL, Svg)

W, H = 1000, 560
TITLE = "Chapter 26: the meshlet pipeline, task shader to mesh shader to rasteriser"
DESCRIPTION = ("Top: vkCmdDrawMeshTasksEXT(13, 1, 1) launches 13 task workgroups of 32 invocations, one "
               "per meshlet; each tests its meshlet's sphere against the frustum and its normal cone "
               "against the eye, and the workgroup launches one mesh workgroup per survivor, which writes "
               "up to 64 vertices and 124 triangles straight to the rasteriser. Bottom: chapter 15's "
               "vertex pipeline, where every triangle goes through input assembly and the vertex shader.")


def main() -> None:
    if os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow":
        narrow()
        return
    s = Svg(W, H, TITLE, DESCRIPTION)

    # ---- The data, built once on the CPU ------------------------------------------------
    s.text(20, 30, "At start-up, on the CPU (meshlets.hpp): 30,720 triangles \u2192 389 meshlets",
           size=14, bold=True)
    s.box(20, 46, 300, 74, ["meshlets[389]", "sphere (centre, radius), cone (axis, cutoff)",
                            "vertex and triangle ranges"], fill=GREY_FILL, stroke=GREY, size=12.5,
          bold_first=True)
    s.box(340, 46, 300, 74, ["meshlet_vertices[]", "per meshlet \u2264 64 indices into", "the model's vertices"],
          fill=GREY_FILL, stroke=GREY, size=12.5, bold_first=True)
    s.box(660, 46, 320, 74, ["meshlet_triangles[]", "per meshlet \u2264 124, three 8-bit local",
                             "indices packed in one uint"], fill=GREY_FILL, stroke=GREY, size=12.5,
          bold_first=True)

    # ---- The draw ---------------------------------------------------------------------------
    # Every text at least 12.5 units (10 px when the figure is shown 800 px wide), so the
    # boxes are sized to their longest line: task 212..438, mesh 508..808.
    y = 160
    s.box(20, y, 172, 64, ["`vkCmdDrawMeshTasksEXT`", "(cmd, 13, 1, 1)"], fill="#ffffff", stroke=INK,
          size=12.5)
    s.line(192, y + 32, 212, y + 32, stroke=INK, width=1.6, arrow="end")

    # Task workgroups.
    tx, tw = 212, 226
    tc = tx + tw / 2
    s.box(tx, y - 16, tw, 160, [], fill=BLUE_FILL, stroke=BLUE)
    s.text(tc, y + 4, "task shader", size=14, bold=True, anchor="middle", fill=BLUE)
    s.text(tc, y + 22, "13 workgroups \u00d7 32 invocations", size=12.5, anchor="middle", fill=MUTED)
    for k in range(8):
        cx = tc - (7 * 26 + 20) / 2 + k * 26
        outside = k in (6,)
        away = k in (2, 5)
        fill = RED_FILL if (outside or away) else "#ffffff"
        stroke = RED if (outside or away) else BLUE
        s.rect(cx, y + 37, 20, 20, fill=fill, stroke=stroke, width=1.3, rx=3)
        if outside or away:
            s.line(cx + 3, y + 40, cx + 17, y + 54, stroke=RED, width=1.5)
    s.text(tc, y + 78, "one invocation per meshlet:", size=12.5, anchor="middle")
    s.text(tc, y + 95, "sphere outside the frustum?", size=12.5, anchor="middle", fill=RED)
    s.text(tc, y + 112, "cone facing away from the eye?", size=12.5, anchor="middle", fill=RED)
    s.text(tc, y + 132, "culled: atomicAdd(counters)", size=12.5, anchor="middle", mono=True, fill=MUTED)

    mx, mw = 508, 300
    mc = mx + mw / 2
    s.line(tx + tw, y + 32, mx, y + 32, stroke=INK, width=1.6, arrow="end")
    s.text((tx + tw + mx) / 2, y + 22, "payload", size=12.5, anchor="middle", fill=PURPLE)
    s.text((tx + tw + mx) / 2, y + 52, "survivors", size=12.5, anchor="middle", fill=PURPLE)

    # Mesh workgroups.
    s.box(mx, y - 16, mw, 160, [], fill=GREEN_FILL, stroke=GREEN)
    s.text(mc, y + 4, "mesh shader", size=14, bold=True, anchor="middle", fill=GREEN)
    s.text(mc, y + 22, "EmitMeshTasksEXT(survivors, 1, 1)", size=12.5, anchor="middle", mono=True,
           fill=MUTED)
    for k in range(5):
        s.rect(mc - (4 * 40 + 34) / 2 + k * 40, y + 36, 34, 22, fill="#ffffff", stroke=GREEN, width=1.3,
               rx=3)
    s.text(mc, y + 78, "one workgroup per meshlet kept:", size=12.5, anchor="middle")
    s.text(mc, y + 95, "SetMeshOutputsEXT(vertices, triangles)", size=12.5, anchor="middle", mono=True)
    s.text(mc, y + 112, "gl_MeshVerticesEXT[i].gl_Position", size=12.5, anchor="middle", mono=True)
    s.text(mc, y + 129, "gl_PrimitiveTriangleIndicesEXT[i]", size=12.5, anchor="middle", mono=True)

    s.line(mx + mw, y + 32, 836, y + 32, stroke=INK, width=1.6, arrow="end")
    s.box(836, y, 144, 64, ["rasteriser", "and fragment", "shader"], fill=ORANGE_FILL, stroke=ORANGE,
          size=12.5, bold_first=True)

    s.text(20, y + 190, "The default view: 65 of 389 meshlets culled in the task shader (they face away);"
           " 324 drawn, 26,766 of 30,720 triangles reach the rasteriser.", size=12.5)
    s.text(20, y + 210, "No vertex buffer, index buffer, vertex input or input assembly: the mesh shader"
           " reads the buffers above and writes its primitives itself.", size=12.5, fill=MUTED)

    # ---- The vertex pipeline, for comparison --------------------------------------------
    y2 = 430
    s.text(20, y2 - 16, "Chapter 15's way (--draw indirect): every triangle, every frame", size=14,
           bold=True)
    steps = [("`vkCmdDrawIndexedIndirect`", "one command, 92,160 indices", "#ffffff", INK),
             ("input assembly", "index buffer \u2192 triangles", GREY_FILL, GREY),
             ("vertex shader", "per vertex index", BLUE_FILL, BLUE),
             ("rasteriser", "30,720 triangles", ORANGE_FILL, ORANGE)]
    x = 20
    for i, (title, note, fill, stroke) in enumerate(steps):
        s.box(x, y2, 210, 56, [title, note], fill=fill, stroke=stroke, size=12.5, bold_first=i > 0)
        if i < len(steps) - 1:
            s.line(x + 210, y2 + 28, x + 247, y2 + 28, stroke=INK, width=1.6, arrow="end")
        x += 247
    s.text(20, y2 + 86, "Back faces are still culled one triangle at a time by the rasteriser, after the "
           "vertex shader has run for them.", size=12.5, fill=MUTED)
    s.write()


def task_squares(s: Svg, cx: float, y: float) -> None:
    """Eight invocations, three of them culled (crossed out)."""
    for k in range(8):
        x = cx - (7 * 26 + 20) / 2 + k * 26
        culled = k in (2, 5, 6)
        s.rect(x, y, 20, 20, fill=RED_FILL if culled else "#ffffff", stroke=RED if culled else BLUE,
               width=1.3, rx=3)
        if culled:
            s.line(x + 3, y + 3, x + 17, y + 17, stroke=RED, width=1.5)


def narrow() -> None:
    """The same figure for a phone: 400 units wide, every stage below the one before."""
    size, big, lead = 11, 12.5, 14.5
    s = Svg(400, 100, TITLE, DESCRIPTION)
    x0, w = 10, 380
    s.text(x0, 22, "At start-up, on the CPU (meshlets.hpp):", size=big, bold=True)
    s.text(x0, 22 + lead + 2, "30,720 triangles \u2192 389 meshlets", size=big, bold=True)
    y = 54
    for lines in (["meshlets[389]", "sphere (centre, radius), cone (axis, cutoff)", "vertex and triangle ranges"],
                  ["meshlet_vertices[]", "per meshlet \u2264 64 indices into the model's vertices"],
                  ["meshlet_triangles[]", "per meshlet \u2264 124, three 8-bit local indices",
                   "packed in one uint"]):
        h = 10 + lead * len(lines)
        s.box(x0, y, w, h, lines, fill=GREY_FILL, stroke=GREY, size=size, bold_first=True)
        y += h + 6

    y += 14
    s.box(x0 + 90, y, 200, 44, ["`vkCmdDrawMeshTasksEXT`", "(cmd, 13, 1, 1)"], fill="#ffffff", stroke=INK,
          size=size)
    y += 44
    s.line(200, y, 200, y + 20, stroke=INK, width=1.6, arrow="end")
    y += 20

    s.box(x0, y, w, 150, [], fill=BLUE_FILL, stroke=BLUE)
    s.text(200, y + 20, "task shader", size=big, bold=True, anchor="middle", fill=BLUE)
    s.text(200, y + 20 + lead, "13 workgroups \u00d7 32 invocations", size=size, anchor="middle", fill=MUTED)
    task_squares(s, 200, y + 44)
    s.text(200, y + 84, "one invocation per meshlet:", size=size, anchor="middle")
    s.text(200, y + 84 + lead, "sphere outside the frustum?", size=size, anchor="middle", fill=RED)
    s.text(200, y + 84 + 2 * lead, "cone facing away from the eye?", size=size, anchor="middle", fill=RED)
    s.text(200, y + 84 + 3 * lead + 2, "culled: atomicAdd(counters)", size=size, anchor="middle", mono=True,
           fill=MUTED)
    y += 150
    s.line(200, y, 200, y + 30, stroke=INK, width=1.6, arrow="end")
    s.text(210, y + 19, "payload: the survivors", size=size, fill=PURPLE)
    y += 30

    s.box(x0, y, w, 150, [], fill=GREEN_FILL, stroke=GREEN)
    s.text(200, y + 20, "mesh shader", size=big, bold=True, anchor="middle", fill=GREEN)
    s.text(200, y + 20 + lead, "EmitMeshTasksEXT(survivors, 1, 1)", size=size, anchor="middle", mono=True,
           fill=MUTED)
    for k in range(5):
        s.rect(200 - (4 * 40 + 34) / 2 + k * 40, y + 44, 34, 20, fill="#ffffff", stroke=GREEN, width=1.3, rx=3)
    s.text(200, y + 84, "one workgroup per meshlet kept:", size=size, anchor="middle")
    for i, line in enumerate(["SetMeshOutputsEXT(vertices, triangles)", "gl_MeshVerticesEXT[i].gl_Position",
                              "gl_PrimitiveTriangleIndicesEXT[i]"]):
        s.text(200, y + 84 + (i + 1) * lead, line, size=size, anchor="middle", mono=True)
    y += 150
    s.line(200, y, 200, y + 20, stroke=INK, width=1.6, arrow="end")
    y += 20
    s.box(x0 + 90, y, 200, 40, ["rasteriser and fragment shader"], fill=ORANGE_FILL, stroke=ORANGE, size=size)
    y += 40

    y += 26
    for i, line in enumerate(["The default view: 65 of 389 meshlets culled in the task",
                              "shader (they face away); 324 drawn, 26,766 of 30,720",
                              "triangles reach the rasteriser."]):
        s.text(x0, y + i * lead, line, size=size)
    y += 3 * lead + 4
    for i, line in enumerate(["No vertex buffer, index buffer, vertex input or input",
                              "assembly: the mesh shader reads the buffers above and",
                              "writes its primitives itself."]):
        s.text(x0, y + i * lead, line, size=size, fill=MUTED)
    y += 3 * lead + 26

    s.text(x0, y, "Chapter 15's way (--draw indirect):", size=big, bold=True)
    s.text(x0, y + lead + 2, "every triangle, every frame", size=big, bold=True)
    y += lead + 16
    steps = [("`vkCmdDrawIndexedIndirect`", "one command, 92,160 indices", "#ffffff", INK),
             ("input assembly", "index buffer \u2192 triangles", GREY_FILL, GREY),
             ("vertex shader", "per vertex index", BLUE_FILL, BLUE),
             ("rasteriser", "30,720 triangles", ORANGE_FILL, ORANGE)]
    for i, (title, note, fill, stroke) in enumerate(steps):
        s.box(x0 + 70, y, 240, 40, [title, note], fill=fill, stroke=stroke, size=size, bold_first=i > 0)
        y += 40
        if i < len(steps) - 1:
            s.line(200, y, 200, y + 14, stroke=INK, width=1.6, arrow="end")
            y += 14
    y += 24
    for i, line in enumerate(["Back faces are still culled one triangle at a time by the",
                              "rasteriser, after the vertex shader has run for them."]):
        s.text(x0, y + i * lead, line, size=size, fill=MUTED)
    s.height = y + lead + 4
    s.write()


if __name__ == "__main__":
    main()
