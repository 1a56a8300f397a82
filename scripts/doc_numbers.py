#!/usr/bin/env python3
"""The numbers the docs pages quote from runs: docs/numbers.json, and the pages' tags.

A page quotes a run's number as the number followed at once by a tag naming it:

    the mean radiance was 0.0913<!--n:ch01.mean_radiance-->
    trapezoid $-2.04$<!--n:ch03.slope_smooth_1d_trapezoid-->     (a maths span holding a number)
    $1.4 \\times 10^{-4}$<!--n:ch03.rmse_smooth_1d_monte_carlo-->  (or a \\times 10^{e} number)
    0.6 %<!--n:ch05.depth_cut_shortfall_percent-->               (a percent sign may sit between)

The named value rounded to the printed precision must be the printed number: see check(). In
the pages of CHECKED_PAGES a decimal of 3 or more significant digits in prose (outside code,
maths and comments) must carry a tag or be listed in CLOSED_FORM; closed forms are written as
maths, where the check does not look.

    scripts/doc_numbers.py write SCRATCH [LABEL...]   docs/numbers.json from the runs in SCRATCH
                                                  (scripts/make-figures' run folders); only
                                                  the names of the given run labels change
    scripts/doc_numbers.py check                      every page against docs/numbers.json

The assignments page (docs/assignments/README.md) quotes the fairness measurement instead, as
`fairness.<part>.<name>.<column>` (fairness.summary.<key>, fairness.checks.<check>.<column>,
fairness.bugs.<bug>.<column>, fairness.variants.<row>.<column>,
fairness.thresholds.<row>.<column>): the numbers of docs/assignments/fairness.json, the file
measure_assignment_fairness writes. That file holds many more numbers than the page quotes, so
none of them has to be quoted; its own program writes it, so it is not in numbers.json's
sources. In that page only the Fairness section must tag its measured-looking numbers (the
rest quotes build times, machine-dependent, untagged).
"""

import csv
import json
import math
import os
import re
import struct
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))

TAG = re.compile(r"<!--n:([A-Za-z0-9_.\-]+)-->")
PLAIN = r"[-+]?\d[\d,]*(?:\.\d+)?"
# What a tag quotes: a maths span holding one number (maybe times a power of ten), or a plain
# number, each maybe followed by a percent sign.
QUOTED = re.compile(
    r"(?:\$(?P<mant>" + PLAIN + r")(?:\s*\\times\s*10\^\{?(?P<exp>-?\d+)\}?)?\$"
    r"|(?<![\w.])(?P<plain>" + PLAIN + r"))(?:\s?\\?%)?$")

# Pages whose every measured-looking decimal must be tagged (under-the-hood keeps
# machine-dependent numbers, untagged).
CHECKED_PAGES = ["01_ray_tracing.md", "02_disk_area.md", "03_trapezoid_vs_mc.md",
                 "04_recursive_nk.md", "05_path_tracer.md", "06_russian_roulette.md",
                 "07_importance_sampling.md", "08_next_event_estimation.md",
                 "09_stratified_qmc.md", "index.md", "answers.md"]

# The assignments page, its measured numbers (measure_assignment_fairness's output) and the
# section of it where every measured-looking decimal must carry a tag.
ASSIGNMENT_PAGE = "assignments/README.md"
FAIRNESS_JSON = os.path.join("docs", "assignments", "fairness.json")
CHECKED_SECTIONS = {ASSIGNMENT_PAGE: "## Fairness"}

# Closed-form constants a page may print untagged, each with what it is.
CLOSED_FORM = {
    "99.9",      # the confidence level of chapter 06's intervals, a chosen constant
}

# A decimal with 3 or more significant digits looks measured.
# (a full stop after it ends the sentence; a digit after a second point is a version, not a number)
DECIMAL = re.compile(r"(?<![\w.])\d[\d,]*\.\d+(?!\w|\.\d)")


def significant_digits(text):
    return len(text.replace(",", "").replace(".", "").lstrip("0"))


class Quote:
    def __init__(self, page, line, name, printed, value, half_step):
        self.page, self.line, self.name = page, line, name
        self.printed, self.value, self.half_step = printed, value, half_step

    def where(self):
        return f"{self.page}:{self.line}"


def parse_quoted(before):
    """The number a tag quotes, from the text just before the tag: (printed, value, half a step
    of its last printed digit), or None."""
    match = QUOTED.search(before)
    if not match:
        return None
    digits = match.group("mant") or match.group("plain")
    decimals = len(digits.split(".")[1]) if "." in digits else 0
    value = float(digits.replace(",", ""))
    half_step = 0.5 * 10.0 ** -decimals
    if match.group("exp"):
        scale = 10.0 ** int(match.group("exp"))
        value, half_step = value * scale, half_step * scale
    return match.group(0), value, half_step


def prose_lines(text):
    """Each line with code (fenced and inline), maths and HTML comments blanked out; lines in
    a fenced block come back empty."""
    lines, fenced = [], False
    for line in text.split("\n"):
        if line.lstrip().startswith("```"):
            fenced = not fenced
            lines.append("")
        else:
            lines.append("" if fenced else line)
    prose = "\n".join(lines)
    # Over the whole page, since maths may run across lines; each character blanked by a space
    # (a line break kept), so that lines and positions stay those of the page.
    for pattern in (r"`[^`\n]*`", r"\$\$.*?\$\$|\$[^$]*\$", r"<!--.*?-->"):
        prose = re.sub(pattern, lambda found: re.sub(r"[^\n]", " ", found.group()), prose,
                       flags=re.DOTALL)
    return prose.split("\n")


