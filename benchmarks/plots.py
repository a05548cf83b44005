#!/usr/bin/python3
"""The book's charts, drawn from the raw results in benchmarks/results/ as SVG.

    /usr/bin/python3 benchmarks/plots.py                 # every chart, into book/images/
    /usr/bin/python3 benchmarks/plots.py --out DIR       # somewhere else
    /usr/bin/python3 benchmarks/plots.py --list          # which chart comes from which files

Each chart has labelled axes with their units, logarithmic axes where the data
spans decades, a legend, the device and the date of the measurement in its
title, and the frame budgets of 60 and 144 frames a second drawn and labelled
(chart 14's instead: the real-time budget of one physics step, 1/120 s, since
the world steps at a fixed 120 steps a second whatever the frame rate; the axis widened to take in one that lies just outside the data; one far
outside is named in the legend, with the side it lies on), each label placed
where no data line passes under it. Where a case ran several times, the point
is the median of the runs' medians and a bar spans the fastest run to the
slowest; a note under the legend says which series ran once (no spread to
show) and names every point the data lacks, with the reason. The date is the
one in the results file's name, else that of the last commit that changed it. Text stays text in the SVG (searchable, and checked
by tests/book_browser.py through the ids x-axis-label, y-axis-label, legend
and title). Needs Debian's python3-matplotlib; run it with /usr/bin/python3.

The charts (CHARTS below):
  14_physics_bench.svg                   results/physics.jsonl (physics_bench)
  17_tiled_deferred_bench_lavapipe.svg   results/2026-11-27-quiet-17_tiled_deferred-lavapipe.md (bench-lights.sh --tiled)
  17_tiled_deferred_bench_h100.svg       results/17_tiled_deferred-h100.md
  20_ndim_compute_bench.svg              results/2026-11-27-quiet-{18,19,20}_*-lavapipe.txt
  29_async_sweep_h200.svg                results/h200-2026-11-29-29_async_sweep-df79176.txt
"""

from __future__ import annotations

import argparse
import json
import re
import statistics
import subprocess
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
RESULTS = HERE / "results"

# Frame budgets: a frame at 60 and at 144 frames a second, each (ms, label).
BUDGETS = [(1000.0 / 60.0, "60 fps budget: {ms:.1f} ms"),
           (1000.0 / 144.0, "144 fps budget: {ms:.1f} ms")]
# Chapter 14's world steps at a fixed 1/120 s (chapters/14_physics/main.cpp,
# kStepsPerSecond), so a step keeps up with real time below 8.3 ms at any frame rate.
PHYSICS_BUDGETS = [(1000.0 / 120.0, "real time: {ms:.1f} ms a step (120 steps/s)")]
NEAR_BUDGET = 3.0
# The book's palette (book/diagrams/svg.py): one colour per path or chapter.
RED, ORANGE, BLUE, CYAN, GREEN, GREY = "#c0362c", "#d9822b", "#1f5fbf", "#1a9bb0", "#1e7b34", "#6e7781"


@dataclass
class Chart:
    output: str                       # file name in the output folder
    inputs: list[str]                 # files under benchmarks/results/
    draw: Callable                    # draw(chart, axes) -> (device, date): fills in the axes
    options: dict = field(default_factory=dict)

    def paths(self) -> list[Path]:
        return [RESULTS / name for name in self.inputs]


# ----------------------------------------------------------------------------------------------
# Reading the results
# ----------------------------------------------------------------------------------------------

def measured_on(path: Path) -> str:
    """The date of a results file: from its name, else from the last commit that changed it
    (a file re-measured in place keeps its name; the commit that first added it would date
    the chart by the oldest run)."""
    match = re.search(r"\d{4}-\d{2}-\d{2}", path.name)
    if match:
        return match.group(0)
    try:
        run = subprocess.run(["git", "log", "-1", "--format=%cs", "--", path.name],
                             cwd=path.parent, capture_output=True, text=True, timeout=30)
        dates = run.stdout.split()
        if run.returncode == 0 and dates:
            return dates[0]
    except OSError:
        pass
    import datetime
    return datetime.date.fromtimestamp(path.stat().st_mtime).isoformat()


