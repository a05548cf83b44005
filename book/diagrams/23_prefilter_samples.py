"""Chapter 23: where the prefilter's samples land, drawn with matplotlib when the book is built.

prefilter.comp for one texel whose direction n points straight up (n = v = r):
its Hammersley points turned into GGX half vectors h, each reflected into a
direction l = 2 (n.h) h - n, for the roughness of two levels of the cube (0.2
and 0.6). Seen from above: the outer circle is the horizon, the rings are 15,
30 and 60 degrees from n; a sample below the horizon (n.l <= 0) is skipped
by the shader and drawn as a cross. Each dot is coloured by the sky's mip
level it reads (source_lod in shaders/23_materials/cube.glsl: wider apart,
coarser level). The same formulas, the same count (Environment::
specular_samples) and the same sky size. Prints the SVG; text stays text.
With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the two
views stand one above the other. Needs python3-matplotlib.
"""

import math
import os
import sys
from pathlib import Path

from charts import print_svg, pyplot  # book/diagrams/charts.py
from ggx_sampling import ggx_half_vector  # book/diagrams/ggx_sampling.py

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ENVIRONMENT_HPP = Path(__file__).resolve().parents[2] / "chapters" / "23_materials" / "environment.hpp"
SAMPLES = int(constant(ENVIRONMENT_HPP, "specular_samples"))
SKY_SIZE = int(constant(ENVIRONMENT_HPP, "sky_size"))
LEVELS = int(constant(ENVIRONMENT_HPP, "specular_levels"))


def distribution_ggx(n_dot_h: float, alpha: float) -> float:
    a2 = alpha * alpha
    d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0
    return a2 / (math.pi * d * d)


def source_lod(pdf: float, count: int) -> float:
    sample_angle = 1.0 / (count * pdf)
    texel_angle = 4.0 * math.pi / (6.0 * SKY_SIZE * SKY_SIZE)
    return max(0.5 * math.log2(sample_angle / texel_angle) + 1.0, 0.0)


def samples(roughness: float):
    """(l.x, l.y, n.l, sky level) for each sample of prefilter.comp, n = (0, 0, 1)."""
    alpha = max(roughness * roughness, 1e-3)
    out = []
    for i in range(SAMPLES):
        h = ggx_half_vector(i, SAMPLES, alpha)
        cos_h = h[2]
        l = (2.0 * cos_h * h[0], 2.0 * cos_h * h[1], 2.0 * cos_h * h[2] - 1.0)
        lod = source_lod(distribution_ggx(cos_h, alpha) / 4.0, SAMPLES)
        out.append((l[0], l[1], l[2], lod))
    return out


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    plt = pyplot("prefilter samples", plain_axes=False, title_size=12)
    from matplotlib.patches import Circle
    if narrow:
        figure, axes = plt.subplots(2, 1, figsize=(4.4, 9.4), layout="constrained")
    else:
        figure, axes = plt.subplots(1, 2, figsize=(9.6, 5.0), layout="constrained")
    cmap = plt.colormaps["viridis"]
    last = float(constant(ENVIRONMENT_HPP, "sky_levels")) - 1  # the sampler clamps a higher lod to it
    reach = 0.0  # both panels to one scale
    for ax, level in zip(axes, (1, 3)):
        roughness = level / (LEVELS - 1)
        points = samples(roughness)
        # Drawn at their angle from n (90 degrees: the horizon), in the direction they lean.
        def place(p):
            angle = math.degrees(math.acos(max(-1.0, min(1.0, p[2]))))
            lean = math.hypot(p[0], p[1]) or 1.0
            return angle / 90.0 * p[0] / lean, angle / 90.0 * p[1] / lean, angle
        kept = [place(p) + (min(p[3], last),) for p in points if p[2] > 0.0]
        skipped = [place(p) for p in points if p[2] <= 0.0]
        for ring in (15, 30, 60, 90):
            ax.add_patch(Circle((0, 0), ring / 90.0, fill=False,
                                                   color="#59636e" if ring == 90 else "#d1d9e0",
                                                   linewidth=1.6 if ring == 90 else 1.0))
            ax.text(ring / 90.0 * 0.71 + 0.02, ring / 90.0 * 0.71 + 0.02, f"{ring}°", fontsize=9.5, color="#59636e")
        dots = ax.scatter([p[0] for p in kept], [p[1] for p in kept], c=[p[3] for p in kept], cmap=cmap,
                          vmin=0, vmax=last, s=18, edgecolors="none", label=f"sample kept ({len(kept)})")
        if skipped:
            ax.scatter([p[0] for p in skipped], [p[1] for p in skipped], marker="x", color="#cf222e", s=24,
                       linewidths=1.3, label=f"below the horizon, skipped ({len(skipped)})")
        widest = max(p[2] for p in kept)
        lods = sorted(p[3] for p in kept)
        gap = "\n" if narrow else " "
        ax.set_title(f"roughness {roughness:.1f} (the cube's level {level}):{gap}{len(kept)} of {SAMPLES} kept,"
                     f"{gap if narrow else chr(10)}all within {widest:.0f}° of n;{gap}"
                     f"they read sky levels {lods[0]:.1f} to {lods[-1]:.1f}",
                     loc="left", fontsize=10.5 if narrow else 11)
        reach = max([reach, 1.08] + [math.hypot(p[0], p[1]) + 0.08 for p in skipped])
        ax.set_aspect("equal")
        ax.set_xticks([])
        ax.set_yticks([])
        for side in ax.spines.values():
            side.set_visible(False)
        legend = ax.legend(loc="upper center", fontsize=9.5, frameon=False, bbox_to_anchor=(0.5, 0.02))
        handles = getattr(legend, "legend_handles", None) or legend.legendHandles  # 3.7+, before
        handles[0].set_color(cmap(0.55))  # a mid colour for "a kept sample"
    for ax in axes:
        ax.set_xlim(-reach, reach)
        ax.set_ylim(-reach, reach)
    bar = figure.colorbar(dots, ax=axes, shrink=0.6, location="bottom" if narrow else "right")
    bar.set_label("the sky's mip level a sample reads")
    if narrow:
        figure.suptitle("Chapter 23: where the prefilter's samples\nland, for one texel whose n points at the\n"
                        "centre (the distance from the centre is\nthe angle from n; the dark circle is the horizon)",
                        x=0.01, ha="left", fontsize=11)
    else:
        figure.suptitle("Chapter 23: where the prefilter's samples land, for one texel whose n points at the centre\n"
                        "(the distance from the centre is the angle from n; the dark circle is the horizon)",
                        x=0.01, ha="left", fontsize=12)
    print_svg(plt, figure, "book/diagrams/23_prefilter_samples.py")


if __name__ == "__main__":
    main()
