"""Chapter 23: how GGX's lobe widens with roughness, drawn with matplotlib when the book is built.

The normal distribution D(n.h) of distribution_ggx (shaders/23_materials/pbr.glsl,
alpha = roughness^2), the same formula, against the angle between the half
vector h and the normal n, for the roughnesses of the prefiltered cube's
levels 1 to 5 (0.2 to 1). Log scale: at roughness 0.2 the peak is 199, at 1 the
distribution is flat, 1 / pi. The legend gives, for each, the angle at which D
falls to half its peak, computed here from the same formula. Prints the SVG;
text stays text (the ids title, x-axis-label, y-axis-label and legend, as the
book's other charts). With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it,
for phones) a narrower chart, its legend below. Needs python3-matplotlib.
"""

import math
import os
import sys
from pathlib import Path

from charts import print_svg, pyplot  # book/diagrams/charts.py

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ENVIRONMENT_HPP = Path(__file__).resolve().parents[2] / "chapters" / "23_materials" / "environment.hpp"
LEVELS = int(constant(ENVIRONMENT_HPP, "specular_levels"))  # roughness 0, 0.2, .. 1


def distribution_ggx(n_dot_h: float, alpha: float) -> float:
    """pbr.glsl's distribution_ggx, line for line."""
    a2 = alpha * alpha
    d = n_dot_h * n_dot_h * (a2 - 1.0) + 1.0
    return a2 / (math.pi * d * d)


def half_peak_degrees(alpha: float) -> float | None:
    """The angle of h from n where D is half of D(1); None where D is flat (alpha = 1)."""
    peak = distribution_ggx(1.0, alpha)
    lo, hi = 0.0, 90.0
    if distribution_ggx(0.0, alpha) >= 0.5 * peak:
        return None
    for _ in range(60):  # D falls monotonically with the angle for alpha < 1
        mid = 0.5 * (lo + hi)
        if distribution_ggx(math.cos(math.radians(mid)), alpha) > 0.5 * peak:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    plt = pyplot("GGX lobe", title_size=11 if narrow else 12.5)
    colours = ("#0969da", "#1a7f37", "#8250df", "#bc4c00", "#cf222e")
    angles = [i * 0.25 for i in range(361)]
    figure, ax = plt.subplots(figsize=(4.2, 6.4) if narrow else (8.4, 5.0))
    for level, colour in zip(range(1, LEVELS), colours):
        roughness = level / (LEVELS - 1)
        alpha = roughness * roughness
        ds = [distribution_ggx(math.cos(math.radians(a)), alpha) for a in angles]
        half = half_peak_degrees(alpha)
        where = f"half its peak at {half:.1f}°" if half is not None else "flat: every angle alike"
        gap = "\n" if narrow else " "
        ax.plot(angles, ds, color=colour, linewidth=2.2,
                label=f"roughness {roughness:.1f} (α = {alpha:.2f}):{gap}peak {ds[0]:.3g}, {where}")
    ax.set_yscale("log")
    ax.set_xlim(0, 90)
    ax.set_xticks(range(0, 91, 15))
    ax.set_ylim(0.01, 400)
    if narrow:  # plain tick labels: a log axis's superscripts are too small on a phone
        ax.set_yticks([0.01, 0.1, 1, 10, 100], ["0.01", "0.1", "1", "10", "100"])
        ax.minorticks_off()
        ax.set_xlabel("angle between h and n (degrees)")
        ax.set_ylabel("D(n·h), GGX (log scale)")
        title = ax.set_title("Chapter 23: GGX's lobe widens\nand flattens as the roughness grows", loc="left")
        legend = ax.legend(loc="upper center", fontsize=9.5, frameon=False, bbox_to_anchor=(0.42, -0.14))
    else:
        ax.set_xlabel("angle between the half vector h and the normal n (degrees)")
        ax.set_ylabel("D(n·h), GGX's normal distribution (log scale)")
        title = ax.set_title("Chapter 23: GGX's lobe widens and flattens as the roughness grows", loc="left")
        legend = ax.legend(loc="upper right", fontsize=9.5, frameon=False)
    title.set_gid("title")
    ax.xaxis.label.set_gid("x-axis-label")
    ax.yaxis.label.set_gid("y-axis-label")
    legend.set_gid("legend")
    figure.tight_layout()
    print_svg(plt, figure, "book/diagrams/23_ggx_lobe.py")


if __name__ == "__main__":
    main()