def number(cell: str) -> float | None:
    try:
        return float(cell.replace(",", ""))
    except ValueError:
        return None


def table_rows(path: Path) -> list[dict]:
    """The rows of a Markdown table, as {header: cell}; a file of several runs holds one
    table per run, each with the same header, and gives all their rows."""
    rows, header = [], None
    for line in path.read_text().splitlines():
        if not line.startswith("|"):
            continue
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if header is None:
            header = cells
        elif cells != header and not set("".join(cells)) <= set("-: "):
            rows.append(dict(zip(header, cells)))
    return rows


def runner_runs(path: Path) -> list[tuple[list[str], dict]]:
    """(command line, JSON) for each run in a benchmark script's raw output: a line
    "# CHAPTER ARGS..." followed by the runner's JSON line."""
    runs, header = [], None
    for line in path.read_text().splitlines():
        if line.startswith("# "):
            header = line[2:].split()
        elif line.startswith("{") and header:
            runs.append((header, json.loads(line)))
            header = None
    return runs


def short_device(name: str) -> str:
    """'llvmpipe (LLVM 15.0.6, 256 bits)' -> 'lavapipe (llvmpipe, LLVM 15.0.6)'."""
    match = re.match(r"llvmpipe \((LLVM [0-9.]+)", name)
    return f"lavapipe (llvmpipe, {match.group(1)}), 2 CPU cores" if match else name


# ----------------------------------------------------------------------------------------------
# The charts
# ----------------------------------------------------------------------------------------------

def draw_physics(chart: Chart, ax) -> tuple[str, str]:
    path = chart.paths()[0]
    rows = [json.loads(line) for line in path.read_text().splitlines() if line.strip()]
    boxes = [r["boxes"] for r in rows]
    series = [("step_brute_force_ms", "whole step, brute-force pairs", RED, "-", "o"),
              ("step_sweep_ms", "whole step, sort-and-sweep", BLUE, "-", "o"),
              ("pairs_brute_force_ms", "pair finding alone, brute force", ORANGE, "--", "s"),
              ("pairs_sweep_ms", "pair finding alone, sort-and-sweep", CYAN, "--", "s")]
    for key, label, colour, style, marker in series:
        ax.plot(boxes, [r[key] for r in rows], style, marker=marker, color=colour, label=label, linewidth=2,
                markersize=5)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks(boxes)
    ax.set_xticklabels([f"{b:,}" for b in boxes])
    ax.minorticks_off()
    ax.set_xlabel("boxes in the world")
    ax.set_ylabel("time per physics step (ms, median)")
    return chart.options["device"], measured_on(path)


