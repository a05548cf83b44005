#!/usr/bin/env python3
"""Lists blocks of code that stand twice in chapters/ and common/.

A block is a run of at least --min-lines lines (default 10) that appears, line
for line, in two places; lines are compared with their indentation, blank lines
and // comments taken out, so a copy that was re-indented or re-commented still
counts. The blocks listed in CONTRIBUTING.md's table "Repeated on purpose" (by
the two files and a line of the block) are allowed; any other is printed and
the exit status is 1. The book's CTest label `house` runs it.

  scripts/find_duplicates.py            check the tree (exit 1 on a new block)
  scripts/find_duplicates.py --all      list every block, allowed ones too
  scripts/find_duplicates.py --root D   check the tree D instead (a test fixture)

A block that stands in three places is three pairs, each checked on its own:
listing two of its files does not allow a third copy.
"""
import argparse
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def code_lines(path):
    """(line number, normalised text) for each line that carries code."""
    out = []
    for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
        text = re.sub(r"//.*$", "", line).strip()
        if text and text not in ("{", "}", "};", ")", ");"):
            out.append((number, text))
    return out


def blocks(files, min_lines):
    """Maximal runs of >= min_lines normalised lines that occur in two places.

    Every pair of places is looked at, not only the first two: a block written
    three times is three pairs, so a third copy of an allowed pair is reported
    (unless its own pair is listed too)."""
    index = {}
    lines = {f: code_lines(f) for f in files}
    for f, ls in lines.items():
        for i in range(len(ls) - min_lines + 1):
            key = tuple(t for _, t in ls[i:i + min_lines])
            index.setdefault(key, []).append((f, i))
    found = {}
    for places in index.values():
        for p, (fa, ia) in enumerate(places):
            for fb, ib in places[p + 1:]:
                run = grow(lines, fa, ia, fb, ib)
                if run is None or run[4] < min_lines:
                    continue
                ia0, ib0, n = run[1], run[3], run[4]
                key = (fa, lines[fa][ia0][0], fb, lines[fb][ib0][0])
                found[key] = (fa, lines[fa][ia0][0], lines[fa][ia0 + n - 1][0],
                              fb, lines[fb][ib0][0], lines[fb][ib0 + n - 1][0], n)
    return sorted(found.values(), key=lambda b: (str(b[0]), b[1], str(b[3]), b[4]))


def grow(lines, fa, ia, fb, ib):
    """The whole run through places (fa, ia) and (fb, ib): (fa, start, fb, start, length).

    Grown back to the run's start, so that each run is reported once; within
    one file the two copies may not overlap."""
    if (fa, ia) == (fb, ib):
        return None
    while ia > 0 and ib > 0 and lines[fa][ia - 1][1] == lines[fb][ib - 1][1] and (fa, ia - 1) != (fb, ib):
        ia, ib = ia - 1, ib - 1
    n = 0
    while (ia + n < len(lines[fa]) and ib + n < len(lines[fb])
           and lines[fa][ia + n][1] == lines[fb][ib + n][1] and (fa != fb or ia + n < ib)):
        n += 1
    return fa, ia, fb, ib, n


def allowed_pairs(root):
    """File pairs from CONTRIBUTING.md's table: | `a` | `b` | reason |."""
    text = (root / "CONTRIBUTING.md").read_text() if (root / "CONTRIBUTING.md").exists() else ""
    section = text.split("### Repeated on purpose", 1)[-1] if "### Repeated on purpose" in text else ""
    # Only that section's own table: a later heading (such as "Alike in shape",
    # pairs this script does not see) allows nothing.
    section = re.split(r"^#", section, maxsplit=1, flags=re.M)[0]
    pairs = set()
    for a, b in re.findall(r"^\|\s*`([^`]+)`\s*\|\s*`([^`]+)`\s*\|", section, re.M):
        pairs.add(frozenset((a, b)))
    return pairs


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--min-lines", type=int, default=10)
    parser.add_argument("--all", action="store_true", help="list allowed blocks too")
    parser.add_argument("--root", type=pathlib.Path, default=ROOT,
                        help="the tree to scan: its chapters/, common/ and CONTRIBUTING.md "
                             "(default: this repository; the tests give a fixture)")
    args = parser.parse_args()
    root = args.root.resolve()
    files = sorted(p for d in ("chapters", "common") for p in (root / d).rglob("*")
                   if p.suffix in (".cpp", ".hpp"))
    allowed = allowed_pairs(root)
    new = 0
    for fa, a0, a1, fb, b0, b1, n in blocks(files, args.min_lines):
        ra, rb = fa.relative_to(root).as_posix(), fb.relative_to(root).as_posix()
        ok = frozenset((ra, rb)) in allowed
        if ok and not args.all:
            continue
        new += not ok
        print(f"{'allowed' if ok else 'REPEATED'}: {ra}:{a0}-{a1} and {rb}:{b0}-{b1} ({n} code lines)")
    if new:
        print(f"{new} block(s) of {args.min_lines} or more code lines stand twice: make one a helper in "
              "common/ (if an earlier chapter taught it), or list the pair with its reason in "
              "CONTRIBUTING.md under 'Repeated on purpose'.", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
