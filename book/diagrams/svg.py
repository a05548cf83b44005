"""A small SVG writer for the book's diagrams: boxes, arrows and real text.

Each book/diagrams/NN_name.py draws one diagram with it and prints the SVG;
book/build_book.py runs them when it builds the book. Standard library only.

Text is laid out with the advance widths of DejaVu Sans (the font the SVGs ask
for first; Arial and Helvetica, the fallbacks, are narrower), so boxes can be
sized to their labels. A label may hold light markup:

    _{c}  subscript      ^{2}  superscript      *x*  italic      **x**  bold
    `code`  monospace
"""

from __future__ import annotations

import html
import math
import re

# Advance widths of ASCII 32..126 per 1000 units of font size (DejaVu Sans).
_SANS = [318, 401, 460, 838, 636, 950, 780, 275, 390, 390, 500, 838, 318, 361, 318, 337, 636, 636,
         636, 636, 636, 636, 636, 636, 636, 636, 337, 337, 838, 838, 838, 531, 1000, 684, 686, 698,
         770, 632, 575, 775, 752, 295, 295, 656, 557, 863, 748, 787, 603, 787, 695, 635, 611, 732,
         684, 989, 685, 611, 685, 390, 337, 390, 838, 500, 500, 613, 635, 550, 635, 615, 352, 635,
         634, 278, 278, 579, 278, 974, 634, 612, 635, 635, 411, 521, 392, 634, 592, 818, 592, 592,
         525, 636, 337, 636, 838]
_BOLD = [348, 456, 521, 838, 696, 1002, 872, 306, 457, 457, 523, 838, 380, 415, 380, 365, 696, 696,
         696, 696, 696, 696, 696, 696, 696, 696, 400, 400, 838, 838, 838, 580, 1000, 774, 762, 734,
         830, 683, 683, 821, 837, 372, 372, 775, 637, 995, 837, 850, 733, 850, 770, 720, 682, 812,
         774, 1103, 771, 724, 725, 457, 365, 457, 838, 500, 500, 675, 716, 593, 716, 678, 435, 716,
         712, 343, 343, 665, 343, 1042, 712, 687, 716, 716, 493, 595, 478, 712, 652, 924, 645, 652,
         582, 712, 365, 712, 838]
_MONO = 602

SANS_FONT = "'DejaVu Sans', Arial, Helvetica, sans-serif"
MONO_FONT = "'DejaVu Sans Mono', Menlo, Consolas, monospace"

# The book's palette: one colour per actor, each with a light fill.
INK = "#1f2328"
MUTED = "#59636e"
GRID = "#d1d9e0"
BLUE, BLUE_FILL = "#1f5fbf", "#e3edfb"      # the GPU, its queue
ORANGE, ORANGE_FILL = "#b35900", "#fdebd7"  # the CPU
GREEN, GREEN_FILL = "#1e7b34", "#e0f3e4"    # the presentation engine, results
PURPLE, PURPLE_FILL = "#6f42c1", "#eee6fa"  # synchronisation objects
RED, RED_FILL = "#c0362c", "#fbe3e1"        # what is refused, culled, idle
GREY, GREY_FILL = "#6e7781", "#f2f4f6"      # neutral


def char_width(c: str, bold: bool = False, mono: bool = False) -> float:
    if mono:
        return _MONO
    code = ord(c)
    if 32 <= code <= 126:
        return (_BOLD if bold else _SANS)[code - 32]
    return 700 if bold else 660  # arrows, minus signs, Greek letters: about this wide


_MARKUP = re.compile(r"_\{([^}]*)\}|\^\{([^}]*)\}|\*\*([^*]+)\*\*|\*([^*]+)\*|`([^`]+)`")


def _segments(text: str) -> list[tuple[str, str]]:
    """(kind, text) pieces of a label: kind is '', 'sub', 'sup', 'b', 'i' or 'm'."""
    out, at = [], 0
    for match in _MARKUP.finditer(text):
        if match.start() > at:
            out.append(("", text[at:match.start()]))
        kind = ("sub", "sup", "b", "i", "m")[match.lastindex - 1]
        out.append((kind, match.group(match.lastindex)))
        at = match.end()
    if at < len(text):
        out.append(("", text[at:]))
    return out


def text_width(text: str, size: float, bold: bool = False, mono: bool = False) -> float:
    total = 0.0
    for kind, piece in _segments(text):
        scale = 0.8 if kind in ("sub", "sup") else 1.0
        total += sum(char_width(c, bold or kind == "b", mono or kind == "m") for c in piece) * scale
    return total * size / 1000.0


