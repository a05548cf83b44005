"""Chapter 23f: what the split sum gets wrong, drawn with matplotlib when the book is built.

A floor (n straight up) of white metal (F0 = 1) under the chapter's sky without
its sun: sky() of shaders/23_materials/sky.comp, its colours read from the
shader and reduced to luminance (Rec. 709 weights). For each view (n.v) and
roughness, the specular light the floor sends towards v, two ways:

- brute force: the sky times the BRDF times n.l, summed over GGX half
  vectors as environment() in shaders/23_materials/pbr.glsl sums a uniform
  sky (each sample weighs 4 V n.l v.h / n.h, Fresnel 1), with the sky's
  formula read in the sample's direction l;
- the split sum: the prefiltered sky at r, as prefilter.comp makes it (the
  lobe seen head on, n = v = r, samples weighted by n.l), times A + B, as
  split_sum_lut in pbr.glsl makes the table.

The same GGX (distribution_ggx), Smith V (visibility_smith), Hammersley points
and alpha = max(roughness^2, 0.001) as the shaders; the script exits if they
no longer say the lines it reproduces. Both sides read the formula directly,
with many samples, at the exact roughness: no cube map, no mip levels, no
blend between levels, so the figure shows the approximation alone. The
points are Hammersley's, so every build draws the same figure.

Left, the two sides against n.v for three roughnesses; right, the split sum's
error in percent over n.v and roughness. book/23f_ibl_accuracy.md quotes
numbers this script computes; a page that no longer agrees stops the build.
Prints the SVG; text stays text (ids title, x-axis-label, y-axis-label,
legend, as the book's other charts). With VKT_DIAGRAM_LAYOUT=narrow (the
builder asks for it, for phones) the panels stand one above the other.
Needs python3-matplotlib (and numpy, which it brings).
"""

import os
import re
import sys
from pathlib import Path

import numpy as np

from charts import print_svg, pyplot  # book/diagrams/charts.py

ROOT = Path(__file__).resolve().parents[2]
SHADERS = ROOT / "shaders" / "23_materials"
PAGE = ROOT / "book" / "23f_ibl_accuracy.md"
SAMPLES = 8192  # per point, both sides; 65536 moves no error on the map by 0.7 points or more
LUMINANCE = np.array([0.2126, 0.7152, 0.0722])

# What this script reproduces, as the shaders say it (whitespace folded).
SHADER_LINES = {
    "pbr.glsl": [
        "return a2 / (PI * d * d);",
        "float gv = n_dot_l * sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2);",
        "float gl = n_dot_v * sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2);",
        "return sum > 0.0 ? 0.5 / sum : 0.0;",
        "float cos_h = sqrt((1.0 - u.x) / (1.0 + (alpha * alpha - 1.0) * u.x));",
        "float alpha = max(roughness * roughness, 1e-3);",
        "float n_dot_l = 2.0 * v_dot_h * cos_h - n_dot_v;",
        "if (n_dot_l <= 0.0 || v_dot_h <= 0.0) continue;",
        "float g = visibility_smith(n_dot_l, n_dot_v, alpha) * (4.0 * n_dot_l * v_dot_h / cos_h);",
    ],
    "prefilter.comp": [
        "mat3 frame = frame_towards(n, n);",
        "vec3 l = 2.0 * cos_h * h - n;",
        "if (n_dot_l <= 0.0) continue;",
        "* n_dot_l; weight += n_dot_l;",
        "imageStore(target, p, vec4(sum / weight, 1.0));",
    ],
    "sky.comp": [
        "vec3 colour = d.y >= 0.0 ? mix(horizon, zenith, sqrt(d.y)) "
        ": mix(0.5 * horizon, ground, smoothstep(0.0, 0.15, -d.y));",
    ],
}


def check_shaders() -> None:
    for name, lines in SHADER_LINES.items():
        code = " ".join((SHADERS / name).read_text(encoding="utf-8").split())
        for want in lines:
            if want not in code:
                raise SystemExit(f"shaders/23_materials/{name}: no longer says `{want[:60]}`; "
                                 "redraw book/diagrams/23f_split_sum_error.py")


def sky_colours() -> dict[str, float]:
    """The luminance of sky.comp's zenith, horizon and ground colours."""
    code = (SHADERS / "sky.comp").read_text(encoding="utf-8")
    out = {}
    for name in ("zenith", "horizon", "ground"):
        found = re.search(rf"\b{name}\s*=\s*vec3\(([^)]*)\)", code)
        if not found:
            raise SystemExit(f"shaders/23_materials/sky.comp: no colour `{name} = vec3(...)`; "
                             "redraw book/diagrams/23f_split_sum_error.py")
        out[name] = float(np.array([float(x) for x in found.group(1).split(",")]) @ LUMINANCE)
    return out


