"""Chapter 23: the vectors of the BRDF at one surface point, and the frame's two passes.

Left: the normal n, the directions to the eye (v) and to the light (l), and
the half vector h between them; the microfacets whose normal is h are the
ones that mirror l into v. Right: the scene pass writes radiance into the
R16G16B16A16_SFLOAT image, a barrier, and the tone-mapping pass turns it into
the _SRGB target. Angles as drawn, not to scale.
"""

import math

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, GREY, INK, MUTED, ORANGE, ORANGE_FILL,
                 PURPLE, RED, Svg)

W, H = 1000, 500


def ray(s, x0, y0, angle_deg, length, colour, label, dx=0, dy=0):
    a = math.radians(angle_deg)
    x1, y1 = x0 + length * math.sin(a), y0 - length * math.cos(a)
    s.line(x0, y0, x1, y1, stroke=colour, width=2.2, arrow="end")
    s.text(x1 + dx, y1 + dy, label, size=15, anchor="middle", fill=colour, bold=True)


def main() -> None:
    s = Svg(W, H, "Chapter 23: the BRDF's vectors at one point, and the frame's two passes",
            "Left: a rough surface seen as tiny mirror facets; at the point, the normal n, the "
            "direction v to the eye and l to the light, and the half vector h between them. D counts "
            "the facets facing h, G the ones neither hidden nor shadowed, F how much a facet "
            "reflects at the angle v.h. Right: the scene pass writes radiance into a 16-bit float "
            "image, a barrier, optionally the bloom's compute chain, then a full-screen pass "
            "multiplies by the exposure, applies the ACES curve and writes the sRGB target.")
    s.text(20, 28, "At one point: n, v, l and the half vector h", size=14, bold=True)
    # The surface as a row of small facets, tilted this way and that.
    x0, y0 = 70, 300
    tilts = [12, -18, 8, -6, 20, -12, 4, -20, 14, -8, 10, -14]
    x = x0
    for t in tilts:
        w = 30
        dy = w * math.tan(math.radians(t)) / 2
        s.line(x, y0 + dy, x + w, y0 - dy, stroke=GREY, width=2)
        x += w
    cx = x0 + 6 * 30
    s.line(x0 - 10, y0 + 14, x + 10, y0 + 14, stroke=MUTED, width=1, dash="4 4")
    s.text(x + 14, y0 + 18, "surface", size=12.5, fill=MUTED)
    ray(s, cx, y0, 0, 150, INK, "n", dy=-8)
    ray(s, cx, y0, -55, 170, BLUE, "v (to the eye)", dx=-20, dy=-10)
    ray(s, cx, y0, 35, 170, ORANGE, "l (to the light)", dx=30, dy=-10)
    ray(s, cx, y0, -10, 130, GREEN, "h = normalize(v + l)", dx=-75, dy=-4)
    s.lines(30, 350, ["D(n·h): how many facets face h (GGX, width α = roughness²)",
                      "G(n·l, n·v): how many of those the light reaches and the eye sees (Smith)",
                      "F(v·h): how much a facet reflects at that angle (Schlick, from F₀)",
                      "specular = D G F / (4 n·l n·v);  diffuse = (1 − F) c / π"], size=12.5)

    # The two passes.
    y = 120
    s.text(560, 28, "One frame: radiance first, the picture second", size=14, bold=True)
    s.box(560, y - 60, 400, 80, ["scene pass", "glTF material → BRDF × each light, + the sky",
                                 "writes radiance, any size: 0.01 or 40"],
          fill=ORANGE_FILL, stroke=ORANGE, bold_first=True, size=12.5)
    s.line(760, y + 20, 760, y + 50, stroke=INK, width=1.6, arrow="end")
    s.box(560, y + 50, 400, 60, ["HDR image: R16G16B16A16_SFLOAT",
                                 "COLOR_ATTACHMENT → SHADER_READ_ONLY barrier"],
          fill="#eee6fa", stroke=PURPLE, bold_first=True, size=12.5)
    # Where the bloom's compute chain runs, in two lines beside a longer arrow.
    s.line(760, y + 110, 760, y + 170, stroke=INK, width=1.6, arrow="end")
    s.lines(772, y + 134, ["with --bloom: the compute", "chain blurs it here"], size=12.5, fill=MUTED)
    y += 30
    s.box(560, y + 140, 400, 80, ["tone-mapping pass (one full-screen triangle)",
                                  "× 2^exposure, then the ACES curve: 0..1",
                                  "written to the _SRGB target, which encodes it"],
          fill=GREEN_FILL, stroke=GREEN, bold_first=True, size=12.5)
    s.line(760, y + 220, 760, y + 250, stroke=INK, width=1.6, arrow="end")
    s.box(610, y + 250, 300, 44, ["the picture on screen"], fill=BLUE_FILL, stroke=BLUE,
          bold_first=True, size=12.5)
    s.text(760, y + 325, "--verify reads the HDR image back: the CPU reference checks it there",
           size=12.5, anchor="middle", fill=RED)
    s.write()


if __name__ == "__main__":
    main()
