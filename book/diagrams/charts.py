"""What the book's matplotlib charts share (23's tone curve, BRDF table,
GGX lobe and prefilter samples): one look, SVG whose text stays text and
whose ids are the same every build, printed to standard output as every
diagram script's is."""
import io
import sys

# The look of every chart; plain axes (spines, grid) for x-y plots only.
STYLE = {
    "svg.fonttype": "none",          # text stays text
    "svg.hashsalt": "vulkan-book",   # the same ids every build
    "font.family": "DejaVu Sans",
    "font.size": 11,
}
PLAIN_AXES = {
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.grid": True,
    "grid.color": "#e3e6ea",
    "axes.edgecolor": "#59636e",
}


def pyplot(what: str, plain_axes: bool = True, title_size: float = 12.5):
    """matplotlib.pyplot set up for the book, or a one-line exit naming the package."""
    try:
        import matplotlib
    except ImportError:
        sys.exit(f"the {what} chart needs python3-matplotlib (scripts/install-deps.sh installs it)")
    matplotlib.use("svg")
    import matplotlib.pyplot as plt

    matplotlib.rcParams.update(STYLE)
    if plain_axes:
        matplotlib.rcParams.update(PLAIN_AXES)
    matplotlib.rcParams["axes.titlesize"] = title_size
    return plt


def print_svg(plt, figure, creator: str) -> None:
    """The figure as SVG on standard output, with no date in it."""
    out = io.StringIO()
    figure.savefig(out, format="svg", metadata={"Date": None, "Creator": creator})
    plt.close(figure)
    sys.stdout.write(out.getvalue())
