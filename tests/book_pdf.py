#!/usr/bin/python3
"""Prints the whole book to one PDF with headless Chromium, and checks that it holds every chapter.

    /usr/bin/python3 tests/book_pdf.py BOOK_DIR [--chromium PATH] [--skip-without-chromium]

BOOK_DIR is the output of book/build_book.py, which writes book.html there:
every page of the book in reading order on one page, each on new sheets when
printed (book/theme/style.css, @media print), ids prefixed with the page's
name so that links between pages become links inside the document. Chromium
prints it (--print-to-pdf, with the document outline from the headings) to
BOOK_DIR/book.pdf, and the run fails unless that PDF has:

  - every chapter (NN_name.html in BOOK_DIR) in its outline, by its title;
  - every chapter as a named destination at the top of a sheet (its page break);
  - working internal links: link annotations that go to named destinations,
    every one of which exists, at least one to each chapter.

Only the standard library reads the PDF (Chromium writes its objects
uncompressed; only page contents are compressed). The browser is found as
tests/book_browser.py finds it; without one the run fails, or with
--skip-without-chromium says so and exits 77 (CTest: skipped). Exit status: 0
all good, 1 a problem (one line each), 2 the command line was wrong, 77 skipped.
"""

from __future__ import annotations

import argparse
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.dont_write_bytecode = True
from book_browser import CHROMIUM_NAMES, SKIPPED, find_chromium  # noqa: E402

PRINT_FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
               "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-extensions",
               "--no-pdf-header-footer", "--generate-pdf-document-outline"]


def pdf_string(token: bytes) -> str:
    """A PDF string as text: (literal) or <hex>, the latter UTF-16 with its mark."""
    if token.startswith(b"<"):
        raw = bytes.fromhex(token[1:-1].decode())
        return raw[2:].decode("utf-16-be") if raw[:2] == b"\xfe\xff" else raw.decode("latin-1")
    text = re.sub(rb"\\([()\\])", rb"\1", token[1:-1])
    return text.decode("latin-1")


def check_pdf(pdf: bytes, chapters: dict[str, str]) -> tuple[list[str], str]:
    problems = []
    if not pdf.startswith(b"%PDF-"):
        return ["book.pdf is not a PDF"], ""
    sheets = len(re.findall(rb"/Type\s*/Page\b", pdf))
    titles = {pdf_string(t) for t in re.findall(rb"/Title\s*(<[0-9A-Fa-f]+>|\((?:[^()\\]|\\.)*\))", pdf)}
    # Named destinations: /name [page 0 R /XYZ left top zoom].
    dests = {m.group(1).decode(): (int(m.group(2)), float(m.group(3)))
             for m in re.finditer(rb"/([A-Za-z0-9_.#-]+) \[(\d+) 0 R /XYZ [0-9.-]+ ([0-9.-]+)", pdf)}
    heights = [float(h) for h in re.findall(rb"/MediaBox \[0 0 [0-9.]+ ([0-9.]+)\]", pdf)]
    height = max(heights) if heights else 792.0
    links = [m.decode() for m in re.findall(rb"/Subtype /Link\b[^>]*?/Dest /([A-Za-z0-9_.#-]+)", pdf, re.S)]
    for stem, title in chapters.items():
        if title not in titles:
            problems.append(f"book.pdf: chapter {stem} ('{title}') is not in the outline")
        if stem not in dests:
            problems.append(f"book.pdf: chapter {stem} is not a destination in the PDF (is it in book.html?)")
        elif dests[stem][1] < 0.85 * height:
            problems.append(f"book.pdf: chapter {stem} does not start a sheet (it begins {dests[stem][1]:.0f} pt "
                            f"up a {height:.0f} pt page)")
        if stem not in links:
            problems.append(f"book.pdf: no link goes to chapter {stem}")
    for target in sorted(set(links) - set(dests)):
        problems.append(f"book.pdf: a link goes to {target}, which is not a destination")
    if not links:
        problems.append("book.pdf: no internal links")
    return problems, f"{sheets} sheets, {len(chapters)} chapters in the outline, {len(links)} internal links"


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="book_pdf.py", description=__doc__.splitlines()[0])
    parser.add_argument("book", type=Path, help="the built book (book/build_book.py --out DIR)")
    parser.add_argument("--chromium", default="",
                        help="the browser (default: the first of " + ", ".join(CHROMIUM_NAMES) + ")")
    parser.add_argument("--skip-without-chromium", action="store_true",
                        help=f"without a browser, exit {SKIPPED} (skipped) instead of 1")
    parser.add_argument("--timeout", type=float, default=400.0, help="seconds printing may take")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:
        return 0 if exit_.code == 0 else 2
    book = args.book.resolve()
    source = book / "book.html"
    if not source.is_file():
        print(f"book_pdf.py: {book} holds no book.html (build the book with book/build_book.py)", file=sys.stderr)
        return 1
    chromium = find_chromium(args.chromium)
    if not chromium:
        tried = args.chromium or ", ".join(CHROMIUM_NAMES)
        if args.skip_without_chromium:
            print(f"book_pdf.py: skipped: no Chromium here (tried {tried}); the PDF is made where it is "
                  "(Debian: apt install chromium)")
            return SKIPPED
        print(f"book_pdf.py: error: Chromium is not installed ({tried} not found); on Debian, apt install "
              "chromium", file=sys.stderr)
        return 1

    # A link the PDF cannot follow is not printed as one: the screen's "What
    # changed since chapter NN" line links a page the PDF does not hold.
    printed = source.read_text(encoding="utf-8")
    if "changes_" in printed:
        print("book_pdf.py: book.html links a changes page (changes_NN_name.html), which the PDF does not hold",
              file=sys.stderr)
        return 1

    chapters = {}
    for page in sorted(book.glob("[0-9][0-9]_*.html")):
        title = re.search(r"<h1[^>]*>(.*?)</h1>", page.read_text(encoding="utf-8"), re.S)
        chapters[page.stem] = re.sub(r"<[^>]+>", "", title.group(1)).strip() if title else page.stem
    target = book / "book.pdf"
    target.unlink(missing_ok=True)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="book-pdf-") as profile:
        try:
            run = subprocess.run([chromium, *PRINT_FLAGS, f"--user-data-dir={profile}",
                                  f"--print-to-pdf={target}", source.as_uri()],
                                 capture_output=True, text=True, timeout=args.timeout, start_new_session=True)
        except subprocess.TimeoutExpired:
            print(f"book_pdf.py: Chromium did not print the book within {args.timeout:.0f} s", file=sys.stderr)
            return 1
    if run.returncode != 0 or not target.is_file():
        last = (run.stderr.strip().splitlines() or ["no message"])[-1]
        print(f"book_pdf.py: Chromium did not print the book (status {run.returncode}): {last}", file=sys.stderr)
        return 1
    problems, summary = check_pdf(target.read_bytes(), chapters)
    # The maths is typeset in the PDF too: KaTeX's fonts are embedded, not the TeX printed.
    if 'class="math' in printed and not re.search(rb"/BaseFont\s*/[A-Z]+\+KaTeX_Main", target.read_bytes()):
        problems.append("book.pdf: the book has maths but embeds no KaTeX font: it printed before KaTeX "
                        "typeset it, or without it")
    for problem in problems:
        print(f"book_pdf.py: {problem}", file=sys.stderr)
    if problems:
        return 1
    size = target.stat().st_size / (1 << 20)
    print(f"book_pdf.py: wrote {target} ({size:.1f} MiB, {summary}; {time.monotonic() - started:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
