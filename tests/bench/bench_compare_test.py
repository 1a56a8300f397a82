#!/usr/bin/env python3
"""scripts/bench-compare: its table (scripts/bench_compare.py) from made-up reports whose
medians and ratios are known, and its usage errors (exit code 2 and one line naming what is
wrong, before anything is built).

    bench_compare_test.py REPO_ROOT
"""

import os
import subprocess
import sys
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
sys.path.insert(0, os.path.join(REPO, "scripts"))
import bench_compare  # noqa: E402


def report(*benchmarks):
    return {"benchmarks": list(benchmarks)}


def with_counter(name, per_second):
    return {"name": name, "real_time": 1.0, "time_unit": "ms", "rays_per_second": per_second}


class RatesTest(unittest.TestCase):
    def test_a_per_second_counter_is_the_rate(self):
        self.assertEqual(bench_compare.rates(report(with_counter("a", 2.5e7))), {"a": 2.5e7})

    def test_without_a_counter_the_rate_is_iterations_per_second_of_real_time(self):
        for unit, seconds in (("ns", 1e-9), ("us", 1e-6), ("ms", 1e-3), ("s", 1.0)):
            rate = bench_compare.rates(report({"name": "b", "real_time": 4.0, "time_unit": unit}))
            self.assertAlmostEqual(rate["b"], 1.0 / (4.0 * seconds), delta=1e-12 / seconds)


class SummarizeTest(unittest.TestCase):
    def test_medians_paired_ratios_range_and_faster_rounds(self):
        # Round by round the host drifts (the rates of both halve by round 3), yet `after` is
        # 1.1x `before` in every round but one: the paired ratios see through the drift.
        before = [{"x": 10.0}, {"x": 8.0}, {"x": 5.0}, {"x": 9.0}, {"x": 10.0}]
        after = [{"x": 11.0}, {"x": 8.8}, {"x": 5.5}, {"x": 8.1}, {"x": 11.0}]
        [row] = bench_compare.summarize(before, after)
        self.assertEqual(row.name, "x")
        self.assertEqual(row.before, 9.0)                     # median of 10, 8, 5, 9, 10
        self.assertEqual(row.after, 8.8)                      # median of 11, 8.8, 5.5, 8.1, 11
        self.assertAlmostEqual(row.ratio, 1.1, places=12)      # ratios 1.1, 1.1, 1.1, 0.9, 1.1
        self.assertAlmostEqual(row.lowest, 0.9, places=12)
        self.assertAlmostEqual(row.highest, 1.1, places=12)
        self.assertEqual((row.faster, row.rounds), (4, 5))
        # The medians of the rates alone would say 0.98x: slower.
        self.assertLess(row.after / row.before, 1.0)

    def test_a_round_with_equal_rates_is_not_counted_faster(self):
        [row] = bench_compare.summarize([{"x": 3.0}, {"x": 3.0}], [{"x": 3.0}, {"x": 6.0}])
        self.assertEqual((row.faster, row.rounds), (1, 2))

    def test_a_benchmark_missing_from_a_run_is_marked_not_compared(self):
        before = [{"x": 1.0}, {"x": 1.0, "y": 2.0}]
        after = [{"x": 2.0, "y": 2.0}, {"x": 2.0, "y": 2.0}]
        rows = {row.name: row for row in bench_compare.summarize(before, after)}
        self.assertTrue(rows["x"].in_both)
        self.assertEqual(rows["x"].ratio, 2.0)
        self.assertFalse(rows["y"].in_both)
        lines = [" ".join(l.split()) for l in bench_compare.format_table(rows.values()).splitlines()]
        self.assertIn("y (not in every run of both programs)", lines)

    def test_the_table_prints_each_benchmark_once_with_its_figures(self):
        rows = bench_compare.summarize([{"BM_A/1": 2.0e7}], [{"BM_A/1": 2.2e7}])
        table = bench_compare.format_table(rows)
        [line] = [l for l in table.splitlines() if l.startswith("BM_A/1")]
        self.assertEqual(line.split(), ["BM_A/1", "2e+07", "2.2e+07", "1.100x", "1.100-1.100",
                                        "1/1"])


class UsageTest(unittest.TestCase):
    """Each mistake: exit code 2, one line on stderr naming it, and nothing built."""

    def run_script(self, *args, **env):
        return subprocess.run([os.path.join(REPO, "scripts", "bench-compare"), *args],
                              capture_output=True, text=True, timeout=60,
                              env={**os.environ, **env})

    def check_refused(self, result, words):
        self.assertEqual(result.returncode, 2, result.stderr)
        lines = result.stderr.strip().splitlines()
        self.assertEqual(len(lines), 1, result.stderr)
        self.assertIn(words, lines[0])
        self.assertNotIn("== Building", result.stdout)

    def test_no_revision(self):
        self.check_refused(self.run_script(), "revision")

    def test_an_option_it_does_not_have(self):
        self.check_refused(self.run_script("--rounds", "5"), "unknown option '--rounds'")

    def test_more_than_two_arguments(self):
        self.check_refused(self.run_script("HEAD", "BM_A", "BM_B"), "at most two arguments")

    def test_a_revision_that_does_not_exist(self):
        self.check_refused(self.run_script("no-such-revision-anywhere"), "'no-such-revision-anywhere'")

    def test_rounds_not_a_whole_number(self):
        for rounds in ("0", "-3", "two", "1.5"):
            self.check_refused(self.run_script("HEAD", ROUNDS=rounds), "ROUNDS must be")

    def test_a_benchmark_program_that_does_not_exist(self):
        self.check_refused(self.run_script("HEAD", BENCH="no_such"), "BENCH must name")

    def test_help(self):
        result = self.run_script("--help")
        self.assertEqual(result.returncode, 0)
        self.assertIn("scripts/bench-compare REF", result.stdout)


if __name__ == "__main__":
    unittest.main(verbosity=2)
