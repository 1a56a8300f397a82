"""I/O errors in the middle of a run (issue #43, items 5 and 8): renames fail with EIO from the
N-th on, for every N from 0 until a run gets through, through tests/robustness/
failing_renames.cpp loaded with LD_PRELOAD (its path in $MCRT_FAILING_RENAMES).

Imported by robustness.py, which passes itself in (groups(r)). Group:

  io-errors  "Failure paths never destroy": whatever rename fails, a run either ends whole
             (exit 0) or says so in one line (exit 1) with the system's reason, and the previous
             run in --out is still there, byte for byte, in --out or where the line says; a new
             --out is whole or absent; a valid entry of the reference cache is never removed.
"""

import os
import re
import shutil
from pathlib import Path

REASON = "Input/output error"  # strerror(EIO)
MAX_RENAMES = 80  # a tiny run renames far fewer files (each file, then the folder)


def failing(after):
    env = dict(os.environ)
    env["LD_PRELOAD"] = os.environ["MCRT_FAILING_RENAMES"]
    env["MCRT_FAIL_RENAMES_AFTER"] = str(after)
    return env


def run_with(r, command, cwd, env):
    saved = dict(os.environ)
    os.environ.clear()
    os.environ.update(env)
    try:
        return r.run(command, cwd=cwd)
    finally:
        os.environ.clear()
        os.environ.update(saved)


def named_paths(err):
    """The paths a message names in quotes."""
    return [Path(p) for p in re.findall(r"'([^']+)'", err)]


def previous_kept_problems(r, out, previous, err):
    """The previous run is byte-identical in --out or in a folder the message names."""
    for place in [out] + named_paths(r.text(err)):
        if r.snapshot(place) == previous:
            return []
    return [f"the previous run is gone (not in --out nor where the message says): "
            f"{r.text(err)[:300]!r}"]


def failure_problems(r, code, err, parent):
    if code != 1:
        return r.exit_problems(code, 1, err)
    problems = r.one_line_problems(err, [parent])
    if REASON not in r.text(err):
        problems.append(f"message lacks the system's reason ({REASON}): {r.text(err)!r}")
    return problems


def case_replacing(r, chapters, tmp, checks, name):
    """Over a previous run: each failing step keeps the previous run."""
    command = [chapters[name]] + r.TINY[name] + ["--quiet"]
    # The previous run is the same at every step (seed 1, a healthy disk): made once, then
    # copied into each step's --out (files, modes and the manifest: all a later run looks at).
    # Each step still starts from a whole run of its own; the chapter ran once, not 20 times.
    template = r.fresh(tmp / f"previous-{name}") / "out"
    code, _, err, _ = r.run(command + ["--seed", "1", "--out", str(template)],
                            cwd=template.parent)
    if code != 0:
        checks.case(f"{name} previous run", r.exit_problems(code, 0, err))
        return
    previous = r.snapshot(template)
    failures = 0
    for after in range(MAX_RENAMES):
        parent = r.fresh(tmp / f"replace{after}")
        out = parent / "out"
        shutil.copytree(template, out, symlinks=True)
        code, _, err, _ = run_with(r, command + ["--seed", "2", "--out", str(out)], parent,
                                   failing(after))
        if code == 0:
            problems = r.output_problems(out)
            if r.snapshot(out) == previous:
                problems.append("exit 0 but --out still holds the previous run")
            checks.case(f"{name} over a previous run, renames fail from the {after}th on",
                        problems)
            break
        failures += 1
        problems = failure_problems(r, code, err, parent)
        problems += previous_kept_problems(r, out, previous, err)
        # And the next run, on a healthy disk, replaces what is there.
        code, _, err, _ = r.run(command + ["--seed", "3", "--out", str(out)], cwd=parent)
        problems += [f"the next run: {p}" for p in r.exit_problems(code, 0, err)]
        checks.case(f"{name} over a previous run, renames fail from the {after}th on", problems)
    else:
        checks.case(f"{name} over a previous run", [f"no run got through {MAX_RENAMES} renames"])
    if failures == 0:
        checks.case(f"{name} over a previous run", ["no rename failed: the shim is not loaded"])


def case_new_out(r, chapters, tmp, checks, name):
    """A new --out: whole or absent, and nothing left beside it."""
    command = [chapters[name]] + r.TINY[name] + ["--quiet"]
    for after in range(MAX_RENAMES):
        parent = r.fresh(tmp / f"new{after}")
        out = parent / "out"
        code, _, err, _ = run_with(r, command + ["--out", str(out)], parent, failing(after))
        if code == 0:
            checks.case(f"{name} new --out, renames fail from the {after}th on",
                        r.output_problems(out))
            return
        problems = failure_problems(r, code, err, parent)
        if out.exists():
            problems.append(f"--out exists after a failed run: {sorted(os.listdir(out))}")
        if r.beside_out(parent):
            problems.append(f"left beside --out: {r.beside_out(parent)}")
        checks.case(f"{name} new --out, renames fail from the {after}th on", problems)
    checks.case(f"{name} new --out", [f"no run got through {MAX_RENAMES} renames"])


def case_cache_entry_kept(r, chapters, tmp, checks):
    """A valid cache entry survives a run whose own cache writes fail at every step."""
    name = "ch05_path_tracer"
    command = [chapters[name]] + r.TINY[name] + ["--quiet"]
    cache = r.fresh(tmp / "cache")
    parent = r.fresh(tmp / "cache-first")
    code, _, err, _ = r.run(command + ["--reference-dir", str(cache), "--out",
                                       str(parent / "out")], cwd=parent)
    if code != 0:
        checks.case(f"{name} first run", r.exit_problems(code, 0, err))
        return
    entry = r.snapshot(cache)
    other = r.with_flags(r.TINY[name], "--width", "20") + ["--quiet"]
    for after in range(MAX_RENAMES):
        parent = r.fresh(tmp / f"cache{after}")
        code, _, err, _ = run_with(r, [chapters[name]] + other +
                                   ["--reference-dir", str(cache), "--out", str(parent / "out")],
                                   parent, failing(after))
        problems = [] if code == 0 else failure_problems(r, code, err, parent)
        now = r.snapshot(cache)
        lost = [k for k, v in entry.items() if k.endswith((".pfm", ".json")) and now.get(k) != v]
        if lost:
            problems.append(f"a valid cache entry changed or went: {lost}")
        checks.case(f"{name} cache, renames fail from the {after}th on", problems)
        if code == 0:
            return
    checks.case(f"{name} cache", [f"no run got through {MAX_RENAMES} renames"])


def group_io_errors(r, chapters, tmp, checks):
    if not os.environ.get("MCRT_FAILING_RENAMES"):
        checks.case("io-errors", ["$MCRT_FAILING_RENAMES names no shim"])
        return
    for name in ("ch01_ray_tracing", "ch05_path_tracer"):
        if name not in chapters:
            checks.case(name, ["not built"])
            return
    case_replacing(r, chapters, tmp, checks, "ch01_ray_tracing")
    case_new_out(r, chapters, tmp, checks, "ch01_ray_tracing")
    case_replacing(r, chapters, tmp, checks, "ch05_path_tracer")
    case_cache_entry_kept(r, chapters, tmp, checks)


def groups(r):
    """The groups of this module, as robustness.py's GROUPS takes them."""
    return {"io-errors": lambda chapters, tmp, checks: group_io_errors(r, chapters, tmp, checks)}
