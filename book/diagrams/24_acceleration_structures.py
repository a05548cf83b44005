"""Chapter 24: the scene's acceleration structures, top level to buffers.

The counts are chapter 24's: four meshes (the floor of 2 triangles, the cube
of 12, the sphere of 32 x 16 with its poles' empty triangles left out, 960,
the torus of 48 x 16, 1536), nineteen instances of them.
"""

from svg import (BLUE, BLUE_FILL, GREY, GREY_FILL, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE,
                 PURPLE_FILL, Svg)

W, H = 1000, 600
MESHES = [("floor", 2, 1), ("cube", 12, 16), ("sphere", 960, 1), ("torus", 1536, 1)]


def main() -> None:
    s = Svg(W, H, "Chapter 24: a top level of instances over four bottom levels",
            "Top: one top-level acceleration structure holding 19 instances, built again or "
            "refitted every frame. Middle: the instances, each a 3 by 4 transform, a mask and the "
            "address of a bottom-level structure: one floor, sixteen pillars that share the cube, "
            "the sphere and the torus. Below: four bottom-level structures, one per mesh, built "
            "once and compacted, whose triangles are read from the shared vertex and index "
            "buffers by device address.")
    s.text(20, 28, "The scene's acceleration structures: what a ray query walks", size=14,
           bold=True)

    col_w, gap = 220, 25
    x0 = (W - 4 * col_w - 3 * gap) / 2
    # The top level.
    s.box(x0, 50, 4 * col_w + 3 * gap, 74, ["top level (TLAS): 19 instances",
                             "VK_GEOMETRY_TYPE_INSTANCES_KHR, read from a host-visible buffer",
                             "every frame: --tlas update (refit, ALLOW_UPDATE) or rebuild"],
          fill=PURPLE_FILL, stroke=PURPLE, bold_first=True, size=13)

    # The instances and the bottom levels, one column per mesh.
    for i, (name, triangles, count) in enumerate(MESHES):
        x = x0 + i * (col_w + gap)
        cx = x + col_w / 2
        s.line(cx, 124, cx, 176, stroke=INK, width=1.4, arrow="end")
        label = f"{count} instances" if count > 1 else "1 instance"
        if count > 1:  # a stack of boxes behind: many instances, one bottom level
            for k in (2, 1):
                s.rect(x + 5 * k, 178 - 5 * k, col_w, 92, fill=ORANGE_FILL, stroke=ORANGE,
                       width=0.8, rx=6)
        s.box(x, 178, col_w, 92, [f"{name}: {label}", "transform: 3×4, row-major",
                                  "mask 0xFF, no face culling", "→ bottom level's address"],
              fill=ORANGE_FILL, stroke=ORANGE, bold_first=True, size=12.5)
        s.line(cx, 270, cx, 318, stroke=INK, width=1.4, arrow="end")
        s.box(x, 320, col_w, 92, [f"bottom level: {name}", f"{triangles} triangles, opaque",
                                  "built once, then compacted", "(query size, copy, destroy)"],
              fill=BLUE_FILL, stroke=BLUE, bold_first=True, size=12.5)
        s.line(cx, 462, cx, 414, stroke=GREY, width=1.2, arrow="end")
    s.text(x0 + col_w + gap + col_w / 2 + 8, 299, "16 pillars share one cube: instancing",
           size=12, fill=MUTED)

    # The buffers.
    s.box(x0, 464, 4 * col_w + 3 * gap, 56,
          ["vertex buffer and index buffer: usage BUILD_INPUT_READ_ONLY | SHADER_DEVICE_ADDRESS",
           "the same buffers the draws bind; each mesh's triangles start at its first index"],
          fill=GREY_FILL, stroke=GREY, size=12.5)
    s.lines(x0, 548, ["A ray enters the top level in world space; at an instance's box it is "
                      "moved by that instance's inverse transform into its",
                      "bottom level, where the triangles are. So sixteen pillars cost one cube's "
                      "triangles, and moving an object changes only",
                      "its instance: the top level is built again each frame, the bottom levels "
                      "never."], size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