def draw_lights(chart: Chart, ax) -> tuple[str, str]:
    """GPU time against lights for chapter 16's paths and 17's; where the file holds several
    runs (one table each), each point is the median of the runs' medians, with a bar from
    the fastest run to the slowest."""
    path = chart.paths()[0]
    rows = table_rows(path)
    lights = sorted({number(r["lights"]) for r in rows})
    series = [("forward ms", "forward (chapter 16's forward path)", RED, "o", -0.06),
              ("deferred ms (G-buffer + lighting)", "deferred (chapter 16)", ORANGE, "o", -0.02),
              ("tiled fragment ms", "tiled, fragment lighting", BLUE, "s", 0.02),
              ("tiled compute ms", "tiled, compute lighting", CYAN, "s", 0.06)]
    missing: dict[float, list[str]] = {}
    runs = set()
    for column, label, colour, marker, shift in series:
        points = {}
        for r in rows:
            value = number(r[column])
            if value is not None:
                points.setdefault(number(r["lights"]), []).append(value)
        xs = sorted(points)
        ms = [statistics.median(points[x]) for x in xs]
        ax.plot(xs, ms, "-", marker=marker, color=colour, label=label, linewidth=2, markersize=5)
        for x, m in zip(xs, ms):
            runs.add(len(points[x]))
            if len(points[x]) > 1:  # the spread, offset a little sideways per series (log axis)
                low, high = min(points[x]), max(points[x])
                ax.errorbar([x * 4 ** shift], [m], yerr=[[m - low], [high - m]], fmt="none",
                            ecolor=colour, elinewidth=1.3, capsize=4, capthick=1.3, zorder=3)
        for x in lights:
            if x not in points:
                missing.setdefault(x, []).append(label.split(" (")[0])
    # Every point the table lacks is named under the chart, with the reason the results give.
    notes = [f"No {' or '.join(names)} point at {int(x):,} lights: {chart.options.get('missing', 'not measured')}"
             for x, names in sorted(missing.items())]
    if max(runs) > 1:
        notes.append(f"Each point: the median of {max(runs)} runs' medians (3 frames each), the bar from "
                     f"the fastest run to the slowest.")
    if chart.options.get("repeats"):
        notes.append(chart.options["repeats"])
    chart.options["notes"] = notes
    ax.set_xscale("log", base=4)
    ax.set_yscale("log")
    ax.set_xticks(lights)
    ax.set_xticklabels([f"{int(x):,}" for x in lights])
    ax.minorticks_off()
    ax.set_xlabel("lights in the scene")
    ax.set_ylabel("GPU time per frame (ms, median)")
    device, size = rows[0]["device"], rows[0]["size"].replace("x", "\u00d7")
    return f"{short_device(device)}, {size}", measured_on(path)


def draw_ndim(chart: Chart, ax) -> tuple[str, str]:
    """Median frame time against n for chapters 18, 19 and 20, one n-cube and 250;
    where a file holds several runs of one case, the median of their medians."""
    samples: dict[tuple[str, str], dict[int, list[float]]] = {}
    device, size = "", ""
    for path in chart.paths():
        for args, run in runner_runs(path):
            chapter = args[0][:2]
            if chapter not in ("18", "19", "20") or "--dim" not in args:
                continue
            options = {a for a in args[1:] if a.startswith("--")}
            if options - {"--scene", "--dim", "--raster", "--frames"}:
                continue  # 18's --matrix, 19's --edge-order: not the chapters' defaults
            scene = args[args.index("--scene") + 1]
            series = chapter + (" " + args[args.index("--raster") + 1] if chapter == "20" else "")
            n = int(args[args.index("--dim") + 1])
            samples.setdefault((series, scene), {}).setdefault(n, []).append(run["cpu_frame_ms"]["median"])
            device, size = run["device"], f"{run['width']}\u00d7{run['height']}"
    names = {"18": ("chapter 18: CPU transform", RED), "19": ("chapter 19: vertex shader", GREEN),
             "20 graphics": ("chapter 20: compute transform, line draw", ORANGE),
             "20 compute": ("chapter 20: compute transform, compute raster", BLUE)}
    from matplotlib.lines import Line2D
    runs: dict[str, set[int]] = {}
    for (series, scene), points in sorted(samples.items(), key=lambda kv: (list(names).index(kv[0][0]), kv[0][1])):
        label, colour = names[series]
        ns = sorted(points)
        ms = [statistics.median(points[n]) for n in ns]
        many = scene == "many"
        ax.plot(ns, ms, "-" if many else ":", color=colour, linewidth=2.4 if many else 1.6,
                marker="o", markersize=6, markerfacecolor=colour if many else "white", markeredgewidth=1.5)
        # The spread: where a case ran several times, a bar from its fastest run's median to
        # its slowest's (offset a little sideways per chapter, so that bars do not hide each other).
        shift = {"18": -0.12, "19": -0.04, "20 graphics": 0.04, "20 compute": 0.12}[series]
        for n, m in zip(ns, ms):
            if len(points[n]) > 1:
                low, high = min(points[n]), max(points[n])
                ax.errorbar([n + shift], [m], yerr=[[m - low], [high - m]], fmt="none", ecolor=colour,
                            elinewidth=1.3, capsize=4, capthick=1.3, zorder=3)
        runs.setdefault(label.split(":")[0], set()).update(len(v) for v in points.values())
    # The legend: a colour per chapter, a line style per scene.
    chart.options["handles"] = (
        [Line2D([], [], color=colour, linewidth=2.4, label=label) for label, colour in names.values()] +
        [Line2D([], [], color=GREY, linewidth=2.4, marker="o", label="solid, filled: 250 n-cubes"),
         Line2D([], [], color=GREY, linewidth=1.6, linestyle=":", marker="o", markerfacecolor="white",
                markeredgewidth=1.5, label="dotted, hollow: one n-cube")])
    once = sorted(c for c, counts in runs.items() if counts == {1})
    several = sorted(c for c, counts in runs.items() if max(counts) > 1)
    notes = []
    if several:
        notes.append(f"Each point: the median of {max(max(runs[c]) for c in several)} runs' median frames "
                     f"({', '.join(several)}), the bar from the fastest run to the slowest.")
    if once:
        notes.append(f"{' and '.join(once)}: one run each, so no spread is shown.")
    expected = {(s, scene, n) for s in names for scene in ("cube", "many") for n in (4, 8, 12)}
    missing = sorted(expected - {(s, scene, n) for (s, scene), points in samples.items() for n in points})
    notes.append("Every chapter, scene and n from 4 to 12 in steps of 4 was measured: no point is missing."
                 if not missing else "Not measured: " + "; ".join(f"{names[s][0]}, {scene}, n = {n}"
                                                                   for s, scene, n in missing) + ".")
    chart.options["notes"] = notes
    ax.set_yscale("log")
    ax.set_xticks([4, 8, 12])
    ax.set_xlim(3.5, 12.5)
    ax.set_xlabel("dimensions n")
    ax.set_ylabel("frame time (ms, median)")
    dates = sorted(measured_on(p) for p in chart.paths())
    return f"{short_device(device)}, {size}", dates[-1]


