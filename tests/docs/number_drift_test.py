#!/usr/bin/env python3
"""Every number the docs pages quote from a run matches docs/numbers.json (written by
scripts/make-figures from its pinned runs), and the check catches what it is for: a wrong
digit, an unknown name, a name no page quotes, a measured-looking number left untagged.

    number_drift_test.py REPO_ROOT
"""

import json
import os
import sys
import tempfile
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
sys.path.insert(0, os.path.join(REPO, "scripts"))
import doc_numbers  # noqa: E402


class ThePagesTest(unittest.TestCase):
    def test_every_quoted_number_matches_numbers_json(self):
        with open(os.path.join(REPO, "docs", "numbers.json"), encoding="utf-8") as file:
            numbers = json.load(file)
        # the assignments page quotes docs/assignments/fairness.json (measure_assignment_fairness)
        problems = doc_numbers.check(doc_numbers.read_pages(REPO), numbers,
                                     optional=doc_numbers.fairness_numbers(REPO))
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_the_assignments_fairness_section_quotes_the_measurement(self):
        page = os.path.join(REPO, "docs", doc_numbers.ASSIGNMENT_PAGE)
        if not os.path.isfile(page):
            self.skipTest("no assignments page (a kit)")
        with open(page, encoding="utf-8") as file:
            quotes = doc_numbers.find_quotes(doc_numbers.ASSIGNMENT_PAGE, file.read())
        self.assertGreaterEqual(sum(q.name.startswith("fairness.") for q in quotes), 10)

    def test_every_name_has_a_source_run(self):
        with open(os.path.join(REPO, "docs", "numbers.json"), encoding="utf-8") as file:
            numbers = json.load(file)
        self.assertEqual(sorted(set(numbers) - set(doc_numbers.SOURCES)), [])
        self.assertEqual(sorted(set(doc_numbers.SOURCES) - set(numbers)), [])


PAGE = "x.md"


def problems(text, numbers):
    return doc_numbers.check({PAGE: text}, numbers, checked_pages=[PAGE])


class TheCheckTest(unittest.TestCase):
    def test_a_number_rounded_to_its_printed_digits_passes(self):
        numbers = {"a.mean": 0.09129, "a.slope": -2.0412, "a.small": 1.43e-4, "a.rays": 1991691,
                   "a.share": 0.64, "a.rise": 0.4455}
        text = ("mean 0.0913<!--n:a.mean--> and 0.09<!--n:a.mean-->, slope $-2.04$<!--n:a.slope-->,"
                " error $1.4 \\times 10^{-4}$<!--n:a.small-->, 1,991,691<!--n:a.rays--> rays,"
                " 0.6 %<!--n:a.share--> less, **0.45<!--n:a.rise-->**, $+0.45$<!--n:a.rise-->")
        self.assertEqual(problems(text, numbers), [])

    def test_a_wrong_digit_fails(self):
        found = problems("mean 0.0914<!--n:a.mean-->", {"a.mean": 0.09129})
        self.assertEqual(len(found), 1)
        self.assertIn("a.mean is 0.09129, the page prints 0.0914", found[0])

    def test_a_wrong_power_of_ten_fails(self):
        found = problems("$1.4 \\times 10^{-3}$<!--n:a.small-->", {"a.small": 1.43e-4})
        self.assertEqual(len(found), 1)
        self.assertIn("a.small", found[0])

    def test_an_unknown_name_fails(self):
        found = problems("mean 0.0913<!--n:a.mean_typo-->", {"a.mean": 0.09129})
        self.assertIn("x.md:1: unknown name a.mean_typo", found)

    def test_a_tag_after_no_number_fails(self):
        found = problems("the mean<!--n:a.mean-->", {"a.mean": 0.09129})
        self.assertEqual(found, ["x.md:1: the tag a.mean follows no number"])

    def test_a_name_no_page_quotes_fails(self):
        found = problems("mean 0.0913<!--n:a.mean-->", {"a.mean": 0.09129, "a.unused": 1.0})
        self.assertEqual(found, ["numbers.json: a.unused is quoted by no page"])

    def test_an_untagged_measured_number_fails(self):
        found = problems("the mean radiance was 0.0793 (seed 1)", {})
        self.assertEqual(len(found), 1)
        self.assertIn("x.md:1: 0.0793 looks measured", found[0])
        # At the end of a sentence too (the full stop after it is not part of the number).
        found = problems("its mean radiance was 0.0793.\nand 2.79, then", {})
        self.assertEqual([line.split(" looks")[0] for line in found],
                         ["x.md:1: 0.0793", "x.md:2: 2.79"])

    def test_code_maths_short_numbers_and_closed_forms_are_not_measured(self):
        text = "\n".join([
            "```sh", "build/bin/ch07 --albedo 0.625 # cosine.pfm: 2.38336", "```",
            "run `--fixed-q 0.725`, where $E[L] = 1.75$ and $$b = 0.3333$$, $J \\approx",
            "0.598144$ over two lines,",
            "about 0.5 of it, or 12 %, at a 99.9 % interval",
            "<!-- a comment with 1.234 -->"])
        self.assertEqual(problems(text, {}), [])


