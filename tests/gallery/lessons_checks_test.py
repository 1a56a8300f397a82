#!/usr/bin/env python3
"""The gallery's checks against theory (scripts/make-gallery's chNN_checks) read the chapters'
numbers as the chapters write them, without a browser:
  - chapter 08's image means carry 95% intervals (mean +- 1.96 standard errors,
    chapters/08_next_event_estimation/shootout.hpp): the gallery turns the half-width into a
    standard error by 1.96, so a mean 2 standard errors from its reference reads "2.0";
  - chapter 03's trapezoid slopes are compared with the slope the count c (n - 1)^-2 predicts
    over the run's own n's, as a ratio (their errors are deterministic: a least-squares
    standard error is no statistical error);
  - chapter 04's missing-light ratio is compared with the a of the law a^(k+1) fitted to every
    depth, not with the first measured ratio;
  - chapter 09's render study (when the run made one): depth-1 slopes of jittered and Sobol'
    steeper than independent's beyond their standard errors, full-depth slopes near -1/2.

    lessons_checks_test.py REPO_ROOT
"""

import importlib.machinery
import importlib.util
import math
import os
import sys
import tempfile
import unittest
from pathlib import Path

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
loader = importlib.machinery.SourceFileLoader(
    "make_gallery", os.path.join(REPO, "scripts", "make-gallery"))
spec = importlib.util.spec_from_loader("make_gallery", loader)
gallery = importlib.util.module_from_spec(spec)
loader.exec_module(gallery)


def named(checks, start):
    found = [c for c in checks if c is not None and c.what.startswith(start)]
    assert len(found) == 1, [c.what for c in checks if c is not None]
    return found[0]


class Chapter08IntervalTest(unittest.TestCase):
    def shootout_row(self, scene, light_scale, mean, half_width, reference):
        return {"scene": scene, "light_scale": light_scale, "estimator": "mis_power",
                "rays_per_pixel": 512, "rel_mse": 0.01, "mean": mean,
                "mean_ci_low": mean - half_width, "mean_ci_high": mean + half_width,
                "reference_mean": reference}

    def test_a_95_percent_half_width_is_1_96_standard_errors(self):
        # standard error 0.01: the chapter's interval is +- 0.0196; the mean sits 0.02 off
        summary = {"shootout": [self.shootout_row("furnace", 1.0, 2.02, 0.0196, 2.0),
                                self.shootout_row("cornell", 0.1, 0.13, 0.00196, 0.1)]}
        checks = gallery.ch08_checks(summary)
        furnace = named(checks, "furnace radiance")
        self.assertAlmostEqual(furnace.error, 0.01, places=12)
        self.assertEqual(furnace.agreement(), "2.0 standard errors apart")
        small = named(checks, "small light, MIS (power): image mean")
        self.assertEqual(small.agreement(), "30.0 standard errors apart")

    def test_the_conversion_is_the_chapters_z(self):
        # the chapter's z, read from its source: a change there must come here too
        source = Path(REPO, "chapters", "08_next_event_estimation", "shootout.hpp").read_text()
        self.assertIn(f"return {{mean_radiance(image), {gallery.CH08_INTERVAL_Z} * std::sqrt(",
                      source)


class Chapter03SlopeTest(unittest.TestCase):
    def test_the_trapezoid_slopes_are_compared_with_the_count_corrected_law(self):
        n = [2, 3, 5, 8, 12, 19, 31, 48, 76, 119]
        summary = {"dims": [1, 2], "slopes": [
            {"integrand": "gaussian_1d", "dims": 1, "method": "trapezoid",
             "fitted_slope": -2.05, "standard_error": 0.01, "theory_slope": -2.0},
            {"integrand": "ceil_sin_1d", "dims": 1, "method": "trapezoid",
             "fitted_slope": -0.95, "standard_error": 0.05, "theory_slope": -1.0}],
            "_trapezoid_points_per_axis": {"gaussian_1d": n, "ceil_sin_1d": n}}
        checks = gallery.ch03_checks(summary)
        smooth = named(checks, "trapezoid rule, smooth 1D")
        logs = [math.log(k) for k in n]
        mean = sum(logs) / len(logs)
        # the least-squares slope of log (n-1)^-2 against log n, by hand
        expected = sum((x - mean) * -2 * math.log(k - 1) for x, k in zip(logs, n)) / \
            sum((x - mean) ** 2 for x in logs)
        self.assertAlmostEqual(smooth.predicted, expected, places=12)
        self.assertLess(smooth.predicted, -2.0)  # steeper than n^-2 at small n
        self.assertIsNone(smooth.error)
        self.assertNotIn("standard errors", smooth.agreement())
        jump = named(checks, "trapezoid rule, a jump in 1D")
        self.assertAlmostEqual(jump.predicted, expected / 2, places=12)

    def test_the_grids_are_read_from_errors_csv(self):
        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder, "errors.csv")
            path.write_text("integrand,dims,method,points_per_axis,evaluations,estimate,"
                            "reference,abs_error,rmse\n"
                            "gaussian_1d,1,trapezoid,2,2,0.7,0.75,5e-2,\n"
                            "gaussian_1d,1,trapezoid,3,3,0.74,0.75,1e-2,\n"
                            "gaussian_1d,1,trapezoid,4,4,0.75,0.75,0,\n"
                            "gaussian_1d,1,monte_carlo,,8,0.74,0.75,1e-2,1e-2\n"
                            "gaussian_kd,2,trapezoid,3,9,0.5,0.55,5e-2,\n", encoding="utf-8")
            # the exact row (error 0) is left out, as the chapter's fit leaves it out
            self.assertEqual(gallery.trapezoid_grids(path), {"gaussian_1d": [2, 3]})


