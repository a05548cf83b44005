#!/usr/bin/env python3
"""Every test accounted for: the last step of each test workflow.

    account_tests.py --preset NAME --junit FILE [--list FILE] [--skips FILE]
                     [--system ID:CODENAME]
    account_tests.py --preset NAME --junit FILE --update

CTest calls a run good when nothing failed: a test that skipped (a Catch2
SKIP, the book's browser test without Chromium) or was never registered (a
window test without Xvfb, a fuzz regression whose folder is empty) goes by
without a word. This reads the JUnit report of the run that just ended and
fails, one line per test, unless

  - every test the preset's list names (tests/accounting/PRESET.txt) ran,
    and no test ran that the list does not name (a new test is added to the
    list with --update, and the diff shows it in review);
  - every test that skipped is named, for this system, in
    tests/expected_skips.txt, with its reason.

It ends with one line: tests run, passed, skipped as expected (and why).
--update rewrites the preset's list from the report (after a run that
registered everything: look at the diff before committing it).
"""
import argparse
import os
import re
import sys
import xml.etree.ElementTree as ET

HERE = os.path.dirname(os.path.abspath(__file__))


def this_system():
    """ID:VERSION_CODENAME from /etc/os-release, e.g. debian:bookworm."""
    fields = {}
    try:
        with open("/etc/os-release", encoding="utf-8") as f:
            for line in f:
                key, _, value = line.strip().partition("=")
                fields[key] = value.strip('"')
    except OSError:
        pass
    return f"{fields.get('ID', 'unknown')}:{fields.get('VERSION_CODENAME', 'unknown')}"


def read_report(path):
    """{name: 'passed' | 'failed' | 'skipped'} and each skip's message."""
    try:
        root = ET.parse(path).getroot()
    except (OSError, ET.ParseError) as e:
        sys.exit(f"account_tests: cannot read the JUnit report {path}: {e}")
    results, why = {}, {}
    for case in root.iter("testcase"):
        name = case.get("name")
        status = case.get("status", "run")
        skipped = case.find("skipped")
        if case.find("failure") is not None or case.find("error") is not None or status == "fail":
            results[name] = "failed"
        elif skipped is not None or status in ("notrun", "disabled"):
            results[name] = "skipped"
            out = case.findtext("system-out") or ""
            said = re.search(r"(?im)^.*skip.*$", out)  # the test's own word on it
            parts = [skipped.get("message", "") if skipped is not None else "",
                     said.group(0).strip() if said else ""]
            why[name] = "; ".join(p for p in parts if p)
        else:
            results[name] = "passed"
    return results, why


def read_skips(path, system):
    """The (pattern, reason) pairs of expected_skips.txt that hold on `system`."""
    entries = []
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            parts = [p.strip() for p in line.split("|")]
            if len(parts) != 3 or not parts[2]:
                sys.exit(f"account_tests: {path}:{number}: want 'TEST REGEX | SYSTEMS | WHY'")
            pattern, systems, reason = parts
            if systems == "*" or system in [s.strip() for s in systems.split(",")]:
                entries.append((re.compile(pattern), reason))
    return entries


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--preset", required=True)
    parser.add_argument("--junit", required=True)
    parser.add_argument("--list")
    parser.add_argument("--skips", default=os.path.join(HERE, "expected_skips.txt"))
    parser.add_argument("--system", default=this_system())
    parser.add_argument("--update", action="store_true")
    args = parser.parse_args()
    listing = args.list or os.path.join(HERE, "accounting", f"{args.preset}.txt")

    results, why = read_report(args.junit)
    # The accounting step itself runs after the report was written.
    if args.update:
        os.makedirs(os.path.dirname(listing), exist_ok=True)
        with open(listing, "w", encoding="utf-8") as f:
            f.write(f"# Every test the {args.preset} preset runs (tests/account_tests.py "
                    f"--update wrote it;\n# a test missing from a run, or run but not listed, "
                    f"fails the run's accounting).\n")
            for name in sorted(results):
                f.write(name + "\n")
        print(f"account_tests: {listing}: {len(results)} tests")
        return 0

    try:
        with open(listing, encoding="utf-8") as f:
            expected = {l.strip() for l in f if l.strip() and not l.startswith("#")}
    except OSError as e:
        sys.exit(f"account_tests: no list of the {args.preset} preset's tests: {e}")
    skips = read_skips(args.skips, args.system)

    problems = []
    for name in sorted(expected - results.keys()):
        problems.append(f"not run: {name} (not registered on this system, or filtered out)")
    for name in sorted(results.keys() - expected):
        problems.append(f"not in {os.path.relpath(listing)}: {name} "
                        f"(a new test? tests/account_tests.py --update)")
    for name, result in sorted(results.items()):
        if result == "failed":
            problems.append(f"failed: {name}")
    expected_skips = []
    for name, result in sorted(results.items()):
        if result != "skipped":
            continue
        reason = next((r for p, r in skips if p.fullmatch(name)), None)
        if reason is None:
            problems.append(f"skipped, and not expected to on {args.system}: {name}"
                            + (f" ({why[name]})" if why.get(name) else ""))
        else:
            expected_skips.append(f"{name}: {reason}")

    ran = sum(1 for r in results.values() if r != "skipped")
    passed = sum(1 for r in results.values() if r == "passed")
    for line in problems:
        print(f"account_tests: {line}")
    summary = (f"{args.preset} on {args.system}: {len(results)} tests, {ran} run, {passed} passed, "
               f"{len(expected_skips)} skipped as expected")
    print(f"account_tests: {summary}")
    for line in expected_skips:
        print(f"  skipped as expected: {line}")
    if problems:
        print(f"account_tests: FAILED: {len(problems)} tests unaccounted for")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
