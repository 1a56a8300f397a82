#!/usr/bin/env python3
"""The table of scripts/bench-compare: two benchmark programs run in turns, compared by round.

    bench_compare.py FOLDER ROUNDS

reads FOLDER/before.R.json and FOLDER/after.R.json for R = 1..ROUNDS (Google Benchmark's
--benchmark_format=json) and prints, for each benchmark, the median rate of each program, the
median of the paired ratios after / before (one pair per round, so drift common to both
cancels), their range, and the rounds in which `after` was faster.
"""

import json
import statistics
import sys
from dataclasses import dataclass

_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def rates(report):
    """Each benchmark's rate: its first counter named *_per_second (rays, samples, queries),
    else iterations per second of real time."""
    out = {}
    for b in report["benchmarks"]:
        per_second = [key for key in b if key.endswith("_per_second")]
        if per_second:
            out[b["name"]] = float(b[per_second[0]])
        else:
            out[b["name"]] = 1.0 / (b["real_time"] * _SECONDS[b["time_unit"]])
    return out


@dataclass
class Row:
    name: str
    before: float = 0.0      # median rate over the rounds
    after: float = 0.0
    ratio: float = 0.0       # median of the rounds' after / before
    lowest: float = 0.0      # the smallest and largest of those ratios
    highest: float = 0.0
    faster: int = 0          # rounds in which after > before
    rounds: int = 0
    in_both: bool = True     # False: some run of either program lacks this benchmark


def summarize(before_runs, after_runs):
    """One Row per benchmark of the first `after` run, from the rates of the two programs'
    runs, round by round (before_runs[r] and after_runs[r] ran side by side)."""
    assert len(before_runs) == len(after_runs) > 0
    rows = []
    for name in after_runs[0]:
        if not all(name in run for run in before_runs + after_runs):
            rows.append(Row(name, in_both=False))
            continue
        before = [run[name] for run in before_runs]
        after = [run[name] for run in after_runs]
        ratios = [a / b for a, b in zip(after, before)]
        rows.append(Row(name, statistics.median(before), statistics.median(after),
                        statistics.median(ratios), min(ratios), max(ratios),
                        sum(r > 1.0 for r in ratios), len(ratios)))
    return rows


def format_table(rows):
    width = max([len("benchmark")] + [len(row.name) for row in rows])
    lines = [f"{'benchmark':<{width}} {'before':>10} {'after':>10} {'after/before':>13}"
             f" {'range':>13} {'faster':>7}"]
    for row in rows:
        if not row.in_both:
            lines.append(f"{row.name:<{width}} (not in every run of both programs)")
            continue
        lines.append(f"{row.name:<{width}} {row.before:>10.4g} {row.after:>10.4g}"
                     f" {row.ratio:>12.3f}x {row.lowest:>6.3f}-{row.highest:<6.3f}"
                     f" {row.faster:>3}/{row.rounds}")
    lines += [
        "",
        "before, after: medians of the rates (per second) over the rounds; after/before: the",
        "median of each round's ratio, and range: the smallest and largest; faster: the rounds",
        "in which the working tree was faster. Two builds of the same code differ here by the",
        "host's noise alone, so a change shows only if its ratios clear that range.",
    ]
    return "\n".join(lines)


def main(argv):
    folder, rounds = argv[1], int(argv[2])

    def load(which, r):
        with open(f"{folder}/{which}.{r}.json") as handle:
            return rates(json.load(handle))

    before = [load("before", r) for r in range(1, rounds + 1)]
    after = [load("after", r) for r in range(1, rounds + 1)]
    print(format_table(summarize(before, after)))


if __name__ == "__main__":
    main(sys.argv)