def draw_async(chart: Chart, ax) -> tuple[str, str]:
    """Chapter 29: the GPU's frame time ("gpu pace") against the bloom's own time (measured
    on the single queue), --queues single and async, at 48 lamps and at one; each point the
    median of the rounds' medians, a bar from the fastest round to the slowest."""
    path = chart.paths()[0]
    samples: dict[tuple[int, str], dict[int, dict[str, list[float]]]] = {}
    case, device, size = None, "", ""
    for line in path.read_text().splitlines():
        match = re.match(r"# round \d+: 29_async_compute --queues (\w+) --lamps (\d+) --bloom-radius (\d+)", line)
        if match:
            queues, lamps, radius = match.group(1), int(match.group(2)), int(match.group(3))
            case = samples.setdefault((lamps, queues), {}).setdefault(radius, {"pace": [], "bloom": []})
        elif line.startswith("{") and case is not None:
            run = json.loads(line)
            device, size = run["device"], f"{run['width']}\u00d7{run['height']}"
        elif case is not None and (match := re.match(r"gpu pace .* a frame every ([0-9.]+) ms", line)):
            case["pace"].append(float(match.group(1)))
        elif case is not None and (match := re.match(r"overlap .*: bloom ([0-9.]+) ms median", line)):
            case["bloom"].append(float(match.group(1)))
    styles = {(48, "single"): ("48 lamps, --queues single", RED, "-", "o"),
              (48, "async"): ("48 lamps, --queues async", BLUE, "-", "s"),
              (1, "single"): ("1 lamp, --queues single", ORANGE, ":", "o"),
              (1, "async"): ("1 lamp, --queues async", CYAN, ":", "s")}
    rounds = set()
    for key, (label, colour, style, marker) in styles.items():
        points = samples.get(key, {})
        single = samples.get((key[0], "single"), {})
        radii = sorted(r for r in points if r in single)
        xs = [statistics.median(single[r]["bloom"]) for r in radii]  # the bloom alone, on one queue
        ms = [statistics.median(points[r]["pace"]) for r in radii]
        ax.plot(xs, ms, style, marker=marker, color=colour, label=label, linewidth=2, markersize=5)
        for x, m, r in zip(xs, ms, radii):
            paces = points[r]["pace"]
            rounds.add(len(paces))
            if len(paces) > 1 and max(paces) > min(paces):
                ax.errorbar([x], [m], yerr=[[m - min(paces)], [max(paces) - m]], fmt="none", ecolor=colour,
                            elinewidth=1.3, capsize=4, capthick=1.3, zorder=3)
    chart.options["notes"] = [
        f"Each point: the median of {max(rounds)} rounds' medians (150 frames each); the spread between "
        "rounds is under 0.2%, smaller than the markers. The bloom's radius runs from 1 (left) to 64 "
        "at 48 lamps and to 32 at one lamp; every point of the sweep is drawn."]
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xticks([0.05, 0.1, 0.2, 0.5, 1, 2, 5, 10])
    ax.set_xticklabels(["0.05", "0.1", "0.2", "0.5", "1", "2", "5", "10"])
    ax.set_xlabel("the bloom's own GPU time, on one queue (ms, median)")
    ax.set_ylabel("GPU frame time (ms, median)")
    return f"{device}, {size}", measured_on(path)


