#!/usr/bin/env python3
"""The figures in docs/figures are what scripts/make-figures makes (scripts/figure_manifest.py
says how, and why the check does not render them again), and the check catches what it is for:
a figure edited by hand, a figure left from an older command, a run whose default changed, a
chapter figure no page shows.

    figure_drift_test.py REPO_ROOT [BIN_DIR]    (BIN_DIR: the chapter programs, for the flags)
"""

import copy
import json
import os
import shutil
import sys
import tempfile
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
BIN_DIR = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else None
sys.path.insert(0, os.path.join(REPO, "scripts"))
import figure_manifest  # noqa: E402


def load():
    with open(os.path.join(REPO, "docs", "figures", "manifest.json"), encoding="utf-8") as file:
        manifest = json.load(file)
    with open(os.path.join(REPO, "scripts", "make-figures"), encoding="utf-8") as file:
        script = file.read()
    return manifest, script, figure_manifest.read_docs(os.path.join(REPO, "docs"))


class TheFiguresTest(unittest.TestCase):
    def test_docs_figures_are_what_make_figures_made(self):
        manifest, script, docs = load()
        problems = figure_manifest.check(REPO, manifest, script, docs, BIN_DIR)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_every_run_records_its_seed(self):
        manifest, _, _ = load()
        for label, run in manifest["runs"].items():
            self.assertIn("seed", run["flags"], label)


class TheCheckTest(unittest.TestCase):
    """Each drift the check exists for, played on a copy of docs/figures."""

    def setUp(self):
        self.manifest, self.script, self.docs = load()
        self.repo = tempfile.mkdtemp()
        shutil.copytree(os.path.join(REPO, "docs", "figures"),
                        os.path.join(self.repo, "docs", "figures"))

    def tearDown(self):
        shutil.rmtree(self.repo)

    def check(self, manifest=None, script=None, bin_dir=None):
        return figure_manifest.check(self.repo, manifest or self.manifest, script or self.script,
                                     self.docs, bin_dir)

    def test_the_copy_passes(self):
        self.assertEqual(self.check(), [])

    def test_a_figure_changed_by_one_byte_fails(self):
        figure = sorted(self.manifest["figures"])[0]
        path = os.path.join(self.repo, "docs", "figures", figure)
        with open(path, "r+b") as file:
            file.seek(40)
            byte = file.read(1)
            file.seek(40)
            file.write(bytes([byte[0] ^ 1]))
        problems = self.check()
        self.assertEqual(len(problems), 1, problems)
        self.assertIn(figure, problems[0])

    def test_a_missing_figure_fails(self):
        figure = sorted(self.manifest["figures"])[-1]
        os.remove(os.path.join(self.repo, "docs", "figures", figure))
        self.assertTrue(any(figure in p and "missing" in p for p in self.check()))

    def test_a_figure_no_manifest_lists_fails(self):
        manifest = copy.deepcopy(self.manifest)
        figure = sorted(manifest["figures"])[0]
        del manifest["figures"][figure]
        self.assertTrue(any(figure in p for p in self.check(manifest)))

    def test_a_figure_no_page_shows_fails(self):
        # A copy of a shown figure under a chapter name no page uses: a leftover.
        shutil.copy(os.path.join(self.repo, "docs", "figures", sorted(self.manifest["figures"])[0]),
                    os.path.join(self.repo, "docs", "figures", "08_unused.png"))
        problems = self.check()
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("08_unused.png", problems[0])
        self.assertIn("no docs page shows it", problems[0])

    def test_a_changed_command_fails(self):
        label = "ch05"
        command = self.manifest["runs"][label]["command"]
        script = self.script.replace(f'"{label}|{command}"', f'"{label}|{command} --spp 1,4"')
        self.assertNotEqual(script, self.script)
        problems = self.check(script=script)
        self.assertTrue(any(p.startswith(f"run {label}:") for p in problems), problems)

    def test_a_figure_taken_from_another_file_fails(self):
        script = self.script.replace('[05_cornell]="ch05-converged:spp_4096.png"',
                                     '[05_cornell]="ch05:spp_0256.png"')
        self.assertNotEqual(script, self.script)
        self.assertTrue(any("05_cornell.png" in p for p in self.check(script=script)))

    @unittest.skipIf(BIN_DIR is None, "no chapter programs given")
    def test_a_changed_default_fails(self):
        # The recorded flags of one run as if made when --depth's default was 9: today's
        # program says 10, so the figures are stale.
        manifest = copy.deepcopy(self.manifest)
        flags = manifest["runs"]["ch05"]["flags"]
        self.assertEqual(flags["depth"], "10")
        flags["depth"] = "9"
        problems = self.check(manifest, bin_dir=BIN_DIR)
        self.assertEqual(len(problems), 1, problems)
        self.assertIn("run ch05", problems[0])
        self.assertIn("depth", problems[0])


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1], verbosity=2)