def find_quotes(page, text):
    """Every tag of a page as a Quote; a tag that quotes no number is a Quote with printed None."""
    quotes, fenced = [], False
    for number, line in enumerate(text.split("\n"), start=1):
        if line.lstrip().startswith("```"):
            fenced = not fenced
        if fenced:
            continue
        # A tag shown in inline code is an example, not a quote: blank code spans out.
        line = re.sub(r"`[^`]*`", lambda code: " " * len(code.group()), line)
        for tag in TAG.finditer(line):
            parsed = parse_quoted(line[:tag.start()])
            printed, value, half_step = parsed if parsed else (None, None, None)
            quotes.append(Quote(page, number, tag.group(1), printed, value, half_step))
    return quotes


def find_untagged(page, text):
    """Measured-looking decimals of a page's prose that no tag names: [(line, number)]."""
    found = []
    raw = text.split("\n")
    for number, line in enumerate(prose_lines(text), start=1):
        # A tagged number's tag was blanked with the other comments: find tags in the raw line.
        tagged_ends = {t.start() for t in TAG.finditer(raw[number - 1])}
        for match in DECIMAL.finditer(line):
            if significant_digits(match.group()) < 3 or match.group() in CLOSED_FORM:
                continue
            end = match.end()
            rest = raw[number - 1][end:]
            gap = re.match(r"\s?\\?%?", rest).end()
            if end + gap in tagged_ends:
                continue
            found.append((number, match.group()))
    return found


def section_text(text, heading):
    """The page with every line outside the section opened by `heading` (up to the next
    heading of its level) blanked, so that line numbers stay those of the page."""
    level = heading.split(" ")[0] + " "
    lines, inside = [], False
    for line in text.split("\n"):
        if line.startswith(level):
            inside = line.strip() == heading
        lines.append(line if inside else "")
    return "\n".join(lines)


def check(docs, numbers, checked_pages=CHECKED_PAGES, optional=None,
          checked_sections=CHECKED_SECTIONS):
    """Every problem of the pages in `docs` ({page: text}) against `numbers` ({name: value}),
    one line each: a wrong number, an unknown name, a tag that quotes no number, a name no
    page quotes, a measured-looking number without a tag (in `checked_pages`, or in the
    section `checked_sections` names of a page). Names of `optional` ({name: value}) may be
    quoted like those of `numbers`, but need not be."""
    optional = optional or {}
    problems, quoted = [], set()
    for page, text in sorted(docs.items()):
        for quote in find_quotes(page, text):
            quoted.add(quote.name)
            if quote.name not in numbers and quote.name not in optional:
                problems.append(f"{quote.where()}: unknown name {quote.name}")
            elif quote.printed is None:
                problems.append(f"{quote.where()}: the tag {quote.name} follows no number")
            else:
                value = numbers[quote.name] if quote.name in numbers else optional[quote.name]
                # The printed number is the value rounded: within half a step of its last digit
                # (plus a relative 1e-9 for the binary representation of both).
                if not abs(quote.value - value) <= quote.half_step + 1e-9 * abs(value):
                    problems.append(f"{quote.where()}: {quote.name} is {value!r}, the page "
                                    f"prints {quote.printed}")
        scope = text if page in checked_pages else (
            section_text(text, checked_sections[page]) if page in checked_sections else None)
        if scope is not None:
            for line, number in find_untagged(page, scope):
                problems.append(f"{page}:{line}: {number} looks measured but has no "
                                f"<!--n:name--> tag (or belongs in CLOSED_FORM)")
    for name in sorted(set(numbers) - quoted):
        problems.append(f"numbers.json: {name} is quoted by no page")
    return problems


def read_docs(folder):
    return {name: open(os.path.join(folder, name), encoding="utf-8").read()
            for name in sorted(os.listdir(folder)) if name.endswith(".md")}


def flatten(value, prefix):
    """{prefix.key.key...: number} for every number in nested JSON objects (booleans and text
    left out)."""
    if isinstance(value, dict):
        out = {}
        for key, item in value.items():
            out.update(flatten(item, f"{prefix}.{key}"))
        return out
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return {prefix: float(value)}
    return {}


def fairness_numbers(repo):
    """The names the assignments page may quote: fairness.summary.*, fairness.checks.*,
    fairness.bugs.*, fairness.variants.*, fairness.thresholds.* of
    docs/assignments/fairness.json ({} when the tree has none: a kit)."""
    try:
        with open(os.path.join(repo, FAIRNESS_JSON), encoding="utf-8") as file:
            measured = json.load(file)
    except FileNotFoundError:
        return {}
    return flatten({part: measured.get(part, {})
                    for part in ("summary", "checks", "bugs", "variants", "thresholds")}, "fairness")


def read_pages(repo):
    """Every page that quotes numbers: docs/*.md and, when the tree has it (a kit does not),
    the assignments page."""
    docs = read_docs(os.path.join(repo, "docs"))
    path = os.path.join(repo, "docs", ASSIGNMENT_PAGE)
    if os.path.isfile(path):
        with open(path, encoding="utf-8") as file:
            docs[ASSIGNMENT_PAGE] = file.read()
    return docs


# ---------------------------------------------------------------------------------------------
# The runs: where each name's value comes from.

