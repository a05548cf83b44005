"""Chapter 24: frame 9 and frame 39 side by side, enlarged.

Drawn from the chapter's two reviewed test pictures (tests/golden/
24_ray_queries.png after 10 frames, 24_ray_queries_frame40.png after 40, both
headless at 320x240; the last frames are 9 and 39, at index / 60 s, so 0.15 s
and 0.65 s). The same crop of each, around the sphere and the torus, every pixel
enlarged 2.75 times; a dashed line marks the top of the sphere at frame 9.
Between the two frames the sphere (y = 0.7 + 0.3 sin 2t) rises from 0.79 to
0.99 and the torus (angle 0.6 + t about x) turns 0.5 radians further
(chapters/24_ray_queries/main.cpp, make_scene).
"""

from golden import GOLDEN, enlarged, read_png
from svg import MUTED, RED, Svg

LEFT, TOP, CROP_W, CROP_H, ZOOM = 64, 100, 168, 112, 2.75
SPHERE_TOP_FRAME_9 = 131  # the picture's row where the sphere begins at frame 9
PICTURES = [("24_ray_queries.png", "frame 9 (t = 0.15 s)", "--frames 10"),
            ("24_ray_queries_frame40.png", "frame 39 (t = 0.65 s)", "--frames 40")]


def main() -> None:
    w, h, gap, x0, y0 = CROP_W * ZOOM, CROP_H * ZOOM, 24, 26, 92
    s = Svg(1000, y0 + h + 82, "Chapter 24: frame 9 and frame 39, enlarged",
            "The same part of chapter 24's picture at frame 9 and at frame 39, each pixel enlarged "
            "2.75 times. At frame 39 the blue sphere stands higher, above the dashed line that marks "
            "its top at frame 9, and its shadow on the floor has moved further from it; the green "
            "torus has turned, so its hole faces the camera at a different angle and its shadow "
            "changed shape. The top level's instances moved; the bottom levels did not change.")
    s.text(20, 28, "The objects move, the instances follow: frame 9 and frame 39, enlarged 2.75 times",
           size=14, bold=True)
    for i, (name, title, flag) in enumerate(PICTURES):
        x = x0 + i * (w + gap)
        s.text(x + w / 2, 58, title, size=14, anchor="middle", bold=True)
        s.text(x + w / 2, 78, flag, size=12.5, anchor="middle", fill=MUTED, mono=True)
        enlarged(s, read_png(GOLDEN / name), LEFT, TOP, CROP_W, CROP_H, x, y0, ZOOM)
        line_y = y0 + (SPHERE_TOP_FRAME_9 - TOP) * ZOOM
        s.line(x, line_y, x + w, line_y, stroke=RED, width=1.4, dash="6 4")
    s.lines(20, y0 + h + 28, [
        "Dashed: the top of the sphere at frame 9. By frame 39 it has risen 0.2 units (9 pixels here)"
        " and its shadow lies further from it;",
        "the torus has turned 0.5 radians further about the x axis. Refit or rebuilt, the top level "
        "gives exactly these two pictures."], size=12.5, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
