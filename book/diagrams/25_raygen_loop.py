"""Chapter 25: the other way to bounce, a loop in the ray-generation shader.

Not what the chapter's shaders do (they recurse: closest.rchit traces the
reflected ray itself, drawn in 25_ray_flow.py), but the form renderers with
many bounces use, sketched for the same scene and the same colours: the
ray-generation shader traces one ray at a time and keeps the running total;
the closest-hit shader shades its hit (with its shadow ray, as now) and,
instead of tracing the reflection, hands the next ray back in the payload.
mix(local, reflected, r) = (1 - r) local + r reflected, unrolled: each
surface adds (1 - r) of its colour times the product of the reflectivities
before it; the last surface, or one that does not reflect, adds all of it.
"""

from svg import (BLUE, BLUE_FILL, GREEN, GREEN_FILL, INK, MUTED, ORANGE, ORANGE_FILL, PURPLE,
                 PURPLE_FILL, Svg)

W, H = 1000, 560


def main() -> None:
    s = Svg(W, H, "Chapter 25, sketched: bounces as a loop in the ray-generation shader",
            "The ray-generation shader holds a running colour and a weight, and loops over the "
            "bounces: it traces one ray at depth 1, the closest-hit shader shades the hit and "
            "writes its colour, its reflectivity and the reflected ray into the payload, or the "
            "sky miss shader writes the sky and marks a miss; back in the ray-generation shader "
            "the colour is added with the weight, the weight multiplied by the reflectivity, and "
            "the next ray taken from the payload. No ray is traced deeper than the shadow ray at "
            "depth 2, whatever the number of bounces.")
    s.text(20, 28, "Bounces as a loop in raygen: one ray at a time, the payload carries the next one",
           size=14, bold=True)
    s.text(20, 50, "a sketch of the common alternative to this chapter's recursion, for the same "
           "scene and the same colour", size=12.5, fill=MUTED)
    # The ray-generation shader and its loop.
    code = [
        "vec3 total = vec3(0); float weight = 1;",
        "ray = the camera's ray through the pixel;",
        "for (uint b = 0; b <= pc.bounces; ++b) {",
        "    traceRayEXT(scene, ..., ray, 0);  // depth 1",
        "    if (hit.missed) {",
        "        total += weight * hit.colour;  // sky",
        "        break;",
        "    }",
        "    float r = b < pc.bounces ? hit.reflectivity : 0;",
        "    vec3 c = weight * hit.colour;",
        "    total += (1 - r) * c;  // r of it reflects on",
        "    if (r == 0) break;",
        "    weight *= r;",
        "    ray = (hit.next_origin, hit.next_direction);",
        "}",
        "imageStore(image, pixel, vec4(total, 1));",
    ]
    size, leading = 12.5, 19.5
    x0, y0 = 20, 72
    bw = 500
    bh = 44 + leading * len(code)
    s.rect(x0, y0, bw, bh, fill=ORANGE_FILL, stroke=ORANGE, rx=6, width=1.4)
    s.text(x0 + 12, y0 + 24, "raygen.rgen, looping", size=13, bold=True)
    top = y0 + 50
    for i, line in enumerate(code):
        s.text(x0 + 30, top + i * leading, line, size=size, mono=True)
    trace_y = top + 3 * leading - 4
    trace_x = x0 + 30 + 48 * size * 0.602  # the end of the trace's line
    # The loop's back edge, from the end of the body to the trace.
    s.path(f"M{x0 + 24:.0f},{top + 13 * leading - 4:.0f} L{x0 + 10:.0f},{top + 13 * leading - 4:.0f} "
           f"L{x0 + 10:.0f},{trace_y:.0f} L{x0 + 24:.0f},{trace_y:.0f}", stroke=ORANGE, width=1.6,
           arrow="end")
    # The shaders the trace runs.
    rx, rw = 610, 340
    s.box(rx, 80, rw, 112, ["closest.rchit", "shades the hit: normal, light, the shadow ray",
                            "(depth 2, as in this chapter); traces no",
                            "reflection: writes colour, reflectivity, next ray"],
          fill=GREEN_FILL, stroke=GREEN, bold_first=True, size=12.5)
    s.box(rx, 222, rw, 62, ["sky.rmiss", "writes the sky's colour, sets missed"],
          fill=BLUE_FILL, stroke=BLUE, bold_first=True, size=12.5)
    s.line(trace_x, trace_y - 4, rx - 2, 136, stroke=GREEN, width=1.6, arrow="end")
    s.text(548, 138, "hits", size=12, fill=GREEN)
    s.line(trace_x, trace_y + 2, rx - 2, 253, stroke=BLUE, width=1.6, arrow="end")
    s.text(548, 238, "misses", size=12, fill=BLUE)
    # The payload, written there and read back here.
    py = 318
    payload = ["struct Hit {", "  vec3 colour;        // shaded, or sky",
               "  float reflectivity; // 0: none",
               "  vec3 next_origin;   // the reflected",
               "  vec3 next_direction;// ray", "  bool missed;", "};"]
    s.rect(rx, py, rw, 30 + 17 * len(payload), fill=PURPLE_FILL, stroke=PURPLE, rx=6, width=1.4)
    s.text(rx + 12, py + 18, "the payload, written by either", size=12.5, bold=True, fill=PURPLE)
    for i, line in enumerate(payload):
        s.text(rx + 12, py + 38 + 17 * i, line, size=11.5, mono=True)
    s.polyline([(rx + rw + 2, 136), (rx + rw + 24, 136), (rx + rw + 24, py + 30), (rx + rw + 2, py + 30)],
               stroke=GREEN, width=1.4, arrow="end")
    s.polyline([(rx + rw + 2, 253), (rx + rw + 16, 253), (rx + rw + 16, py + 50), (rx + rw + 2, py + 50)],
               stroke=BLUE, width=1.4, arrow="end")
    s.path(f"M{rx - 2:.0f},{py + 60:.0f} C{rx - 50:.0f},{py + 60:.0f} {x0 + bw + 30:.0f},"
           f"{top + 10 * leading:.0f} {x0 + bw + 2:.0f},{top + 10 * leading:.0f}", stroke=PURPLE,
           width=1.6, arrow="end")
    s.text(x0 + bw + 8, top + 10 * leading + 26, "read back", size=12, fill=PURPLE)
    s.lines(20, H - 62, [
        "Every ray the loop traces is at depth 1, and the shadow ray at 2: the recursion depth "
        "stays 2 for any number of bounces,",
        "so the driver's stack stays shallow. The chapter's recursion, above, needs bounces + 2 "
        "and keeps each level's state on it;",
        "the loop pays instead with a larger payload (the next ray) and a colour built front to "
        "back with a running weight."], size=12.5)
    s.write()


if __name__ == "__main__":
    main()
