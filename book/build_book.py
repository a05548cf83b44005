#!/usr/bin/python3
r"""Builds the tutorial's book: book/*.md -> browsable HTML.

    /usr/bin/python3 book/build_book.py --out DIR     build the HTML into DIR
    /usr/bin/python3 book/build_book.py --check       validate only, write nothing

Code in the book is never pasted. A line

    {{#include ../chapters/04_triangle/main.cpp:pipeline}}

inside a fenced code block is replaced by the lines between the source's marker
comments `// [pipeline]` and `// [/pipeline]` (marker lines excluded, common
indentation removed), and a caption after the block names the file and lines.

A number that a page quotes from the sources names its constant, so that it
cannot drift from the code: `{{#number ../shaders/17_tiled_deferred/tiles.glsl:MAX_TILE_LIGHTS 2,048}}`
shows "2,048" and fails the build unless that file defines MAX_TILE_LIGHTS as
2048 (`*K` and `/K` after the name scale it, `NAME#N` picks its N-th definition;
book/source_constants.py, which the diagrams use to read their numbers too).
A colour a page quotes from a chapter's picture names the reviewed test picture
and the pixel in the same way: `{{#pixel ../tests/golden/23_materials.png:0,239 (44, 39, 33)}}`
shows "(44, 39, 33)" and fails unless that pixel is that colour. A frame is named
by its index (`frame 9 (t = 0.15 s)`), never by its position ("the tenth frame"):
the build fails on either slip, on the pages and in the diagrams' text.

The build fails (exit status 1, one line per problem) when an included file or
marker does not exist, when a marker in chapters/, common/ or shaders/ is
opened and not closed (or closed and not opened, or opened twice), when such a
marker is quoted by no page (a stale marker), and on a broken link between
pages or to a heading, a link to a file that does not exist, or an unknown
code language. A picture that does not exist (yet) is only a warning, shown
as a placeholder, unless --strict is given.

Every chapter page (NN_name.md) must end with the sections "What you should
see", "Try it" (at least three exercises, one with a command that checks it)
and "Recap" (linking into the page), and neither its prose nor the program
output its code blocks quote may hold lab notes: no load average, driver,
LLVM or other major.minor.patch version, or commit id. Those belong in the performance
part (performance.md and perf_*.md), which the sidebar shows as a part of its
own after the appendices.

Links to repository files (`../chapters/04_triangle/main.cpp`) become pages of
their own under DIR/src/, with line numbers; each include's caption links to
the quoted lines there. Pictures are copied into DIR/images/.

Diagrams are drawn at build time: a page shows `diagrams/NAME.svg`, and the
builder makes it from book/diagrams/NAME.py (a script that prints the SVG, with
book/diagrams/svg.py) or book/diagrams/NAME.dot (Graphviz's dot), into
DIR/images/NAME.svg. A diagram that fails to draw, or has no text, is an error.

Each page gets the sidebar (sticky on a wide screen, with a search box at its
top; on a phone a bar at the top of the page links to it), and the builder
writes search-index.js, the text of every page by section, for the search in
book/theme/search.js: each section's words sorted by where they stand (its
heading; what the chapter's recap, whose entries link to their sections, says
it teaches; its prose; its code; the comments in that code, without their
`//`), so that the search ranks where a word is taught above where it is
mentioned. The stylesheet is book/theme/style.css.

The builder also writes book.html, every page in reading order on one page
(ids prefixed with the page's name, links between pages made links within
it), which tests/book_pdf.py prints to book.pdf with Chromium, a chapter to a
new sheet.

Every SVG figure opens full size on a tap or click (book/theme/book.js), zoomed
so that its smallest text is at least FIGURE_TEXT_PX pixels, and says so under
it; every table scrolls sideways as a whole in a box of its own, with a line
above it where it is wider than the column.

Maths is TeX between \( and \) in a line, or \[ and \] on a line of its own,
typeset in the reader's browser (and in the PDF) by KaTeX, which the builder
copies into DIR/katex/ from Debian's libjs-katex (/usr/share/javascript/katex,
or the folder VKT_KATEX_DIR names).

Needs the standard library, python3-markdown and python3-pygments (Debian 12:
markdown 3.4, pygments 2.14), Graphviz's dot for the .dot diagrams, and
libjs-katex.
"""

from __future__ import annotations

import argparse
import difflib
import html
import json
import os
import re
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ElementTree
from dataclasses import dataclass, field
from pathlib import Path, PurePosixPath

from source_constants import NUMBER_RE, NUMBER_START_RE, ConstantError, constant, scaled, shown_matches

try:
    import markdown
    import pygments
    from pygments.formatters import HtmlFormatter
    from pygments.lexers import get_lexer_by_name, get_lexer_for_filename
    from pygments.lexers.special import TextLexer
    from pygments.util import ClassNotFound
except ImportError as missing:  # pragma: no cover - depends on the machine
    sys.stderr.write(
        f"build_book.py: error: {missing.name} is missing: install python3-markdown "
        "python3-pygments and run this with /usr/bin/python3\n")
    sys.exit(1)

# The folders whose markers must all be quoted by some page, and the files
# there that can hold markers.
MARKER_DIRS = ("chapters", "common", "shaders")
MARKER_SUFFIXES = (".cpp", ".hpp", ".vert", ".frag", ".comp", ".glsl", ".task", ".mesh", ".rgen", ".rchit",
                   ".rmiss")

MARKER_RE = re.compile(r"^// \[(/?)([A-Za-z0-9_-]+)\]$")
# A comment line that is only a bracketed word but not exactly "// [name]":
# almost certainly a mistyped marker, which would otherwise be ignored.
NEAR_MARKER_RE = re.compile(r"^//\s*\[\s*/?\s*[A-Za-z0-9_-]+\s*\]\s*$")
INCLUDE_RE = re.compile(r"^\s*\{\{#include\s+([^\s:{}]+):([A-Za-z0-9_-]+)\s*\}\}\s*$")
DIRECTIVE_RE = re.compile(r"\{\{#")
FENCE_RE = re.compile(r"^(\s*)(`{3,}|~{3,})\s*([^`\s]*)")
# The book has three parts after its index: the chapters (NN_name.md), the
# appendices (appendix_name.md) and the performance part (performance.md, its
# front page, then perf_NN_name.md per measured chapter and perf_name.md).
# A chapter whose page grew past one sitting keeps its core on NN_name.md and
# goes further on sub-pages NNb_name.md, NNc_name.md ... (one idea each, in that
# reading order, right after the core); the chapter's program stays whole, and
# its checks (the picture, the closing sections, the changes page) are the core's.
PAGE_RE = re.compile(r"^(index|performance|\d\d[b-z]?_[a-z0-9_]+|appendix_[a-z0-9_]+|perf_[a-z0-9_]+)\.md$")
CHAPTER_PAGE_RE = re.compile(r"^\d\d_")
SUB_PAGE_RE = re.compile(r"^\d\d[b-z]_")


def is_chapter(name: str) -> bool:
    """A chapter's core page (NN_name.md), not one of its sub-pages (NNb_name.md)."""
    return bool(CHAPTER_PAGE_RE.match(name))
IMAGE_SUFFIXES = (".png", ".jpg", ".jpeg", ".gif", ".svg", ".webp")
# A picture `NAME.svg` that does not exist is drawn from NAME.py or NAME.dot beside it.
DIAGRAM_SOURCES = (".py", ".dot")
# The stylesheet and the search script, next to this file.
THEME = Path(__file__).resolve().parent / "theme"
# A chapter's list of its sources and how to run it: kept apart from the list before it.
CHAPTER_FILES_RE = re.compile(r"^- (Sources|Run it):")


class BookError(Exception):
    """A problem in the book or its sources; reported as one line."""


# --------------------------------------------------------------------------
# Markers in the sources
# --------------------------------------------------------------------------

@dataclass
class Region:
    start: int  # line number of the opening marker (1-based)
    end: int    # line number of the closing marker


@dataclass
class SourceFile:
    rel: str                  # path relative to the root, with forward slashes
    lines: list[str]
    regions: dict[str, Region]
    problems: list[str]


class Sources:
    """Reads each source once and remembers its markers."""

    def __init__(self, root: Path):
        self.root = root
        self.cache: dict[str, SourceFile] = {}

    def get(self, rel: str) -> SourceFile:
        if rel not in self.cache:
            self.cache[rel] = scan_markers(self.root, rel)
        return self.cache[rel]


def scan_markers(root: Path, rel: str) -> SourceFile:
    text = (root / rel).read_text(encoding="utf-8")
    lines = text.splitlines()
    regions: dict[str, Region] = {}
    open_at: dict[str, int] = {}
    problems: list[str] = []
    for number, line in enumerate(lines, start=1):
        stripped = line.strip()
        match = MARKER_RE.match(stripped)
        if not match:
            if NEAR_MARKER_RE.match(stripped):
                problems.append(f"{rel}:{number}: '{stripped}' looks like a marker but is not "
                                "written exactly '// [name]' or '// [/name]'")
            continue
        closing, name = match.group(1) == "/", match.group(2)
        if not closing:
            if name in open_at:
                problems.append(f"{rel}:{number}: marker [{name}] opened again inside itself "
                                f"(first opened on line {open_at[name]})")
            elif name in regions:
                problems.append(f"{rel}:{number}: marker [{name}] used twice in one file "
                                f"(first on lines {regions[name].start}-{regions[name].end})")
            else:
                open_at[name] = number
        else:
            if name not in open_at:
                problems.append(f"{rel}:{number}: marker [/{name}] closes a marker that is not open")
            else:
                regions[name] = Region(open_at.pop(name), number)
    for name, number in open_at.items():
        problems.append(f"{rel}:{number}: marker [{name}] is opened but never closed")
    return SourceFile(rel, lines, regions, problems)


def all_marker_files(root: Path) -> list[str]:
    found = []
    for folder in MARKER_DIRS:
        base = root / folder
        if not base.is_dir():
            continue
        for dirpath, dirnames, filenames in os.walk(base):
            dirnames.sort()
            for name in sorted(filenames):
                if name.endswith(MARKER_SUFFIXES):
                    found.append(Path(dirpath, name).relative_to(root).as_posix())
    return found


