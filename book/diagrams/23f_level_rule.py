"""Chapter 23f: the level rule of filtered importance sampling, worked for two samples.

The prefilter's level for roughness 0.2 (the cube's level 1): two of its
Environment::specular_samples samples, the first (its half vector almost
along n) and one in the lobe's tail, each followed from its angle to the sky
level it reads. The numbers are computed when the book is built by running the
shader's own lines: source_lod() from shaders/23_materials/cube.glsl's
[source-lod] region and distribution_ggx() from pbr.glsl, statement by
statement, with the half vector of prefilter.comp (ggx_sampling.py), the sample
count and the sky's size read from environment.hpp. A line this cannot run, or
a prefilter.comp that no longer passes D / 4 as the density, stops the build.

With VKT_DIAGRAM_LAYOUT=narrow (the builder asks for it, for phones) the table
is 400 units wide, its labels on two lines.
"""

import math
import os
import re
import sys
from pathlib import Path
from types import SimpleNamespace

from ggx_sampling import ggx_half_vector  # book/diagrams/ggx_sampling.py
from svg import BLUE, MUTED, ORANGE, Svg

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))
from source_constants import constant  # noqa: E402  (book/, above this folder)

ROOT = Path(__file__).resolve().parents[2]
SHADERS = ROOT / "shaders" / "23_materials"
ENVIRONMENT_HPP = ROOT / "chapters" / "23_materials" / "environment.hpp"
SAMPLES = int(constant(ENVIRONMENT_HPP, "specular_samples"))
SKY_SIZE = int(constant(ENVIRONMENT_HPP, "sky_size"))
SKY_LEVELS = int(constant(ENVIRONMENT_HPP, "sky_levels"))
LEVELS = int(constant(ENVIRONMENT_HPP, "specular_levels"))
LEVEL = 1  # the prefiltered cube's level: roughness 1 / (LEVELS - 1)
PICKED = (0, 120)  # the first sample, and one in the tail (book/23f_ibl_accuracy.md names both)

# What prefilter.comp must still say for this to be its rule (whitespace folded).
PREFILTER_LINES = [
    "float alpha = max(params.roughness * params.roughness, 1e-3);",
    "float pdf = distribution_ggx(cos_h, alpha) / 4.0;",
    "textureLod(source, l, source_lod(pdf, params.samples))",
]


def glsl_function(path: Path, name: str, params: object):
    """A Python function that runs the GLSL function NAME of PATH line by line."""
    text = path.read_text(encoding="utf-8")
    match = re.search(r"\bfloat\s+" + name + r"\s*\(([^)]*)\)\s*\{(.*?)\n\}", text, re.S)
    where = f"shaders/23_materials/{path.name}: {name}()"
    if not match:
        raise SystemExit(f"{where} not found; redraw book/diagrams/23f_level_rule.py")
    arguments = [a.split()[-1] for a in match.group(1).split(",")]
    body = " ".join(line.split("//", 1)[0] for line in match.group(2).splitlines())
    statements = [s.strip() for s in body.split(";") if s.strip()]
    scope = {"PI": math.pi, "log2": math.log2, "max": max, "min": min, "float": float, "params": params}

    def run(*values):
        local = dict(zip(arguments, values))
        for statement in statements:
            declared = re.fullmatch(r"float\s+([A-Za-z_]\w*)\s*=\s*(.+)", statement)
            try:
                if declared:
                    local[declared.group(1)] = eval(declared.group(2), scope, local)
                elif statement.startswith("return "):
                    return eval(statement[len("return "):], scope, local)
                else:
                    raise SyntaxError("not a declaration or a return")
            except Exception as error:  # one line naming the statement
                raise SystemExit(f"{where}: cannot run `{statement}` ({error}); "
                                 "redraw book/diagrams/23f_level_rule.py")
        raise SystemExit(f"{where}: no return")
    return run


def sci(value: float) -> str:
    """Three significant digits, written out (no superscripts: they would be the smallest text)."""
    digits = max(0, 2 - math.floor(math.log10(abs(value))))
    return f"{value:.{digits}f}"