class Chapter04RatioTest(unittest.TestCase):
    def test_the_predicted_ratio_is_the_fitted_law(self):
        fractions = [0.45, 0.21, 0.10, 0.05, 0.026]
        summary = {"missing_light": [{"depth": k, "missing_fraction": f}
                                     for k, f in enumerate(fractions)]}
        ratio = named(gallery.ch04_checks(summary), "missing light, ratio")
        xs = [k + 1 for k in range(len(fractions))]
        fitted = math.exp(sum(x * math.log(f) for x, f in zip(xs, fractions)) /
                          sum(x * x for x in xs))
        self.assertAlmostEqual(ratio.predicted, fitted, places=12)
        self.assertAlmostEqual(ratio.measured, 0.026 / 0.05, places=12)
        self.assertNotAlmostEqual(ratio.predicted, 0.21 / 0.45, places=3)  # not the first ratio


class Chapter09RenderStudyTest(unittest.TestCase):
    # slopes of the pinned cornell run (docs/09_stratified_qmc.md): (sampler, depth) ->
    # (fitted slope, standard error)
    PINNED = {("independent", 1): (-0.48, 0.008), ("jittered", 1): (-0.59, 0.015),
              ("sobol", 1): (-0.61, 0.010), ("independent", 10): (-0.48, 0.016),
              ("jittered", 10): (-0.55, 0.012), ("sobol", 10): (-0.53, 0.008)}

    def summary(self, changed=None):
        slopes = dict(self.PINNED)
        slopes.update(changed or {})
        return {"render": {"scene": "cornell", "depths": [1, 10], "slopes": [
            {"sampler": sampler, "depth": depth, "fitted_slope": slope, "standard_error": error,
             "points": 11} for (sampler, depth), (slope, error) in slopes.items()]}}

    def test_the_pinned_run_passes_every_check(self):
        checks = [c for c in gallery.ch09_render_checks(self.summary()) if c]
        self.assertEqual(len(checks), 5)
        for c in checks:
            self.assertEqual(c.agreement(), "inside", c.what)
        # and the chapter's checks include them
        named(gallery.ch09_checks(self.summary()), "path tracer, cornell, depth 1, sobol")

    def test_a_stratified_slope_no_steeper_than_independent_fails(self):
        # a sampler that stratified nothing: the slope of independent points within its errors
        checks = gallery.ch09_render_checks(self.summary({("sobol", 1): (-0.50, 0.010)}))
        self.assertEqual(named(checks, "path tracer, cornell, depth 1, sobol").agreement(),
                         "OUTSIDE")
        self.assertEqual(named(checks, "path tracer, cornell, depth 1, jittered").agreement(),
                         "inside")

    def test_a_full_depth_slope_far_from_one_half_fails(self):
        # padding that kept the sets' nesting (-0.35, correlated bounces) or a slope too steep
        for slope in (-0.35, -0.70):
            checks = gallery.ch09_render_checks(self.summary({("sobol", 10): (slope, 0.01)}))
            self.assertEqual(named(checks, "path tracer, cornell, depth 10, sobol").agreement(),
                             "OUTSIDE", slope)

    def test_a_run_without_the_study_has_no_render_checks(self):
        self.assertEqual(gallery.ch09_render_checks({}), [])


class CaptionsTest(unittest.TestCase):
    def test_no_caption_repeats_its_title(self):
        for number, stems in gallery.CAPTIONS.items():
            for stem, caption in stems.items():
                title = gallery.IMAGE_TITLES.get(number, {}).get(stem)
                # what to see: at least 6 words beyond those of the figure's name
                extra = len(caption.split()) - len((title or "").split())
                self.assertGreaterEqual(extra, 6, f"{number} {stem}: '{caption}' says little "
                                                  f"more than its name '{title}'")
        for stem in ("spp_0001", "spp_0016"):
            caption = gallery.caption_for("05", stem)
            # the old caption was the title again ("The render at 1 sample per pixel.")
            self.assertNotIn("the render at", caption.lower())
            self.assertGreaterEqual(len(caption.split()), 10)

    def test_chapter_07_speaks_of_rays_not_time(self):
        for text in list(gallery.CAPTIONS["07"].values()) + \
                list(gallery.IMAGE_TITLES["07"].values()):
            self.assertNotIn("time", text.lower())


if __name__ == "__main__":
    unittest.main(verbosity=2)