class Runs:
    """The outputs of scripts/make-figures' runs, folder per run label."""

    def __init__(self, scratch):
        self.scratch = scratch

    def has(self, label):
        return os.path.isfile(os.path.join(self.scratch, label, "summary.json"))

    def summary(self, label):
        with open(os.path.join(self.scratch, label, "summary.json"), encoding="utf-8") as file:
            return json.load(file)

    def rows(self, label, name):
        with open(os.path.join(self.scratch, label, name), encoding="utf-8", newline="") as file:
            return list(csv.DictReader(file))

    def cell(self, label, name, column, **where):
        """The `column` of the one row of CSV `name` whose columns equal `where`."""
        rows = [row for row in self.rows(label, name)
                if all(row[key] == str(value) for key, value in where.items())]
        if len(rows) != 1:
            raise KeyError(f"{label}/{name}: {len(rows)} rows match {where}")
        return float(rows[0][column])


SOURCES = {}  # name -> (run label, function of Runs giving the value)


def number(name, label, function):
    SOURCES[name] = (label, function)


def write(scratch, labels, path):
    """Updates numbers.json at `path` with every name whose run is in `labels` (all runs in
    `scratch` when empty); the other names keep their values, names no longer listed go."""
    runs = Runs(scratch)
    try:
        with open(path, encoding="utf-8") as file:
            numbers = json.load(file)
    except FileNotFoundError:
        numbers = {}
    numbers = {name: value for name, value in numbers.items() if name in SOURCES}
    failed = []
    for name, (label, function) in sorted(SOURCES.items()):
        if labels and label not in labels or not runs.has(label):
            continue
        try:
            value = float(function(runs))
        except (KeyError, IndexError, ValueError, OSError) as error:
            failed.append(f"{name}: {error}")
            continue
        if not math.isfinite(value):
            failed.append(f"{name}: not finite ({value})")
            continue
        numbers[name] = value
    text = json.dumps(dict(sorted(numbers.items())), indent=1) + "\n"
    temporary = path + ".tmp"
    with open(temporary, "w", encoding="utf-8") as file:
        file.write(text)
    os.replace(temporary, path)
    for line in failed:
        print(f"scripts/doc_numbers.py: {line}", file=sys.stderr)
    return not failed


def main(argv):
    if len(argv) >= 2 and argv[1] == "write":
        if len(argv) < 3:
            print("scripts/doc_numbers.py: write needs the scratch folder", file=sys.stderr)
            return 2
        return 0 if write(argv[2], set(argv[3:]), os.path.join(REPO, "docs", "numbers.json")) else 1
    if len(argv) == 2 and argv[1] == "check":
        with open(os.path.join(REPO, "docs", "numbers.json"), encoding="utf-8") as file:
            numbers = json.load(file)
        problems = check(read_pages(REPO), numbers, optional=fairness_numbers(REPO))
        for line in problems:
            print(line)
        return 1 if problems else 0
    print("usage: scripts/doc_numbers.py write SCRATCH [LABEL...] | check", file=sys.stderr)
    return 2


# ---------------------------------------------------------------------------------------------
# Every name, chapter by chapter.

def summary_value(label, *keys):
    """A number of run `label`'s summary.json, at the path `keys`."""
    def read(runs):
        value = runs.summary(label)
        for key in keys:
            value = value[key]
        return value
    return read


def cell(label, file, column, **where):
    return lambda runs: runs.cell(label, file, column, **where)


# Chapter 01: the default run (cornell).
number("ch01.rays", "ch01", summary_value("ch01", "rays"))
number("ch01.mean_radiance", "ch01", summary_value("ch01", "mean_radiance"))
number("ch01.falloff_below_lamp", "ch01", summary_value("ch01", "falloff", "measured_below_lamp"))
number("ch01.falloff_points", "ch01", summary_value("ch01", "falloff", "points"))
number("ch01.falloff_deviation", "ch01",
       summary_value("ch01", "falloff", "largest_relative_deviation"))

# Chapter 02: the default run.
number("ch02.disk_slope", "ch02", summary_value("ch02", "disk", "fitted_slope"))
number("ch02.disk_slope_se", "ch02",
       summary_value("ch02", "disk", "fitted_slope_standard_error"))
number("ch02.median_std_ratio", "ch02",
       summary_value("ch02", "disk", "median_empirical_over_theory_std"))
number("ch02.rmse_at_largest_n", "ch02", cell("ch02", "disk_area.csv", "rmse", n=10000000))
for k in (2, 5, 10):
    number(f"ch02.ball_slope_k{k}", "ch02", lambda runs, k=k: next(
        row["fitted_slope"] for row in runs.summary("ch02")["ball"]["fitted_slopes"]
        if row["k"] == k))
    number(f"ch02.ball_std_n10_k{k}", "ch02",
           cell("ch02", "ball_error_vs_n.csv", "empirical_std", k=k, n=10))
    number(f"ch02.ball_theory_std_n10_k{k}", "ch02",
           cell("ch02", "ball_error_vs_n.csv", "theory_std", k=k, n=10))

# Chapter 03: the default run.
def ch03_slope(integrand, dims, method, column="fitted_slope"):
    return cell("ch03", "slopes.csv", column, integrand=integrand, dims=dims, method=method)


def ch03_at_budget(integrand, dims, method, column):
    return cell("ch03", "errors.csv", column, integrand=integrand, dims=dims, method=method,
                evaluations=1048576)


for stem, integrand, dims in (("smooth_1d", "gaussian_1d", 1), ("jump_1d", "ceil_sin_1d", 1),
                              ("disk", "unit_ball_kd", 2)):
    for method in ("trapezoid", "monte_carlo") if stem == "smooth_1d" else ("trapezoid",):
        number(f"ch03.slope_{stem}_{method}", "ch03", ch03_slope(integrand, dims, method))
        number(f"ch03.slope_{stem}_{method}_se", "ch03",
               ch03_slope(integrand, dims, method, "standard_error"))
    if stem != "disk":
        number(f"ch03.error_{stem}_trapezoid", "ch03",
               ch03_at_budget(integrand, dims, "trapezoid", "abs_error"))
        number(f"ch03.rmse_{stem}_monte_carlo", "ch03",
               ch03_at_budget(integrand, dims, "monte_carlo", "rmse"))
