"""Chapter 22: the view split into cascades, each with its own light box, and the frame's passes.

Distances from chapter 22's defaults: near 0.1, far 60, three cascades, the
practical split scheme with lambda 0.6 (boundaries 8.5 and 20.3), seen from
above: distances to scale along the view (one unit = 14 px), widths at a
fifth of that so the far slice fits.
"""

import math

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, RED, Svg)

W, H = 1000, 590
SPLITS = [0.1, 8.53, 20.28, 60.0]
COLOURS = [(RED, "#fbe3e1"), (GREEN, GREEN_FILL), (BLUE, BLUE_FILL)]


def main() -> None:
    s = Svg(W, H, "Chapter 22: the view split into three cascades, and the passes of one frame",
            "Top: the camera's view seen from above, split at 8.5 and 20.3 units into three "
            "cascades; each slice has its own shadow map, a square box around the slice's bounding "
            "circle, so the near slice's map covers a small area in fine texels and the far one a "
            "large area in coarse texels. Bottom: each frame draws the scene from the light into "
            "each cascade's layer of one depth image, a barrier from depth writes to fragment "
            "shader reads, then the lit pass, which picks a cascade by distance and compares.")
    s.text(20, 28, "Seen from above: the view in three cascades, a light box around each", size=14,
           bold=True)
    x0, y0, scale, half = 40, 170, 14.0, math.tan(math.radians(50) / 2) * 4 / 3
    across = scale / 5  # widths drawn at a fifth of the distances' scale
    for i in range(3):
        d0, d1 = SPLITS[i], SPLITS[i + 1]
        stroke, fill = COLOURS[i]
        pts = [(x0 + d0 * scale, y0 - d0 * half * across), (x0 + d1 * scale, y0 - d1 * half * across),
               (x0 + d1 * scale, y0 + d1 * half * across), (x0 + d0 * scale, y0 + d0 * half * across)]
        s.polygon(pts, fill=fill, stroke=stroke, width=1.6)
        # The light's box around the slice (its own shadow map).
        s.rect(x0 + d0 * scale - 4, y0 - d1 * half * across - 6, (d1 - d0) * scale + 8,
               2 * d1 * half * across + 12, stroke=stroke, width=1.2, dash="5 4")
        s.text(x0 + (d0 + d1) / 2 * scale, y0 + 4, f"cascade {i}", size=12.5, anchor="middle",
               bold=True)
        s.text(x0 + d1 * scale, y0 + d1 * half * across + 24, f"{d1:.1f}", size=12, anchor="middle",
               fill=MUTED)
    s.circle(x0, y0, 4, fill=INK, stroke=INK)
    s.text(x0 - 4, y0 - 12, "eye", size=12, anchor="middle")
    s.lines(40, 318, ["Dashed: each cascade's light box, one layer of the shadow map each, the same "
                      "texel count. Near the eye a box is small: fine texels",
                      "where the screen shows detail; far away it is large: coarse texels where "
                      "everything is small on screen."], size=12.5, fill=MUTED)

    # The passes of one frame.
    y = 410
    s.text(20, y - 24, "One frame: the shadow pass, the barrier, the lit pass", size=14, bold=True)
    s.box(20, y, 270, 110, ["shadow pass, per cascade c", "depth only into layer c",
                            "light_from_world[c] · world", "depth bias: constant + slope"],
          fill=ORANGE_FILL, stroke=ORANGE, bold_first=True)
    s.box(320, y + 15, 340, 80, ["barrier: layers 0..N-1",
                                 "DEPTH_ATTACHMENT → SHADER_READ_ONLY",
                                 "fragment tests' writes → fragment shader's reads"],
          fill="#eee6fa", stroke=PURPLE, bold_first=True, size=12)
    s.box(690, y, 290, 110, ["lit pass", "cascade: by the point's distance",
                             "compare its light depth (sampler)", "3x3 taps averaged: PCF"],
          fill=GREEN_FILL, stroke=GREEN, bold_first=True)
    s.line(290, y + 55, 320, y + 55, stroke=INK, width=1.6, arrow="end")
    s.line(660, y + 55, 690, y + 55, stroke=INK, width=1.6, arrow="end")
    s.text(500, y + 140, "next frame: its shadow pass waits for this lit pass's reads before it "
           "clears the map", size=12.5, anchor="middle", fill=GREY)
    s.write()


if __name__ == "__main__":
    main()