def excerpt(source: SourceFile, name: str) -> tuple[list[str], int, int]:
    """The lines inside a marker, dedented, with their first and last line numbers."""
    region = source.regions[name]
    numbered = [(n, source.lines[n - 1]) for n in range(region.start + 1, region.end)]
    # Other markers nested inside are bookkeeping, not code.
    numbered = [(n, l) for n, l in numbered if not MARKER_RE.match(l.strip())]
    while numbered and not numbered[0][1].strip():
        numbered.pop(0)
    while numbered and not numbered[-1][1].strip():
        numbered.pop()
    if not numbered:
        raise BookError(f"{source.rel}: marker [{name}] encloses no code")
    texts = [l.expandtabs(4).rstrip() for _, l in numbered]
    indent = min(len(t) - len(t.lstrip()) for t in texts if t.strip())
    texts = [t[indent:] if t.strip() else "" for t in texts]
    return texts, numbered[0][0], numbered[-1][0]


# --------------------------------------------------------------------------
# Pages
# --------------------------------------------------------------------------

@dataclass
class Include:
    rel: str     # the source, relative to the root
    marker: str
    first: int
    last: int


@dataclass
class Page:
    md_name: str      # "03_swapchain.md"
    title: str = ""
    markdown: str = ""  # after includes are expanded
    body: str = ""      # HTML of the page's content
    toc: list = field(default_factory=list)
    ids: set = field(default_factory=set)
    includes: list[Include] = field(default_factory=list)
    math: list[tuple[str, bool]] = field(default_factory=list)  # (TeX, display) by placeholder number
    recap_elsewhere: list = field(default_factory=list)  # (sub-page, anchor, words) its recap teaches there

    @property
    def html_name(self) -> str:
        return self.md_name[:-3] + ".html"


def page_order(names: list[str]) -> list[str]:
    def key(name: str):
        if name == "index.md":
            return (0, 0, name)
        if name.startswith("appendix_"):
            return (2, 0, name)
        if name == "performance.md":
            return (3, 0, name)
        if name.startswith("perf_"):
            number = name[5:7]
            return (3, int(number) if number.isdigit() else 100, name)
        return (1, int(name[:2]), name)
    return sorted(names, key=key)


def part_of(name: str) -> str:
    """The part of the book a page belongs to, as the sidebar labels it."""
    if name.startswith("appendix_"):
        return "Appendices"
    if name == "performance.md" or name.startswith("perf_"):
        return "Performance"
    return ""


def inside_root(root: Path, target: Path) -> bool:
    try:
        target.resolve().relative_to(root.resolve())
        return True
    except ValueError:
        return False


def source_page_name(rel: str) -> str:
    return "src/" + rel + ".html"


def expand_page(root: Path, book: Path, page: Page, sources: Sources, problems: list[str]) -> None:
    """Expands {{#include}} lines, finds the title, checks code languages."""
    where = f"book/{page.md_name}"
    lines = (book / page.md_name).read_text(encoding="utf-8").splitlines()
    out: list[str] = []
    fence: str | None = None       # the fence that opened the current code block
    fence_indent = ""
    captions: list[Include] = []
    for number, line in enumerate(lines, start=1):
        fence_match = FENCE_RE.match(line)
        if fence is None and NUMBER_START_RE.search(line):
            line = expand_numbers(root, book, line, f"{where}:{number}", problems)
        if fence is None and PIXEL_START_RE.search(line):
            line = expand_pixels(root, book, line, f"{where}:{number}", problems)
        if fence is None:
            problems.extend(frame_name_problems(line, f"{where}:{number}"))
            if "\\(" in line or "\\[" in line:
                line = extract_math(line, page, f"{where}:{number}", problems)
        if fence is None:
            if fence_match:
                fence, fence_indent, language = fence_match.group(2), fence_match.group(1), fence_match.group(3)
                if language:
                    try:
                        get_lexer_by_name(language)
                    except ClassNotFound:
                        problems.append(f"{where}:{number}: unknown code language '{language}'")
                captions = []
            elif DIRECTIVE_RE.search(line):
                problems.append(f"{where}:{number}: {{{{#include}}}} belongs on its own line inside "
                                "a fenced code block")
            elif not page.title and line.startswith("# "):
                page.title = line[2:].strip()
            elif CHAPTER_FILES_RE.match(line) and len(out) >= 2 and out[-1] == "" and out[-2].strip():
                # Markdown would continue the list above (the chapter's new
                # ideas) across the blank line; an HTML comment ends it.
                out.extend(["<!-- the chapter's files -->", ""])
            out.append(line)
            continue

        # Inside a code block.
        if fence_match and fence_match.group(2).startswith(fence) and not fence_match.group(3):
            fence = None
            out.append(line)
            if captions:
                out.append("")
                links = []
                for inc in captions:
                    lines_text = (f"line {inc.first}" if inc.first == inc.last
                                  else f"lines {inc.first}-{inc.last}")
                    href = f"{source_page_name(inc.rel)}#L-{inc.first}"
                    links.append(f'<a href="{html.escape(href)}">{html.escape(inc.rel)}, {lines_text}</a>')
                out.append(f'<p class="source">{" &middot; ".join(links)}</p>')
                out.append("")
            continue
        if not DIRECTIVE_RE.search(line):
            out.append(line)
            continue
        match = INCLUDE_RE.match(line)
        if not match:
            problems.append(f"{where}:{number}: malformed directive {line.strip()!r} "
                            "(want '{{#include <path>:<marker>}}')")
            continue
        path_text, marker = match.groups()
        target = (book / path_text)
        if not inside_root(root, target):
            problems.append(f"{where}:{number}: {path_text} lies outside the repository")
            continue
        if not target.is_file():
            problems.append(f"{where}:{number}: included file {path_text} does not exist")
            continue
        rel = target.resolve().relative_to(root.resolve()).as_posix()
        source = sources.get(rel)
        if marker not in source.regions:
            problems.append(f"{where}:{number}: marker [{marker}] not found in {rel}")
            continue
        try:
            texts, first, last = excerpt(source, marker)
        except BookError as error:
            problems.append(f"{where}:{number}: {error}")
            continue
        out.extend(fence_indent + t if t else "" for t in texts)
        inc = Include(rel, marker, first, last)
        page.includes.append(inc)
        captions.append(inc)
    if fence is not None:
        problems.append(f"{where}: a fenced code block is never closed")
    if not page.title:
        problems.append(f"{where}: the page has no '# ' title heading")
    page.markdown = "\n".join(out) + "\n"


def expand_numbers(root: Path, book: Path, line: str, where: str, problems: list[str]) -> str:
    """A line's {{#number path:NAME shown}} directives replaced by the number shown,
    each checked against the constant in the source (book/source_constants.py)."""
    def one(match: re.Match) -> str:
        path_text, name, which, scale, shown = match.groups()
        target = book / path_text
        if not inside_root(root, target):
            problems.append(f"{where}: {path_text} lies outside the repository")
            return shown
        rel = target.resolve().relative_to(root.resolve()).as_posix() if target.exists() else path_text
        if not target.is_file():
            problems.append(f"{where}: {{{{#number}}}} names {path_text}, which does not exist")
            return shown
        try:
            value = scaled(constant(target, name, int(which) if which else None, rel), scale or "")
        except ConstantError as error:
            problems.append(f"{where}: {error}")
            return shown
        if not shown_matches(shown, value):
            exact = f"{float(value):g}" if value.denominator != 1 else str(value.numerator)
            problems.append(f"{where}: the page says {shown} where {rel} gives {exact} "
                            f"({name}{'#' + which if which else ''}{scale.replace(' ', '') if scale else ''})")
        return shown
    line = NUMBER_RE.sub(one, line)
    if NUMBER_START_RE.search(line):
        problems.append(f"{where}: malformed {{{{#number}}}} (want '{{{{#number <path>:<NAME> <number "
                        "shown>}}', optionally NAME#N and *K or /K after the name)")
        line = NUMBER_START_RE.sub("{{number", line)
    return line


# A colour a page quotes from a chapter's picture names the reviewed test picture
# and the pixel: {{#pixel ../tests/golden/23_materials.png:0,239 (44, 39, 33)}} shows
# "(44, 39, 33)" and fails the build unless that pixel of the golden image is that
# colour, exactly: the golden image is what a run of the chapter wrote, so a page
# cannot quote a hand-worked value as what the program writes.
PIXEL_RE = re.compile(r"\{\{#pixel\s+([^\s:{}]+):([0-9]+),([0-9]+)\s+(\(\s*[0-9]+,\s*[0-9]+,\s*[0-9]+\s*\))\s*\}\}")
PIXEL_START_RE = re.compile(r"\{\{#pixel\b")
_pictures: dict[Path, list] = {}


def expand_pixels(root: Path, book: Path, line: str, where: str, problems: list[str]) -> str:
    """A line's {{#pixel picture.png:X,Y (R, G, B)}} directives replaced by the colour
    shown, each checked against that pixel of the picture."""
    def one(match: re.Match) -> str:
        path_text, x, y, shown = match.groups()
        target = book / path_text
        if not inside_root(root, target) or not target.is_file():
            problems.append(f"{where}: {{{{#pixel}}}} names {path_text}, which does not exist here")
            return shown
        if target not in _pictures:
            sys.path.insert(0, str(Path(__file__).resolve().parent / "diagrams"))
            from golden import read_png  # the diagrams' PNG reader, standard library only
            try:
                _pictures[target] = read_png(target)
            except SystemExit as error:
                problems.append(f"{where}: {error}")
                return shown
        rows = _pictures[target]
        x, y = int(x), int(y)
        if not (0 <= y < len(rows) and 0 <= x < len(rows[0])):
            problems.append(f"{where}: pixel ({x}, {y}) lies outside {path_text}")
            return shown
        written = tuple(int(v) for v in re.findall(r"[0-9]+", shown))
        if written != tuple(rows[y][x]):
            problems.append(f"{where}: the page says {shown} where pixel ({x}, {y}) of {path_text} is "
                            f"{tuple(rows[y][x])}")
        return shown
    line = PIXEL_RE.sub(one, line)
    if PIXEL_START_RE.search(line):
        problems.append(f"{where}: malformed {{{{#pixel}}}} (want '{{{{#pixel <picture.png>:X,Y (R, G, B)}}}}')")
        line = PIXEL_START_RE.sub("{{pixel", line)
    return line


