#!/usr/bin/python3
"""Opens every page of the built book in headless Chromium and checks what a reader sees.

    /usr/bin/python3 tests/book_browser.py BOOK_DIR [--chromium PATH] [--pages REGEX]
                                          [--skip-without-chromium] [--layout-only]

BOOK_DIR is the output of book/build_book.py. Every HTML page in it is loaded
at 1280 and at 400 pixels wide (the second as a phone: a mobile viewport), and
the run fails on:

  - a picture that did not load (an <img> that is not complete, or 0 pixels wide);
  - horizontal overflow: the page wider than the window, so it scrolls sideways,
    or an element past the window's edge in no scrolling box (cut off where
    the page hides its overflow), or a code block wider than its box that
    neither scrolls nor wraps;
  - a console error, an uncaught exception, or a resource that failed to load;
  - a broken link: a file:// link to a file that does not exist, or to an
    anchor that the target page does not have.

It also types each of SEARCH_QUERIES into the search box of the index and
checks that the first result is the chapter that teaches it, linked at the
section that does (vkCmdPipelineBarrier2: chapter 03's barriers of a frame;
quaternion: 14; subgroup: 20d, a sub-page of 20; ...), with no raw `//` comment in any snippet,
and checks that every chart that
benchmarks/plots.py draws is in the book with labelled axes and a legend (as
SVG text).

Chromium is driven through its DevTools protocol over a WebSocket, with the
standard library only. It runs with a fresh profile and no network; the book
is read from file:// URLs. The browser is --chromium, else the first of
chromium, chromium-browser (on PATH) and /snap/bin/chromium. Without one the
run fails and says how to install it (Debian: apt install chromium), unless
--skip-without-chromium is given: then it says so and exits 77, which CTest
reports as skipped (book/CMakeLists.txt passes it when its configure step
found no Chromium). Exit status: 0 all good, 1 a problem (one line each), 2
the command line was wrong, 77 skipped.
"""

from __future__ import annotations

import argparse
import base64
import html
import json
import os
import re
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time
import urllib.parse
import urllib.request
import xml.etree.ElementTree as ElementTree
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
WIDTHS = (1280, 400)
FLAGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run",
         "--no-default-browser-check", "--disable-extensions", "--hide-scrollbars",
         "--remote-debugging-port=0", "--remote-debugging-address=127.0.0.1"]
# The search ranks a word by where the book teaches it (a heading, the recap's
# list of new calls) over where it mentions it (prose, code, code comments):
# each query, its teaching page, and the section the first result must link to
# (a regular expression over the anchor: pages 14 and 20 are being rewritten,
# and the section that teaches there may change its name, not its subject).
SEARCH_QUERIES = (
    ("vkCmdPipelineBarrier2", "03_swapchain.html", r"the-barriers-of-a-frame"),
    ("quaternion", "14_physics.html", r"a-rigid-body-that-turns|.*(?:orientation|quaternion|turns).*"),
    ("subgroup", "20d_binning.html", r"boxes|.*subgroup.*"),
    ("G-buffer", "16_deferred.html", r"the-g-buffer-what-to-store-in-which-format"),
    ("descriptor", "07_uniform_buffers.html", r"the-descriptor-set-layout"),
    ("push constants", "06_push_constants.html", r"the-push-constant-block|06-push-constants"),
    ("specialization constant", "19_ndim_gpu.html", r"the-dimension-as-a-specialization-constant"),
    ("queue family", "02_device.html", r"queue-families"),
    ("depth format", "08_depth.html", r"choosing-a-depth-format"),
    ("sampler", "09_textures.html", r"samplers"),
    ("std430", "13_compute.html", r"storage-buffers-and-std430"),
    ("memory types", "05_vertex_buffers.html", r"memory-types"),
    ("debug messenger", "01_instance.html", r"the-debug-messenger"),
    ("shader module", "04_triangle.html", r"shader-modules"),
    ("normal matrix", "12_lighting.html", r"the-normal-matrix"),
    ("buffer device address", "15_bindless.html", r"buffer-device-address"),
    ("vertex pulling", "19_ndim_gpu.html", r"no-vertex-input-pulling"),
    ("glTF", "10_gltf.html", r"what-is-in-a-gltf-file"),
    ("secondary command buffer", "27_threads.html", r"a-secondary-command-buffer-inside-dynamic-rendering"),
    ("pipeline cache", "27_threads.html", r"a-pipeline-cache-on-disk"),
    ("shader binding table", "25_ray_tracing.html", r"the-shader-binding-table"),
    ("frames in flight", "03_swapchain.html", r"frames-in-flight"),
    ("PCF", "22_shadows.html", r"looking-a-point-up-compare-filter"),
    ("timeline semaphore", "29_async_compute.html", r"timeline-semaphores"),
    ("depth pyramid", "28_gpu_culling.html", r"the-depth-pyramid"),
    ("vkCmdDrawIndexedIndirectCount", "28_gpu_culling.html", r"drawing-with-a-count"),
)
# The "taught here" mark: on these queries' first result (the chapter that
# teaches the whole phrase first, in a heading or its recap) and on no other
# result of any query (it once marked 14 for "shader binding table", and 17 and
# 21 for "frames in flight").
TAUGHT_QUERIES = ("shader binding table", "frames in flight", "PCF", "descriptor", "queue family")


