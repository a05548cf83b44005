"""Chapter 23: the uniform sky's sample directions, drawn with matplotlib when the book is built.

environment() in shaders/23_materials/pbr.glsl, for one pixel whose view
direction v leans 45 degrees from n: its Hammersley points turned into
cosine-distributed diffuse directions l, and into GGX half vectors h
reflected into specular directions l = 2 (v.h) h - v, for two of the grid's
roughness values. Seen from straight above: each dot is where the tip of a
unit direction lands (x and y in the frame around n whose first axis leans
towards v), the circle is the horizon. A specular sample that the shader
skips (n.l <= 0 or v.h <= 0) is a cross. The same count (grid.hpp's
sky_samples), and the script exits if pbr.glsl no longer says the lines it
reproduces, so the figure cannot drift from the shader.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the
three panels stand one above the other. Prints the SVG; text stays text.
Needs python3-matplotlib.
"""

import math
import os
import sys
from pathlib import Path

from charts import print_svg, pyplot  # book/diagrams/charts.py
from ggx_sampling import ggx_half_vector, hammersley  # book/diagrams/ggx_sampling.py

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ROOT = Path(__file__).resolve().parents[2]
PBR_GLSL = ROOT / "shaders" / "23_materials" / "pbr.glsl"
SAMPLES = int(constant(ROOT / "chapters" / "23_materials" / "grid.hpp", "sky_samples"))
VIEW_DEGREES = 45.0
ROUGHNESS = (0.325, 0.55)  # the grid's second and third columns

# What this script reproduces, as pbr.glsl says it (whitespace folded).
SHADER_LINES = [
    "return vec2((float(i) + 0.5) / float(count), float(bitfieldReverse(i)) * 2.3283064365386963e-10);",
    "float alpha = max(m.roughness * m.roughness, 1e-3);",
    "float phi = 2.0 * PI * u.y;",
    "float r = sqrt(u.x);",
    "vec3 l = frame * vec3(r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u.x)));",
    "float cos_h = sqrt((1.0 - u.x) / (1.0 + (alpha * alpha - 1.0) * u.x));",
    "float sin_h = sqrt(max(0.0, 1.0 - cos_h * cos_h));",
    "vec3 h = frame * vec3(sin_h * cos(phi), sin_h * sin(phi), cos_h);",
    "vec3 ls = 2.0 * v_dot_h * h - v;",
    "if (n_dot_l > 0.0 && v_dot_h > 0.0)",
]


def check_shader() -> None:
    code = " ".join(PBR_GLSL.read_text(encoding="utf-8").split())
    for want in SHADER_LINES:
        if want not in code:
            raise SystemExit(f"shaders/23_materials/pbr.glsl: no longer says `{want[:60]}`; "
                             "redraw book/diagrams/23_sky_samples.py")


def diffuse(v):
    """The diffuse lobe's directions (frame around n = (0, 0, 1), first axis towards v)."""
    out = []
    for i in range(SAMPLES):
        u, w = hammersley(i, SAMPLES)
        phi, r = 2.0 * math.pi * w, math.sqrt(u)
        out.append((r * math.cos(phi), r * math.sin(phi), math.sqrt(max(0.0, 1.0 - u))))
    return out


def specular(v, roughness: float):
    """(l, kept) for each of the specular lobe's samples."""
    alpha = max(roughness * roughness, 1e-3)
    out = []
    for i in range(SAMPLES):
        h = ggx_half_vector(i, SAMPLES, alpha)
        v_dot_h = sum(a * b for a, b in zip(v, h))
        l = tuple(2.0 * v_dot_h * a - b for a, b in zip(h, v))
        out.append((l, l[2] > 0.0 and v_dot_h > 0.0))
    return out


def main() -> None:
    check_shader()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    plt = pyplot("sky samples", plain_axes=False, title_size=11)
    from matplotlib.patches import Circle
    theta = math.radians(VIEW_DEGREES)
    v = (math.sin(theta), 0.0, math.cos(theta))
    mirror = (-v[0], 0.0, v[2])
    if narrow:
        figure, axes = plt.subplots(3, 1, figsize=(4.2, 12.4), layout="constrained")
    else:
        figure, axes = plt.subplots(1, 3, figsize=(9.6, 4.3), layout="constrained")
    panels = [("diffuse: cosine-weighted,\nthe same for every roughness", [(l, True) for l in diffuse(v)], "#0969da")]
    for roughness in ROUGHNESS:
        points = specular(v, roughness)
        kept = sum(1 for _, k in points if k)
        panels.append((f"specular, roughness {roughness:g}:\n{kept} of {SAMPLES} kept, round the mirror r",
                       points, "#bc4c00"))
    for ax, (title, points, colour) in zip(axes, panels):
        ax.add_patch(Circle((0, 0), 1.0, fill=False, color="#59636e", linewidth=1.6))
        ax.add_patch(Circle((0, 0), math.sin(math.radians(45)), fill=False, color="#d1d9e0", linewidth=1.0))
        ax.text(0.73, -0.73, "45°", fontsize=9.5, color="#59636e")
        kept = [l for l, k in points if k]
        skipped = [l for l, k in points if not k]
        ax.scatter([l[0] for l in kept], [l[1] for l in kept], s=16, color=colour, edgecolors="none",
                   label=f"sample ({len(kept)})")
        if skipped:
            ax.scatter([l[0] for l in skipped], [l[1] for l in skipped], marker="x", color="#cf222e", s=22,
                       linewidths=1.2, label=f"skipped: n·l ≤ 0, below the horizon ({len(skipped)})")
        ax.plot([0], [0], marker="+", color="#1f2328", markersize=11, markeredgewidth=1.6, zorder=5)
        ax.text(0.04, 0.06, "n", fontsize=10.5, color="#1f2328", zorder=5)
        ax.plot([v[0]], [v[1]], marker="o", markersize=8, markerfacecolor="white", markeredgecolor="#1f2328",
                markeredgewidth=1.6, zorder=5)
        ax.text(v[0], v[1] + 0.09, "v", fontsize=10.5, color="#1f2328", ha="center", zorder=5)
        ax.plot([mirror[0]], [mirror[1]], marker="D", markersize=8, markerfacecolor="white",
                markeredgecolor="#1f2328", markeredgewidth=1.6, zorder=5)
        ax.text(mirror[0], mirror[1] + 0.11, "r", fontsize=10.5, color="#1f2328", ha="center", zorder=5,
                bbox=dict(boxstyle="round,pad=0.1", facecolor="white", edgecolor="none", alpha=0.8))
        ax.set_title(title, loc="left", fontsize=10.5)
        ax.set_aspect("equal")
        ax.set_xlim(-1.12, 1.12)
        ax.set_ylim(-1.12, 1.12)
        ax.set_xticks([])
        ax.set_yticks([])
        for side in ax.spines.values():
            side.set_visible(False)
        ax.legend(loc="upper center", fontsize=9.5, frameon=False, bbox_to_anchor=(0.5, 0.02))
    heading = (f"Chapter 23: the sky's {SAMPLES} directions per lobe, seen from above\n"
               f"(n at the centre, v {VIEW_DEGREES:g}° from it, r its mirror; the circle is the horizon)")
    if narrow:
        heading = (f"Chapter 23: the sky's {SAMPLES}\ndirections per lobe, seen from above\n"
                   f"(n at the centre, v {VIEW_DEGREES:g}° from it,\nr its mirror; the circle is the horizon)")
    figure.suptitle(heading, x=0.01, ha="left", fontsize=11.5)
    print_svg(plt, figure, "book/diagrams/23_sky_samples.py")


if __name__ == "__main__":
    main()