# Maths is typeset by KaTeX (Debian's libjs-katex, copied into the book), from
# TeX between \( and \) in a line, or \[ and \] on a line of its own (a
# display). The builder keeps the TeX away from Markdown (whose _ and * would
# make emphasis of it) and hands it to the page as <span class="math">TeX</span>,
# which book/theme/book.js renders; a formula KaTeX cannot parse is a console
# error, which the browser test reports. Never inside `code`.
MATH_RE = re.compile(r"(`+)(.*?)\1|\\\[(.+?)\\\]|\\\((.+?)\\\)")
MATH_TOKEN = "VKTMATH{}X"
MATH_TOKEN_RE = re.compile(r"(<p>)?VKTMATH([0-9]+)X(</p>)?")
KATEX_DIR = Path(os.environ.get("VKT_KATEX_DIR", "/usr/share/javascript/katex"))
KATEX_FILES = ("katex.min.js", "katex.min.css")


def extract_math(line: str, page: Page, where: str, problems: list[str]) -> str:
    def one(match: re.Match) -> str:
        if match.group(1):
            return match.group(0)  # inline code stays code
        display = match.group(3) is not None
        tex = (match.group(3) if display else match.group(4)).strip()
        if not tex:
            problems.append(f"{where}: an empty formula")
        if display and line.strip() != match.group(0):
            problems.append(f"{where}: a display formula \\[ ... \\] stands on a line of its own")
        page.math.append((tex, display))
        return MATH_TOKEN.format(len(page.math) - 1)
    line = MATH_RE.sub(one, line)
    unclosed = re.sub(r"`+.*?`+", "", line)
    if "\\(" in unclosed or "\\[" in unclosed:
        problems.append(f"{where}: a formula opened with \\( or \\[ is not closed on the same line")
    return line


def place_math(body: str, math: list[tuple[str, bool]]) -> str:
    def one(match: re.Match) -> str:
        tex, display = math[int(match.group(2))]
        if display:
            inner = f'<div class="math display">{html.escape(tex)}</div>'
            return inner if match.group(1) and match.group(3) else \
                (match.group(1) or "") + inner + (match.group(3) or "")
        return (match.group(1) or "") + f'<span class="math">{html.escape(tex)}</span>' + (match.group(3) or "")
    return MATH_TOKEN_RE.sub(one, body)


# Frames are named by their index, from 0 (appendix_headless.md, "Which frame the
# pictures show"): never by position ("the tenth frame"), and a frame's time is
# its index / 60 s, so "frame 10 (t = 0.15 s)" is wrong twice over.
FRAME_POSITION_RE = re.compile(r"\b(third|fourth|fifth|sixth|seventh|eighth|ninth|tenth|[0-9]+(?:st|nd|rd|th)) "
                               r"frame\b", re.I)
FRAME_TIME_RE = re.compile(r"\bframe ([0-9]+) \(t = ([0-9.]+) s\)")


def frame_name_problems(text: str, where: str) -> list[str]:
    problems = []
    for match in FRAME_POSITION_RE.finditer(text):
        problems.append(f"{where}: '{match.group(0)}': name a frame by its index from 0 (a run with "
                        "--frames N ends on frame N-1), not by its position")
    for match in FRAME_TIME_RE.finditer(text):
        index, shown = int(match.group(1)), match.group(2)
        decimals = len(shown.split(".", 1)[1]) if "." in shown else 0
        if round(index / 60, decimals) != float(shown):
            problems.append(f"{where}: '{match.group(0)}': frame {index} is at t = {index / 60:.{decimals}f} s "
                            f"(its index / 60); t = {shown} s is frame {round(float(shown) * 60)}")
    return problems


# --------------------------------------------------------------------------
# What a chapter page must be
# --------------------------------------------------------------------------

# Every chapter page ends the same way, so a reader always knows where to look.
CHAPTER_ENDING = ("What you should see", "Try it", "Recap")
# Lab notes belong in the performance part (performance.md, perf_*.md), not in
# a chapter: machine load, driver versions and commit ids date a page and teach
# nothing. Program output quoted in a code block is checked too: a sample run
# shows `llvmpipe (LLVM …)` and `Vulkan 1.x.y`, since the reader's versions differ.
LAB_NOTES = (
    (re.compile(r"load average", re.I), "a load average"),
    (re.compile(r"\bdriver (?:version )?\d"), "a driver version"),
    (re.compile(r"\bMesa \d"), "a Mesa version"),
    (re.compile(r"\bLLVM \d[\d.]*"), "an LLVM version"),
    # major.minor.patch, also at the end of a sentence ("... 1.3.239.")
    (re.compile(r"(?<!\d)(?<!\d\.)\d+\.\d+\.\d+(?!\d)(?!\.\d)"), "a version number (driver, loader, SDK or layer)"),
    (re.compile(r"(?<![0-9A-Za-z_-])(?=[0-9a-f]*[a-f])(?=[0-9a-f]*[0-9])[0-9a-f]{7,40}(?![0-9A-Za-z_])"),
     "a commit id"),
)


MAX_PAGE_LINES = 450  # of Markdown, on every page


def scan_lab_notes(where: str, lines: list[str]) -> tuple[list[str], list[tuple[str, int]]]:
    """A page's lab notes (in its prose or in the program output its code blocks quote; the
    sources they include are not read here), and its level-2 headings with their lines."""
    problems = []
    sections: list[tuple[str, int]] = []
    fence = None
    for number, line in enumerate(lines, start=1):
        match = FENCE_RE.match(line)
        if fence is None and match:
            fence = match.group(2)
            continue
        if fence is not None and match and match.group(2).startswith(fence) and not match.group(3):
            fence = None
            continue
        if fence is None and line.startswith("## "):
            sections.append((line[3:].strip(), number))
        if "{{#include" in line:
            continue
        for pattern, what in LAB_NOTES:
            found = pattern.search(line)
            if found:
                inside = " (in a code block)" if fence is not None or line.startswith(("    ", "\t")) else ""
                problems.append(f"{where}:{number}: {what} ('{found.group(0)}'){inside} belongs in the "
                                "performance part, not in a chapter page")
    return problems, sections


def check_chapter_page(book: Path, page: Page) -> list[str]:
    """The ending every chapter page shares, and no lab notes in its prose or in the
    program output its code blocks quote (the sources they include are not read here)."""
    where = f"book/{page.md_name}"
    lines = (book / page.md_name).read_text(encoding="utf-8").splitlines()
    problems, sections = scan_lab_notes(where, lines)
    last = tuple(name for name, _ in sections[-len(CHAPTER_ENDING):])
    if last != CHAPTER_ENDING:
        problems.append(f"{where}: a chapter page must end with the sections "
                        + ", ".join(f"'## {name}'" for name in CHAPTER_ENDING)
                        + " (its last sections are " + ", ".join(f"'{n}'" for n in last) + ")")
        return problems
    start = {name: number for name, number in sections}
    try_it = lines[start["Try it"]:start["Recap"] - 1]
    items = [line for line in try_it if line.startswith("- ")]
    if len(items) < 3:
        problems.append(f"{where}:{start['Try it']}: 'Try it' has {len(items)} exercise(s); "
                        "a chapter page gives at least three")
    if not any("`ctest " in line or "--verify" in line or "`./build/" in line for line in try_it):
        problems.append(f"{where}:{start['Try it']}: no exercise in 'Try it' gives a command "
                        "(a ctest line, a --verify run or a ./build/ command) that checks it")
    if "](#" not in "\n".join(lines[start["Recap"]:]):
        problems.append(f"{where}:{start['Recap']}: the 'Recap' links nothing on the page; "
                        "link each call or structure to where the page first uses it")
    return problems


def check_sub_page(book: Path, page: Page, core: Page | None) -> list[str]:
    """A sub-page goes further than its chapter's core page: the core exists and links
    to it, and it keeps no lab notes (the closing sections are the core's)."""
    where = f"book/{page.md_name}"
    if core is None:
        return [f"{where}: a sub-page of chapter {page.md_name[:2]}, which has no core page "
                f"book/{page.md_name[:2]}_name.md"]
    problems = []
    if f"]({page.md_name}" not in (book / core.md_name).read_text(encoding="utf-8"):
        problems.append(f"{where}: its chapter's core page, book/{core.md_name}, does not link to it")
    problems += scan_lab_notes(where, (book / page.md_name).read_text(encoding="utf-8").splitlines())[0]
    return problems


ATTR_RE = re.compile(r'\b(href|src)="([^"]*)"')


@dataclass
class Assets:
    images: dict[str, Path] = field(default_factory=dict)        # output name -> source file
    missing_images: dict[str, str] = field(default_factory=dict)  # output name -> rel path
    source_pages: set[str] = field(default_factory=set)           # rel paths to render
    diagrams: dict[str, Path] = field(default_factory=dict)       # output name -> .py or .dot
    diagram_svgs: dict[str, str] = field(default_factory=dict)    # output name -> the SVG drawn