class Failure(Exception):
    pass


# ----------------------------------------------------------------------------------------------
# A WebSocket client, just enough for the DevTools protocol (RFC 6455, text frames).
# ----------------------------------------------------------------------------------------------

class WebSocket:
    def __init__(self, url: str, timeout: float):
        parts = urllib.parse.urlsplit(url)
        self.sock = socket.create_connection((parts.hostname, parts.port), timeout=timeout)
        key = base64.b64encode(os.urandom(16)).decode()
        request = (f"GET {parts.path} HTTP/1.1\r\nHost: {parts.hostname}:{parts.port}\r\n"
                   "Upgrade: websocket\r\nConnection: Upgrade\r\n"
                   f"Sec-WebSocket-Key: {key}\r\nSec-WebSocket-Version: 13\r\n\r\n")
        self.sock.sendall(request.encode())
        response = b""
        while b"\r\n\r\n" not in response:
            chunk = self.sock.recv(4096)
            if not chunk:
                raise Failure("Chromium closed the DevTools connection during the handshake")
            response += chunk
        head, self.buffer = response.split(b"\r\n\r\n", 1)
        if b" 101 " not in head.split(b"\r\n")[0]:
            raise Failure(f"Chromium refused the DevTools WebSocket: {head.decode(errors='replace')}")

    def _read(self, n: int) -> bytes:
        while len(self.buffer) < n:
            chunk = self.sock.recv(1 << 16)
            if not chunk:
                raise Failure("Chromium closed the DevTools connection")
            self.buffer += chunk
        data, self.buffer = self.buffer[:n], self.buffer[n:]
        return data

    def send(self, text: str) -> None:
        payload = text.encode()
        header = bytearray([0x81])  # FIN, text
        if len(payload) < 126:
            header.append(0x80 | len(payload))
        elif len(payload) < 1 << 16:
            header += bytes([0x80 | 126]) + struct.pack(">H", len(payload))
        else:
            header += bytes([0x80 | 127]) + struct.pack(">Q", len(payload))
        mask = os.urandom(4)
        header += mask
        self.sock.sendall(bytes(header) + bytes(b ^ mask[i % 4] for i, b in enumerate(payload)))

    def receive(self) -> str:
        message = b""
        while True:
            first, second = self._read(2)
            opcode, length = first & 0x0F, second & 0x7F
            if length == 126:
                length = struct.unpack(">H", self._read(2))[0]
            elif length == 127:
                length = struct.unpack(">Q", self._read(8))[0]
            mask = self._read(4) if second & 0x80 else None
            data = self._read(length)
            if mask:
                data = bytes(b ^ mask[i % 4] for i, b in enumerate(data))
            if opcode == 0x8:
                raise Failure("Chromium closed the DevTools connection")
            if opcode == 0x9:  # ping: answer, keep reading
                continue
            if opcode in (0x0, 0x1, 0x2):
                message += data
                if first & 0x80:
                    return message.decode()


