"""Chapter 23: the split sum's BRDF table, drawn with matplotlib when the book is built.

A and B of split_sum_lut (shaders/23_materials/pbr.glsl, and in C++
common/scene/include/vkt/scene/pbr.hpp), the same formula and the same Hammersley samples (Environment::lut_samples)
the chapter's table takes per texel, against n.v for three
roughnesses. F0 A + B is the share of the light the specular lobe reflects.
Prints the SVG; text stays text (the ids title, x-axis-label, y-axis-label and
legend, as the book's other charts). Needs python3-matplotlib (and numpy,
which it brings). With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for
phones) a narrower chart, its legend below.
"""

import os
import sys
from pathlib import Path

from charts import print_svg, pyplot  # book/diagrams/charts.py

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ENVIRONMENT_HPP = Path(__file__).resolve().parents[2] / "chapters" / "23_materials" / "environment.hpp"
SAMPLES = int(constant(ENVIRONMENT_HPP, "lut_samples"))  # Environment::lut_samples


def hammersley(count: int):
    import numpy as np
    i = np.arange(count, dtype=np.uint32)
    bits = i.copy()
    bits = (bits << 16) | (bits >> 16)
    bits = ((bits & 0x55555555) << 1) | ((bits & 0xAAAAAAAA) >> 1)
    bits = ((bits & 0x33333333) << 2) | ((bits & 0xCCCCCCCC) >> 2)
    bits = ((bits & 0x0F0F0F0F) << 4) | ((bits & 0xF0F0F0F0) >> 4)
    bits = ((bits & 0x00FF00FF) << 8) | ((bits & 0xFF00FF00) >> 8)
    return (i + 0.5) / count, bits.astype(np.float64) * 2.3283064365386963e-10


def split_sum(n_dot_v: float, roughness: float) -> tuple[float, float]:
    import numpy as np
    u, w = hammersley(SAMPLES)
    alpha = max(roughness * roughness, 1e-3)
    phi = 2 * np.pi * w
    cos_h = np.sqrt((1 - u) / (1 + (alpha * alpha - 1) * u))
    sin_h = np.sqrt(np.maximum(0, 1 - cos_h * cos_h))
    v = np.array([np.sqrt(1 - n_dot_v * n_dot_v), 0.0, n_dot_v])
    v_dot_h = v[0] * sin_h * np.cos(phi) + v[2] * cos_h
    n_dot_l = 2 * v_dot_h * cos_h - n_dot_v
    ok = (n_dot_l > 0) & (v_dot_h > 0)
    a2 = alpha * alpha
    gv = n_dot_l * np.sqrt(n_dot_v * n_dot_v * (1 - a2) + a2)
    gl = n_dot_v * np.sqrt(n_dot_l * n_dot_l * (1 - a2) + a2)
    visibility = np.where(gv + gl > 0, 0.5 / np.maximum(gv + gl, 1e-30), 0)
    g = np.where(ok, visibility * 4 * n_dot_l * v_dot_h / cos_h, 0)
    fc = np.clip(1 - v_dot_h, 0, 1) ** 5
    return float(np.sum((1 - fc) * g) / SAMPLES), float(np.sum(fc * g) / SAMPLES)


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    plt = pyplot("BRDF table", title_size=11 if narrow else 12.5)
    xs = [(i + 0.5) / 64 for i in range(64)]
    figure, ax = plt.subplots(figsize=(4.2, 6.0) if narrow else (8.4, 5.0))
    for roughness, colour in ((0.2, "#0969da"), (0.6, "#8250df"), (1.0, "#cf222e")):
        table = [split_sum(x, roughness) for x in xs]
        ax.plot(xs, [a for a, _ in table], color=colour, linewidth=2.2,
                label=f"A, roughness {roughness:.1f}")
        ax.plot(xs, [b for _, b in table], color=colour, linewidth=1.6, linestyle="--",
                label=f"B, roughness {roughness:.1f}")
    ax.set_xlim(0, 1)
    ax.set_ylim(0, 1.05)
    ax.set_xlabel("n·v: 0 grazing, 1 head on")
    ax.set_ylabel("A (scale on F0) and B (bias)")
    if narrow:
        title = ax.set_title("Chapter 23: the BRDF table;\nthe specular lobe reflects F0 A + B", loc="left")
        legend = ax.legend(loc="upper center", fontsize=9.5, frameon=False, ncol=2,
                           bbox_to_anchor=(0.42, -0.14))
    else:
        title = ax.set_title("Chapter 23: the BRDF table; the specular lobe reflects F0 A + B",
                             loc="left")
        legend = ax.legend(loc="center right", fontsize=9.5, frameon=False, ncol=2)
    title.set_gid("title")
    ax.xaxis.label.set_gid("x-axis-label")
    ax.yaxis.label.set_gid("y-axis-label")
    legend.set_gid("legend")
    figure.tight_layout()
    print_svg(plt, figure, "book/diagrams/23_brdf_table.py")


if __name__ == "__main__":
    main()