def wrap(text: str, width: float, size: float, bold: bool = False) -> list[str]:
    """The words of text broken into lines no wider than width at this size."""
    lines: list[str] = []
    for word in text.split():
        if lines and text_width(lines[-1] + " " + word, size, bold) <= width:
            lines[-1] += " " + word
        else:
            lines.append(word)
    return lines


def esc(text: str) -> str:
    return html.escape(text, quote=True)


class Svg:
    def __init__(self, width: float, height: float, title: str, description: str = ""):
        self.width, self.height = width, height
        self.title, self.description = title, description
        self.items: list[str] = []
        self.markers: dict[str, str] = {}

    # ---- primitives ---------------------------------------------------------------

    def add(self, element: str) -> None:
        self.items.append(element)

    def rect(self, x, y, w, h, fill="none", stroke=INK, width=1.2, rx=0, dash=None, opacity=None):
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' fill-opacity="{opacity}"' if opacity is not None else ""
        self.add(f'<rect x="{x:.1f}" y="{y:.1f}" width="{w:.1f}" height="{h:.1f}" rx="{rx}" '
                 f'fill="{fill}" stroke="{stroke}" stroke-width="{width}"{extra}/>')

    def circle(self, cx, cy, r, fill="none", stroke=INK, width=1.2, dash=None, opacity=None):
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        extra += f' fill-opacity="{opacity}"' if opacity is not None else ""
        self.add(f'<circle cx="{cx:.1f}" cy="{cy:.1f}" r="{r:.1f}" fill="{fill}" stroke="{stroke}" '
                 f'stroke-width="{width}"{extra}/>')

    def polygon(self, points, fill="none", stroke=INK, width=1.2, opacity=None, dash=None):
        pts = " ".join(f"{x:.1f},{y:.1f}" for x, y in points)
        extra = f' fill-opacity="{opacity}"' if opacity is not None else ""
        extra += f' stroke-dasharray="{dash}"' if dash else ""
        self.add(f'<polygon points="{pts}" fill="{fill}" stroke="{stroke}" stroke-width="{width}"{extra}/>')

    def _marker(self, colour: str) -> str:
        name = "arrow-" + colour.lstrip("#")
        if name not in self.markers:
            self.markers[name] = (
                f'<marker id="{name}" viewBox="0 0 10 10" refX="9" refY="5" markerWidth="7" '
                f'markerHeight="7" orient="auto-start-reverse" markerUnits="userSpaceOnUse">'
                f'<path d="M0,0.8 L10,5 L0,9.2 z" fill="{colour}"/></marker>')
        return name

    def path(self, d, stroke=INK, width=1.2, fill="none", dash=None, arrow=None):
        """arrow: None, 'end', 'start' or 'both'."""
        extra = f' stroke-dasharray="{dash}"' if dash else ""
        if arrow in ("end", "both"):
            extra += f' marker-end="url(#{self._marker(stroke)})"'
        if arrow in ("start", "both"):
            extra += f' marker-start="url(#{self._marker(stroke)})"'
        self.add(f'<path d="{d}" fill="{fill}" stroke="{stroke}" stroke-width="{width}"'
                 f' stroke-linejoin="round"{extra}/>')

    def line(self, x1, y1, x2, y2, stroke=INK, width=1.2, dash=None, arrow=None):
        self.path(f"M{x1:.1f},{y1:.1f} L{x2:.1f},{y2:.1f}", stroke, width, dash=dash, arrow=arrow)

    def polyline(self, points, stroke=INK, width=1.2, dash=None, arrow=None):
        d = "M" + " L".join(f"{x:.1f},{y:.1f}" for x, y in points)
        self.path(d, stroke, width, dash=dash, arrow=arrow)

    def text(self, x, y, label, size=13, anchor="start", fill=INK, bold=False, mono=False,
             italic=False, rotate=None):
        """One line of text with its baseline at y; label may hold the markup above."""
        family = MONO_FONT if mono else SANS_FONT
        attrs = f' font-family="{family}" font-size="{size}" fill="{fill}"'
        if anchor != "start":
            attrs += f' text-anchor="{anchor}"'
        if bold:
            attrs += ' font-weight="bold"'
        if italic:
            attrs += ' font-style="italic"'
        if rotate is not None:
            attrs += f' transform="rotate({rotate} {x:.1f} {y:.1f})"'
        spans = []
        shift = 0.0  # the baseline offset the previous span left behind
        for kind, piece in _segments(label):
            want = {"sub": 0.3 * size, "sup": -0.38 * size}.get(kind, 0.0)
            style = ""
            if kind in ("sub", "sup"):
                style += f' font-size="{size * 0.8:.1f}"'
            if kind == "b":
                style += ' font-weight="bold"'
            if kind == "i":
                style += ' font-style="italic"'
            if kind == "m":
                style += f' font-family="{MONO_FONT}"'
            if want != shift:
                style += f' dy="{want - shift:.1f}"'
                shift = want
            spans.append(f"<tspan{style}>{esc(piece)}</tspan>" if style else esc(piece))
        self.add(f'<text x="{x:.1f}" y="{y:.1f}" xml:space="preserve"{attrs}>{"".join(spans)}</text>')

    def lines(self, x, y, labels, size=13, leading=1.3, **kw):
        """Several lines, the first baseline at y."""
        for i, label in enumerate(labels):
            self.text(x, y + i * size * leading, label, size=size, **kw)

    # ---- composites ---------------------------------------------------------------

    def box(self, x, y, w, h, labels, fill=GREY_FILL, stroke=GREY, size=13, rx=6, bold_first=False,
            mono=False, align="middle", width=1.3, dash=None, text_fill=INK):
        """A rounded box with lines of text centred in it (vertically too)."""
        self.rect(x, y, w, h, fill=fill, stroke=stroke, rx=rx, width=width, dash=dash)
        if isinstance(labels, str):
            labels = [labels]
        leading = size * 1.3
        top = y + h / 2 - leading * (len(labels) - 1) / 2 + size * 0.35
        tx = {"middle": x + w / 2, "start": x + 8, "end": x + w - 8}[align]
        for i, label in enumerate(labels):
            self.text(tx, top + i * leading, label, size=size, anchor=align,
                      bold=bold_first and i == 0, mono=mono, fill=text_fill)

    def label_width(self, labels, size=13, bold=False, mono=False) -> float:
        if isinstance(labels, str):
            labels = [labels]
        return max(text_width(label, size, bold, mono) for label in labels)

    def brace(self, x1, x2, y, depth=6, stroke=MUTED, width=1.1, up=False):
        """A horizontal curly brace from x1 to x2, its tip pointing down (or up)."""
        d = -depth if up else depth
        mid = (x1 + x2) / 2
        self.path(f"M{x1:.1f},{y:.1f} q0,{d:.1f} {d if d > 0 else -d:.1f},{d:.1f} "
                  f"L{mid - abs(d):.1f},{y + d:.1f} q{abs(d):.1f},0 {abs(d):.1f},{d:.1f} "
                  f"q0,{-d:.1f} {abs(d):.1f},{-d:.1f} L{x2 - abs(d):.1f},{y + d:.1f} "
                  f"q{abs(d):.1f},0 {abs(d):.1f},{-d:.1f}", stroke=stroke, width=width)

    def arc_arrow(self, cx, cy, r, a0, a1, stroke=INK, width=1.3):
        """An arc from angle a0 to a1 (degrees, counter-clockwise on screen), arrow at a1."""
        p0 = (cx + r * math.cos(math.radians(a0)), cy - r * math.sin(math.radians(a0)))
        p1 = (cx + r * math.cos(math.radians(a1)), cy - r * math.sin(math.radians(a1)))
        large = 1 if abs(a1 - a0) > 180 else 0
        sweep = 0 if a1 > a0 else 1
        self.path(f"M{p0[0]:.1f},{p0[1]:.1f} A{r:.1f},{r:.1f} 0 {large} {sweep} {p1[0]:.1f},{p1[1]:.1f}",
                  stroke=stroke, width=width, arrow="end")

    # ---- output -------------------------------------------------------------------

    def render(self) -> str:
        defs = "".join(self.markers.values())
        desc = f"<desc>{esc(self.description)}</desc>" if self.description else ""
        return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {self.width:.0f} {self.height:.0f}" '
                f'width="{self.width:.0f}" height="{self.height:.0f}" role="img" '
                f'font-family="{SANS_FONT}">\n'
                f"<title>{esc(self.title)}</title>{desc}\n"
                f"<defs>{defs}</defs>\n"
                f'<rect x="0" y="0" width="{self.width:.0f}" height="{self.height:.0f}" fill="#ffffff"/>\n'
                + "\n".join(self.items) + "\n</svg>\n")

    def write(self) -> None:
        """Prints the SVG: the builder runs each diagram script and reads its output."""
        import sys
        sys.stdout.write(self.render())