class DevTools:
    """One page target: commands, and the events that arrive meanwhile."""

    def __init__(self, url: str, timeout: float):
        self.ws = WebSocket(url, timeout)
        self.next_id = 0
        self.events: list[dict] = []

    def call(self, method: str, **params) -> dict:
        self.next_id += 1
        my_id = self.next_id
        self.ws.send(json.dumps({"id": my_id, "method": method, "params": params}))
        while True:
            message = json.loads(self.ws.receive())
            if message.get("id") == my_id:
                if "error" in message:
                    raise Failure(f"DevTools {method}: {message['error'].get('message')}")
                return message.get("result", {})
            if "method" in message:
                self.events.append(message)

    def wait_for(self, method: str, deadline: float) -> dict:
        for i, event in enumerate(self.events):
            if event["method"] == method:
                return self.events.pop(i)
        while time.monotonic() < deadline:
            message = json.loads(self.ws.receive())
            if message.get("method") == method:
                return message
            if "method" in message:
                self.events.append(message)
        raise Failure(f"timed out waiting for {method}")

    def evaluate(self, expression: str):
        result = self.call("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in result:
            raise Failure(f"script failed in the page: {result['exceptionDetails'].get('text')}")
        return result["result"].get("value")


# ----------------------------------------------------------------------------------------------
# The checks
# ----------------------------------------------------------------------------------------------

# Run in each page once it has loaded: what did not load, what sticks out, where links go.
PAGE_CHECK = r"""
(() => {
  // Asides a first reader may skip are folded (build_book.py's fold_asides):
  // each must be closed as the page loads; then all are opened, so that what
  // they hold is checked with the rest.
  const folds = [...document.querySelectorAll('details.aside')];
  const folded = folds.filter(d => !d.open).length;
  const foldIds = folds.map(d => (d.querySelector('summary [id]') || {}).id || '');
  folds.forEach(d => { d.open = true; });
  const root = document.documentElement;
  const width = root.clientWidth;
  const broken = [...document.images].filter(i => !i.complete || i.naturalWidth === 0)
                                     .map(i => i.getAttribute('src'));
  // Whether or not the page scrolls: an element whose box reaches past the window
  // with no scrolling box around it either widens the page or, where the page
  // hides its overflow, is cut off (a phone shows neither well).
  const wide = [];
  // Down the tree, not into a box that scrolls or clips (a code block's many
  // spans): what lies inside one cannot reach past the window unless it does.
  const walk = (parent) => {
    for (const el of parent.children) {
      if (wide.length >= 3) return;
      const box = el.getBoundingClientRect();
      if (box.right > width + 1 && box.width > 0) {
        wide.push(el.tagName.toLowerCase() + (el.className && typeof el.className === 'string' ? '.' + el.className : '') +
                  ' "' + (el.textContent || '').trim().slice(0, 40) + '" right edge ' + Math.round(box.right));
      }
      const o = getComputedStyle(el).overflowX;
      if (o !== 'auto' && o !== 'scroll' && o !== 'hidden' && o !== 'clip') walk(el);
    }
  };
  walk(document.body);
  // A code or console block wider than its box must scroll inside it, or wrap.
  const unscrolled = [];
  for (const pre of document.querySelectorAll('pre')) {
    if (pre.scrollWidth <= pre.clientWidth + 1) continue;
    const style = getComputedStyle(pre);
    const scrolls = style.overflowX === 'auto' || style.overflowX === 'scroll';
    const wraps = style.whiteSpace === 'pre-wrap' || style.whiteSpace === 'break-spaces';
    if (!scrolls && !wraps) unscrolled.push((pre.textContent || '').trim().slice(0, 40));
  }
  return {scrollWidth: root.scrollWidth, width, broken, wide, unscrolled, folds: folds.length, folded, foldIds,
          links: [...document.querySelectorAll('a[href]')].map(a => a.href)};
})()
"""

# A link into a folded aside opens it (book/theme/book.js): the fold closed
# again, the address's fragment set to its heading, and once the page has had
# the hashchange event, whether the fold is open.
FOLD_CHECK = r"""
(async () => {
  const id = %s;
  const fold = document.getElementById(id).closest('details.aside');
  fold.open = false;
  if (location.hash) { history.replaceState(null, '', location.pathname); }
  await new Promise(resolve => { addEventListener('hashchange', resolve, {once: true}); location.hash = id; });
  return fold.open;
})()
"""

# Figures: where each SVG figure shows, how wide at the default view and opened
# full size (a click on it, book/theme/book.js), and whether the line under it
# says that it opens. Tables: an identifier (inline code) broken over two lines,
# and a table wider than its box without the line that says it scrolls.
FIGURE_CHECK = r"""
(async () => {
  const figures = [];
  for (const img of document.querySelectorAll('article img')) {
    let src = img.getAttribute('src') || '';
    if (!/\.svg$/.test(src)) continue;
    // The picture shown: a diagram's narrow layout on a phone (<picture>), else src.
    if (!img.complete) await new Promise(r => { img.onload = r; img.onerror = r; });
    if (img.currentSrc && img.currentSrc.includes('/images/')) {
      src = 'images/' + img.currentSrc.split('/images/').pop();
    }
    const link = img.closest('a.figure');
    const hint = link && (link.closest('.figure-scroll') || link).nextElementSibling;
    const said = !!(hint && hint.classList.contains('figure-hint') && hint.getBoundingClientRect().height > 0
                    && /open it full size/.test(hint.textContent));
    let opened = 0;
    if (link) {
      link.click();
      const big = document.querySelector('.figure-layer .figure-pane img');
      if (big) {
        if (!big.complete) await new Promise(r => { big.onload = r; big.onerror = r; });
        opened = big.getBoundingClientRect().width;
      }
      document.dispatchEvent(new KeyboardEvent('keydown', {key: 'Escape', bubbles: true}));
      if (document.querySelector('.figure-layer')) opened = -1;  // did not close
    }
    figures.push({src, width: img.getBoundingClientRect().width, opened, said});
  }
  const broken = [];
  for (const code of document.querySelectorAll('article table code')) {
    const lines = new Set([...code.getClientRects()].map(r => Math.round(r.top)));
    if (lines.size > 1) broken.push(code.textContent.slice(0, 40));
  }
  const unsaid = [];
  for (const box of document.querySelectorAll('.table-scroll')) {
    const hint = box.parentElement.querySelector('.scroll-hint');
    const wide = box.scrollWidth > box.clientWidth + 1;
    if (wide && !(hint && hint.getBoundingClientRect().height > 0)) {
      unsaid.push((box.querySelector('th, td') || {}).textContent || '(a table)');
    }
  }
  const loose = [...document.querySelectorAll('article table')].filter(t => !t.closest('.table-scroll')).length;
  return {figures, broken, unsaid, loose};
})()
"""

# In an SVG opened on its own: its rendered width and its smallest rendered text
# (each text or tspan that holds characters: its computed font size times the
# scale its transforms give it), so a figure W pixels wide shows that text at
# smallest / width * W pixels.
SVG_TEXT_CHECK = r"""
(() => {
  const root = document.documentElement;
  let smallest = Infinity, which = '';
  for (const el of document.querySelectorAll('text, tspan')) {
    const own = [...el.childNodes].some(n => n.nodeType === 3 && n.textContent.trim());
    if (!own || !el.getScreenCTM) continue;
    const style = getComputedStyle(el);
    if (style.display === 'none' || style.visibility === 'hidden') continue;
    const m = el.getScreenCTM();
    const px = parseFloat(style.fontSize) * Math.hypot(m.a, m.b);
    if (px < smallest) { smallest = px; which = el.textContent.trim().slice(0, 30); }
  }
  return {width: root.getBoundingClientRect().width, smallest, which};
})()
"""
# The smallest text a reader must read, in CSS pixels (the bar).
MIN_TEXT_PX = 11.0
# And a figure must also read as shown, without opening it: its smallest text at
# least this at 1280 px (raised from none to 7 px by fixing the diagrams below it,
# issue 26; 11 px would need the widest diagrams redrawn narrower) and 9 px on a
# 400 px phone, where the figure is shown wide enough for that in a box of its own
# that scrolls sideways (book/theme/style.css, .figure-scroll; issue 40).
MIN_SHOWN_TEXT_PX = {1280: 7.0, 400: 9.0}

SEARCH_CHECK = r"""
new Promise((resolve) => {
  const input = document.querySelector('form.search input');
  const list = document.querySelector('.search-results');
  if (!input || !list) { resolve({error: 'no search box on the page'}); return; }
  list.textContent = '';  // the previous query's results
  input.focus();
  input.value = %s;
  input.dispatchEvent(new Event('input', {bubbles: true}));
  const start = Date.now();
  (function poll() {
    const items = [...list.querySelectorAll('li')];
    if (items.length || Date.now() - start > 10000) {
      resolve({links: items.map(li => li.querySelector('a').getAttribute('href')),
               snippets: items.map(li => (li.querySelector('.snippet') || {}).textContent || ''),
               taught: items.map(li => !!li.querySelector('.taught')),
               status: (document.querySelector('.search-status') || {}).textContent || ''});
    } else {
      setTimeout(poll, 50);
    }
  })();
})
"""


def check_figures(figures: list[tuple[str, int, dict]], svg_text: dict) -> tuple[list[str], str]:
    """Every SVG figure's smallest text at least MIN_TEXT_PX at its default view, or, where
    it is smaller there, once opened full size, with a line under the figure saying it
    opens; and at the widths of MIN_SHOWN_TEXT_PX at least that as shown, opened or not.
    Returns the problems and a note of which figures reach the bar only opened."""
    problems, only_opened = [], []
    at_default = 0
    smallest_shown = None  # (px, figure) at the widths of MIN_SHOWN_TEXT_PX
    for page, width, figure in figures:
        measured = svg_text.get(figure["src"])
        if not measured or not measured["width"] or measured["smallest"] == float("inf"):
            problems.append(f"{page} at {width} px: the figure {figure['src']} shows no text to measure")
            continue
        ratio = measured["smallest"] / measured["width"]
        default = ratio * figure["width"]
        shown_bar = MIN_SHOWN_TEXT_PX.get(width)
        if shown_bar is not None and (smallest_shown is None or default < smallest_shown[0]):
            smallest_shown = (default, figure["src"].split("/")[-1])
        if shown_bar is not None and default < shown_bar:
            problems.append(f"{page} at {width} px: the figure {figure['src']} shows its smallest text "
                            f"('{measured['which']}') at {default:.1f} px in the column, below the "
                            f"{shown_bar:g} px a figure must read at there without opening it")
        if default >= MIN_TEXT_PX:
            at_default += 1
            continue
        opened = ratio * figure["opened"]
        where = (f"{page} at {width} px: the figure {figure['src']} shows its smallest text "
                 f"('{measured['which']}') at {default:.1f} px")
        if figure["opened"] < 0:
            problems.append(f"{where}; opened full size, it does not close with Escape")
        elif opened < MIN_TEXT_PX:
            problems.append(f"{where}, and at {opened:.1f} px opened full size (the bar: {MIN_TEXT_PX:g} px)")
        elif not figure["said"]:
            problems.append(f"{where}, and nothing under it says it opens full size")
        else:
            only_opened.append(f"{figure['src'].split('/')[-1]} at {width} px: {default:.1f} -> {opened:.1f} px")
    note = (f"{at_default} figure views read at {MIN_TEXT_PX:g} px or more as shown; {len(only_opened)} only "
            f"opened full size ({'; '.join(sorted(set(only_opened)))})")
    if smallest_shown is not None:
        note += (f"; smallest text as shown at {'/'.join(map(str, MIN_SHOWN_TEXT_PX))} px: "
                 f"{smallest_shown[0]:.1f} px ({smallest_shown[1]})")
    return problems, note


def check_changes(book: Path, root: Path = ROOT) -> list[str]:
    """Every chapter after the first links, at its top, to its changes since the chapter
    it builds on (changes_NN_name.html), which names every file of the chapter's own
    folders (chapters/NN_name/ and shaders/NN_name/, whatever the suffix) and each file
    of common/ that the page declares it adds or changes (its first line,
    `<!-- builds on: NN_name common: ... -->`)."""
    problems = []
    chapters = sorted(p for p in book.glob("[0-9][0-9]_*.html"))
    for page in chapters[1:]:
        text = page.read_text(encoding="utf-8")
        link = re.search(r'<p class="changes-link">.*?<a href="(changes_[^"]+\.html)"', text, re.S)
        if not link or text.find('class="changes-link"') > text.find("</h1>") + 200:
            problems.append(f"{page.name}: no link to its changes since the chapter it builds on under its title")
            continue
        changes = book / link.group(1)
        if not changes.is_file():
            problems.append(f"{page.name}: its changes page {link.group(1)} does not exist")
            continue
        shown = changes.read_text(encoding="utf-8")
        files = [path.relative_to(root).as_posix() for folder in ("chapters", "shaders")
                 for path in sorted((root / folder / page.stem).rglob("*")) if path.is_file()]
        source = root / "book" / (page.stem + ".md")
        header = re.match(r"\s*<!--\s*builds on:\s*\S+(?:\s+common:\s*(.*?))?\s*-->",
                          source.read_text(encoding="utf-8") if source.is_file() else "", re.S)
        files += (header.group(1) or "").split() if header else []
        for rel in files:
            if f"<code>{html.escape(rel)}</code>" not in shown:
                problems.append(f"{link.group(1)}: {rel}, a file of chapter {page.stem[:2]}, is missing")
    return problems


def check_search(found: dict, query: str, page: str, section: str, book: Path, links) -> list[str]:
    """The first result of one query is `page`, linked at a section matching `section`
    that the page has; no snippet shows a code comment's raw `//`."""
    if found.get("error"):
        return [f"search: {found['error']}"]
    if not found["links"]:
        return [f"search: '{query}' found nothing ({found['status'].strip()})"]
    first = found["links"][0]
    path, _, anchor = first.partition("#")
    results = ", ".join(found["links"][:4])
    problems = []
    if not path.endswith(page):
        problems.append(f"search: '{query}' lists {first} first, not {page} (the results: {results})")
    elif not re.fullmatch(section, anchor):
        problems.append(f"search: '{query}' links {page} at #{anchor or '(the top)'}, not at the section that "
                        f"teaches it ({section}) (the results: {results})")
    elif anchor not in links.anchors(book / page):
        problems.append(f"search: '{query}' links {first}, which has no such section")
    marked = [link for link, mark in zip(found["links"], found.get("taught", [])) if mark]
    if query in TAUGHT_QUERIES and marked != found["links"][:1]:
        problems.append(f"search: '{query}' marks {marked or 'no result'} 'taught here', not only its first "
                        f"result {found['links'][0]}")
    elif len(marked) > 1:
        problems.append(f"search: '{query}' marks {marked} 'taught here': one result at most")
    for link, text in zip(found["links"], found["snippets"]):
        if re.search(r"(^|\s)//", text):
            problems.append(f"search: '{query}': the snippet of {link} shows a raw '//' comment: {text[:80]!r}")
    return problems


class LinkChecker:
    def __init__(self, book: Path):
        self.book = book.resolve()
        self.ids: dict[Path, set[str]] = {}
        self.checked: set[str] = set()

    def anchors(self, path: Path) -> set[str]:
        if path not in self.ids:
            text = path.read_text(encoding="utf-8", errors="replace")
            self.ids[path] = {html.unescape(v) for v in re.findall(r'\b(?:id|name)="([^"]*)"', text)}
        return self.ids[path]

    def check(self, page: str, url: str) -> str | None:
        parts = urllib.parse.urlsplit(url)
        if parts.scheme in ("http", "https", "mailto"):
            return None  # no network here; the builder leaves these alone
        if parts.scheme != "file":
            return f"{page}: link with an unexpected scheme: {url}"
        key = url
        if key in self.checked:
            return None
        self.checked.add(key)
        path = Path(urllib.parse.unquote(parts.path))
        if not path.is_file():
            return f"{page}: broken link to {url} (no such file)"
        if parts.fragment and path.suffix == ".html":
            anchor = urllib.parse.unquote(parts.fragment)
            if anchor not in self.anchors(path):
                return f"{page}: broken link to {url} (no element with id '{anchor}')"
        return None


def start_chromium(chromium: str, profile: Path, timeout: float) -> tuple[subprocess.Popen, int]:
    log = open(profile.parent / "chromium.log", "w")
    process = subprocess.Popen([chromium, *FLAGS, f"--user-data-dir={profile}", "about:blank"],
                               stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
    port_file = profile / "DevToolsActivePort"
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        if process.poll() is not None:
            raise Failure(f"{chromium} exited at once (status {process.returncode}); its output is in "
                          f"{profile.parent / 'chromium.log'}")
        if port_file.is_file():
            lines = port_file.read_text().split()
            if lines:
                return process, int(lines[0])
        time.sleep(0.1)
    raise Failure(f"{chromium} did not open its DevTools port within {timeout:.0f} s")


def stop_chromium(process: subprocess.Popen) -> None:
    """Ends the browser we started and, by its process group, the helpers it started."""
    process.terminate()
    try:
        process.wait(10)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait(10)
    try:
        os.killpg(process.pid, signal.SIGKILL)  # its own session: start_new_session=True
    except (ProcessLookupError, PermissionError):
        pass


def page_target(port: int) -> str:
    with urllib.request.urlopen(f"http://127.0.0.1:{port}/json/list", timeout=10) as response:
        targets = json.load(response)
    for target in targets:
        if target.get("type") == "page" and target.get("webSocketDebuggerUrl"):
            return target["webSocketDebuggerUrl"]
    raise Failure("Chromium has no page to drive")


def problems_from_events(events: list[dict], page: str, width: int) -> list[str]:
    found = []
    for event in events:
        method, params = event["method"], event.get("params", {})
        if method == "Runtime.exceptionThrown":
            details = params.get("exceptionDetails", {})
            text = details.get("exception", {}).get("description") or details.get("text")
            first_line = (text or "").splitlines()[0] if text else "(no message)"
            found.append(f"{page} at {width} px: uncaught exception: {first_line}")
        elif method == "Runtime.consoleAPICalled" and params.get("type") in ("error", "assert"):
            args = " ".join(str(a.get("value", a.get("description", ""))) for a in params.get("args", []))
            found.append(f"{page} at {width} px: console error: {args}")
        elif method == "Log.entryAdded" and params.get("entry", {}).get("level") == "error":
            entry = params["entry"]
            found.append(f"{page} at {width} px: {entry.get('source')} error: {entry.get('text')} "
                         f"{entry.get('url', '')}".rstrip())
        elif method == "Network.loadingFailed" and not params.get("canceled"):
            found.append(f"{page} at {width} px: a resource failed to load: {params.get('errorText')}")
    return found


def check_charts(book: Path) -> list[str]:
    """Every chart of benchmarks/plots.py is in the book, with axis labels and a legend."""
    sys.path.insert(0, str(ROOT / "benchmarks"))
    sys.dont_write_bytecode = True  # leave no __pycache__ in the source tree
    try:
        import plots  # noqa: E402  (benchmarks/plots.py: the list of charts)
    except ImportError as error:
        return [f"cannot read the list of charts from benchmarks/plots.py: {error}"]
    problems = []
    for chart in plots.CHARTS:
        path = book / "images" / chart.output
        if not path.is_file():
            problems.append(f"chart {chart.output}: not in the built book (no page shows it)")
            continue
        try:
            tree = ElementTree.parse(path)
        except ElementTree.ParseError as error:
            problems.append(f"chart {chart.output}: not well-formed SVG: {error}")
            continue
        by_id = {el.get("id"): el for el in tree.iter() if el.get("id")}
        for part in ("x-axis-label", "y-axis-label", "legend", "title"):
            element = by_id.get(part)
            text = "".join(element.itertext()).strip() if element is not None else ""
            if not text:
                problems.append(f"chart {chart.output}: no {part.replace('-', ' ')} as text")
    return problems


# Where Chromium is: Debian's and Fedora's and Arch's package (chromium), older
# Ubuntu's deb (chromium-browser), and Ubuntu 24.04's snap, whose /snap/bin is
# not always on PATH.
CHROMIUM_NAMES = ("chromium", "chromium-browser", "/snap/bin/chromium")
SKIPPED = 77  # CTest's SKIP_RETURN_CODE for this test


def find_chromium(given: str) -> str | None:
    """The browser to run: `given` if it is one, else the first of CHROMIUM_NAMES found."""
    for name in (given,) if given else CHROMIUM_NAMES:
        path = shutil.which(name) if os.sep not in name else name
        if path and os.path.isfile(path) and os.access(path, os.X_OK):
            return path
    return None


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(prog="book_browser.py", description=__doc__.splitlines()[0])
    parser.add_argument("book", type=Path, nargs="?", help="the built book (book/build_book.py --out DIR)")
    parser.add_argument("--figure-fixture", action="store_true",
                        help="no browser: run the figure-text check on two made-up figures, one too small "
                             "as shown at 1280 px, and print what it finds (the check's own test)")
    parser.add_argument("--changes-only", action="store_true",
                        help="no browser: check only that each changes page names every file of its chapter")
    parser.add_argument("--root", type=Path, default=ROOT,
                        help="the repository the book was built from (default: this one)")
    parser.add_argument("--chromium", default="",
                        help="the browser (default: the first of " + ", ".join(CHROMIUM_NAMES) + ")")
    parser.add_argument("--skip-without-chromium", action="store_true",
                        help=f"without a browser, exit {SKIPPED} (skipped) instead of 1")
    parser.add_argument("--layout-only", action="store_true",
                        help="only the pages' layout at each width (pictures, sideways scrolling, elements cut "
                             "off, code blocks that neither scroll nor wrap, console errors): no links, "
                             "figures, search or charts (the layout check's own test, on a fixture)")
    parser.add_argument("--pages", default="", help="only pages whose path matches this regular expression")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds a page may take to load")
    try:
        args = parser.parse_args(argv)
    except SystemExit as exit_:
        return 0 if exit_.code == 0 else 2

    if args.figure_fixture:
        # A 1000-unit-wide figure whose smallest text is 7.5 units, shown 680 px wide at
        # 1280 px (5.1 px) and opened at 1700 (12.8 px): fine opened, too small as shown.
        # And one whose 11-unit text shows at 8.1 px: above the 1280 px floor.
        # On a 400 px phone: the fine figure shown 900 px wide in its scrolling box reads
        # at 9.9 px; the same figure squeezed into the 360 px column, at 4.0 px, fails.
        svg_text = {"images/small.svg": {"width": 1000, "smallest": 7.5, "which": "tiny label"},
                    "images/fine.svg": {"width": 1000, "smallest": 11.0, "which": "label"},
                    "images/squeezed.svg": {"width": 1000, "smallest": 11.0, "which": "label"}}
        figures = [("fixture.html", 1280, {"src": "images/small.svg", "width": 680, "opened": 1700, "said": True}),
                   ("fixture.html", 1280, {"src": "images/fine.svg", "width": 740, "opened": 1100, "said": True}),
                   ("fixture.html", 400, {"src": "images/fine.svg", "width": 900, "opened": 1100, "said": True}),
                   ("fixture.html", 400, {"src": "images/squeezed.svg", "width": 360, "opened": 1100,
                                          "said": True})]
        problems, note = check_figures(figures, svg_text)
        for problem in problems:
            print(f"book_browser.py: {problem}", file=sys.stderr)
        print(f"book_browser.py: figure fixture: {len(problems)} problem(s); {note}")
        return 1 if problems else 0
    if args.book is None:
        print("book_browser.py: error: name the built book's folder", file=sys.stderr)
        return 2
    book = args.book.resolve()
    if not (book / "index.html").is_file():
        print(f"book_browser.py: {book} holds no built book (no index.html)", file=sys.stderr)
        return 1
    if args.changes_only:
        problems = check_changes(book, args.root.resolve())
        for problem in problems:
            print(f"book_browser.py: {problem}", file=sys.stderr)
        if problems:
            return 1
        print(f"book_browser.py: every changes page names every file of its chapter and the files of common/ "
              f"its page declares ({len(list(book.glob('changes_*.html')))} pages)")
        return 0
    chromium = find_chromium(args.chromium)
    if not chromium:
        tried = args.chromium or ", ".join(CHROMIUM_NAMES)
        if args.skip_without_chromium:
            print(f"book_browser.py: skipped: no Chromium here (tried {tried}). Install it to run this "
                  "test: Debian 12, apt install chromium (scripts/install-deps.sh does); Ubuntu 24.04, "
                  "snap install chromium; Fedora, dnf install chromium; Arch, pacman -S chromium.")
            return SKIPPED
        print(f"book_browser.py: error: Chromium is not installed ({tried} not found). The book's "
              "browser test needs it: on Debian, apt install chromium (scripts/install-deps.sh does).",
              file=sys.stderr)
        return 1

    pages = sorted(p.relative_to(book).as_posix() for p in book.rglob("*.html"))
    pages = [p for p in pages if re.search(args.pages, p)]
    problems: list[str] = []
    figures: list[tuple[str, int, dict]] = []
    figure_notes = ""
    links = LinkChecker(book)
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="book-browser-") as temp:
        profile = Path(temp) / "profile"
        profile.mkdir()
        process = None
        try:
            process, port = start_chromium(chromium, profile, 60)
            tab = DevTools(page_target(port), args.timeout)
            for domain in ("Page", "Runtime", "Log", "Network"):
                tab.call(f"{domain}.enable")
            for width in WIDTHS:
                tab.call("Emulation.setDeviceMetricsOverride", width=width, height=900, deviceScaleFactor=1,
                         mobile=width < 600)
                for page in pages:
                    tab.events.clear()
                    tab.call("Page.navigate", url=(book / page).as_uri())
                    tab.wait_for("Page.loadEventFired", time.monotonic() + args.timeout)
                    result = tab.evaluate(PAGE_CHECK)
                    time.sleep(0)  # let late events arrive with the next call
                    for src in result["broken"]:
                        problems.append(f"{page} at {width} px: the picture {src} did not load")
                    if result["scrollWidth"] > result["width"] + 1:
                        what = "; ".join(result["wide"]) or "no single element found"
                        problems.append(f"{page} at {width} px: scrolls sideways ({result['scrollWidth']} px "
                                        f"wide in a {result['width']} px window): {what}")
                    elif result["wide"]:
                        problems.append(f"{page} at {width} px: cut off at the window's edge ({result['width']} "
                                        f"px), in no scrolling box: {'; '.join(result['wide'])}")
                    for block in result["unscrolled"]:
                        problems.append(f"{page} at {width} px: the code block '{block}' is wider than its box "
                                        "and neither scrolls nor wraps")
                    problems += problems_from_events(tab.events, page, width)
                    if result["folded"] != result["folds"]:
                        problems.append(f"{page} at {width} px: {result['folds'] - result['folded']} of its "
                                        f"{result['folds']} asides to skip on a first read open as it loads")
                    if args.layout_only:
                        continue
                    shown = tab.evaluate(FIGURE_CHECK)
                    for figure in shown["figures"]:
                        figures.append((page, width, figure))
                    for code in shown["broken"]:
                        problems.append(f"{page} at {width} px: a table breaks the identifier '{code}' over lines")
                    for cell in shown["unsaid"]:
                        problems.append(f"{page} at {width} px: the table starting '{cell.strip()[:30]}' is wider "
                                        "than its box and nothing says it scrolls")
                    if shown["loose"]:
                        problems.append(f"{page} at {width} px: {shown['loose']} table(s) outside a scrolling box")
                    if width == WIDTHS[0]:
                        for fold_id in result["foldIds"][:1]:
                            if not tab.evaluate(FOLD_CHECK % json.dumps(fold_id)):
                                problems.append(f"{page}: a link to #{fold_id} leaves its folded aside closed")
                        for url in result["links"]:
                            problem = links.check(page, url)
                            if problem:
                                problems.append(problem)

            if not args.layout_only:  # the figures, their text and the search
                # Each SVG on its own, for its smallest text.
                tab.call("Emulation.setDeviceMetricsOverride", width=1280, height=900, deviceScaleFactor=1,
                         mobile=False)
                svg_text = {}
                for src in sorted({figure["src"] for _, _, figure in figures}):
                    target = book / urllib.parse.unquote(src)
                    tab.call("Page.navigate", url=target.as_uri())
                    tab.wait_for("Page.loadEventFired", time.monotonic() + args.timeout)
                    svg_text[src] = tab.evaluate(SVG_TEXT_CHECK)
                tab.events.clear()
                figure_problems, figure_notes = check_figures(figures, svg_text)
                problems += figure_problems

                # The search: each query's teaching chapter and section first.
                tab.call("Emulation.setDeviceMetricsOverride", width=1280, height=900, deviceScaleFactor=1,
                         mobile=False)
                tab.events.clear()
                tab.call("Page.navigate", url=(book / "index.html").as_uri())
                tab.wait_for("Page.loadEventFired", time.monotonic() + args.timeout)
                for query, page, section in SEARCH_QUERIES:
                    problems += check_search(tab.evaluate(SEARCH_CHECK % json.dumps(query)), query, page, section,
                                             book, links)
                problems += problems_from_events(tab.events, "index.html (search)", 1280)
        except (Failure, OSError, socket.timeout) as error:
            problems.append(f"the browser run stopped: {error}")
        finally:
            if process is not None:
                stop_chromium(process)

    if not args.layout_only:
        problems += check_charts(book)
        problems += check_changes(book)
    for problem in dict.fromkeys(problems):
        print(f"book_browser.py: {problem}", file=sys.stderr)
    seconds = time.monotonic() - started
    if problems:
        print(f"book_browser.py: {len(set(problems))} problem(s) in {len(pages)} pages at "
              f"{' and '.join(map(str, WIDTHS))} px ({seconds:.0f} s)", file=sys.stderr)
        return 1
    if args.layout_only:
        print(f"book_browser.py: {len(pages)} pages at {' and '.join(map(str, WIDTHS))} px: every picture "
              f"loaded, nothing scrolls sideways or is cut off, every wide code block scrolls or wraps "
              f"({seconds:.0f} s)")
        return 0
    print(f"book_browser.py: {len(pages)} pages at {' and '.join(map(str, WIDTHS))} px: every picture loaded, "
          f"nothing scrolls sideways or is cut off, every wide code block scrolls or wraps, no console error, "
          f"{len(links.checked)} links good; the search lists "
          f"the teaching chapter and section first for {len(SEARCH_QUERIES)} queries; every chart has axis "
          f"labels and a legend; every chapter after the first links its changes page; no table breaks an identifier; figure text: {figure_notes} ({seconds:.0f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
