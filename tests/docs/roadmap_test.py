#!/usr/bin/env python3
"""docs/figures/roadmap.svg is what scripts/make-roadmap-figure writes, the index page shows it,
and the script has one row per folder of chapters/: a new chapter left off the roadmap fails.

    roadmap_test.py REPO_ROOT
"""

import importlib.machinery
import importlib.util
import os
import sys
import tempfile
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()


def load_script():
    path = os.path.join(REPO, "scripts", "make-roadmap-figure")
    loader = importlib.machinery.SourceFileLoader("make_roadmap_figure", path)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module


class RoadmapTest(unittest.TestCase):
    def setUp(self):
        self.script = load_script()

    def test_every_chapter_folder_has_a_row(self):
        self.assertEqual(self.script.missing_rows(REPO), [])

    def test_the_figure_is_what_the_script_draws(self):
        with open(os.path.join(REPO, "docs", "figures", "roadmap.svg"), encoding="utf-8") as f:
            self.assertEqual(f.read(), self.script.svg(),
                             "docs/figures/roadmap.svg: run scripts/make-roadmap-figure")

    def test_the_index_shows_it(self):
        with open(os.path.join(REPO, "docs", "index.md"), encoding="utf-8") as f:
            self.assertIn("(figures/roadmap.svg)", f.read())

    def test_a_chapter_without_a_row_is_found(self):
        # A tree with one chapter more than the rows: the check names it.
        with tempfile.TemporaryDirectory() as root:
            for number, *_ in self.script.ROWS:
                os.makedirs(os.path.join(root, "chapters", f"{number}_x"))
            os.makedirs(os.path.join(root, "chapters", "42_new_topic"))
            problems = self.script.missing_rows(root)
            self.assertEqual(len(problems), 1, problems)
            self.assertIn("42", problems[0])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
