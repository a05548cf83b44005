"""Chapter 23: the tone curves, drawn with matplotlib when the book is built.

The ACES fit (Krzysztof Narkowicz, 2015) that shaders/23_materials/pbr.glsl
and common/scene/include/vkt/scene/pbr.hpp use, against cutting at 1 (the
chapter's --tone-map clamp) and Reinhard's x / (1 + x) for comparison, over
exposed radiance from 1/64 to 64 on a logarithmic axis. Prints the SVG; text
stays text (the ids title, x-axis-label, y-axis-label and legend, as the
book's other charts). With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for
it, for phones) a narrower chart, its legend below and its ticks plain
fractions. Needs python3-matplotlib (scripts/install-deps.sh).
"""

import os


from charts import print_svg, pyplot  # book/diagrams/charts.py


def aces(x: float) -> float:  # the same numbers as aces_narkowicz in pbr.glsl
    x = max(x, 0.0)
    return min(1.0, max(0.0, (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)))


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    plt = pyplot("tone curve", title_size=11 if narrow else 12.5)
    xs = [2 ** (i / 32) for i in range(-6 * 32, 6 * 32 + 1)]
    figure, ax = plt.subplots(figsize=(4.2, 6.0) if narrow else (8.4, 5.0))
    ax.plot(xs, [aces(x) for x in xs], color="#cf222e", linewidth=2.4,
            label="ACES, Narkowicz's fit (--tone-map aces)")
    ax.plot(xs, [min(x, 1.0) for x in xs], color="#0969da", linewidth=1.8, linestyle="--",
            label="clamp at 1 (--tone-map clamp)")
    ax.plot(xs, [x / (1 + x) for x in xs], color="#59636e", linewidth=1.5, linestyle=":",
            label="Reinhard, x / (1 + x), for comparison")
    ax.plot([1.0], [aces(1.0)], "o", color="#cf222e")
    ax.annotate(f"radiance 1 → {aces(1.0):.2f}", xy=(1.0, aces(1.0)), xytext=(8, -18),
                textcoords="offset points", fontsize=10)
    ax.set_xscale("log", base=2)
    ax.set_xlim(xs[0], xs[-1])
    ax.set_ylim(0, 1.05)
    if narrow:  # plain tick labels: a log axis's superscripts are too small on a phone
        ticks = [2.0 ** e for e in range(-6, 7, 2)]
        ax.set_xticks(ticks, [f"1/{round(1 / t)}" if t < 1 else f"{t:g}" for t in ticks])
        ax.minorticks_off()
        ax.set_xlabel("exposed radiance (log scale)")
        ax.set_ylabel("value written, before sRGB")
        title = ax.set_title("Chapter 23: the tone curve\nmaps any radiance into 0..1", loc="left")
        legend = ax.legend(loc="upper center", fontsize=9.5, frameon=False, bbox_to_anchor=(0.42, -0.14))
    else:
        ax.set_xlabel("exposed radiance: radiance × 2^exposure (log scale)")
        ax.set_ylabel("value written, before sRGB encoding")
        title = ax.set_title("Chapter 23: the tone curve maps any radiance into 0..1", loc="left")
        legend = ax.legend(loc="upper left", fontsize=9.5, frameon=False)
    title.set_gid("title")
    ax.xaxis.label.set_gid("x-axis-label")
    ax.yaxis.label.set_gid("y-axis-label")
    legend.set_gid("legend")
    figure.tight_layout()
    print_svg(plt, figure, "book/diagrams/23_tone_curve.py")


if __name__ == "__main__":
    main()
