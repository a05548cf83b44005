"""Chapter 26: the meshlet pipeline (task -> mesh -> raster) beside the vertex pipeline.

Numbers from chapter 26: the knot's 30,720 triangles cut into 389 meshlets
(at most 64 vertices and 124 triangles), 32 meshlets per task workgroup
(13 workgroups), and the default view's count: 65 meshlets culled, 324 drawn.
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE,
                 ORANGE_FILL, PURPLE, RED, RED_FILL, Svg)

W, H = 1000, 560


def main() -> None:
    s = Svg(W, H, "Chapter 26: the meshlet pipeline, task shader to mesh shader to rasteriser",
            "Top: vkCmdDrawMeshTasksEXT(13, 1, 1) launches 13 task workgroups of 32 invocations, one "
            "per meshlet; each tests its meshlet's sphere against the frustum and its normal cone "
            "against the eye, and the workgroup launches one mesh workgroup per survivor, which writes "
            "up to 64 vertices and 124 triangles straight to the rasteriser. Bottom: chapter 15's "
            "vertex pipeline, where every triangle goes through input assembly and the vertex shader.")

    # ---- The data, built once on the CPU ------------------------------------------------
    s.text(20, 30, "At start-up, on the CPU (meshlets.hpp): 30,720 triangles \u2192 389 meshlets",
           size=14, bold=True)
    s.box(20, 46, 300, 74, ["meshlets[389]", "sphere (centre, radius), cone (axis, cutoff)",
                            "vertex and triangle ranges"], fill=GREY_FILL, stroke=GREY, size=12,
          bold_first=True)
    s.box(340, 46, 300, 74, ["meshlet_vertices[]", "per meshlet \u2264 64 indices into", "the model's vertices"],
          fill=GREY_FILL, stroke=GREY, size=12, bold_first=True)
    s.box(660, 46, 320, 74, ["meshlet_triangles[]", "per meshlet \u2264 124, three 8-bit local",
                             "indices packed in one uint"], fill=GREY_FILL, stroke=GREY, size=12,
          bold_first=True)

    # ---- The draw ---------------------------------------------------------------------------
    y = 160
    s.box(20, y, 190, 64, ["`vkCmdDrawMeshTasksEXT`", "(cmd, 13, 1, 1)"], fill="#ffffff", stroke=INK,
          size=12.5)
    s.line(210, y + 32, 250, y + 32, stroke=INK, width=1.6, arrow="end")

    # Task workgroups.
    s.box(250, y - 16, 250, 160, [], fill=BLUE_FILL, stroke=BLUE)
    s.text(375, y + 4, "task shader", size=14, bold=True, anchor="middle", fill=BLUE)
    s.text(375, y + 22, "13 workgroups \u00d7 32 invocations", size=11.5, anchor="middle", fill=MUTED)
    for k in range(8):
        cx = 268 + k * 28
        outside = k in (6,)
        away = k in (2, 5)
        fill = RED_FILL if (outside or away) else "#ffffff"
        stroke = RED if (outside or away) else BLUE
        s.rect(cx, y + 36, 22, 22, fill=fill, stroke=stroke, width=1.3, rx=3)
        if outside or away:
            s.line(cx + 3, y + 39, cx + 19, y + 55, stroke=RED, width=1.5)
    s.text(375, y + 78, "one invocation per meshlet:", size=11.5, anchor="middle")
    s.text(375, y + 95, "sphere outside the frustum?", size=11.5, anchor="middle", fill=RED)
    s.text(375, y + 111, "cone facing away from the eye?", size=11.5, anchor="middle", fill=RED)
    s.text(375, y + 131, "culled: atomicAdd(counters)", size=11, anchor="middle", mono=True, fill=MUTED)

    s.line(500, y + 32, 548, y + 32, stroke=INK, width=1.6, arrow="end")
    s.text(524, y + 22, "payload", size=11, anchor="middle", fill=PURPLE)
    s.text(524, y + 52, "survivors", size=11, anchor="middle", fill=PURPLE)

    # Mesh workgroups.
    s.box(548, y - 16, 230, 160, [], fill=GREEN_FILL, stroke=GREEN)
    s.text(663, y + 4, "mesh shader", size=14, bold=True, anchor="middle", fill=GREEN)
    s.text(663, y + 22, "EmitMeshTasksEXT(survivors, 1, 1)", size=10.5, anchor="middle", mono=True,
           fill=MUTED)
    for k in range(5):
        s.rect(566 + k * 40, y + 36, 34, 22, fill="#ffffff", stroke=GREEN, width=1.3, rx=3)
    s.text(663, y + 78, "one workgroup per meshlet kept:", size=11.5, anchor="middle")
    s.text(663, y + 95, "SetMeshOutputsEXT(vertices, triangles)", size=9.8, anchor="middle", mono=True)
    s.text(663, y + 111, "gl_MeshVerticesEXT[i].gl_Position", size=10.5, anchor="middle", mono=True)
    s.text(663, y + 127, "gl_PrimitiveTriangleIndicesEXT[i]", size=10.5, anchor="middle", mono=True)

    s.line(778, y + 32, 818, y + 32, stroke=INK, width=1.6, arrow="end")
    s.box(818, y, 162, 64, ["rasteriser", "and fragment shader"], fill=ORANGE_FILL, stroke=ORANGE,
          size=12.5, bold_first=True)

    s.text(20, y + 190, "The default view: 65 of 389 meshlets culled in the task shader (they face away);"
           " 324 drawn, 26,766 of 30,720 triangles reach the rasteriser.", size=12)
    s.text(20, y + 210, "No vertex buffer, index buffer, vertex input or input assembly: the mesh shader"
           " reads the buffers above and writes its primitives itself.", size=12, fill=MUTED)

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
        s.box(x, y2, 210, 56, [title, note], fill=fill, stroke=stroke, size=12, bold_first=i > 0)
        if i < len(steps) - 1:
            s.line(x + 210, y2 + 28, x + 247, y2 + 28, stroke=INK, width=1.6, arrow="end")
        x += 247
    s.text(20, y2 + 86, "Back faces are still culled one triangle at a time by the rasteriser, after the "
           "vertex shader has run for them.", size=12, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