def rewrite_links(root: Path, book: Path, page: Page, page_names: set[str], assets: Assets,
                  problems: list[str], warnings: list[str], anchors: list) -> None:
    source_lines = (book / page.md_name).read_text(encoding="utf-8").splitlines()

    def at(target: str) -> str:
        """book/page.md:N, N being the first line that mentions the target."""
        for number, line in enumerate(source_lines, start=1):
            if f"({target}" in line or f"<{target}>" in line or f'"{target}"' in line:
                return f"book/{page.md_name}:{number}"
        return f"book/{page.md_name}"

    def fix(match: re.Match) -> str:
        attr, value = match.group(1), html.unescape(match.group(2))
        if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", value) or value.startswith("//"):
            return match.group(0)  # http:, https:, mailto: ... left alone
        if value.startswith("#"):
            anchors.append((at(value), page.md_name, value[1:]))
            return match.group(0)
        if value.startswith("src/") and value.split("#")[0].endswith(".html"):
            return match.group(0)  # an include caption, made above
        path_text, _, anchor = value.partition("#")
        if path_text in page_names:
            if anchor:
                anchors.append((at(value), path_text, anchor))
            new = path_text[:-3] + ".html" + (f"#{anchor}" if anchor else "")
            return f'{attr}="{html.escape(new)}"'
        if path_text.endswith(".md") and "/" not in path_text:
            problems.append(f"{at(path_text)}: link to {path_text}, which is not a page of the book")
            return match.group(0)
        target = book / path_text
        if not inside_root(root, target):
            problems.append(f"{at(path_text)}: link to {path_text}, outside the repository")
            return match.group(0)
        rel = target.resolve().relative_to(root.resolve()).as_posix() if target.exists() else \
            os.path.normpath((Path("book") / path_text).as_posix())
        if path_text.lower().endswith(IMAGE_SUFFIXES):
            name = PurePosixPath(rel).name
            diagram = diagram_source(target)
            if diagram is not None:
                known = assets.diagrams.get(name)
                if name in assets.images or (known is not None and known != diagram):
                    problems.append(f"{at(path_text)}: two different images are called {name}")
                assets.diagrams[name] = diagram
            elif target.is_file():
                known = assets.images.get(name)
                if name in assets.diagrams or (known is not None and known.resolve() != target.resolve()):
                    problems.append(f"{at(path_text)}: two different images are called {name}")
                assets.images[name] = target
            else:
                # A reviewed picture may land after its page; say so and show a placeholder.
                warnings.append(f"{at(path_text)}: image {path_text} does not exist (yet)")
                assets.missing_images[name] = rel
            return f'{attr}="images/{html.escape(name)}"'
        if target.is_dir():
            problems.append(f"{at(path_text)}: link to the folder {path_text}; link a file instead")
            return match.group(0)
        if not target.is_file():
            problems.append(f"{at(path_text)}: link to {path_text}, which does not exist")
            return match.group(0)
        if anchor and not re.fullmatch(r"L-\d+", anchor):
            # A source page's only anchors are its lines (L-N): no headings.
            problems.append(f"{at(value)}: link to {value}: a source file's page has no "
                            f"anchor '{anchor}', only lines (#L-N)")
            return match.group(0)
        assets.source_pages.add(rel)
        new = source_page_name(rel) + (f"#{anchor}" if anchor else "")
        return f'{attr}="{html.escape(new)}"'

    page.body = ATTR_RE.sub(fix, page.body)


def diagram_source(target: Path) -> Path | None:
    """NAME.py or NAME.dot beside a picture NAME.svg that does not exist, else None."""
    if target.suffix.lower() != ".svg" or target.exists():
        return None
    for suffix in DIAGRAM_SOURCES:
        source = target.with_suffix(suffix)
        if source.is_file():
            return source
    return None


# A diagram script that reads VKT_DIAGRAM_LAYOUT also draws a narrow layout of
# itself (VKT_DIAGRAM_LAYOUT=narrow) for phones: NAME.narrow.svg, which a page on
# a narrow screen shows instead of NAME.svg (a <picture>), the wide one still what
# a tap opens.
NARROW_LAYOUT = "VKT_DIAGRAM_LAYOUT"


def render_diagram(root: Path, source: Path, layout: str = "") -> str:
    """Draws one diagram and checks that it is an SVG with text; BookError if not."""
    rel = source.resolve().relative_to(root.resolve()).as_posix()
    if source.suffix == ".py":
        command = [sys.executable, source.name]
    else:
        dot = shutil.which("dot")
        if dot is None:
            raise BookError(f"{rel}: drawing it needs Graphviz's dot (on Debian: apt install graphviz)")
        command = [dot, "-Tsvg", source.name]
    try:
        run = subprocess.run(command, cwd=source.parent, capture_output=True, text=True, timeout=120,
                             env=dict(os.environ, PYTHONDONTWRITEBYTECODE="1", VKT_DIAGRAM_LAYOUT=layout))
    except (OSError, subprocess.TimeoutExpired) as error:
        raise BookError(f"{rel}: cannot draw the diagram: {error}") from None
    if run.returncode != 0:
        last = (run.stderr.strip().splitlines() or ["no message"])[-1]
        raise BookError(f"{rel}: drawing the diagram failed (exit status {run.returncode}): {last}")
    svg = run.stdout
    if source.suffix == ".dot":
        # Graphviz sizes its drawing in points; in a browser 1 pt is 4/3 px, which
        # would show the text a third larger than the .dot file asks for.
        svg = re.sub(r'<svg width="([0-9.]+)pt" height="([0-9.]+)pt"', r'<svg width="\1" height="\2"', svg,
                     count=1)
        svg = re.sub(r"<!-- Generated by graphviz[^>]*-->\n?", "", svg)
    try:
        tree = ElementTree.fromstring(svg)
    except ElementTree.ParseError as error:
        raise BookError(f"{rel}: the diagram is not well-formed SVG: {error}") from None
    if not tree.tag.endswith("svg"):
        raise BookError(f"{rel}: the diagram's output is not an SVG")
    if not any(el.tag.endswith("text") and "".join(el.itertext()).strip() for el in tree.iter()):
        raise BookError(f"{rel}: the diagram has no text (labels must be SVG text, not paths)")
    return svg


INLINE_CODE_RE = re.compile(r"<code>(.*?)</code>", re.S)
PRE_RE = re.compile(r"<pre\b.*?</pre>", re.S)


def polish(body: str) -> str:
    """Small fixes to a page's HTML: flags that do not break, the chapter's list of
    files marked as such, diagrams and charts that open full size."""
    def flags(match: re.Match) -> str:
        # "--size 640x480": a line may break between words, never inside a flag.
        words = re.split(r"( +)", match.group(1))
        return "<code>" + "".join(
            f'<span class="flag">{w}</span>' if w.startswith("-") and len(w) <= 48 else w
            for w in words) + "</code>"
    parts, at = [], 0
    for pre in PRE_RE.finditer(body):
        parts.append(INLINE_CODE_RE.sub(flags, body[at:pre.start()]))
        parts.append(pre.group(0))
        at = pre.end()
    parts.append(INLINE_CODE_RE.sub(flags, body[at:]))
    body = "".join(parts)
    body = re.sub(r"<ul>(\s*<li>(?:Sources|Run it):)", r'<ul class="chapter-files">\1', body)
    body = re.sub(r'(<img\b[^>]*\bsrc="(images/[^"]+\.svg)"[^>]*>)', r'<a class="figure" href="\2">\1</a>', body)
    # A section past a long chapter's core ("## Going further: ...") is marked as such.
    body = re.sub(r'<h2 id="(going-further-[^"]*)">', r'<h2 class="going-further" id="\1">', body)
    return body


# An aside a first reader may skip ("## ... (skip on a first read)", the house
# rule) is folded: a <details> whose summary is its heading, closed on the
# screen until the reader opens it or a link leads into it (book/theme/book.js),
# unfolded in the one-page book that prints. It runs to the next heading of its own
# level or higher.
SKIP_MARK = "(skip on a first read)"
ANY_HEADING_RE = re.compile(r"<h([1-6])\b[^>]*>(.*?)</h\1>", re.S)


def fold_asides(body: str) -> str:
    headings = list(ANY_HEADING_RE.finditer(body))
    out, at = [], 0
    for i, heading in enumerate(headings):
        level = int(heading.group(1))
        if heading.start() < at or not plain(heading.group(2)).strip().endswith(SKIP_MARK):
            continue
        end = next((h.start() for h in headings[i + 1:] if int(h.group(1)) <= level), len(body))
        out.append(body[at:heading.start()])
        out.append(f'<details class="aside"><summary>{heading.group(0)}</summary>'
                   f'{body[heading.end():end]}</details>\n')
        at = end
    out.append(body[at:])
    return "".join(out)


# Figures and tables that read at any width. An SVG figure shows shrunk to the
# column; a tap or click opens it full size (book/theme/book.js), zoomed so its
# smallest text is at least FIGURE_TEXT_PX pixels, and a line under it says so.
FIGURE_TEXT_PX = 12
# A figure's smallest text as shown on a phone (book/theme/style.css shows it at
# least --phone-width wide there): above the browser test's 9 px at 400 px.
PHONE_TEXT_PX = 9.6
PHONE_COLUMN_PX = 360  # the column's width on a 400 px phone, about
FIGURE_HINT = "Tap or click the figure to open it full size."
FIGURE_RE = re.compile(r'<a class="figure" href="images/([^"]+\.svg)">(<img\b[^>]*>)</a>')
FONT_SIZE_RE = re.compile(r"font-size\s*:\s*([0-9.]+)(px|em|%)?|font\s*:[^;]*?([0-9.]+)(px|em|%)")


def svg_text_metrics(svg: str) -> tuple[float, float] | None:
    """An SVG's width in its own units (its viewBox, else its width) and the size of
    its smallest text in the same units, following font sizes down the tree (an
    attribute, a style's font-size or font, em and % of the parent's); None without
    text or a width."""
    try:
        tree = ElementTree.fromstring(svg)
    except ElementTree.ParseError:
        return None
    box = (tree.get("viewBox") or "").replace(",", " ").split()
    try:
        width = float(box[2]) if len(box) == 4 else float(re.match(r"[0-9.]+", tree.get("width", "")).group(0))
    except (AttributeError, ValueError):
        return None
    smallest: list[float] = []

    def size_of(element, inherited: float) -> float:
        found = None
        attribute = element.get("font-size")
        if attribute:
            found = re.match(r"\s*([0-9.]+)(px|em|%)?", attribute)
            found = found and (found.group(1), found.group(2))
        style = FONT_SIZE_RE.search(element.get("style", ""))
        if style:
            found = (style.group(1), style.group(2)) if style.group(1) else (style.group(3), style.group(4))
        if not found:
            return inherited
        number, unit = float(found[0]), found[1]
        return number * inherited if unit == "em" else number * inherited / 100 if unit == "%" else number

    def walk(element, inherited: float) -> None:
        size = size_of(element, inherited)
        tag = element.tag.rsplit("}", 1)[-1]
        if tag in ("text", "tspan") and (element.text or "").strip():
            smallest.append(size)
        for child in element:
            walk(child, size)
            if tag in ("text", "tspan") and (child.tail or "").strip():
                smallest.append(size)
    walk(tree, 16.0)
    return (width, min(smallest)) if smallest and width > 0 else None


