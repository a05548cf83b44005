"""Chapter 23b: the frame's two passes, radiance first and the picture second.

The scene pass writes radiance into the R16G16B16A16_SFLOAT image; a barrier;
with --bloom the compute chain blurs it; then the tone-mapping pass multiplies
by the exposure, applies the curve and writes the _SRGB target. (Page 23 once
showed this beside its microfacet sketch, 23_microfacets.py.)
"""

from svg import BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, PURPLE, RED, Svg

W, H = 440, 492


def main() -> None:
    s = Svg(W, H, "Chapter 23b: one frame, radiance first and the picture second",
            "The scene pass writes radiance into a 16-bit float image; a barrier; optionally the "
            "bloom's compute chain; then a full-screen pass multiplies by the exposure, applies the "
            "ACES curve and writes the sRGB target. --verify reads the HDR image back.")
    x, w, size = 20, 400, 13.5
    mid = x + w / 2
    s.text(x, 28, "One frame: radiance first, the picture second", size=15, bold=True)
    y = 44
    s.box(x, y, w, 80, ["scene pass", "glTF material → BRDF × each light, + the sky",
                        "writes radiance, any size: 0.01 or 40"],
          fill="#fdebd7", stroke="#b35900", bold_first=True, size=size)
    s.line(mid, y + 80, mid, y + 110, stroke=INK, width=1.6, arrow="end")
    y += 110
    s.box(x, y, w, 60, ["HDR image: R16G16B16A16_SFLOAT",
                        "COLOR_ATTACHMENT → SHADER_READ_ONLY barrier"],
          fill="#eee6fa", stroke=PURPLE, bold_first=True, size=size)
    s.line(mid, y + 60, mid, y + 120, stroke=INK, width=1.6, arrow="end")
    s.lines(mid + 12, y + 84, ["with --bloom: the compute", "chain blurs it here"], size=size, fill=MUTED)
    y += 120
    s.box(x, y, w, 80, ["tone-mapping pass (one full-screen triangle)",
                        "× 2^exposure, then the ACES curve: 0..1",
                        "written to the _SRGB target, which encodes it"],
          fill=GREEN_FILL, stroke=GREEN, bold_first=True, size=size)
    s.line(mid, y + 80, mid, y + 110, stroke=INK, width=1.6, arrow="end")
    y += 110
    s.box(x + 50, y, w - 100, 44, ["the picture on screen"], fill=BLUE_FILL, stroke=BLUE,
          bold_first=True, size=size)
    s.lines(mid, y + 70, ["--verify reads the HDR image back:", "the CPU reference checks it there"],
            size=size, anchor="middle", fill=RED)
    s.write()


if __name__ == "__main__":
    main()