for k in range(1, 9):
    number(f"ch03.slope_gaussian_k{k}_trapezoid", "ch03",
           ch03_slope("gaussian_kd", k, "trapezoid"))
for k in (2, 4, 6, 8):
    number(f"ch03.budget_gaussian_k{k}_trapezoid", "ch03",
           cell("ch03", "budget.csv", "trapezoid_error", integrand="gaussian_kd", dims=k))
    number(f"ch03.budget_gaussian_k{k}_monte_carlo", "ch03",
           cell("ch03", "budget.csv", "monte_carlo_rmse", integrand="gaussian_kd", dims=k))


def ch03_monte_carlo_slopes(runs):
    return [float(row["fitted_slope"]) for row in runs.rows("ch03", "slopes.csv")
            if row["method"] == "monte_carlo" and row["integrand"].endswith("_kd")]


number("ch03.mc_slope_steepest", "ch03", lambda runs: min(ch03_monte_carlo_slopes(runs)))
number("ch03.mc_slope_flattest", "ch03", lambda runs: max(ch03_monte_carlo_slopes(runs)))


def ch03_grid_last_win(integrand):
    """The largest k up to which the grid beats Monte Carlo at the budget at every k."""
    def read(runs):
        last = 0
        for row in runs.rows("ch03", "budget.csv"):
            if row["integrand"] != integrand:
                continue
            if float(row["trapezoid_error"]) >= float(row["monte_carlo_rmse"]):
                break
            last = int(row["dims"])
        return last
    return read


number("ch03.grid_last_win_k_smooth", "ch03", ch03_grid_last_win("gaussian_kd"))
number("ch03.grid_last_win_k_ball", "ch03", ch03_grid_last_win("unit_ball_kd"))
number("ch03.budget_ball_k3_trapezoid", "ch03",
       cell("ch03", "budget.csv", "trapezoid_error", integrand="unit_ball_kd", dims=3))
number("ch03.budget_ball_k3_monte_carlo", "ch03",
       cell("ch03", "budget.csv", "monte_carlo_rmse", integrand="unit_ball_kd", dims=3))
for method, column in (("trapezoid", "trapezoid_error"), ("monte_carlo", "monte_carlo_rmse")):
    number(f"ch03.ball_k8_{method}_percent", "ch03", lambda runs, column=column: 100 * runs.cell(
        "ch03", "budget.csv", column, integrand="unit_ball_kd", dims=8) / runs.cell(
        "ch03", "budget.csv", "reference", integrand="unit_ball_kd", dims=8))

number("ch03.budget_gaussian_k1_monte_carlo", "ch03",
       cell("ch03", "budget.csv", "monte_carlo_rmse", integrand="gaussian_kd", dims=1))

# Chapter 05: the default run (cornell) and the depth-0 run.
number("ch05.rays", "ch05", summary_value("ch05", "rays"))
number("ch05.rmse_slope", "ch05", summary_value("ch05", "rmse_slope"))
for spp in (1, 4, 16, 64, 256):
    number(f"ch05.rmse_spp{spp}", "ch05", cell("ch05", "rmse_vs_spp.csv", "rmse", spp=spp))
number("ch05.rmse_fall_1_to_256", "ch05", lambda runs: runs.cell(
    "ch05", "rmse_vs_spp.csv", "rmse", spp=1) / runs.cell("ch05", "rmse_vs_spp.csv", "rmse", spp=256))
number("ch05.mean_radiance", "ch05", summary_value("ch05", "mean_radiance"))
number("ch05.mean_radiance_reference", "ch05", summary_value("ch05", "mean_radiance_reference"))
number("ch05.depth_cut_shortfall_percent", "ch05", lambda runs: 100 * (
    1 - runs.summary("ch05")["mean_radiance"] / runs.summary("ch05")["mean_radiance_reference"]))


def ch05_mean_standard_error(runs):
    """The standard error of the image mean's gap to the reference's: each pixel's noise at the
    largest spp (rmse, the two-render estimate) and the reference's (its standard_error_rms),
    over the pixels, taken as independent: sqrt(rmse^2 + se_ref^2) / sqrt(width height)."""
    summary = runs.summary("ch05")
    rmse = runs.cell("ch05", "rmse_vs_spp.csv", "rmse", spp=max(summary["spp"]))
    reference = summary["reference"]["standard_error_rms"]
    return math.sqrt(rmse ** 2 + reference ** 2) / math.sqrt(summary["width"] * summary["height"])


number("ch05.mean_standard_error", "ch05", ch05_mean_standard_error)
number("ch05.depth_cut_gap_standard_errors", "ch05", lambda runs: (
    runs.summary("ch05")["mean_radiance_reference"] - runs.summary("ch05")["mean_radiance"])
    / ch05_mean_standard_error(runs))
number("ch05.largest_error_gap_percent", "ch05", lambda runs: max(
    100 * abs(float(row["rmse_vs_reference"]) / float(row["rmse"]) - 1)
    for row in runs.rows("ch05", "rmse_vs_spp.csv")))