def annotate_figures(body: str, svgs: dict[str, str]) -> str:
    """Each SVG figure gets its width and smallest text (for the full-size view) and
    the line under it that says it opens full size."""
    def fix(match: re.Match) -> str:
        metrics = svg_text_metrics(svgs.get(html.unescape(match.group(1)), ""))
        if metrics is None:
            return match.group(0)
        width, text = metrics
        img = match.group(2)
        narrow_name = html.unescape(match.group(1))[:-4] + ".narrow.svg"
        narrow = svg_text_metrics(svgs.get(narrow_name, ""))
        if narrow is not None:  # on a phone the narrow layout, and its text decides the width
            img = (f'<picture><source media="screen and (max-width: 52rem)" srcset="images/{html.escape(narrow_name)}">'
                   f'{img}</picture>')
            phone = max(0.0, narrow[0] * PHONE_TEXT_PX / narrow[1])
        else:
            phone = max(0.0, width * PHONE_TEXT_PX / text)
        scrolls = ('<span class="narrow-only"> On a narrow screen it scrolls sideways.</span>'
                   if phone > PHONE_COLUMN_PX else "")
        # On a phone the figure is shown at least `phone` wide, in a box that scrolls
        # sideways, so that its smallest text reads at PHONE_TEXT_PX as shown.
        return (f'<span class="figure-scroll" style="--phone-width: {phone:.0f}px">'
                f'<a class="figure" href="images/{match.group(1)}" data-width="{width:g}" '
                f'data-min-text="{text:g}" data-text-px="{FIGURE_TEXT_PX}">{img}</a></span>'
                f'<span class="figure-hint">{FIGURE_HINT}{scrolls}</span>')
    return FIGURE_RE.sub(fix, body)


def wrap_tables(body: str) -> str:
    """A table scrolls sideways as a whole inside its own box, never the page; a line
    above it (shown by book/theme/book.js only where the table is wider than the
    column) says so."""
    return re.sub(r"(<table\b.*?</table>)",
                  r'<div class="table-wrap"><p class="scroll-hint">Wider than the page: scroll the table '
                  r'sideways &rarr;</p><div class="table-scroll" tabindex="0">\1</div></div>', body, flags=re.S)


# What a word's place on a page says about it, for the search: a section's
# heading, what the recap's list of new calls says is taught there, its prose,
# its code, and the comments inside that code (weakest: a passing remark).
COMMENT_CLASSES = ("c", "c1", "cm", "ch", "cs")
COMMENT_SPAN_RE = re.compile(r'<span class="(?:%s)">(.*?)</span>' % "|".join(COMMENT_CLASSES), re.S)
# In a code block the highlighter did not colour (no language): `// ...` to the end of the line.
PLAIN_COMMENT_RE = re.compile(r"(?:^|(?<=\s))//[^\n]*", re.M)
CAPTION_RE = re.compile(r'<p class="source">.*?</p>', re.S)
FILES_LIST_RE = re.compile(r'<ul class="chapter-files">.*?</ul>', re.S)
HEADING_RE = re.compile(r'<h([1-4])\b[^>]*\bid="([^"]*)"[^>]*>(.*?)</h\1>', re.S)
LOCAL_LINK_RE = re.compile(r'<a\b[^>]*\bhref="((?:\d\d[b-z]_[a-z0-9_]+\.html)?#[^"]+|\d\d[b-z]_[a-z0-9_]+\.html)"[^>]*>(.*?)</a>',
                           re.S)


def plain(fragment: str) -> str:
    """HTML to plain text: block tags part words, inline ones (a highlighter's <span>s) do not."""
    spaced = re.sub(r"</?(?:p|br|li|ul|ol|div|h\d|pre|table|tr|td|th|blockquote)\b[^>]*>", " ", fragment)
    return re.sub(r"\s+", " ", html.unescape(re.sub(r"<[^>]+>", "", spaced))).strip()


def comment_text(comment: str) -> str:
    """A comment's words without its `//`, `/*`, `*/` or `#`."""
    text = re.sub(r"^\s*(?://+|/\*+|\*+/?|#+)\s?", "", comment, flags=re.M)
    return text.replace("*/", " ")


@dataclass
class SearchSection:
    anchor: str
    heading: str
    prose: list[str] = field(default_factory=list)
    code: list[str] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)
    recap: list[str] = field(default_factory=list)


def split_by_kind(fragment: str, section: SearchSection) -> None:
    """Sorts a section's HTML into prose, code (captions and file lists included) and code comments."""
    prose_parts, at = [], 0
    blocks = list(re.finditer(r'<div class="highlight">.*?</pre>\s*</div>|<pre\b.*?</pre>', fragment, re.S))
    for block in blocks:
        prose_parts.append(fragment[at:block.start()])
        at = block.end()
        code = block.group(0)
        if '<span class="' in code:
            comments = [comment_text(html.unescape(re.sub(r"<[^>]+>", "", c)))
                        for c in COMMENT_SPAN_RE.findall(code)]
            section.code.append(plain(COMMENT_SPAN_RE.sub(" ", code)))
        else:
            text = html.unescape(re.sub(r"<[^>]+>", "", code))
            comments = [comment_text(c) for c in PLAIN_COMMENT_RE.findall(text)]
            section.code.append(re.sub(r"\s+", " ", PLAIN_COMMENT_RE.sub(" ", text)).strip())
        section.comments.append(re.sub(r"\s+", " ", " ".join(comments)).strip())
    prose = "".join(prose_parts) + fragment[at:]
    for extra in (CAPTION_RE, FILES_LIST_RE):
        section.code += [plain(m) for m in extra.findall(prose)]
        prose = extra.sub(" ", prose)
    section.prose.append(plain(prose))


def recap_items(fragment: str) -> tuple[list[tuple[str, str]], str]:
    """The recap's entries: (anchor, words) for each link into the page (a link's own
    words, and the rest of its list item or paragraph for the item's first link),
    and what links nowhere (left as the recap's own prose)."""
    found: list[tuple[str, str]] = []
    rest: list[str] = []
    for item in re.findall(r"<li\b[^>]*>(.*?)</li>|<p\b[^>]*>(.*?)</p>", fragment, re.S):
        item = item[0] or item[1]
        links = LOCAL_LINK_RE.findall(item)
        if not links:
            rest.append(item)
            continue
        for anchor, text in links:
            found.append((html.unescape(anchor), plain(text)))
        found.append((html.unescape(links[0][0]), plain(LOCAL_LINK_RE.sub(" ", item))))
    return found, " ".join(rest)


def search_sections(page: Page) -> list[SearchSection]:
    """The page cut at its headings, each part's words sorted by where they stand.
    A chapter's recap is not a section of its own: its entries go to the sections
    they link to, as what those sections teach."""
    body = page.body
    sections: list[SearchSection] = []
    matches = list(HEADING_RE.finditer(body))
    pieces = []
    if not matches or matches[0].start() > 0:
        pieces.append(("", page.title, body[:matches[0].start() if matches else len(body)]))
    for i, match in enumerate(matches):
        end = matches[i + 1].start() if i + 1 < len(matches) else len(body)
        pieces.append((html.unescape(match.group(2)), plain(match.group(3)), body[match.end():end]))
    recap: list[tuple[str, str]] = []
    for anchor, heading, fragment in pieces:
        section = SearchSection(anchor, heading)
        if page.md_name[:2].isdigit() and heading == "Recap":  # a core page's or a sub-page's
            items, fragment = recap_items(fragment)
            recap += items
        split_by_kind(fragment, section)
        sections.append(section)
    by_anchor = {s.anchor: s for s in sections}
    for anchor, words in recap:
        target, _, anchor = anchor.partition("#")
        if target:  # an entry that links a sub-page of the chapter: taught there
            page.recap_elsewhere.append((target, anchor, words))
        elif anchor in by_anchor:
            by_anchor[anchor].recap.append(words)
    return [s for s in sections if s.heading or any(s.prose) or s.code or s.recap]


def search_index(pages: list[Page]) -> str:
    def kind(page: Page) -> str:
        if page.md_name == "index.md":
            return "index"
        if page.md_name == "performance.md" or page.md_name.startswith("perf_"):
            return "performance"
        return "chapter" if page.md_name[:2].isdigit() else "appendix"

    def joined(parts: list[str]) -> str:
        return " \u2022 ".join(p for p in parts if p.strip())
    data = {"pages": [[p.html_name, p.title, kind(p)] for p in pages], "sections": []}
    cut = {page.html_name: search_sections(page) for page in pages}
    for page in pages:  # a core page's recap entries that link its sub-pages' sections
        for target, anchor, words in page.recap_elsewhere:
            there = [s for s in cut.get(target, []) if s.anchor == anchor or (not anchor and s is cut[target][0])]
            if there:
                there[0].recap.append(words)
    for number, page in enumerate(pages):
        for s in cut[page.html_name]:
            data["sections"].append([number, s.anchor, s.heading, joined(s.recap), joined(s.prose),
                                     joined(s.code), joined(s.comments)])
    return ("// The book's search index, written by book/build_book.py; read by search.js.\n"
            "// Each section: [page, anchor, heading, recap, prose, code, code comments].\n"
            "window.BOOK_SEARCH_INDEX = " + json.dumps(data, ensure_ascii=False, separators=(",", ":")) + ";\n")


PLAIN_BLOCK_RE = re.compile(r'<div class="highlight">(<pre>(?:(?!</pre>).)*</pre>)', re.S)
COLUMNS_RE = re.compile(r"^\s*[|+]|\S {3,}\S", re.M)


def mark_plain_output(body: str) -> str:
    """A code block the highlighter did not colour (no language: a program's output,
    indented on the page) wraps its long lines, where code scrolls sideways: a
    count at the end of a printed line must be seen without scrolling."""
    def mark(match: re.Match) -> str:
        # Coloured code, and text laid out in columns (a matrix, a box drawn in
        # characters), keep their lines whole.
        if '<span class="' in match.group(1) or COLUMNS_RE.search(match.group(1)):
            return match.group(0)
        return '<div class="highlight output">' + match.group(1)
    return PLAIN_BLOCK_RE.sub(mark, body)


