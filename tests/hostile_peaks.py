#!/usr/bin/env python3
"""The peak resident memory of each chapter on each hostile file, against
the budget the file was given.

    python3 tests/hostile_peaks.py --bin BIN --max-memory 500M
        [--chapter NAME ...] [--args "--headless ..."] [--nuls]
        [--timeout SECONDS] [--report FILE] PATH [PATH ...]

Each PATH is a file or a folder (its files, not its subfolders). Every
.gltf and .glb among them is given to each chapter named (10_gltf,
23_materials, 26_mesh_shaders: `--model FILE`), every .png and .jpg to
09_textures (`--texture FILE`) where it is named, each run with
`--max-memory` and the arguments of --args (23 with `--sky environment`
too, its image-based light). --nuls adds two sparse files of
1 GiB of NUL bytes (a model and a texture), made in a temporary folder.

A chapter's peak is its maximum resident set (ru_maxrss of the finished
child, as `/usr/bin/time -v` reports it). What Vulkan itself takes (the
instance, the device, the validation layer, the chapter's pipelines and
targets) is measured first for each chapter: its peak drawing a model of one
triangle (written here), or for 09 its own 256 x 256 checker texture. The budget holds
where every file's peak is at most --max-memory plus that baseline.

A run must also end with status 0 or 1: a signal (a crash), or a run past
--timeout seconds, fails the check as surely as a peak past the budget.
One line per run: chapter, file, exit status, seconds, peak MiB, and the
error line it printed. Exit 0 when every run holds, 1 naming those that do
not. The empty scene (a scene without nodes, refused once the device is
up) is measured too, and printed: what a chapter takes with no model drawn.
"""
import argparse
import os
import shlex
import subprocess
import sys
import tempfile
import time

MODELS = (".gltf", ".glb")
IMAGES = (".png", ".jpg", ".jpeg")
EMPTY_SCENE = b'{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": []}]}\n'
# One triangle, (0,0,0) (1,0,0) (0,1,0), 16-bit indices, in a data: URI.
TRIANGLE = b"""{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
  "nodes": [{"mesh": 0}], "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"},
                {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
  "buffers": [{"byteLength": 44, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAIAAAA="}]}
"""


def parse_size(text):
    units = {"": 0, "K": 10, "M": 20, "G": 30}
    number = text.rstrip("KMGkmg")
    return int(number) << units[text[len(number):].upper()]


def run(command, timeout):
    """(exit status or -signal, None past the timeout; seconds; peak bytes; its error line)."""
    start = time.monotonic()
    with tempfile.TemporaryFile() as err:
        child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=err)
        # wait4 gives this child's own usage (RUSAGE_CHILDREN would give the
        # largest of all children so far).
        while True:
            pid, status, usage = os.wait4(child.pid, os.WNOHANG)
            if pid:
                break
            if time.monotonic() - start > timeout:
                child.kill()
                pid, status, usage = os.wait4(child.pid, 0)
                child.returncode = -9
                return None, time.monotonic() - start, usage.ru_maxrss * 1024, \
                    "killed after %d s" % timeout
            time.sleep(0.02)
        child.returncode = os.waitstatus_to_exitcode(status)
        seconds = time.monotonic() - start
        err.seek(0)
        lines = [l for l in err.read().decode("utf-8", "replace").splitlines() if l.strip()]
    line = next((l for l in reversed(lines) if ": error: " in l), lines[-1] if lines else "")
    return child.returncode, seconds, usage.ru_maxrss * 1024, line


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--bin", required=True)
    parser.add_argument("--max-memory", default="500M")
    parser.add_argument("--chapter", action="append")
    parser.add_argument("--args", default="--headless --validation --frames 1 --size 320x240")
    parser.add_argument("--nuls", action="store_true")
    parser.add_argument("--timeout", type=int, default=120)
    parser.add_argument("--report")
    parser.add_argument("paths", nargs="+")
    options = parser.parse_args()
    chapters = options.chapter or ["10_gltf", "23_materials", "26_mesh_shaders"]
    limit = parse_size(options.max_memory)
    extra = shlex.split(options.args)

    files = []
    for path in options.paths:
        if os.path.isdir(path):
            files += sorted(os.path.join(path, f) for f in os.listdir(path)
                            if os.path.isfile(os.path.join(path, f)))
        else:
            files.append(path)
    scratch = tempfile.TemporaryDirectory(prefix="vkt_hostile_peaks.")
    if options.nuls:
        for name in ("nuls_1g.gltf", "nuls_1g.png"):
            with open(os.path.join(scratch.name, name), "wb") as f:
                f.truncate(1 << 30)  # sparse: no disk space
            files.append(os.path.join(scratch.name, name))
    empty = os.path.join(scratch.name, "empty_scene.gltf")
    triangle = os.path.join(scratch.name, "triangle.gltf")
    for name, text in ((empty, EMPTY_SCENE), (triangle, TRIANGLE)):
        with open(name, "wb") as f:
            f.write(text)

    out = open(options.report, "w") if options.report else None
    def say(text):
        print(text, flush=True)
        if out:
            out.write(text + "\n")

    say("command: %s" % " ".join(shlex.quote(a) for a in sys.argv))
    failures = []
    mib = 1 << 20
    for chapter in chapters:
        exe = os.path.join(options.bin, chapter)
        # 23 under its environment (image-based light), its fullest setup.
        args = extra + (["--sky", "environment"] if chapter == "23_materials" else [])
        flag = "--texture" if chapter == "09_textures" else "--model"
        kinds = IMAGES if chapter == "09_textures" else MODELS
        if chapter == "09_textures":
            status, _, baseline, line = run([exe] + args, options.timeout)
            what = "its own checker.png"
        else:
            _, _, peak, _ = run([exe] + args + [flag, empty], options.timeout)
            say("%s: the empty scene (refused once the device is up): %.0f MiB" %
                (chapter, peak / mib))
            status, _, baseline, line = run([exe] + args + [flag, triangle], options.timeout)
            what = "one triangle"
        if status != 0:
            failures.append("%s: the baseline run failed (%s): %s" % (chapter, status, line))
            continue
        allowed = limit + baseline
        say("%s: baseline (%s, drawn) %.0f MiB; allowed %.0f MiB (--max-memory %s + baseline)" %
            (chapter, what, baseline / mib, allowed / mib, options.max_memory))
        for path in files:
            if not path.lower().endswith(kinds):
                continue
            status, seconds, peak, line = run(
                [exe] + args + ["--max-memory", options.max_memory, flag, path], options.timeout)
            verdict = "ok"
            if status is None or status not in (0, 1):
                verdict = "FAIL (exit %s)" % status
            elif peak > allowed:
                verdict = "FAIL (peak %.0f MiB > %.0f MiB)" % (peak / mib, allowed / mib)
            # A name may hold a control character (escape_\x1bc_reset.gltf):
            # never sent to the terminal as it is.
            name = os.path.basename(path).encode("unicode_escape").decode("ascii")
            say("%-16s %-24s exit %-4s %6.2f s %6.0f MiB  %s  %s" %
                (chapter, name, status, seconds, peak / mib, verdict, line[:160]))
            if verdict != "ok":
                failures.append("%s %s: %s" % (chapter, name, verdict))
    for failure in failures:
        say("FAIL: " + failure)
    say("%d failure(s)" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