for spp in (1, 4, 16, 64, 256, 1024):
    for column in ("rmse", "rmse_vs_reference"):
        number(f"ch05.depth0_{column}_spp{spp}", "ch05-depth0",
               cell("ch05-depth0", "rmse_vs_spp.csv", column, spp=spp))

# Chapter 06: the default run (furnace a = 0.5 studies, cornell) and the furnace a = 0.8 render.
def read_pfm_gray_means(path):
    """The mean over channels of every pixel of a PFM (little- or big-endian colour)."""
    with open(path, "rb") as file:
        header = [file.readline().strip() for _ in range(3)]
        width, height = (int(text) for text in header[1].split())
        order = "<" if float(header[2]) < 0 else ">"
        values = struct.unpack(f"{order}{3 * width * height}f", file.read(12 * width * height))
    return [sum(values[i:i + 3]) / 3 for i in range(0, len(values), 3)]


def pixel_mean_standard_error(label, image):
    def read(runs):
        pixels = read_pfm_gray_means(os.path.join(runs.scratch, label, image))
        mean = sum(pixels) / len(pixels)
        variance = sum((p - mean) ** 2 for p in pixels) / (len(pixels) - 1)
        return math.sqrt(variance / len(pixels))
    return read


for estimator in ("depth_cut", "roulette"):
    number(f"ch06.furnace_{estimator}_mean", "ch06-furnace",
           cell("ch06-furnace", "renders.csv", "mean_radiance", estimator=estimator))
    number(f"ch06.cornell_{estimator}_mean", "ch06",
           cell("ch06", "renders.csv", "mean_radiance", estimator=estimator))
    number(f"ch06.cornell_{estimator}_rays_per_sample", "ch06",
           cell("ch06", "renders.csv", "rays_per_sample", estimator=estimator))
def read_pfm_values(path):
    """Every channel of every pixel of a PFM (little- or big-endian colour), in file order."""
    with open(path, "rb") as file:
        header = [file.readline().strip() for _ in range(3)]
        width, height = (int(text) for text in header[1].split())
        order = "<" if float(header[2]) < 0 else ">"
        return struct.unpack(f"{order}{3 * width * height}f", file.read(12 * width * height))


def rms_error_against_reference(label, image, reference):
    """The RMS difference over pixels and channels between run `label`'s PFM `image` and the
    reference PFM that chapter 05's runs cached in the scratch folder's reference/ (make-figures
    gives them --reference-dir there)."""
    def read(runs):
        a = read_pfm_values(os.path.join(runs.scratch, label, image))
        r = read_pfm_values(os.path.join(runs.scratch, "reference", reference))
        if len(a) != len(r):
            raise ValueError(f"{image} and {reference} differ in size")
        return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, r)) / len(a))
    return read


# Chapter 06's Cornell pair against chapter 05's reference of the same scene and size (256x192,
# no depth cut, 1024 spp): the pair's errors, noise and bias together.
for estimator in ("depth_cut", "roulette"):
    number(f"ch06.cornell_{estimator}_rmse_vs_reference", "ch06",
           rms_error_against_reference("ch06", f"{estimator}.pfm", "cornell_ls1_256x192.pfm"))
number("ch06.furnace_roulette_standard_error", "ch06-furnace",
       pixel_mean_standard_error("ch06-furnace", "roulette.pfm"))
number("ch06.cornell_roulette_fewer_rays_percent", "ch06", lambda runs: 100 * (1 - runs.cell(
    "ch06", "renders.csv", "rays", estimator="roulette") / runs.cell(
    "ch06", "renders.csv", "rays", estimator="depth_cut")))


def ch06_largest_roulette_bias(column):
    def read(runs):
        rows = runs.rows("ch06", "bias.csv")
        row = max(rows, key=lambda row: abs(float(row["roulette_bias"])))
        return abs(float(row[column]))
    return read


number("ch06.roulette_largest_bias", "ch06", ch06_largest_roulette_bias("roulette_bias"))
number("ch06.roulette_largest_bias_ci", "ch06", ch06_largest_roulette_bias("roulette_ci"))
ch06_qs = ("0.4", "0.5", "0.6", "0.7", "0.8", "0.9", "0.95")
for q in ch06_qs:
    for column in ("variance", "variance_theory", "rays_per_path"):
        number(f"ch06.q{q}_{column}", "ch06", cell("ch06", "efficiency.csv", column, q=q))
    number(f"ch06.q{q}_variance_times_rays", "ch06", lambda runs, q=q: runs.cell(
        "ch06", "efficiency.csv", "variance", q=q) * runs.cell(
        "ch06", "efficiency.csv", "rays_per_path", q=q))
for column in ("variance", "rays_per_path"):
    number(f"ch06.throughput_{column}", "ch06",
           cell("ch06", "efficiency.csv", column, policy="throughput"))
number("ch06.throughput_variance_times_rays", "ch06", lambda runs: runs.cell(
    "ch06", "efficiency.csv", "variance", policy="throughput") * runs.cell(
    "ch06", "efficiency.csv", "rays_per_path", policy="throughput"))
number("ch06.best_fixed_q_by_rays", "ch06", lambda runs: min(
    (float(row["variance"]) * float(row["rays_per_path"]), float(row["q"]))
    for row in runs.rows("ch06", "efficiency.csv") if row["policy"] == "fixed")[1])
number("ch06.largest_variance_gap_percent_from_q0.5", "ch06", lambda runs: max(
    100 * abs(float(row["variance"]) / float(row["variance_theory"]) - 1)
    for row in runs.rows("ch06", "efficiency.csv")
    if row["policy"] == "fixed" and float(row["q"]) >= 0.5))