def draw_threads(chart: Chart, ax) -> tuple[str, str]:
    """Chapter 27: the CPU time to record the frame's draws against the number of threads
    (the median of each round's median), a bar from the fastest round to the slowest, and
    the ideal: one thread's time divided by N."""
    path = chart.paths()[0]
    times: dict[int, list[float]] = {}
    for line in path.read_text().splitlines():
        match = re.match(r"27_threads: recording the draws on (\d+) threads? took ([0-9.]+) ms median", line)
        if match:
            times.setdefault(int(match.group(1)), []).append(float(match.group(2)))
    counts = sorted(times)
    ms = [statistics.median(times[n]) for n in counts]
    ax.plot(counts, ms, "-", marker="o", color=BLUE, label="recording, measured", linewidth=2, markersize=5)
    for n, m in zip(counts, ms):
        if max(times[n]) > min(times[n]):
            ax.errorbar([n], [m], yerr=[[m - min(times[n])], [max(times[n]) - m]], fmt="none", ecolor=BLUE,
                        elinewidth=1.3, capsize=4, capthick=1.3, zorder=3)
    ax.plot(counts, [ms[0] / n for n in counts], ":", color=GREY, label="one thread's time / N", linewidth=1.5)
    rounds = max(len(v) for v in times.values())
    chart.options["notes"] = [
        f"Each point: the median of {rounds} rounds' medians (200 frames each, 4,097 draws, 1280\u00d7720, "
        "validation off); the bar runs from the fastest round to the slowest."]
    ax.set_xscale("log", base=2)
    ax.set_yscale("log")
    ax.set_xticks(counts)
    ax.set_xticklabels([str(n) for n in counts])
    ax.set_yticks([0.05, 0.1, 0.2, 0.5, 1])
    ax.set_yticklabels(["0.05", "0.1", "0.2", "0.5", "1"])
    ax.set_xlabel("recording threads (--threads N)")
    ax.set_ylabel("CPU time to record the draws (ms, median)")
    return "NVIDIA H200 machine, 16 CPU cores", measured_on(path)


CHARTS = [
    Chart("14_physics_bench.svg", ["physics.jsonl"], draw_physics,
          {"title": "Chapter 14: one physics step against the number of boxes",
           "device": "CPU only: AMD EPYC, one thread", "budgets": PHYSICS_BUDGETS}),
    Chart("17_tiled_deferred_bench_lavapipe.svg", ["2026-11-27-quiet-17_tiled_deferred-lavapipe.md"],
          draw_lights,
          {"title": "Chapters 16 and 17: GPU time per frame against the number of lights",
           "repeats": "65,536 lights not run: forward and deferred take 16-21 s a frame at 16,384 "
                      "lights, about four times that at 65,536."}),
    Chart("17_tiled_deferred_bench_h100.svg", ["17_tiled_deferred-h100.md"], draw_lights,
          {"title": "Chapters 16 and 17: GPU time per frame against the number of lights"}),
    Chart("20_ndim_compute_bench.svg", ["2026-11-27-quiet-18_ndim_cpu-lavapipe.txt",
                                        "2026-11-27-quiet-19_ndim_gpu-lavapipe.txt",
                                        "2026-11-27-quiet-20_ndim_compute-lavapipe.txt"], draw_ndim,
          {"title": "Chapters 18 to 20: frame time against the number of dimensions"}),
    Chart("27_threads_h200.svg", ["h200-2026-11-29-gpu-check-27_threads-4ad1492.txt"], draw_threads,
          {"title": "Chapter 27: recording 4,097 draws on N threads", "budgets": []}),
    Chart("29_async_sweep_h200.svg", ["h200-2026-11-29-29_async_sweep-df79176.txt"], draw_async,
          {"title": "Chapter 29: GPU frame time against the bloom's work, one queue or two"}),
]


