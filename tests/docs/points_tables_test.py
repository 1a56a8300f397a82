#!/usr/bin/env python3
"""Every points figure of the assignment handouts and README is what the grader's sources give
(scripts/points-tables --check: points.json, the tests of each assignment, the written
questions' key), and the check catches what it is for: a wrong figure, a test no row counts,
a test counted twice, a total that is not the sum.

    points_tables_test.py REPO_ROOT
"""

import importlib.machinery
import importlib.util
import os
import sys
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
loader = importlib.machinery.SourceFileLoader(
    "points_tables", os.path.join(REPO, "scripts", "points-tables"))
spec = importlib.util.spec_from_loader("points_tables", loader)
points_tables = importlib.util.module_from_spec(spec)
loader.exec_module(points_tables)

ASSIGNMENTS = points_tables.load(REPO)


def a5_page(graded_rows, task_rows="| a5.1 | 5<!--p:Task1*--> |\n| a5.2 | 6<!--p:Task2*--> |\n"
                                   "| a5.3 | 11<!--p:Task3*--> |\n"):
    return ("## Tasks, points and expected time\n| task | points |\n|---|---|\n" + task_rows +
            "\n## How it is graded (points)\n| test | points |\n|---|---|\n" + graded_rows)


# One row per public test of a5, and the hidden ones together.
A5_ROWS = [("roulette", "Task1RouletteFurnaceMatchesTheClosedForms", "4"),
           ("min depth", "Task1NoRouletteBeforeMinDepth", "1"),
           ("cosine", "Task2CosineFurnaceIsExact", "3"),
           ("uniform", "Task2UniformFurnaceMeanAndVariance", "2"),
           ("cos^2", "Task2CosineSquaredFurnaceMean", "1"),
           ("nee furnace", "Task3FurnaceIsExact", "3"),
           ("regions", "Task3RegionsAgreeWithThePathTracer", "4"),
           ("two lights", "Task3TwoLightsAgreeWithThePathTracer", "2"),
           ("beyond the cap", "Task3LightBeyondTheCapAgreesWithThePathTracer", "2"),
           ("hidden", "hidden:*", "2 + 1 + 1")]


def rows(skip=None, wrong=None, twice=None):
    out = ""
    for what, spec, points in A5_ROWS:
        if spec == skip:
            continue
        printed = "99" if spec == wrong else points
        out += f"| {what} | {printed}<!--p:{spec}--> |\n"
        if spec == twice:
            out += f"| {what} again | {printed}<!--p:{spec}--> |\n"
    return out


@unittest.skipIf(ASSIGNMENTS is None, "no key or points.json (a kit)")
class ThePagesTest(unittest.TestCase):
    def test_every_points_figure_is_the_sources(self):
        self.assertEqual(points_tables.main(["points-tables", "--check"]), 0)


@unittest.skipIf(ASSIGNMENTS is None, "no key or points.json (a kit)")
class TheCheckTest(unittest.TestCase):
    def check(self, text, own="a5"):
        return points_tables.rewrite("x.md", text, ASSIGNMENTS, own)

    def test_a_page_matching_the_sources_is_left_as_it_is(self):
        text = a5_page(rows())
        self.assertEqual(self.check(text), (text, []))

    def test_a_wrong_figure_is_rewritten(self):
        new, problems = self.check(a5_page(rows(wrong="Task3TwoLightsAgreeWithThePathTracer")))
        self.assertEqual(problems, [])
        self.assertEqual(new, a5_page(rows()))

    def test_a_test_no_row_counts_fails(self):
        # the old a5 handout: the two-lights test (2 points) was in no row
        _, problems = self.check(a5_page(rows(skip="Task3TwoLightsAgreeWithThePathTracer")))
        self.assertEqual(problems, ["x.md: the section '## How it is graded' counts no points "
                                    "for test Task3TwoLightsAgreeWithThePathTracer"])

    def test_a_test_counted_twice_fails(self):
        _, problems = self.check(a5_page(rows(twice="Task2CosineFurnaceIsExact")))
        self.assertEqual(len(problems), 1)
        self.assertIn("counts test Task2CosineFurnaceIsExact 2 times", problems[0])

    def test_a_pattern_naming_no_test_fails(self):
        _, problems = self.check(a5_page(rows() + "| typo | 1<!--p:Task9*--> |\n"))
        self.assertIn("x.md:21: <!--p:Task9*--> names no test of a5", problems)

    def test_totals_and_written_points_are_sums(self):
        a5 = ASSIGNMENTS["a5"]
        public = sum(a5.public.values())
        new, _ = self.check("| total | 0<!--p:total--> |\n| written | 0<!--p:written--> |\n")
        self.assertIn(f"| total | {public} + {a5.written_key + a5.written_hand} written", new)
        self.assertIn(f"| written | {a5.written_key} + {a5.written_hand} by hand", new)
        new, _ = self.check("| 1 (1 tests)<!--p:a5:public--> |", own=None)
        self.assertEqual(new, f"| {public} ({len(a5.public)} tests)<!--p:a5:public--> |")


if __name__ == "__main__":
    unittest.main(verbosity=2)