number("ch06.mean_path_length", "ch06", summary_value("ch06", "mean_path_length"))
# splitting.csv: the first hit split n ways; gains are efficiency at n = 16 over n = 1.
for q in ("0.6", "0.8"):
    for n in ("1", "16"):
        for column in ("efficiency", "efficiency_theory"):
            number(f"ch06.split_q{q}_n{n}_{column}", "ch06",
                   cell("ch06", "splitting.csv", column, q=q, n=n))
    for column in ("efficiency", "efficiency_theory"):
        number(f"ch06.split_q{q}_gain_{column}", "ch06", lambda runs, q=q, column=column: runs.cell(
            "ch06", "splitting.csv", column, q=q, n="16") / runs.cell(
            "ch06", "splitting.csv", column, q=q, n="1"))

# Chapter 07: the default run.
ch07_pdfs = {"uniform": "uniform", "cosine": "cosine", "cos2": "cos^2", "cos4": "cos^4",
             "cos8": "cos^8", "grazing": "grazing"}
for key, pdf in ch07_pdfs.items():
    columns = ["furnace_variance", "scene_variance"]
    if key != "uniform":
        columns.append("scene_variance_vs_uniform")
    if key in ("uniform", "cos2", "grazing"):
        columns.append("furnace_variance_theory")
    for column in columns:
        number(f"ch07.{key}_{column}", "ch07", cell("ch07", "variance_vs_m.csv", column, pdf=pdf))
for image in ("uniform", "cosine", "cosine_equal_time"):
    number(f"ch07.{image}_relative_mse", "ch07",
           cell("ch07", "equal_time.csv", "relative_mse", image=image))
for image in ("uniform", "cosine_equal_time"):
    number(f"ch07.{image}_rays", "ch07", cell("ch07", "equal_time.csv", "rays", image=image))
# The equal-cost image's spp is the uniform image's rays over a cosine sample's, rounded to the
# nearest: it may spend a little more than the uniform image.
number("ch07.equal_time_overspend_percent", "ch07", lambda runs: 100 * (runs.cell(
    "ch07", "equal_time.csv", "rays", image="cosine_equal_time") / runs.cell(
    "ch07", "equal_time.csv", "rays", image="uniform") - 1))
number("ch07.cosine_equal_time_spp", "ch07",
       cell("ch07", "equal_time.csv", "spp", image="cosine_equal_time"))
number("ch07.equal_time_less_error_percent", "ch07", lambda runs: 100 * (1 - runs.cell(
    "ch07", "equal_time.csv", "relative_mse", image="cosine_equal_time") / runs.cell(
    "ch07", "equal_time.csv", "relative_mse", image="uniform")))
number("ch07.rays", "ch07", summary_value("ch07", "rays"))

# Chapter 04: the default run (equal cost), --branching 1 --max-depth 10 (the missing light)
# and the furnace of albedo 0.5.
for n in (1, 2, 4, 8):
    for column in ("spp", "rays_per_pixel", "rms_error", "rms_error_at_budget"):
        number(f"ch04.equal_cost_n{n}_{column}", "ch04",
               cell("ch04", "equal_cost.csv", column, branching=n))
number("ch04.equal_cost_n8_over_n1", "ch04", lambda runs: runs.cell(
    "ch04", "equal_cost.csv", "rms_error_at_budget", branching=8) / runs.cell(
    "ch04", "equal_cost.csv", "rms_error_at_budget", branching=1))
for k in (0, 1, 2, 3, 4, 5, 6, 8, 10):
    number(f"ch04.missing_percent_k{k}", "ch04-depth10", lambda runs, k=k: 100 * runs.cell(
        "ch04-depth10", "missing_light.csv", "missing_fraction", depth=k))
for k in range(5):
    number(f"ch04.furnace_missing_percent_k{k}", "ch04-furnace", lambda runs, k=k: 100 * runs.cell(
        "ch04-furnace", "missing_light.csv", "missing_fraction", depth=k))

# The answers' runs.
# The fraction of the square's points inside the disk at the largest N, over every trial: the
# acceptance rate of the disk sampled by rejection from the square (under-the-hood.md).
number("ch02.acceptance_rate", "ch02", lambda runs: runs.summary("ch02")["disk"]["estimate_at_largest_n"] / 4)
number("ch02.theory_std_n1e6", "ch02", cell("ch02", "disk_area.csv", "theory_std", n=1000000))
number("ch02.ball15_mean", "ch02-ball15",
       cell("ch02-ball15", "ball_volume.csv", "mean_estimate", k=15))
number("ch02.ball15_relative_std", "ch02-ball15",
       cell("ch02-ball15", "ball_volume.csv", "relative_std", k=15))
number("ch05.furnace_mean_radiance", "ch05-furnace", summary_value("ch05-furnace", "mean_radiance"))
number("ch05.furnace_rmse_spp64", "ch05-furnace",
       cell("ch05-furnace", "rmse_vs_spp.csv", "rmse", spp=64))
number("ch05.rmse_fall_1_to_64", "ch05", lambda runs: runs.cell(
    "ch05", "rmse_vs_spp.csv", "rmse", spp=1) / runs.cell("ch05", "rmse_vs_spp.csv", "rmse", spp=64))
for depth in (1, 2, 4):
    label = f"ch05-depth{depth}"
    for spp in (256, 1024):
        for column in ("rmse", "rmse_vs_reference"):
            number(f"ch05.depth{depth}_{column}_spp{spp}", label,
                   cell(label, "rmse_vs_spp.csv", column, spp=spp))
    number(f"ch05.depth{depth}_mean_radiance", label, summary_value(label, "mean_radiance"))