# ----------------------------------------------------------------------------------------------
# Drawing and writing
# ----------------------------------------------------------------------------------------------

def render(chart: Chart, target: Path) -> None:
    import matplotlib
    matplotlib.use("svg")
    import matplotlib.pyplot as plt
    from matplotlib.lines import Line2D
    from matplotlib.ticker import FuncFormatter

    matplotlib.rcParams.update({
        "svg.fonttype": "none",          # text stays text
        "svg.hashsalt": "vulkan-book",   # the same ids every run: a re-run changes nothing
        "font.family": "DejaVu Sans",
        "font.size": 11,
        "axes.spines.top": False,
        "axes.spines.right": False,
        "axes.grid": True,
        "grid.color": "#e3e6ea",
        "grid.linewidth": 0.8,
        "axes.edgecolor": "#59636e",
        "axes.titlesize": 12.5,
    })
    figure, ax = plt.subplots(figsize=(8.4, 5.6))
    device, date = chart.draw(chart, ax)

    def plain(value, _):
        return f"{value:,.0f}" if value >= 1 else f"{value:g}"
    ax.yaxis.set_major_formatter(FuncFormatter(plain))

    # A budget just outside the data (within a factor of NEAR_BUDGET on these log axes)
    # widens the axis to show it; one further off is named in the legend instead, so
    # that a chart never leaves a reader wondering where 144 fps went.
    low, high = ax.get_ylim()
    off_axis = []
    budget_labels = []
    budgets = chart.options.get("budgets", BUDGETS)
    for ms, name in budgets:
        if low / NEAR_BUDGET < ms <= low:
            low = ms / 1.25
        elif high <= ms < high * NEAR_BUDGET:
            high = ms * 1.25
    for ms, name in budgets:
        if not low < ms < high:
            where = "below" if ms <= low else "above"
            off_axis.append(Line2D([], [], color=GREY, linestyle=(0, (5, 4)), linewidth=1.2,
                                   label=f"{name.format(ms=ms)}, {where} the axis"))
            continue
        ax.axhline(ms, color=GREY, linestyle=(0, (5, 4)), linewidth=1.2, zorder=1, gid="budget")
        budget_labels.append(ax.annotate(
            name.format(ms=ms), xy=(1.0, ms), xycoords=("axes fraction", "data"),
            xytext=(-4, 3), textcoords="offset points", ha="right", va="bottom", fontsize=9.5,
            color="#3d444d", bbox={"boxstyle": "round,pad=0.2", "facecolor": "white",
                                   "edgecolor": "none", "alpha": 0.85}))
    ax.set_ylim(low, high)
    import textwrap
    heading = [chart.options["title"]] + textwrap.wrap(f"{device}; measured {date}", 72)
    title = ax.set_title("\n".join(heading), loc="left")
    # Below the axes, where it hides no data.
    handles = chart.options.get("handles") or ax.get_legend_handles_labels()[0]
    legend = ax.legend(handles=handles + off_axis, loc="upper center", bbox_to_anchor=(0.5, -0.13),
                       ncol=2, fontsize=9.5, frameon=False)
    title.set_gid("title")
    ax.xaxis.label.set_gid("x-axis-label")
    ax.yaxis.label.set_gid("y-axis-label")
    legend.set_gid("legend")
    # Notes under the legend: the spread shown, and every point the data lacks, and why.
    notes = chart.options.get("notes") or []
    if notes:
        lines = [part for text in notes for part in textwrap.wrap(text, 96)]
        note = ax.annotate("\n".join(lines), xy=(0.5, 0.0), xycoords=legend, xytext=(0, -6),
                           textcoords="offset points", ha="center", va="top", fontsize=9.5, color="#3d444d",
                           wrap=False)
        note.set_gid("notes")
    figure.tight_layout()
    place_budget_labels(figure, ax, budget_labels)
    figure.savefig(target, format="svg", metadata={"Date": None, "Creator": "benchmarks/plots.py"})
    plt.close(figure)