def convert(page: Page) -> None:
    md = markdown.Markdown(
        extensions=["fenced_code", "codehilite", "tables", "toc"],
        extension_configs={
            "codehilite": {"css_class": "highlight", "guess_lang": False},
            "toc": {"permalink": False},
        },
        output_format="html")
    page.body = place_math(mark_plain_output(md.convert(page.markdown)), page.math)
    page.toc = md.toc_tokens
    page.ids = set(re.findall(r'\bid="([^"]+)"', page.body))


def swallowed_list_items(page: Page) -> list[str]:
    """A list item written right after an indented paragraph, with no blank line
    between, is read as more of that paragraph: the page shows a literal "- "
    and the item's text runs on. Found in the HTML, outside code blocks."""
    text = re.sub(r"<pre[\s\S]*?</pre>", "", page.body)
    found = []
    for line in text.splitlines():
        if re.match(r"\s*- \S", line):
            shown = re.sub(r"<[^>]+>", "", line).strip()[:60]
            found.append(f"book/{page.md_name}: the list item '{shown}' runs into the "
                         "paragraph before it: put a blank line above it")
    return found


def missing_image_placeholders(body: str, missing: dict[str, str]) -> str:
    """Replaces <img> of pictures that do not exist yet by a visible note."""
    def fix(match: re.Match) -> str:
        tag = match.group(0)
        src = re.search(r'src="images/([^"]+)"', tag)
        if not src or html.unescape(src.group(1)) not in missing:
            return tag
        rel = missing[html.unescape(src.group(1))]
        alt = re.search(r'alt="([^"]*)"', tag)
        return (f'<span class="missing-image">Picture not available yet: {html.escape(rel)}'
                f'{" (" + alt.group(1) + ")" if alt and alt.group(1) else ""}</span>')
    return re.sub(r"<img\b[^>]*>", fix, body)


# --------------------------------------------------------------------------
# HTML
# --------------------------------------------------------------------------

def pygments_css() -> str:
    light = HtmlFormatter(style="default").get_style_defs(".highlight")
    dark = HtmlFormatter(style="monokai").get_style_defs(".highlight")
    # The panels' colours come from style.css, so the styles only colour tokens.
    strip = re.compile(r"^(?:pre \{ line-height: 125%; \}|\.highlight \{ background: [^}]*\}|"
                       r"\.highlight \.hll \{[^}]*\})$", re.M)
    light, dark = strip.sub("", light), strip.sub("", dark)
    dark = "\n".join("  " + line for line in dark.splitlines() if line.strip())
    return ("/* Code colours (pygments), written by book/build_book.py. */\n"
            f"{light.strip()}\n@media (prefers-color-scheme: dark) {{\n{dark}\n}}\n")


def sidebar(pages: list[Page], current: Page | None, prefix: str) -> str:
    items = []
    part = ""
    for page in pages:
        if part_of(page.md_name) != part:
            part = part_of(page.md_name)
            items.append(f'<li class="part">{html.escape(part)}</li>')
        mark = ' class="current" aria-current="page"' if page is current else ""
        sub = ' class="sub-page"' if SUB_PAGE_RE.match(page.md_name) else ""
        item = f'<li{sub}><a href="{prefix}{page.html_name}"{mark}>{html.escape(page.title)}</a>'
        if page is current and page.toc:
            sections = [t for t in page.toc if t["level"] == 1]
            subs = sections[0]["children"] if len(sections) == 1 else page.toc
            if subs:
                item += '<ol class="sections">' + "".join(
                    f'<li><a href="#{html.escape(t["id"])}">{t["name"]}</a></li>' for t in subs) + "</ol>"
        items.append(item + "</li>")
    return "<ol>" + "".join(items) + "</ol>"


def pager(pages: list[Page], index: int, where: str) -> str:
    parts = []
    if index > 0:
        prev = pages[index - 1]
        parts.append(f'<a class="prev" href="{prev.html_name}" rel="prev">&larr; {html.escape(prev.title)}</a>')
    if index + 1 < len(pages):
        nxt = pages[index + 1]
        parts.append(f'<a class="next" href="{nxt.html_name}" rel="next">{html.escape(nxt.title)} &rarr;</a>')
    return f'<nav class="pager {where}" aria-label="Previous and next page">{"".join(parts)}</nav>'


def document(title: str, book_title: str, prefix: str, side: str, content: str) -> str:
    full_title = title if title == book_title else f"{title} - {book_title}"
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(full_title)}</title>
<link rel="stylesheet" href="{prefix}style.css">
<link rel="stylesheet" href="{prefix}pygments.css">
<link rel="stylesheet" href="{prefix}katex/katex.min.css">
<script src="{prefix}search.js" defer></script>
<script src="{prefix}katex/katex.min.js" defer></script>
<script src="{prefix}book.js" defer></script>
</head>
<body>
<header class="topbar">
<a class="book-title" href="{prefix}index.html">{html.escape(book_title)}</a>
<a class="jump" href="#contents">Contents and search</a>
</header>
<div class="layout">
<nav class="sidebar" id="contents" aria-label="Pages of the book">
<p class="book-title"><a href="{prefix}index.html">{html.escape(book_title)}</a></p>
<form class="search" role="search" action="{prefix}index.html">
<input type="search" name="q" placeholder="Search the book (press /)" aria-label="Search the book"
 autocomplete="off" spellcheck="false">