number("ch05.depth4_mean_radiance_reference", "ch05-depth4",
       summary_value("ch05-depth4", "mean_radiance_reference"))

number("ch04.rays", "ch04", summary_value("ch04", "rays"))
number("ch04.bounce3_share_percent", "ch04-depth10", lambda runs: 100 * (runs.cell(
    "ch04-depth10", "missing_light.csv", "missing_fraction", depth=2) - runs.cell(
    "ch04-depth10", "missing_light.csv", "missing_fraction", depth=3)))

def ch03_dims12(integrand, column, percent=False):
    def read(runs):
        value = runs.cell("ch03-dims12", "budget.csv", column, integrand=integrand, dims=12)
        if percent:
            value *= 100 / runs.cell("ch03-dims12", "budget.csv", "reference",
                                     integrand=integrand, dims=12)
        return value
    return read


number("ch03.k12_gaussian_trapezoid", "ch03-dims12", ch03_dims12("gaussian_kd", "trapezoid_error"))
number("ch03.k12_gaussian_trapezoid_percent", "ch03-dims12",
       ch03_dims12("gaussian_kd", "trapezoid_error", percent=True))
number("ch03.k12_gaussian_monte_carlo", "ch03-dims12",
       ch03_dims12("gaussian_kd", "monte_carlo_rmse"))
number("ch03.k12_ball_monte_carlo", "ch03-dims12", ch03_dims12("unit_ball_kd", "monte_carlo_rmse"))
number("ch03.k12_ball_monte_carlo_percent", "ch03-dims12",
       ch03_dims12("unit_ball_kd", "monte_carlo_rmse", percent=True))
number("ch03.k12_ball_trapezoid_slope", "ch03-dims12", cell(
    "ch03-dims12", "slopes.csv", "fitted_slope", integrand="unit_ball_kd", dims=12,
    method="trapezoid"))

for n in (1, 2, 4, 8):
    for k in (1, 2, 3, 4):
        number(f"ch04.rays_n{n}_k{k}", "ch04", cell("ch04", "rays.csv", "rays", branching=n, depth=k))
number("ch04.rays_ratio_n8_k3_to_k4", "ch04", lambda runs: runs.cell(
    "ch04", "rays.csv", "rays", branching=8, depth=4) / runs.cell(
    "ch04", "rays.csv", "rays", branching=8, depth=3))


def ch04_fitted_albedo(runs):
    """The a of the guide a^(k+1) in missing_light_vs_depth: least squares of log(missing)
    against k + 1 through the origin, as chapters/04_recursive_nk/plots.hpp fits it."""
    sum_xy = sum_xx = 0.0
    for row in runs.rows("ch04", "missing_light.csv"):
        missing = float(row["missing_fraction"])
        if missing > 0:
            x = int(row["depth"]) + 1
            sum_xy += x * math.log(missing)
            sum_xx += x * x
    return math.exp(sum_xy / sum_xx)


number("ch04.fitted_albedo", "ch04", ch04_fitted_albedo)

# Chapter 08: the default run (cornell): its two images and the shoot-out at the largest ray
# budget. The cosine estimator is exact in the furnace: its relMSE is 0 and its efficiency
# infinite, which no page quotes as a number.
CH08_LARGEST_BUDGET = 512
CH08_SCENES = (("furnace", "1", "furnace"), ("cornell", "0.1", "cornell_x0.1"),
               ("cornell", "1", "cornell_x1"), ("cornell", "3", "cornell_x3"),
               ("cornell-spheres", "1", "cornell-spheres"), ("smallpt", "1", "smallpt"))
CH08_ESTIMATORS = ("uniform", "cosine", "cosine_rr", "nee", "mis_balance", "mis_power")
for image in ("nee", "mis"):
    number(f"ch08.{image}_rel_mse", "ch08", cell("ch08", "images.csv", "rel_mse", image=image))
for scene, scale, slug in CH08_SCENES:
    for estimator in CH08_ESTIMATORS:
        exact = scene == "furnace" and estimator == "cosine"
        for column in ("spp", "rel_mse", "efficiency", "efficiency_vs_uniform"):
            if exact and column != "spp":
                continue
            number(f"ch08.{slug}.{estimator}.{column}", "ch08",
                   cell("ch08", "efficiency.csv", column, scene=scene, light_scale=scale,
                        estimator=estimator, budget_rays_per_pixel=CH08_LARGEST_BUDGET))



def ch08_means_within_interval(runs):
    """How many of the shoot-out's images at the largest budget have the reference's mean
    inside their 95% interval."""
    return sum(1 for row in runs.rows("ch08", "efficiency.csv")
               if float(row["budget_rays_per_pixel"]) == CH08_LARGEST_BUDGET
               and float(row["mean_ci_low"]) <= float(row["reference_mean"])
               <= float(row["mean_ci_high"]))


number("ch08.means_within_interval", "ch08", ch08_means_within_interval)

# Chapter 08's Veach plates (plates.csv): relMSE per plate x light x strategy, and MIS power's
# ratio to the best strategy, worst and geometric mean over the 16 cells.
CH08_PLATE_STRATEGIES = ("light", "bsdf", "mis_balance", "mis_power")
for plate in range(4):
    for light in range(4):
        for strategy in CH08_PLATE_STRATEGIES:
            number(f"ch08.plates.p{plate}_l{light}.{strategy}", "ch08",
                   cell("ch08", "plates.csv", "rel_mse", plate=plate, light=light,
                        strategy=strategy))


