"""Chapter 23f: the two lobes at a grazing view, seen from the side, drawn with matplotlib when the book is built.

The white metal floor of 23f_split_sum_error.py (n up, F0 = 1) seen at
n.v = 0.05 and roughness 1, where book/23f_ibl_accuracy.md quotes the split
sum's worst error. A cross-section in the plane of n and v of two lobes over
the light directions l, each drawn as a polar curve, its distance from the
point on the floor the weight per steradian:

- brute force: the integrand that multiplies the sky, D V n.l (Fresnel 1),
  zero below the horizon;
- the split sum: prefilter.comp's lobe around r, seen head on (n = v = r):
  D(r.h) r.l, made to hold the same total as the brute-force lobe (A + B),
  since the split sum multiplies its mean by A + B.

D is distribution_ggx of 23_ggx_lobe.py, V visibility_smith and sky() those of
23f_split_sum_error.py (imported, not copied); the background is sky()'s
luminance in the direction of each spot seen from the point, bright just
above the horizon and dark in the ground. The totals
and the share of the split sum's lobe below the horizon are integrated here
over the sphere. Prints the SVG; text stays text (ids title and legend). With
VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) a narrower
figure, its legend below. Needs python3-matplotlib (and numpy).
"""

import importlib
import os

import numpy as np

from charts import print_svg, pyplot  # book/diagrams/charts.py

error = importlib.import_module("23f_split_sum_error")  # visibility_smith, sky
lobe = importlib.import_module("23_ggx_lobe")  # distribution_ggx

N_DOT_V = 0.05
ROUGHNESS = 1.0
ALPHA = max(ROUGHNESS * ROUGHNESS, 1e-3)
SIN_V = np.sqrt(1.0 - N_DOT_V * N_DOT_V)
V = np.array([SIN_V, 0.0, N_DOT_V])  # towards the eye, on the right
R = np.array([-SIN_V, 0.0, N_DOT_V])  # reflect(-v, n), on the left


def brute(l):
    """D V n.l for light directions l (..., 3), n = (0, 0, 1): the integrand that weighs the sky."""
    n_dot_l = l[..., 2]
    h = l + V
    h = h / np.linalg.norm(h, axis=-1, keepdims=True)
    d = lobe.distribution_ggx(h[..., 2], ALPHA)
    vis = error.visibility_smith(np.maximum(n_dot_l, 0.0), N_DOT_V, ALPHA)
    return np.where(n_dot_l > 0.0, d * vis * n_dot_l, 0.0)


def prefiltered(l):
    """prefilter.comp's weight around r, unscaled: D(r.h) r.l, with n = v = r."""
    r_dot_l = l @ R
    h = l + R
    h = h / np.maximum(np.linalg.norm(h, axis=-1, keepdims=True), 1e-12)
    d = lobe.distribution_ggx(h @ R, ALPHA)
    return np.where(r_dot_l > 0.0, d * r_dot_l, 0.0)


def sphere(count: int = 720):
    """Directions over the whole sphere and the solid angle each stands for (midpoint rule)."""
    theta = (np.arange(count) + 0.5) * np.pi / count
    phi = (np.arange(2 * count) + 0.5) * np.pi / count
    t, p = np.meshgrid(theta, phi, indexing="ij")
    dirs = np.stack([np.sin(t) * np.cos(p), np.sin(t) * np.sin(p), np.cos(t)], axis=-1)
    return dirs, np.sin(t) * (np.pi / count) ** 2


def main() -> None:
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    dirs, area = sphere()
    total = float(np.sum(brute(dirs) * area))  # A + B
    split_scale = total / float(np.sum(prefiltered(dirs) * area))
    below = float(np.sum(np.where(dirs[..., 2] < 0.0, prefiltered(dirs), 0.0) * area)
                  / np.sum(prefiltered(dirs) * area))

    plt = pyplot("grazing lobes", plain_axes=False, title_size=11 if narrow else 12.5)
    from matplotlib.lines import Line2D
    figure, ax = plt.subplots(figsize=(4.4, 4.0) if narrow else (7.6, 4.6), layout="constrained")

    # Behind the lobes, sky()'s luminance in the direction of each spot as seen from the point.
    extent = (-0.33, 0.24, -0.17, 0.20)
    xs, ys = np.meshgrid(np.linspace(extent[0], extent[1], 456), np.linspace(extent[2], extent[3], 296))
    up = ys / np.maximum(np.hypot(xs, ys), 1e-9)  # the direction's up component
    ax.imshow(error.sky(up), extent=extent, origin="lower", aspect="auto", cmap="Greys_r",
              vmin=0.0, vmax=0.35, interpolation="bilinear")

    # The two lobes in the plane of n and v: l = (sin a, 0, cos a), a from n.
    angles = np.linspace(-np.pi, np.pi, 1441)
    plane = np.stack([np.sin(angles), np.zeros_like(angles), np.cos(angles)], axis=-1)
    for weights, colour, dash in ((brute(plane), "#e69f00", "-"),
                                  (prefiltered(plane) * split_scale, "#56b4e9", "--")):
        ax.plot(weights * plane[:, 0], weights * plane[:, 2], color=colour, linewidth=2.6, linestyle=dash)

    ax.axhline(0.0, color="#f6f8fa", linewidth=1.0)
    arrow = dict(arrowstyle="-|>", color="#ffffff", linewidth=1.4, mutation_scale=12)
    for name, (x, z), where in (("n", (0.0, 0.17), (0.008, 0.15)), ("v", 0.22 * V[[0, 2]], (0.2, 0.022)),
                                ("r", 0.31 * R[[0, 2]], (-0.31, 0.024))):
        ax.annotate("", xy=(x, z), xytext=(0.0, 0.0), arrowprops=arrow)
        ax.text(*where, name, color="#ffffff", fontsize=12, fontweight="bold")
    ax.text(0.235, -0.008, "horizon", color="#f6f8fa", fontsize=10, ha="right", va="top")
    ax.text(0.235, -0.16, "dark ground", color="#d0d7de", fontsize=10, ha="right", va="bottom")
    ax.text(-0.30, -0.145, f"{100 * below:.0f}% of the dashed\nlobe lies below the horizon",
            color="#ffffff", fontsize=10, va="bottom")
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])

    handles = [Line2D([], [], color="#e69f00", linewidth=2.6, label="brute force: D V n·l"),
               Line2D([], [], color="#56b4e9", linewidth=2.6, linestyle="--",
                      label="split sum: the prefilter's lobe around r,\nscaled to the same total")]
    legend = ax.legend(handles=handles, loc="upper center", bbox_to_anchor=(0.5, -0.01), ncol=1 if narrow else 2,
                       frameon=False, fontsize=10)
    legend.set_gid("legend")
    title = figure.suptitle("Chapter 23f: the floor seen at n·v = 0.05,\nroughness 1, from the side"
                            if narrow else "Chapter 23f: the floor seen at n·v = 0.05, roughness 1, from the side",
                            x=0.02, ha="left", fontsize=11 if narrow else 12.5)
    title.set_gid("title")
    print_svg(plt, figure, "book/diagrams/23f_grazing_lobes.py")


if __name__ == "__main__":
    main()