def main() -> None:
    prefilter = " ".join((SHADERS / "prefilter.comp").read_text(encoding="utf-8").split())
    for want in PREFILTER_LINES:
        if want not in prefilter:
            raise SystemExit(f"shaders/23_materials/prefilter.comp: no longer says `{want}`; "
                             "redraw book/diagrams/23f_level_rule.py")
    params = SimpleNamespace(source_size=float(SKY_SIZE))
    source_lod = glsl_function(SHADERS / "cube.glsl", "source_lod", params)
    distribution_ggx = glsl_function(SHADERS / "pbr.glsl", "distribution_ggx", params)

    # The extra blur, as source_lod's return line says it: `log2(...) + 1.0`.
    cube = " ".join((SHADERS / "cube.glsl").read_text(encoding="utf-8").split())
    extra = re.search(r"return max\(0\.5 \* log2\(sample_angle / texel_angle\) \+ ([0-9.]+), 0\.0\);", cube)
    if not extra:
        raise SystemExit("shaders/23_materials/cube.glsl: source_lod() no longer returns "
                         "max(0.5 * log2(sample_angle / texel_angle) + K, 0.0); redraw book/diagrams/23f_level_rule.py")
    extra = float(extra.group(1))
    roughness = LEVEL / (LEVELS - 1)
    alpha = max(roughness * roughness, 1e-3)
    texel = 4.0 * math.pi / (6.0 * SKY_SIZE * SKY_SIZE)
    columns = []
    for i in PICKED:
        cos_h = ggx_half_vector(i, SAMPLES, alpha)[2]
        d = distribution_ggx(cos_h, alpha)
        pdf = d / 4.0
        patch = 1.0 / (SAMPLES * pdf)
        lod = source_lod(pdf, SAMPLES)
        # The same number the long way round, step by step, as the table shows it.
        by_hand = max(0.5 * math.log2(patch / texel) + extra, 0.0)
        if abs(by_hand - lod) > 1e-9:
            raise SystemExit(f"source_lod gives {lod} where the table's steps give {by_hand}: "
                             "redraw book/diagrams/23f_level_rule.py")
        reads = min(lod, SKY_LEVELS - 1)
        columns.append([
            f"{math.degrees(math.acos(cos_h)):.2f}°",
            f"{d:.3g}",
            f"{pdf:.3g}",
            f"{sci(patch)}",
            f"{sci(texel)}",
            f"{patch / texel:.3g}",
            f"{0.5 * math.log2(patch / texel):.2f}",
            f"{lod:.2f}",
            f"{math.floor(reads)} and {math.floor(reads) + 1}" if reads < SKY_LEVELS - 1 else f"{SKY_LEVELS - 1}",
        ])
    rows = [  # (what, how): one line on a wide screen, two on a phone
        ("h's angle from n", ""),
        ("D(n·h):", "GGX's density of h"),
        ("pdf = D / 4:", "the density of l, per sr"),
        ("the sample's patch:", f"1 / ({SAMPLES} · pdf), in sr"),
        ("a texel of the sky's level 0:", f"4π / (6 · {SKY_SIZE}²), in sr"),
        ("patch / texel", ""),
        ("levels up, ½ log₂ of that:", "each level's texel is 4 times larger"),
        (f"+ {extra:g}, at least 0:", "source_lod's level"),
        ("the two levels it blends", ""),
    ]

    narrow = os.environ.get("VKT_DIAGRAM_LAYOUT") == "narrow"
    size = 12 if narrow else 13
    width = 400 if narrow else 740
    label_w = 200 if narrow else 420
    col_w = (width - label_w - 16) / 2
    row_h = (2 * size * 1.25 + 8) if narrow else (size * 1.25 + 16)
    top = 104 if narrow else 90
    title = f"Chapter 23f: which sky level two samples read, roughness {roughness:.1f}"
    description = (f"A table worked from the shader's own lines for the prefiltered cube's level {LEVEL} "
                   f"(roughness {roughness:.1f}, {SAMPLES} samples, a sky of {SKY_SIZE} texels a side). "
                   "Two columns: sample 0, whose half vector lies almost along n, and sample "
                   f"{PICKED[1]}, in the lobe's tail. Rows: the angle, GGX's D, the density D / 4, "
                   "the patch of sphere the sample stands for, one texel of the sky's level 0, their "
                   "ratio, half its log base 2, then plus one: the level source_lod returns, and the "
                   "two levels the sampler blends. Sample 0's patch is about one texel, so it reads "
                   "just above level 1; the tail sample's patch is hundreds of texels, so it reads "
                   "level 5 or so.")
    s = Svg(width, top + row_h * len(rows) + (52 if narrow else 30), title, description)
    if narrow:
        s.lines(8, 18, [f"Roughness {roughness:.1f} (the cube's level {LEVEL}),",
                        f"{SAMPLES} samples, a {SKY_SIZE}-texel sky:",
                        "which level two samples read"], size=size + 0.5, bold=True)
    else:
        s.lines(8, 20, [f"Roughness {roughness:.1f} (the cube's level {LEVEL}), {SAMPLES} samples, "
                        f"a sky of {SKY_SIZE} texels a side:", "which level of the sky two samples read"],
                size=size + 1, bold=True)
    heads = [(f"sample {PICKED[0]}", "near n", BLUE), (f"sample {PICKED[1]}", "in the tail", ORANGE)]
    for c, (head, sub, colour) in enumerate(heads):
        x = label_w + 8 + col_w * (c + 0.5)
        s.text(x, top - 24 if not narrow else top - 20, head, size=size, anchor="middle", bold=True, fill=colour)
        s.text(x, top - 8 if not narrow else top - 6, sub, size=size - 1, anchor="middle", fill=MUTED)
    for r, label in enumerate(rows):
        y = top + r * row_h
        if r % 2 == 0:
            s.rect(4, y, width - 8, row_h, fill="#f6f8fa", stroke="none")
        base = y + size + 4
        what, how = label
        if narrow:
            s.text(10, base + (0 if how else size * 0.6), what, size=size - 0.5)
            if how:
                s.text(10, base + size * 1.25, how, size=size - 0.5, fill=MUTED)
        else:
            s.text(10, base + 3, what + (" " + how if how else ""), size=size)
        for c, column in enumerate(columns):
            s.text(label_w + 8 + col_w * (c + 0.5), base + (size * 0.6 if narrow else 3), column[r],
                   size=size, anchor="middle", fill=BLUE if c == 0 else ORANGE,
                   bold=(r == 7))
    foot = top + row_h * len(rows) + 18
    s.lines(8, foot, ["computed by source_lod() in shaders/23_materials/cube.glsl,", "run line by line"]
            if narrow else ["computed by source_lod() in shaders/23_materials/cube.glsl, run line by line"],
            size=size - 1, fill=MUTED)
    s.write()


if __name__ == "__main__":
    main()