def ch08_mis_power_over_best(runs):
    return [float(row["rel_mse_vs_best"]) for row in runs.rows("ch08", "plates.csv")
            if row["strategy"] == "mis_power"]


number("ch08.plates.mis_power_worst_ratio", "ch08",
       lambda runs: max(ch08_mis_power_over_best(runs)))
number("ch08.plates.mis_power_mean_ratio", "ch08", lambda runs: math.exp(
    sum(math.log(r) for r in ch08_mis_power_over_best(runs)) / 16))

# MIS (one light and one BSDF sample) against two light samples, at equal rays: where the BSDF
# sample adds almost nothing, MIS has one useful sample where light sampling has two, so the
# ratio of their relative MSEs is about 2 (the allocation, not the weights).
for plate in range(4):
    for light in range(4):
        number(f"ch08.plates.p{plate}_l{light}.mis_balance_over_light", "ch08",
               lambda runs, plate=plate, light=light: runs.cell(
                   "ch08", "plates.csv", "rel_mse", plate=plate, light=light,
                   strategy="mis_balance") / runs.cell(
                   "ch08", "plates.csv", "rel_mse", plate=plate, light=light, strategy="light"))

# Chapter 09: the default run. Per study and sampler the fitted slope, its standard error and
# the rms error at the largest N; at the budget, the relative errors and the gains over
# independent points; the largest k at which the grid still beats independent points.
CH09_SERIES = {"disk": ["independent", "jittered", "latin_hypercube", "sobol_xor", "sobol_owen",
                        "halton"],
               "smooth": ["independent", "jittered", "latin_hypercube", "sobol_xor", "sobol_owen",
                          "halton", "sobol_owen_odd_n"]}
for study, samplers in CH09_SERIES.items():
    for sampler in samplers:
        number(f"ch09.{study}_{sampler}", "ch09",
               summary_value("ch09", study, sampler, "fitted_slope"))
        number(f"ch09.{study}_{sampler}_rmse", "ch09",
               summary_value("ch09", study, sampler, "rmse_at_largest_n"))
        if study == "disk" or sampler == "sobol_owen":  # the slopes the page gives errors of
            number(f"ch09.{study}_{sampler}_se", "ch09",
                   summary_value("ch09", study, sampler, "fitted_slope_standard_error"))
for k in (1, 2, 4, 8, 16):
    for method in ("independent", "trapezoid"):
        number(f"ch09.relative_{method}_k{k}", "ch09",
               cell("ch09", "dimension.csv", "relative_error", dims=k, method=method))
    for method in ("latin_hypercube", "sobol_owen"):
        number(f"ch09.gain_{method}_k{k}", "ch09", lambda runs, k=k, method=method: next(
            row[method] for row in runs.summary("ch09")["dimension"]["gain_over_independent"]
            if row["dims"] == k))


def ch09_grid_last_win(runs):
    """The largest k up to which the trapezoid rule beats independent points at every k."""
    rows = runs.rows("ch09", "dimension.csv")
    error = {(int(r["dims"]), r["method"]): float(r["rmse"]) for r in rows}
    last = 0
    for k in sorted({k for k, _ in error}):
        if (k, "trapezoid") not in error or error[(k, "trapezoid")] >= error[(k, "independent")]:
            break
        last = k
    return last


number("ch09.grid_last_win_k", "ch09", ch09_grid_last_win)

# Chapter 09's render study (runs ch09-render on cornell, ch09-render-spheres on
# cornell-spheres): per sampler and depth (1 and the full 10) the fitted slope of the rms error
# against spp, its standard error, and the rms error at 1024 spp; per sampler the rays (in
# millions) at 1024 spp and full depth, which make equal spp equal rays.
for run, prefix in (("ch09-render", "ch09.render_"),
                    ("ch09-render-spheres", "ch09.render_spheres_")):
    for sampler in ("independent", "jittered", "sobol"):
        for depth in (1, 10):
            number(f"{prefix}{sampler}_d{depth}", run,
                   cell(run, "render_slopes.csv", "fitted_slope", sampler=sampler, depth=depth))
            number(f"{prefix}{sampler}_d{depth}_se", run,
                   cell(run, "render_slopes.csv", "standard_error", sampler=sampler, depth=depth))
            number(f"{prefix}{sampler}_d{depth}_rmse", run,
                   cell(run, "render_error.csv", "rmse", sampler=sampler, depth=depth, spp=1024))
        number(f"{prefix}{sampler}_d10_megarays", run,
               lambda runs, run=run, sampler=sampler: runs.cell(
                   run, "render_error.csv", "rays", sampler=sampler, depth=10, spp=1024) / 1e6)

# Chapter 08's light choice (light_choice.csv): relMSE of uniform and power-proportional
# choice over the floor, the ratio of the two away from the dim light and beside it, and the
# probability power choice gives the dim light.
for choice in ("uniform", "power"):
    number(f"ch08.light_choice.{choice}.all", "ch08",
           cell("ch08", "light_choice.csv", "rel_mse", choice=choice, region="all"))
number("ch08.light_choice.power.p_dim", "ch08",
       cell("ch08", "light_choice.csv", "p_dim", choice="power", region="all"))
for region in ("beside_dim", "rest"):
    number(f"ch08.light_choice.uniform_over_power.{region}", "ch08",
           lambda runs, region=region: runs.cell(
               "ch08", "light_choice.csv", "rel_mse", choice="uniform", region=region) /
           runs.cell("ch08", "light_choice.csv", "rel_mse", choice="power", region=region))

# (end of sources)

if __name__ == "__main__":
    sys.exit(main(sys.argv))
