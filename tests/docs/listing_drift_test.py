#!/usr/bin/env python3
"""The code a chapter page shows is the code that runs: every C++ listing of a chapter page
names its source file on its first line (`// common/render/path_tracer.hpp`) and its lines
appear in that file, in order.

    listing_drift_test.py REPO_ROOT

Lines are compared with their indentation stripped and runs of spaces made one (the aligned
trailing comments clang-format writes are layout, not code); blank lines and the assignment markers of
the source are ignored. A line of the listing that starts with `...` or `// ...` elides source
lines: what comes after it must follow later in the file. A kit's stubbed file (a region
replaced by NOT_IMPLEMENTED) is not compared: the kit's pages leave its solution out.
"""

import os
import re
import sys
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()

CHAPTERS = ["01_ray_tracing.md", "02_disk_area.md", "03_trapezoid_vs_mc.md",
            "04_recursive_nk.md", "05_path_tracer.md", "06_russian_roulette.md",
            "07_importance_sampling.md", "08_next_event_estimation.md",
            "09_stratified_qmc.md"]

LISTING = re.compile(r"^```(?:cpp|c\+\+)\n(.*?)^```", re.S | re.M)
SOURCE = re.compile(r"//\s*((?:common|chapters)/[\w./-]+\.(?:hpp|cpp))")


def elision(line):
    return line.startswith("...") or line.startswith("// ...")


def normal(line):
    """The line without its indentation, its runs of spaces made one."""
    return " ".join(line.split())


def source_lines(path):
    with open(path, encoding="utf-8") as f:
        return [normal(l) for l in f if l.strip() and "ASSIGNMENT " not in l]


def listings(page):
    """(line number, [stripped non-blank lines]) of every C++ listing of a page."""
    with open(os.path.join(REPO, "docs", page), encoding="utf-8") as f:
        text = f.read()
    for m in LISTING.finditer(text):
        lines = [normal(l) for l in m.group(1).splitlines() if l.strip()]
        yield text.count("\n", 0, m.start()) + 1, lines


def first_drift(listing, source):
    """The first listing line not found in order in `source`, or None."""
    segments, current = [], []
    for line in listing:
        if elision(line):
            segments.append(current)
            current = []
        else:
            current.append(line)
    segments.append(current)
    position = 0
    for segment in segments:
        if not segment:
            continue
        n = len(segment)
        start = next((i for i in range(position, len(source) - n + 1)
                      if source[i:i + n] == segment), None)
        if start is None:
            # the longest prefix that is found names the line that drifted
            for k in range(n - 1, 0, -1):
                if any(source[i:i + k] == segment[:k] for i in range(position, len(source) - k + 1)):
                    return segment[k]
            return segment[0]
        position = start + n
    return None


class ListingDrift(unittest.TestCase):
    maxDiff = None

    def test_every_listing_names_its_file_and_matches_it(self):
        problems = []
        count = 0
        for page in CHAPTERS:
            for line, listing in listings(page):
                count += 1
                where = f"docs/{page}:{line}"
                m = SOURCE.match(listing[0]) if listing else None
                if not m:
                    problems.append(f"{where}: the first line must name the source file "
                                    f"(// common/... or // chapters/...)")
                    continue
                path = os.path.join(REPO, m.group(1))
                if not os.path.isfile(path):
                    problems.append(f"{where}: {m.group(1)} does not exist")
                    continue
                source = source_lines(path)
                if any("NOT_IMPLEMENTED(" in l for l in source):
                    continue  # a kit's stub: its page leaves the solution out
                drift = first_drift(listing[1:], source)
                if drift is not None:
                    problems.append(f"{where}: not in {m.group(1)} (in this order): {drift}")
        self.assertGreater(count, 5, "the chapter pages lost their listings")
        self.assertEqual(problems, [], "\n".join(problems))

    def test_a_drifted_line_is_found(self):
        source = ["int f() {", "return 1;", "}"]
        self.assertIsNone(first_drift(["int f() {", "...", "}"], source))
        self.assertEqual(first_drift(["int f() {", "return 2;"], source), "return 2;")
        self.assertEqual(first_drift(["}", "...", "int f() {"], source), "int f() {")


if __name__ == "__main__":
    unittest.main()