def place_budget_labels(figure, ax, labels) -> None:
    """Moves each budget's label off the data: at the right end of its line, above it, is
    the first choice; then the left end, then below the line at the right and at the left.
    A place is taken when no data line (nor a marker on it) passes under the label."""
    import numpy as np
    # The SVG canvas has no get_renderer() of its own; the figure's (matplotlib 3.6) measures
    # text the same way the SVG will place it.
    renderer = figure.canvas.get_renderer() if hasattr(figure.canvas, "get_renderer") else figure._get_renderer()
    points = []
    for line in ax.get_lines():
        if line.get_gid() == "budget" or not line.get_visible():
            continue
        xy = ax.transData.transform(np.column_stack(line.get_data()).astype(float))
        for (x0, y0), (x1, y1) in zip(xy, xy[1:]):
            steps = max(2, int(np.hypot(x1 - x0, y1 - y0)))
            points.append(np.column_stack((np.linspace(x0, x1, steps), np.linspace(y0, y1, steps))))
        points.append(xy)
    if not points:
        return
    points = np.concatenate(points)
    margin = 5.0  # display pixels: the line's width and its markers
    places = [(x, dx, dy, ha, va) for dy, va in ((3, "bottom"), (-3, "top"))
              for x, dx, ha in ((1.0, -4, "right"), (0.0, 4, "left"), (0.5, 0, "center"))]
    for label in labels:
        crossed = []
        for place in places:
            x, dx, dy, ha, va = place
            label.xy = (x, label.xy[1])
            label.set_position((dx, dy))
            label.set_ha(ha)
            label.set_va(va)
            box = label.get_window_extent(renderer)
            inside = ((points[:, 0] > box.x0 - margin) & (points[:, 0] < box.x1 + margin) &
                      (points[:, 1] > box.y0 - margin) & (points[:, 1] < box.y1 + margin))
            crossed.append(int(inside.sum()))
            if not crossed[-1]:
                break
        else:
            # Nowhere free: the place that the least of the data crosses.
            x, dx, dy, ha, va = places[crossed.index(min(crossed))]
            label.xy = (x, label.xy[1])
            label.set_position((dx, dy))
            label.set_ha(ha)
            label.set_va(va)


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="plots.py", description="Draw the book's charts from benchmarks/results/.")
    parser.add_argument("--out", type=Path, default=ROOT / "book" / "images",
                        help="where the SVGs go (default: book/images)")
    parser.add_argument("--list", action="store_true", help="list the charts and their inputs, draw nothing")
    args = parser.parse_args(argv)
    if args.list:
        for chart in CHARTS:
            print(f"{chart.output}: {', '.join('benchmarks/results/' + i for i in chart.inputs)}")
        return 0
    try:
        import matplotlib  # noqa: F401
    except ImportError:
        print("plots.py: error: needs matplotlib: apt install python3-matplotlib, and run it with /usr/bin/python3",
              file=sys.stderr)
        return 1
    args.out.mkdir(parents=True, exist_ok=True)
    for chart in CHARTS:
        missing = [str(p) for p in chart.paths() if not p.is_file()]
        if missing:
            print(f"plots.py: error: {chart.output}: no such results file: {', '.join(missing)}", file=sys.stderr)
            return 1
        render(chart, args.out / chart.output)
        print(f"plots.py: wrote {args.out / chart.output}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