SKY = sky_colours()


def sky(y):
    """sky() of sky.comp without its sun, as luminance, for directions whose up component is y."""
    t = np.clip(-y / 0.15, 0.0, 1.0)
    below = 0.5 * SKY["horizon"] + (SKY["ground"] - 0.5 * SKY["horizon"]) * t * t * (3.0 - 2.0 * t)
    above = SKY["horizon"] + (SKY["zenith"] - SKY["horizon"]) * np.sqrt(np.maximum(y, 0.0))
    return np.where(y >= 0.0, above, below)


def hammersley(count: int):
    i = np.arange(count, dtype=np.uint32)
    bits = (i << 16) | (i >> 16)
    bits = ((bits & 0x55555555) << 1) | ((bits & 0xAAAAAAAA) >> 1)
    bits = ((bits & 0x33333333) << 2) | ((bits & 0xCCCCCCCC) >> 2)
    bits = ((bits & 0x0F0F0F0F) << 4) | ((bits & 0xF0F0F0F0) >> 4)
    bits = ((bits & 0x00FF00FF) << 8) | ((bits & 0xFF00FF00) >> 8)
    return (i + 0.5) / count, bits.astype(np.float64) * 2.3283064365386963e-10


U, W = hammersley(SAMPLES)


def visibility_smith(n_dot_l, n_dot_v, alpha):
    a2 = alpha * alpha
    gv = n_dot_l * np.sqrt(n_dot_v * n_dot_v * (1.0 - a2) + a2)
    gl = n_dot_v * np.sqrt(n_dot_l * n_dot_l * (1.0 - a2) + a2)
    total = gv + gl
    return np.where(total > 0.0, 0.5 / np.maximum(total, 1e-30), 0.0)


def both_sides(n_dot_v: float, roughness: float) -> tuple[float, float]:
    """(brute force, split sum) for the floor seen at n.v, at one roughness.

    Frame: n = (0, 0, 1) is up, so a direction's up component is its z;
    v = (sin, 0, n.v) and r = reflect(-v, n) = (-sin, 0, n.v)."""
    alpha = max(roughness * roughness, 1e-3)
    phi = 2.0 * np.pi * W
    cos_h = np.sqrt((1.0 - U) / (1.0 + (alpha * alpha - 1.0) * U))
    sin_h = np.sqrt(np.maximum(0.0, 1.0 - cos_h * cos_h))
    hx, hz = sin_h * np.cos(phi), cos_h
    sin_v = np.sqrt(1.0 - n_dot_v * n_dot_v)
    # Brute force: h around n, l = 2 (v.h) h - v.
    v_dot_h = sin_v * hx + n_dot_v * hz
    n_dot_l = 2.0 * v_dot_h * cos_h - n_dot_v
    kept = (n_dot_l > 0.0) & (v_dot_h > 0.0)
    g = np.where(kept, visibility_smith(np.maximum(n_dot_l, 0.0), n_dot_v, alpha) *
                 4.0 * n_dot_l * v_dot_h / cos_h, 0.0)
    brute = float(np.sum(sky(n_dot_l) * g)) / SAMPLES
    a_plus_b = float(np.sum(g)) / SAMPLES  # the table's A + B: F0 = 1
    # The split sum's first factor: h around r, l = 2 (r.h) h - r, weighted by r.l; the sky
    # reads l's up component. The frame's first axis is (n.v, 0, sin), in the vertical plane
    # (prefilter.comp's frame_towards picks another; the lobe is round, so only the pattern turns).
    up_of_h = hx * sin_v + hz * n_dot_v
    up_of_l = 2.0 * cos_h * up_of_h - n_dot_v
    r_dot_l = 2.0 * cos_h * cos_h - 1.0
    weight = np.where(r_dot_l > 0.0, r_dot_l, 0.0)
    prefiltered = float(np.sum(sky(up_of_l) * weight) / np.sum(weight))
    return brute, prefiltered * a_plus_b


def error_percent(n_dot_v: float, roughness: float) -> float:
    brute, split = both_sides(n_dot_v, roughness)
    return 100.0 * (split - brute) / brute


