#!/usr/bin/python3
"""Renders every drawing chapter headless and writes a labelled contact sheet.

    /usr/bin/python3 scripts/gallery.py                       # -> book/images/gallery.png
    /usr/bin/python3 scripts/gallery.py --bin build/release/bin --out /tmp/gallery.png --keep /tmp/frames

A drawing chapter is one whose test keeps a golden picture (tests/golden/NN_name.png).
Each runs with --headless --no-validation --frames F --size WxH --screenshot, at
the same frame for all (F = 60: one second of the fixed 1/60 s clock, so the
sheet is the same on every run and device that draws alike); the pictures are
laid out three to a row under the titles of their book pages. Without a GPU,
point the loader at lavapipe as the tests do:

    VK_DRIVER_FILES=/usr/share/vulkan/icd.d/lvp_icd.json /usr/bin/python3 scripts/gallery.py

Needs the built chapters and Pillow (python3-pil, which python3-matplotlib
brings along). Exit status: 0 written, 1 a chapter failed or is not built, 2
the command line was wrong.
"""

from __future__ import annotations

import argparse
import concurrent.futures
import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
COLUMNS = 3
FONT = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
FONT_BOLD = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"


def drawing_chapters() -> list[str]:
    chapters = sorted(p.name for p in (ROOT / "chapters").iterdir() if p.is_dir() and p.name[:2].isdigit())
    return [c for c in chapters if (ROOT / "tests" / "golden" / f"{c}.png").is_file()]


def title_of(chapter: str) -> str:
    """'03 - The swapchain and the frame loop' from the chapter's book page."""
    page = ROOT / "book" / f"{chapter}.md"
    if page.is_file():
        for line in page.read_text(encoding="utf-8").splitlines():
            if line.startswith("# "):
                return line[2:].strip()
    return chapter


def render(binary: Path, chapter: str, frames: int, size: str, out: Path) -> tuple[str, str | None]:
    command = [str(binary), "--headless", "--no-validation", "--frames", str(frames), "--size", size,
               "--screenshot", str(out)]
    try:
        run = subprocess.run(command, capture_output=True, text=True, timeout=600)
    except subprocess.TimeoutExpired:
        return chapter, "took longer than 10 minutes"
    if run.returncode != 0 or not out.is_file():
        last = (run.stderr.strip().splitlines() or ["no message"])[-1]
        return chapter, f"exit status {run.returncode}: {last}"
    return chapter, None


def contact_sheet(pictures: list[tuple[str, Path]], target: Path) -> None:
    from PIL import Image, ImageDraw, ImageFont

    images = [(title, Image.open(path).convert("RGB")) for title, path in pictures]
    cell_w = max(im.width for _, im in images)
    cell_h = max(im.height for _, im in images)
    pad, label_h, head_h = 16, 30, 56
    rows = (len(images) + COLUMNS - 1) // COLUMNS
    width = COLUMNS * cell_w + (COLUMNS + 1) * pad
    height = head_h + rows * (cell_h + label_h + pad) + pad
    sheet = Image.new("RGB", (width, height), (255, 255, 255))
    draw = ImageDraw.Draw(sheet)
    try:
        font, bold = ImageFont.truetype(FONT, 15), ImageFont.truetype(FONT_BOLD, 22)
    except OSError:
        font = bold = ImageFont.load_default()
    draw.text((pad, 16), "Vulkan in C++20: every chapter that draws, headless, at frame 59 (the last of --frames 60)", fill=(31, 35, 40),
              font=bold)
    for i, (title, image) in enumerate(images):
        row, col = divmod(i, COLUMNS)
        x = pad + col * (cell_w + pad)
        y = head_h + row * (cell_h + label_h + pad)
        draw.text((x, y + 4), title, fill=(31, 35, 40), font=font)
        sheet.paste(image, (x, y + label_h))
        draw.rectangle([x - 1, y + label_h - 1, x + image.width, y + label_h + image.height], outline=(209, 217, 224))
    target.parent.mkdir(parents=True, exist_ok=True)
    sheet.save(target, optimize=True)


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="gallery.py", description=__doc__.splitlines()[0])
    parser.add_argument("--bin", type=Path, default=ROOT / "build" / "release" / "bin",
                        help="where the chapters are built (default: build/release/bin)")
    parser.add_argument("--out", type=Path, default=ROOT / "book" / "images" / "gallery.png",
                        help="the contact sheet (default: book/images/gallery.png)")
    parser.add_argument("--frames", type=int, default=60, help="the frame to show (default: %(default)s)")
    parser.add_argument("--size", default="400x225", help="each picture's size (default: %(default)s)")
    parser.add_argument("--keep", type=Path, help="keep each chapter's picture in this folder")
    parser.add_argument("--jobs", type=int, default=2, help="chapters rendered at once (default: %(default)s)")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:
        return 0 if exit_.code == 0 else 2
    if not re.fullmatch(r"\d+x\d+", args.size):
        print(f"gallery.py: --size wants WIDTHxHEIGHT, not '{args.size}'", file=sys.stderr)
        return 2

    chapters = drawing_chapters()
    missing = [c for c in chapters if not (args.bin / c).is_file()]
    if missing:
        print(f"gallery.py: error: not built in {args.bin}: {', '.join(missing)} "
              "(cmake --build --preset release)", file=sys.stderr)
        return 1
    with tempfile.TemporaryDirectory(prefix="gallery-") as temp:
        folder = args.keep or Path(temp)
        folder.mkdir(parents=True, exist_ok=True)
        failures = []
        with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.jobs)) as pool:
            jobs = [pool.submit(render, args.bin / c, c, args.frames, args.size, folder / f"{c}.png")
                    for c in chapters]
            for job in concurrent.futures.as_completed(jobs):
                chapter, problem = job.result()
                print(f"gallery.py: {chapter}: {problem or 'rendered'}", file=sys.stderr)
                if problem:
                    failures.append(chapter)
        if failures:
            print(f"gallery.py: error: {len(failures)} chapter(s) failed: {', '.join(sorted(failures))}",
                  file=sys.stderr)
            return 1
        contact_sheet([(title_of(c), folder / f"{c}.png") for c in chapters], args.out)
    print(f"gallery.py: wrote {args.out} ({len(chapters)} chapters)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
