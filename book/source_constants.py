"""The numbers a page or a diagram quotes from the sources, read from the sources.

A page names a constant instead of copying it silently:

    a list holds {{#number ../shaders/17_tiled_deferred/tiles.glsl:MAX_TILE_LIGHTS 2,048}} lights

shows "2,048", and book/build_book.py fails when MAX_TILE_LIGHTS in that file is
not 2048. After the name, `*K` and `/K` (whole numbers) scale it first:
`MAX_TILE_LIGHTS*4/1024 8` says that 2,048 four-byte entries are 8 KiB. A name
defined more than once in the file (a default, then a value for another device)
takes `#N`, its N-th definition in the file: `transform_group#2 64`.

A definition is a line (its `//` comment left out) that says `#define NAME 16`
or `NAME = 16`, with an optional integer or float suffix (`16u`, `0.5f`) and
digit separators (`1'024`). Diagrams (book/diagrams/*.py) read their numbers
with `constant()` in the same way, so a drawing cannot disagree with the code.

Standard library only.
"""

from __future__ import annotations

import re
from fractions import Fraction
from pathlib import Path

NUMBER_RE = re.compile(
    r"\{\{#number\s+([^\s:{}]+):([A-Za-z_][A-Za-z0-9_]*)(?:#([0-9]+))?((?:\s*[*/]\s*[0-9]+)*)\s+"
    r"([0-9][0-9,.]*)\s*\}\}")
# Anything that starts like the directive, to report a malformed one.
NUMBER_START_RE = re.compile(r"\{\{#number\b")

_LITERAL = r"([0-9][0-9']*(?:\.[0-9]+)?)(?:[uUlLfF]{0,3})\b"


class ConstantError(Exception):
    """A constant that is missing, ambiguous or not a number; one line."""


def definitions(text: str, name: str) -> list[tuple[int, Fraction]]:
    """Each definition of NAME in a source, as (line number, value), in file order."""
    define = re.compile(r"^\s*#\s*define\s+" + re.escape(name) + r"\s+\(?" + _LITERAL)
    assign = re.compile(r"(?<![A-Za-z0-9_])" + re.escape(name) + r"\s*=(?!=)\s*\(?" + _LITERAL)
    found = []
    for number, line in enumerate(text.splitlines(), start=1):
        code = line.split("//", 1)[0]
        match = define.search(code) or assign.search(code)
        if match:
            found.append((number, Fraction(match.group(1).replace("'", ""))))
    return found


def constant(path: Path | str, name: str, which: int | None = None, rel: str | None = None) -> Fraction:
    """The value of NAME in the source at PATH (its WHICH-th definition, 1-based,
    where there are several); ConstantError if there is none, or several and no WHICH."""
    path = Path(path)
    rel = rel or path.as_posix()
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as error:
        raise ConstantError(f"cannot read {rel}: {error.strerror}") from None
    found = definitions(text, name)
    if not found:
        raise ConstantError(f"{rel} defines no constant {name} (want '{name} = N' or '#define {name} N')")
    if which is None:
        if len(found) > 1:
            lines = ", ".join(str(n) for n, _ in found)
            raise ConstantError(f"{rel} defines {name} {len(found)} times (lines {lines}): "
                                f"say which, {name}#1 to {name}#{len(found)}")
        return found[0][1]
    if not 1 <= which <= len(found):
        raise ConstantError(f"{rel} defines {name} {len(found)} time(s), so {name}#{which} does not exist")
    return found[which - 1][1]


def scaled(value: Fraction, scale: str) -> Fraction:
    """VALUE after the page's `*K` and `/K`, in order."""
    for op, k in re.findall(r"([*/])\s*([0-9]+)", scale):
        if op == "*":
            value *= int(k)
        else:
            if int(k) == 0:
                raise ConstantError("a scale divides by 0")
            value /= int(k)
    return value


def shown_matches(shown: str, value: Fraction) -> bool:
    """Whether the number a page shows ("2,048", "8", "0.5") is VALUE, to the decimals shown."""
    digits = shown.replace(",", "")
    try:
        written = Fraction(digits)
    except ValueError:
        return False
    decimals = len(digits.split(".", 1)[1]) if "." in digits else 0
    return written == round(value, decimals) if decimals else written == value