def main() -> None:
    check_shaders()
    check_page()
    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    plt = pyplot("split sum's error", title_size=11 if narrow else 12)
    from matplotlib.lines import Line2D
    if narrow:
        figure, (left, right) = plt.subplots(2, 1, figsize=(4.4, 10.4), layout="constrained",
                                             height_ratios=(1.0, 1.1))
    else:
        figure, (left, right) = plt.subplots(1, 2, figsize=(10.8, 5.0), layout="constrained")
    xs = np.linspace(0.02, 1.0, 50)
    roughnesses = np.linspace(0.0, 1.0, 26)  # steps of 0.04: the rows 0.2, 0.6 and 1 are the lines
    sides = np.array([[both_sides(x, r) for x in xs] for r in roughnesses])

    # Left: the two sides for three roughnesses, colour the roughness, dashes the split sum.
    colours = {0.2: "#0969da", 0.6: "#8250df", 1.0: "#cf222e"}
    for roughness, colour in colours.items():
        row = sides[int(round(roughness / 0.04))]
        left.plot(xs, row[:, 0], color=colour, linewidth=2.2)
        left.plot(xs, row[:, 1], color=colour, linewidth=1.6, linestyle="--")
    handles = [Line2D([], [], color=c, linewidth=2.2, label=f"roughness {r:.1f}") for r, c in colours.items()]
    handles += [Line2D([], [], color="#59636e", linewidth=2.2, label="brute force"),
                Line2D([], [], color="#59636e", linewidth=1.6, linestyle="--", label="split sum")]
    left.set_xlim(0, 1)
    left.set_ylim(0, 0.25)
    left.set_xlabel("n·v: 0 grazing, 1 head on")
    left.set_ylabel("specular light from the floor")
    left.set_title("Both sides", loc="left")
    legend = left.legend(handles=handles, loc="upper right", fontsize=9, frameon=False, ncol=2)
    legend.set_gid("legend")
    left.xaxis.label.set_gid("x-axis-label")
    left.yaxis.label.set_gid("y-axis-label")

    # Right: the split sum's error over n.v and roughness.
    grid = 100.0 * (sides[:, :, 1] - sides[:, :, 0]) / sides[:, :, 0]
    limit = 30.0
    right.grid(False)
    image = right.pcolormesh(xs, roughnesses, grid, cmap="RdBu", vmin=-limit, vmax=limit, shading="gouraud",
                             rasterized=True)
    lines = right.contour(xs, roughnesses, grid, levels=[-20, -10, -5], colors="#24292f", linewidths=0.9)
    right.clabel(lines, fmt=lambda v: f"{v:.0f}%", fontsize=9)
    right.set_xlim(xs[0], 1)  # the map starts where its samples do
    right.set_xlabel("n·v: 0 grazing, 1 head on")
    right.set_ylabel("roughness")
    right.set_title("The split sum's error", loc="left")
    bar = figure.colorbar(image, ax=right, orientation="horizontal" if narrow else "vertical",
                          shrink=0.9, pad=0.02)
    bar.set_label("split sum against brute force, %\n(red: too dark, blue: too bright)")

    title = figure.suptitle("Chapter 23f: a white metal floor under\nthe chapter's sky, the split sum against\nbrute force"
                            if narrow else "Chapter 23f: a white metal floor under the chapter's sky, "
                            "the split sum against brute force",
                            x=0.02, ha="left", fontsize=11 if narrow else 12.5)
    title.set_gid("title")
    print_svg(plt, figure, "book/diagrams/23f_split_sum_error.py")


def off(percent: float) -> str:
    """'27% too dark' or '3% too bright'."""
    return f"{abs(percent):.0f}% too {'dark' if percent < 0 else 'bright'}"


def quoted() -> dict[str, str]:
    """The phrases book/23f_ibl_accuracy.md must say, computed here."""
    grazing = error_percent(0.05, 1.0)
    head_on = error_percent(1.0, 1.0)
    smooth = max(abs(error_percent(x, r)) for r in np.linspace(0.0, 0.2, 6) for x in np.linspace(0.1, 1.0, 19))
    return {
        f"{off(grazing)} at n·v = 0.05 and roughness 1": "the rough floor at a grazing view",
        f"within {smooth:.1f}% wherever the roughness is 0.2 or less and n·v at least 0.1":
            "the smooth floor",
        f"{off(head_on)} even head on": "the rough floor head on",
    }


def check_page() -> None:
    """The page's numbers, as this script computes them; a page that disagrees stops the build."""
    text = " ".join(PAGE.read_text(encoding="utf-8").split())
    for phrase, what in quoted().items():
        if phrase not in text:
            sys.exit(f"book/23f_ibl_accuracy.md: {what}: the page should say '{phrase}' "
                     "(book/diagrams/23f_split_sum_error.py computes it)")


if __name__ == "__main__":
    if sys.argv[1:] == ["--numbers"]:
        check_shaders()
        for phrase in quoted():
            print(phrase)
    else:
        main()