class TheFairnessQuotesTest(unittest.TestCase):
    """The assignments page against fairness.json: its names need not all be quoted, a wrong
    digit fails, and its Fairness section (only) must tag what it measured."""

    MEASURED = {"summary": {"majority_min_p": 0.00123, "seeds": 1000, "all": True},
                "checks": {"a1_disk": {"ks_p": 0.4567, "test": "a1.A1.Task1"}}, "bugs": {}}

    def quotes(self, text):
        optional = doc_numbers.flatten(self.MEASURED, "fairness")
        return doc_numbers.check({doc_numbers.ASSIGNMENT_PAGE: text}, {}, checked_pages=[],
                                 optional=optional)

    def test_numbers_of_the_measurement_are_flattened_by_name(self):
        self.assertEqual(doc_numbers.flatten(self.MEASURED, "fairness"),
                         {"fairness.summary.majority_min_p": 0.00123,
                          "fairness.summary.seeds": 1000.0,
                          "fairness.checks.a1_disk.ks_p": 0.4567})

    def test_a_right_quote_passes_and_unquoted_names_are_fine(self):
        self.assertEqual(self.quotes("## Fairness\nsmallest 0.0012<!--n:fairness.summary.majority_min_p-->"), [])

    def test_a_wrong_digit_fails(self):
        found = self.quotes("## Fairness\nKS p 0.457<!--n:fairness.checks.a1_disk.ks_p--> and 0.45<!--n:x-->")
        self.assertIn("assignments/README.md:2: unknown name x", found)
        found = self.quotes("## Fairness\nKS p 0.458<!--n:fairness.checks.a1_disk.ks_p-->")
        self.assertEqual(len(found), 1)
        self.assertIn("fairness.checks.a1_disk.ks_p is 0.4567, the page prints 0.458", found[0])

    def test_an_untagged_number_fails_in_the_fairness_section_only(self):
        text = "## Grading\nbuilt in 7.45 s\n## Fairness\n4.31 % below 0.05\n## Times\n12.5 s"
        found = self.quotes(text)
        self.assertEqual(len(found), 1)
        self.assertIn("assignments/README.md:4: 4.31 looks measured", found[0])


class TheWriterTest(unittest.TestCase):
    """scripts/make-figures' step: numbers.json from the runs it made, the rest kept."""

    def setUp(self):
        self.folder = tempfile.TemporaryDirectory()
        self.scratch = os.path.join(self.folder.name, "scratch")
        for label, mean in (("r1", 0.25), ("r2", 0.5)):
            os.makedirs(os.path.join(self.scratch, label))
            with open(os.path.join(self.scratch, label, "summary.json"), "w") as file:
                json.dump({"mean": mean}, file)
            with open(os.path.join(self.scratch, label, "t.csv"), "w") as file:
                file.write("k,error\n1,0.125\n2,0.0625\n")
        self.path = os.path.join(self.folder.name, "numbers.json")
        with open(self.path, "w") as file:
            json.dump({"r1.mean": 9.0, "r2.mean": 9.0, "r3.mean": 7.0, "gone.mean": 1.0}, file)
        self.saved = dict(doc_numbers.SOURCES)
        doc_numbers.SOURCES.clear()
        for label in ("r1", "r2", "r3"):
            doc_numbers.number(f"{label}.mean", label, doc_numbers.summary_value(label, "mean"))
        doc_numbers.number("r1.error_k2", "r1", doc_numbers.cell("r1", "t.csv", "error", k=2))

    def tearDown(self):
        doc_numbers.SOURCES.clear()
        doc_numbers.SOURCES.update(self.saved)
        self.folder.cleanup()

    def written(self):
        with open(self.path) as file:
            return json.load(file)

    def test_only_the_runs_named_change_and_unlisted_names_go(self):
        self.assertTrue(doc_numbers.write(self.scratch, {"r1"}, self.path))
        # r2 was run but not named: kept; r3 was not run: kept; gone.mean has no source: gone.
        self.assertEqual(self.written(),
                         {"r1.mean": 0.25, "r1.error_k2": 0.0625, "r2.mean": 9.0, "r3.mean": 7.0})

    def test_no_label_means_every_run_in_the_folder(self):
        self.assertTrue(doc_numbers.write(self.scratch, set(), self.path))
        self.assertEqual(self.written()["r2.mean"], 0.5)

    def test_a_value_that_cannot_be_read_fails_and_keeps_the_old_one(self):
        doc_numbers.number("r1.mean", "r1", doc_numbers.cell("r1", "t.csv", "error", k=3))
        self.assertFalse(doc_numbers.write(self.scratch, {"r1"}, self.path))
        self.assertEqual(self.written()["r1.mean"], 9.0)


if __name__ == "__main__":
    unittest.main()