<p class="search-status" aria-live="polite"></p>
<ol class="search-results"></ol>
</form>
{side}
</nav>
<div class="content">
{content}
</div>
</div>
</body>
</html>
"""


def render_page(pages: list[Page], index: int) -> str:
    page = pages[index]
    content = (pager(pages, index, "top") + '\n<main><article>\n' + page.body +
               '\n</article></main>\n' + pager(pages, index, "bottom"))
    return document(page.title, pages[0].title, "", sidebar(pages, page, ""), content)


def render_source(root: Path, rel: str, pages: list[Page]) -> str:
    text = (root / rel).read_text(encoding="utf-8")
    try:
        lexer = get_lexer_for_filename(rel, stripnl=False)
    except ClassNotFound:
        suffix = PurePosixPath(rel).suffix
        lexer = get_lexer_by_name("glsl", stripnl=False) if suffix in (".vert", ".frag", ".comp", ".glsl") \
            else TextLexer(stripnl=False)
    formatter = HtmlFormatter(linenos="inline", linespans="L", cssclass="highlight", wrapcode=True)
    # linespans gives each line <span id="L-N">; "L-N" is what captions link to.
    code = pygments.highlight(text, lexer, formatter)
    prefix = "../" * (rel.count("/") + 1)
    quoting = [p for p in pages if any(inc.rel == rel for inc in p.includes)]
    quoted = ""
    if quoting:
        quoted = ('<p class="quoted-in">Quoted in: ' + ", ".join(
            f'<a href="{prefix}{p.html_name}">{html.escape(p.title)}</a>' for p in quoting) + "</p>")
    content = (f'<main class="source-file"><article>\n<h1><code>{html.escape(rel)}</code></h1>\n'
               f'{quoted}\n{code}\n</article></main>')
    return document(rel, pages[0].title, prefix, sidebar(pages, None, prefix), content)


# --------------------------------------------------------------------------
# What changed since the previous chapter
# --------------------------------------------------------------------------

# A chapter's own files (every file of chapters/NN_name/ and shaders/NN_name/,
# whatever its suffix: CMakeLists.txt, .rgen, .mesh ...), compared with those of
# the chapter it builds on, and the files of common/ (or shaders/common/) it
# adds or changes, shown whole. The page declares both at its top:
#
#   <!-- builds on: 22_shadows
#        common: common/resources/include/vkt/resources/acceleration.hpp common/resources/src/acceleration.cpp -->
#
# Without that line a chapter builds on the chapter before it and touches no
# file of common/.
CHANGE_CONTEXT = 3  # unchanged lines shown around each change
SHADER_SUFFIXES = (".vert", ".frag", ".comp", ".glsl", ".task", ".mesh", ".rgen", ".rchit", ".rmiss", ".rahit",
                   ".rint", ".rcall", ".geom", ".tesc", ".tese")
BUILDS_ON_RE = re.compile(r"\A\s*<!--\s*builds on:\s*(\S+)(?:\s+common:\s*(.*?))?\s*-->", re.S)


@dataclass
class Lineage:
    base: str                 # "22_shadows": the chapter this one builds on
    common: list[str]         # files of common/ or shaders/common/ it adds or changes
    declared: bool            # whether the page says so (else: the chapter before, no common/)


def chapter_lineage(root: Path, book: Path, page: Page, previous: str, chapters: set[str],
                    problems: list[str]) -> Lineage:
    """What a chapter page declares it builds on, checked: an earlier chapter, and
    files of common/ that exist."""
    text = (book / page.md_name).read_text(encoding="utf-8")
    match = BUILDS_ON_RE.match(text)
    if not match:
        return Lineage(previous, [], False)
    where = f"book/{page.md_name}:1"
    base, common = match.group(1), (match.group(2) or "").split()
    if base not in chapters or base >= page.md_name[:-3]:
        problems.append(f"{where}: 'builds on: {base}' names no earlier chapter")
        base = previous
    for rel in common:
        if not rel.startswith(("common/", "shaders/common/")) or not (root / rel).is_file():
            problems.append(f"{where}: 'common: {rel}' is not a file of common/ or shaders/common/")
    return Lineage(base, [rel for rel in common if (root / rel).is_file()], True)


def chapter_files(root: Path, chapter: str) -> dict[str, str]:
    """A chapter's files as {name shown: path relative to the root}: chapters/NN_name/*
    and shaders/NN_name/*, matched with the base chapter's by that name."""
    found = {}
    for folder, label in (("chapters", ""), ("shaders", "shaders/")):
        base = root / folder / chapter
        if base.is_dir():
            for path in sorted(base.rglob("*")):
                if path.is_file():
                    found[label + path.relative_to(base).as_posix()] = path.relative_to(root).as_posix()
    return found


def highlighted_lines(rel: str, text: str) -> list[str]:
    """A file's lines as highlighted HTML, one string per line (the highlighter closes
    its spans at each line end)."""
    if rel.endswith(SHADER_SUFFIXES):
        lexer = get_lexer_by_name("glsl", stripnl=False)
    else:
        try:
            lexer = get_lexer_for_filename(rel, stripnl=False)
        except ClassNotFound:
            lexer = TextLexer(stripnl=False)
    code = pygments.highlight(text, lexer, HtmlFormatter(nowrap=True))
    lines = code.split("\n")
    return lines[:len(text.splitlines())]


@dataclass
class ChapterChanges:
    chapter: str          # "24_ray_queries"
    previous: str         # "22_shadows": the chapter it builds on
    html: str             # the diffs
    files: int            # files that differ, came or went
    added: int
    removed: int
    named: list[str] = field(default_factory=list)     # every file the page names (repository paths)
    common: int = 0       # files of common/ shown
    common_lines: int = 0
    declared: bool = False


def file_anchor(name: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", name.lower()).strip("-")


def file_diff(name: str, old_rel: str | None, new_rel: str | None, root: Path) -> tuple[str, int, int]:
    """One file's changes as HTML (a table of numbered lines: context, removed, added)
    and its counts of added and removed lines."""
    old_text = (root / old_rel).read_text(encoding="utf-8") if old_rel else ""
    new_text = (root / new_rel).read_text(encoding="utf-8") if new_rel else ""
    old_lines, new_lines = old_text.splitlines(), new_text.splitlines()
    old_html = highlighted_lines(old_rel, old_text) if old_rel else []
    new_html = highlighted_lines(new_rel, new_text) if new_rel else []
    matcher = difflib.SequenceMatcher(None, old_lines, new_lines, autojunk=False)
    rows, added, removed = [], 0, 0

    def row(kind: str, old_number, new_number, code: str) -> str:
        sign = {"ctx": " ", "del": "-", "add": "+"}[kind]
        return (f'<span class="d-{kind}"><span class="d-no">{old_number or ""}</span>'
                f'<span class="d-no">{new_number or ""}</span><span class="d-sign">{sign}</span>{code}</span>')
    for group in matcher.get_grouped_opcodes(CHANGE_CONTEXT):
        first_old, first_new = group[0][1], group[0][3]
        rows.append(f'<span class="d-hunk">@@ line {first_old + 1} of {old_rel or "(none)"}, '
                    f'line {first_new + 1} of {new_rel or "(none)"} @@</span>')
        for tag, i1, i2, j1, j2 in group:
            if tag == "equal":
                rows += [row("ctx", i + 1, j + 1, new_html[j]) for i, j in zip(range(i1, i2), range(j1, j2))]
                continue
            rows += [row("del", i + 1, None, old_html[i]) for i in range(i1, i2)]
            rows += [row("add", None, j + 1, new_html[j]) for j in range(j1, j2)]
            removed += i2 - i1
            added += j2 - j1
    if not rows:
        return "", 0, 0
    state = "new file" if not old_rel else "gone" if not new_rel else f"+{added} &minus;{removed}"
    title = new_rel or old_rel
    body = (f'<h2 id="{html.escape(file_anchor(name))}">'
            f'<code>{html.escape(title)}</code> <span class="d-count">{state}</span></h2>\n')
    if not new_rel:
        return (body + f"<p>Not in this chapter: the base chapter's own ({len(old_lines)} lines, "
                f"<code>{html.escape(old_rel)}</code>).</p>\n", 0, removed)
    return body + '<div class="highlight diff"><pre><code>' + "".join(rows) + "</code></pre></div>\n", added, removed


def common_file(rel: str, root: Path) -> tuple[str, int]:
    """A file of common/ that the chapter adds or changes, shown whole, its lines numbered."""
    text = (root / rel).read_text(encoding="utf-8")
    lines = highlighted_lines(rel, text)
    rows = "".join(f'<span class="d-ctx"><span class="d-no"></span><span class="d-no">{n}</span>'
                   f'<span class="d-sign"> </span>{code}</span>' for n, code in enumerate(lines, start=1))
    body = (f'<h2 id="{html.escape(file_anchor(rel))}"><code>{html.escape(rel)}</code> '
            f'<span class="d-count">in common, {len(lines)} lines</span></h2>\n'
            f'<div class="highlight diff"><pre><code>{rows}</code></pre></div>\n')
    return body, len(lines)


def chapter_changes(root: Path, chapter: str, lineage: Lineage) -> ChapterChanges:
    previous = lineage.base
    old, new = chapter_files(root, previous), chapter_files(root, chapter)
    parts, files, added, removed, same = [], 0, 0, 0, []
    names = sorted(set(old) | set(new), key=lambda n: (n.startswith("shaders/"), n != "main.cpp", n))
    for name in names:
        piece, plus, minus = file_diff(name, old.get(name), new.get(name), root)
        if piece:
            parts.append(piece)
            files += 1
            added += plus
            removed += minus
        elif name in new:
            same.append(new[name])
    if same:
        parts.append('<h2 id="unchanged">Unchanged</h2>\n<p>The same, line for line, as in chapter '
                     f'{previous[:2]}: ' + ", ".join(f"<code>{html.escape(rel)}</code>" for rel in same) + ".</p>\n")
    common_lines = 0
    if lineage.common:
        parts.append('<h2 id="common">In common/</h2>\n<p>The files of the helper library (and the shared '
                     'shaders) that this chapter adds or changes, whole: what later chapters call.</p>\n')
        for rel in lineage.common:
            piece, count = common_file(rel, root)
            parts.append(piece)
            common_lines += count
    named = sorted(new.values()) + list(lineage.common)
    return ChapterChanges(chapter, previous, "".join(parts), files, added, removed, named, len(lineage.common),
                          common_lines, lineage.declared)


def changes_page_name(chapter: str) -> str:
    return f"changes_{chapter}.html"


def changes_link(changes: ChapterChanges) -> str:
    common = ""
    if changes.common:
        common = (f"; and {changes.common} file{'s' if changes.common != 1 else ''} of <code>common/</code> "
                  "it adds or changes")
    return (f'<p class="changes-link">Builds on <a href="{changes.previous}.html">chapter {changes.previous[:2]}</a>: '
            f'<a href="{changes_page_name(changes.chapter)}">what changed since it</a>, {changes.files} '
            f'file{"s" if changes.files != 1 else ""}, +{changes.added} &minus;{changes.removed} lines in its own '
            f'folders{common}.</p>')


def render_changes(changes: ChapterChanges, page: Page, previous: Page, pages: list[Page]) -> str:
    title = f"Changes from chapter {changes.previous[:2]} to {changes.chapter[:2]}"
    common = ""
    if changes.common:
        common = (f" Then the {changes.common} file{'s' if changes.common != 1 else ''} of <code>common/</code> "
                  f"that this chapter adds or changes, whole ({changes.common_lines} lines).")
    content = (f'<main class="changes"><article>\n<h1>{html.escape(title)}</h1>\n'
               f'<p>Chapter <a href="{page.html_name}">{html.escape(page.title)}</a> against the chapter it '
               f'builds on, <a href="{previous.html_name}">{html.escape(previous.title)}</a>: each file of '
               f'<code>chapters/{changes.chapter}/</code> and <code>shaders/{changes.chapter}/</code> beside the '
               f'file of the same name in chapter {changes.previous[:2]}\'s folders, the lines that went in red '
               f'(&minus;), those that came in green (+), {CHANGE_CONTEXT} unchanged lines around each change; '
               f'the files that did not change are named after them. {changes.files} '
               f'file{"s" if changes.files != 1 else ""}, +{changes.added} &minus;{changes.removed} lines.'
               f'{common}</p>\n{changes.html}</article></main>')
    return document(title, pages[0].title, "", sidebar(pages, None, ""), content)


# --------------------------------------------------------------------------
# The whole book on one page, for print (and the PDF)
# --------------------------------------------------------------------------

PRINT_PAGE = "book.html"
CHANGES_LINK_RE = re.compile(r'<p class="changes-link">.*?</p>\n?', re.S)
ID_ATTR_RE = re.compile(r'\bid="([^"]*)"')
HREF_RE = re.compile(r'<a\b([^>]*?)\bhref="([^"]*)"')


def print_body(page: Page, page_names: set[str]) -> str:
    """A page's HTML for the one-page book: its ids prefixed with its name, so that
    no two pages' ids meet, and its links pointed at those ids (a link out of the
    book's pages, to a source file or a picture, keeps its words and loses its
    target: a printed page cannot follow it)."""
    stem = page.html_name[:-5]
    # The changes pages are for the screen (a diff beside the sources); the print
    # drops the line that links one rather than print a link that goes nowhere.
    body = CHANGES_LINK_RE.sub("", page.body)
    # Paper cannot unfold: a folded aside prints as its heading and text.
    body = re.sub(r'<details class="aside"><summary>(.*?)</summary>', r'<div class="aside">\1', body, flags=re.S)
    body = body.replace("</details>", "</div>")
    body = ID_ATTR_RE.sub(lambda m: f'id="{stem}--{m.group(1)}"', body)

    def link(match: re.Match) -> str:
        attrs, target = match.group(1), html.unescape(match.group(2))
        if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target):
            return match.group(0)
        path, _, anchor = target.partition("#")
        if not path:
            return f'<a{attrs}href="#{html.escape(stem)}--{html.escape(anchor)}"'
        if path in page_names:
            other = path[:-5]
            return f'<a{attrs}href="#{html.escape(other + "--" + anchor if anchor else other)}"'
        return f"<a{attrs}"
    return HREF_RE.sub(link, body)


def render_print(pages: list[Page]) -> str:
    names = {p.html_name for p in pages}
    parts = []
    for page in pages:
        part = part_of(page.md_name)
        parts.append(f'<section class="print-page" id="{page.html_name[:-5]}" data-part="{html.escape(part)}">\n'
                     f'{print_body(page, names)}\n</section>')
    title = pages[0].title
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{html.escape(title)}</title>
<link rel="stylesheet" href="style.css">
<link rel="stylesheet" href="pygments.css">
<link rel="stylesheet" href="katex/katex.min.css">
<script src="katex/katex.min.js" defer></script>
<script src="book.js" defer></script>
</head>
<body class="print-book">
<main><article>
{"".join(parts)}
</article></main>
</body>
</html>
"""


# --------------------------------------------------------------------------
# The build
# --------------------------------------------------------------------------

def build(root: Path, out: Path | None, strict: bool = False) -> tuple[list[str], list[str], int]:
    problems: list[str] = []
    warnings: list[str] = []
    book = root / "book"
    if not book.is_dir():
        raise BookError(f"{book} does not exist (is --root the repository root?)")

    names = sorted(p.name for p in book.glob("*.md") if p.is_file())
    for name in names:
        if not PAGE_RE.match(name):
            problems.append(f"book/{name}: a page must be called index.md, NN_name.md, "
                            "appendix_name.md, performance.md or perf_name.md (lower case)")
    names = [n for n in names if PAGE_RE.match(n)]
    if "index.md" not in names:
        problems.append("book/index.md does not exist")
    pages = [Page(name) for name in page_order(names)]
    numbers = {}
    for page in pages:
        if is_chapter(page.md_name):
            if page.md_name[:2] in numbers:
                problems.append(f"book/{page.md_name}: chapter number {page.md_name[:2]} is also "
                                f"used by book/{numbers[page.md_name[:2]]}")
            numbers[page.md_name[:2]] = page.md_name

    sources = Sources(root)
    for page in pages:
        expand_page(root, book, page, sources, problems)

    # Every chapter has its page, and a chapter page shows the chapter's
    # picture wherever the tests keep one (tests/golden/NN_name.png).
    page_names_md = {page.md_name for page in pages}
    chapters = root / "chapters"
    if chapters.is_dir():
        for folder in sorted(chapters.iterdir()):
            if folder.is_dir() and folder.name[:2].isdigit() and f"{folder.name}.md" not in page_names_md:
                problems.append(f"chapters/{folder.name} has no page book/{folder.name}.md")
    cores = {page.md_name[:2]: page for page in pages if is_chapter(page.md_name)}
    for page in pages:
        if is_chapter(page.md_name):
            problems.extend(check_chapter_page(book, page))
        elif SUB_PAGE_RE.match(page.md_name):
            problems.extend(check_sub_page(book, page, cores.get(page.md_name[:2])))
    # A page a reader finishes in one sitting: past MAX_PAGE_LINES, split it by
    # idea into a core page and sub-pages (CONTRIBUTING.md).
    for page in pages:
        count = len((book / page.md_name).read_text(encoding="utf-8").splitlines())
        if count > MAX_PAGE_LINES:
            problems.append(f"book/{page.md_name}: {count} lines, over {MAX_PAGE_LINES}: split it "
                            "by idea into a core page and sub-pages (NNb_name.md, CONTRIBUTING.md)")
    for page in pages:
        golden = f"tests/golden/{page.md_name[:-3]}.png"
        if is_chapter(page.md_name) and (root / golden).exists() and golden not in page.markdown:
            problems.append(f"book/{page.md_name}: does not show the chapter's picture, {golden}")

    # Every marker in the chapters, the helper library and the shaders must be
    # well formed and quoted somewhere: a marker nobody quotes is stale.
    quoted = {(inc.rel, inc.marker) for page in pages for inc in page.includes}
    for rel in all_marker_files(root):
        source = sources.get(rel)
        for name, region in source.regions.items():
            if (rel, name) not in quoted:
                problems.append(f"{rel}:{region.start}: marker [{name}] is quoted by no page (stale marker)")
    for source in sources.cache.values():
        problems.extend(source.problems)

    assets = Assets()
    anchors: list = []
    page_names = {p.md_name for p in pages}
    for page in pages:
        convert(page)
        problems.extend(swallowed_list_items(page))
        rewrite_links(root, book, page, page_names, assets, problems, warnings, anchors)
        page.body = fold_asides(polish(missing_image_placeholders(page.body, assets.missing_images)))
    by_name = {p.md_name: p for p in pages}
    for where, target, anchor in anchors:
        if anchor not in by_name[target].ids:
            problems.append(f"{where}: link to {target}#{anchor}, which has no such heading")

    assets.source_pages |= {inc.rel for p in pages for inc in p.includes}

    for name, source in sorted(assets.diagrams.items()):
        try:
            assets.diagram_svgs[name] = render_diagram(root, source)
        except BookError as error:
            problems.append(str(error))
            continue
        if source.suffix == ".py" and NARROW_LAYOUT in source.read_text(encoding="utf-8"):
            try:
                assets.diagram_svgs[name[:-4] + ".narrow.svg"] = render_diagram(root, source, "narrow")
            except BookError as error:
                problems.append(f"{error} (its narrow layout)")
        svg_words = html.unescape(re.sub(r"<[^>]+>", " ", assets.diagram_svgs[name]))
        problems.extend(frame_name_problems(re.sub(r"\s+", " ", svg_words),
                                            source.relative_to(root).as_posix()))

    # Each chapter after the first: what changed since the one before, linked
    # from the top of its page.
    chapter_pages = [p for p in pages if is_chapter(p.md_name)]
    chapter_names = {p.md_name[:-3] for p in chapter_pages}
    changes: list[tuple[ChapterChanges, Page, Page]] = []
    for previous, page in zip(chapter_pages, chapter_pages[1:]):
        lineage = chapter_lineage(root, book, page, previous.md_name[:-3], chapter_names, problems)
        found = chapter_changes(root, page.md_name[:-3], lineage)
        if found.files or found.common:
            changes.append((found, page, by_name[lineage.base + ".md"]))
            page.body = re.sub(r"(</h1>)", lambda m: m.group(1) + "\n" + changes_link(found), page.body, count=1)

    svgs = dict(assets.diagram_svgs)
    for name, path in assets.images.items():
        if name.endswith(".svg"):
            svgs[name] = path.read_text(encoding="utf-8")
    for page in pages:
        page.body = wrap_tables(annotate_figures(page.body, svgs))

    if strict:
        problems += warnings
        warnings = []
    problems = list(dict.fromkeys(problems))  # keep the order, drop repeats
    if problems or out is None:
        return problems, warnings, 0

    written = 0
    out.mkdir(parents=True, exist_ok=True)
    shutil.copyfile(THEME / "style.css", out / "style.css")
    shutil.copyfile(THEME / "search.js", out / "search.js")
    shutil.copyfile(THEME / "book.js", out / "book.js")
    # KaTeX, for the maths: its script, its stylesheet and the fonts beside it, so
    # that the book typesets offline (and in the PDF, which Chromium prints from it).
    if not all((KATEX_DIR / name).is_file() for name in KATEX_FILES):
        raise BookError(f"KaTeX is not in {KATEX_DIR} (the book typesets its maths with it): "
                        "apt install libjs-katex, or set VKT_KATEX_DIR to a folder with katex.min.js, "
                        "katex.min.css and fonts/")
    (out / "katex" / "fonts").mkdir(parents=True, exist_ok=True)
    for name in KATEX_FILES:
        shutil.copyfile(KATEX_DIR / name, out / "katex" / name)
    for font in sorted((KATEX_DIR / "fonts").glob("KaTeX_*.woff2")):
        shutil.copyfile(font, out / "katex" / "fonts" / font.name)
    (out / "pygments.css").write_text(pygments_css(), encoding="utf-8")
    (out / "search-index.js").write_text(search_index(pages), encoding="utf-8")
    written += 5
    for i, page in enumerate(pages):
        (out / page.html_name).write_text(render_page(pages, i), encoding="utf-8")
        written += 1
    (out / PRINT_PAGE).write_text(render_print(pages), encoding="utf-8")
    written += 1
    for found, page, previous in changes:
        text = render_changes(found, page, previous, pages)
        missing = [rel for rel in found.named if f"<code>{html.escape(rel)}</code>" not in text]
        if missing:  # every file of the chapter is on its changes page, diffed or named
            raise BookError(f"{changes_page_name(found.chapter)}: does not show {', '.join(missing)}")
        (out / changes_page_name(found.chapter)).write_text(text, encoding="utf-8")
        written += 1
    if assets.images or assets.diagram_svgs:
        (out / "images").mkdir(exist_ok=True)
        for name, path in sorted(assets.images.items()):
            shutil.copyfile(path, out / "images" / name)
            written += 1
        for name, svg in sorted(assets.diagram_svgs.items()):
            (out / "images" / name).write_text(svg, encoding="utf-8")
            written += 1
    for rel in sorted(assets.source_pages):
        target = out / source_page_name(rel)
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_text(render_source(root, rel, pages), encoding="utf-8")
        written += 1
    return problems, warnings, written


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(
        prog="build_book.py",
        description="Build the tutorial's book (book/*.md) into browsable HTML.")
    mode = parser.add_mutually_exclusive_group(required=True)
    mode.add_argument("--out", metavar="DIR", type=Path, help="write the HTML into DIR")
    mode.add_argument("--check", action="store_true",
                      help="validate includes, markers and links; write nothing")
    parser.add_argument("--root", metavar="DIR", type=Path,
                        default=Path(__file__).resolve().parent.parent,
                        help="the repository root (default: the folder above book/)")
    parser.add_argument("--strict", action="store_true",
                        help="treat warnings (a picture that does not exist yet) as errors")
    args = parser.parse_args(argv)

    try:
        problems, warnings, written = build(args.root.resolve(),
                                            None if args.check else args.out.resolve(), args.strict)
    except BookError as error:
        problems, warnings, written = [str(error)], [], 0
    except (OSError, UnicodeDecodeError) as error:
        problems, warnings, written = [f"cannot read or write a file: {error}"], [], 0

    for warning in warnings:
        sys.stderr.write(f"build_book.py: warning: {warning}\n")
    for problem in problems:
        sys.stderr.write(f"build_book.py: error: {problem}\n")
    if problems:
        count = len(problems)
        sys.stderr.write(f"build_book.py: the book was not built ({count} problem{'s' if count != 1 else ''})\n")
        return 1
    if args.check:
        print("build_book.py: the book checks out")
    else:
        print(f"build_book.py: wrote {written} files to {args.out}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
