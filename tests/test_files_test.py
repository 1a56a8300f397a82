#!/usr/bin/env python3
"""Every source of common/ has a test file of its name: common/<layer>/<name>.hpp|cpp is tested
in tests/<layer>/<name>_test.cpp (or <name>_<aspect>_test.cpp, or its statistical checks
<name>_checks.cpp), so that `ls tests/<layer>/` shows what tests common/<layer>/.

The sources below are the exceptions, each with where it is tested today. The list only
shrinks: the test also fails when a listed source has gained a test file of its name (take it
off the list), when a listed source is gone, and when the file named as its test is gone.

  python3 tests/test_files_test.py ROOT
"""

import os
import sys

# source (layer/name) -> where it is tested today, or why no test of its own.
NOT_YET_OWN_FILE = {
    # No property of their own to test, or only through a clock or the console.
    "core/progress": "a progress bar on stderr; the chapter tests run it (--quiet off)",
    "core/stopwatch": "a wall-clock timer: nothing a fixed-seed test can hold",
    "core/math": "aliases and constants; used by every test",
    "app/usage_error": "one exception type; its exit 2 is tested by tests/chapters/",
    "app/render_summary": "the chapters' summary.json rows, parsed by tests/chapters/",
    "app/summary": "summary.json and timings.json, parsed by tests/chapters/",
    # Tested inside a test file of another name (one file tests several sources).
    "core/cpu_features": "tests/engine/path_lanes_test.cpp",
    "core/parallel": "tests/core/rng_test.cpp",
    "core/pcg32_avx2": "tests/integration/disk_counter_test.cpp",
    "geometry/avx2_lanes": "tests/geometry/engines_differential_test.cpp",
    "geometry/nearest_dispatch": "tests/geometry/engines_differential_test.cpp",
    "geometry/quad_set": "tests/geometry/engines_differential_test.cpp",
    "geometry/sphere_set": "tests/geometry/engines_differential_test.cpp",
    "geometry/ray_lanes": "tests/geometry/engines_differential_test.cpp",
    "geometry/ray": "tests/geometry/hit_test.cpp",
    "integration/convergence": "tests/integration/statistics_test.cpp",
    "integration/domain": "tests/integration/monte_carlo_test.cpp",
    "integration/error_study": "tests/chapters/ch03_trapezoid_vs_mc_test.cpp",
    "integration/integrands": "tests/integration/monte_carlo_test.cpp",
    "integration/log_grid": "tests/integration/quadrature_test.cpp",
    "io/exclusive_file": "tests/app/reference_cache_test.cpp",
    "io/labelled_grid": "tests/io/contact_sheet_test.cpp",
    "io/text": "tests/io/contact_sheet_test.cpp",
    "app/ray_limit": "tests/app/work_limit_test.cpp",
    "render/image": "tests/io/image_file_test.cpp",
    "render/pixel_estimate": "tests/render/path_tracer_test.cpp",
    "render/recursive_render": "tests/render/recursive_estimator_test.cpp",
    "render/relative_error": "tests/chapters/ch08_next_event_estimation_test.cpp",
    "render/render_totals": "tests/render/path_tracer_test.cpp",
    "render/two_render_error": "tests/render/path_tracer_checks.cpp",
    "sampling/cone": "tests/sampling/sampling_checks.cpp",
    "sampling/cosine_power": "tests/render/importance_path_tracer_test.cpp",
    "sampling/sphere": "tests/sampling/sampling_checks.cpp",
}


def own_test_files(root, layer, name):
    folder = os.path.join(root, "tests", layer)
    if not os.path.isdir(folder):
        return []
    return [f for f in os.listdir(folder)
            if f in (f"{name}_test.cpp", f"{name}_checks.cpp")
            or (f.startswith(f"{name}_") and f.endswith("_test.cpp"))]


def problems(root):
    sources = set()
    common = os.path.join(root, "common")
    for layer in sorted(os.listdir(common)):
        if not os.path.isdir(os.path.join(common, layer)):
            continue
        for f in os.listdir(os.path.join(common, layer)):
            stem, ext = os.path.splitext(f)
            if ext in (".hpp", ".cpp"):
                sources.add(f"{layer}/{stem}")
    found = []
    for source in sorted(sources):
        layer, name = source.split("/")
        has_own = bool(own_test_files(root, layer, name))
        if source in NOT_YET_OWN_FILE:
            if has_own:
                found.append(f"common/{source}: has a test file of its name now; "
                             f"take it off NOT_YET_OWN_FILE")
            where = NOT_YET_OWN_FILE[source]
            if where.startswith("tests/") and not os.path.isfile(os.path.join(root, where)):
                found.append(f"common/{source}: listed as tested in {where}, which is gone")
        elif not has_own:
            found.append(f"common/{source}: no tests/{layer}/{name}_test.cpp "
                         f"(nor {name}_<aspect>_test.cpp, {name}_checks.cpp)")
    for source in sorted(set(NOT_YET_OWN_FILE) - sources):
        found.append(f"NOT_YET_OWN_FILE lists common/{source}, which is gone")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    found = problems(root)
    for line in found:
        print(line)
    if found:
        return 1
    print(f"every source of common/ has a test file of its name, but the "
          f"{len(NOT_YET_OWN_FILE)} listed")
    return 0


if __name__ == "__main__":
    sys.exit(main())
