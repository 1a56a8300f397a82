"""--out as careless scripts, unlucky users and a hostile neighbour try it (issue #34, part 1).

Imported by robustness.py, which passes itself in (groups(r)) so the helpers are shared. Each
case names the README guarantee it checks. Groups:

  out-manifest  "A run replaces only what runs wrote": only a folder whose manifest lists
                everything in it is replaced; $HOME never; a FIFO is refused without blocking.
                "Shared folders keep their owner and mode" (root only), overlayfs (root only)
  out-ends      "Signals and pipes": a closed stdout pipe, every handled signal beyond INT and
                TERM; "Whole folders": the staging folder of a killed run
  out-flags     "Refused work": `--flag=` with nothing after it, values that are not UTF-8;
                "Whole folders": folder names of the longest length
"""

import os
import shutil
import signal
import stat
import subprocess
import time
from pathlib import Path

MANIFEST = ".mcrt-manifest"
CH01 = "ch01_ray_tracing"
# A uid and gid that are not root's: the owner of a shared folder in the root-only cases.
NOBODY = 65534


def manifest_problems(out):
    """The manifest lists exactly what --out holds, itself included (folders end in '/')."""
    out = Path(out)
    path = out / MANIFEST
    if not path.is_file():
        return [f"no {MANIFEST} in {out.name}"]
    listed = set(path.read_text(encoding="utf-8", errors="replace").splitlines())
    present = {str(p.relative_to(out)) + ("/" if p.is_dir() else "") for p in out.rglob("*")}
    problems = []
    if listed != present:
        problems.append(f"manifest differs from the folder: unlisted {sorted(present - listed)}, "
                        f"missing {sorted(listed - present)}")
    return problems


def whole_run_problems(r, out):
    """A complete run: every file complete (robustness.output_problems) and all listed."""
    problems = r.output_problems(out)
    return problems + (manifest_problems(out) if not problems else [])


def tiny(r, chapters, name="ch01_ray_tracing"):
    return [chapters[name]] + r.TINY[name]


def refused_problems(r, code, err, seconds, names, paths):
    """Exit 2 within the refusal time, one line naming one of `names`."""
    problems = r.exit_problems(code, 2, err) + r.one_line_problems(err, paths)
    if not any(n in r.text(err) for n in names):
        problems.append(f"message names none of {names}: {r.text(err)[:300]!r}")
    if seconds > r.REFUSAL_TIMEOUT:
        problems.append(f"took {seconds:.1f} s to refuse")
    return problems


# ---------------------------------------------------------------------------------------------
# "A run replaces only what runs wrote", "Shared folders keep their owner and mode"

def case_home(r, chapters, tmp):
    """HOME=H --out ~ (run from another folder), H holding .ssh/, a thesis and a copied
    summary.json of a real run: refused, H untouched."""
    parent = r.fresh(tmp / "home")
    first = parent / "run"
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(first)], cwd=parent)
    if code != 0:
        return [f"the first run failed: {r.text(err)[:300]!r}"]
    home = parent / "H"
    (home / ".ssh").mkdir(parents=True)
    (home / ".ssh" / "id_ed25519").write_text("secret\n")
    (home / "Documents").mkdir()
    (home / "Documents" / "thesis.tex").write_text("\\chapter{mine}\n")
    shutil.copy(first / "summary.json", home / "summary.json")
    if (first / MANIFEST).exists():  # even a copied manifest does not make a home replaceable
        shutil.copy(first / MANIFEST, home / MANIFEST)
    before = r.snapshot(home)
    elsewhere = parent / "elsewhere"
    elsewhere.mkdir()
    start = time.monotonic()
    # As typed: `HOME=H chapter --out ~`, the shell expanding ~ to H.
    script = 'export HOME="$1"; shift; exec "$@" --quiet --out ~'
    p = subprocess.run(["bash", "-c", script, "bash", str(home)] + tiny(r, chapters),
                       cwd=elsewhere, stdin=subprocess.DEVNULL, capture_output=True,
                       timeout=r.CASE_TIMEOUT)
    problems = refused_problems(r, p.returncode, p.stderr, time.monotonic() - start,
                                ["--out"], [home])
    if r.snapshot(home) != before:
        problems.append("the home folder changed")
    if sorted(os.listdir(parent)) != ["H", "elsewhere", "run"]:
        problems.append(f"left beside it: {sorted(os.listdir(parent))}")
    return problems


def case_added_to_previous_run(r, chapters, tmp):
    """A user's notes.txt and my_edits/ added inside a previous run's folder: refused, the first
    of them named, nothing deleted."""
    parent = r.fresh(tmp / "added")
    out = parent / "out"
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
    if code != 0:
        return [f"the first run failed: {r.text(err)[:300]!r}"]
    (out / "notes.txt").write_text("remember\n")
    (out / "my_edits").mkdir()
    (out / "my_edits" / "image.png").write_bytes(b"edited")
    before = r.snapshot(out)
    code, _, err, seconds = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
    problems = refused_problems(r, code, err, seconds, ["my_edits"], [out])
    if r.snapshot(out) != before:
        problems.append("--out changed")
    if sorted(os.listdir(parent)) != ["out"]:
        problems.append(f"left beside --out: {sorted(os.listdir(parent))}")
    return problems


def case_summary_alone(r, chapters, tmp):
    """A folder holding only a summary.json naming a chapter is no longer a run's."""
    parent = r.fresh(tmp / "summary_alone")
    out = parent / "out"
    out.mkdir()
    (out / "summary.json").write_text('{"chapter": "ch01_ray_tracing", "seed": 1}\n')
    before = r.snapshot(out)
    code, _, err, seconds = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
    problems = refused_problems(r, code, err, seconds, ["summary.json"], [out])
    return problems + (["--out changed"] if r.snapshot(out) != before else [])


def case_fifo(r, chapters, tmp):
    """A FIFO in place of a previous run's summary.json: refused at once (never opened), where
    it used to block forever and swallow SIGINT."""
    parent = r.fresh(tmp / "fifo")
    out = parent / "out"
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
    if code != 0:
        return [f"the first run failed: {r.text(err)[:300]!r}"]
    (out / "summary.json").unlink()
    os.mkfifo(out / "summary.json")
    code, _, err, seconds = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent,
                                  timeout=r.REFUSAL_TIMEOUT)
    problems = refused_problems(r, code, err, seconds, ["summary.json"], [out])
    if not stat.S_ISFIFO(os.lstat(out / "summary.json").st_mode):
        problems.append("the FIFO was replaced")
    return problems


def case_manifest_lists_everything(r, chapters, tmp, name):
    """Every chapter's tiny run: its manifest lists exactly what its folder holds."""
    parent = r.fresh(tmp / f"manifest_{name}")
    out = parent / "out"
    code, _, err, _ = r.run([chapters[name]] + r.TINY[name] + ["--quiet", "--out", str(out)],
                            cwd=parent)
    return r.exit_problems(code, 0, err) + (whole_run_problems(r, out) if code == 0 else [])


def case_shared_folder(r, chapters, tmp):
    """An empty shared folder (another user's, mode 3777) given to root as --out: written into,
    its owner and mode kept, through a first run, a second that replaces it, and a refused one."""
    parent = r.fresh(tmp / "shared")
    os.chmod(parent, 0o755)
    out = parent / "shared"
    out.mkdir()
    os.chown(out, NOBODY, NOBODY)
    os.chmod(out, 0o3777)
    problems = []
    for seed in ("1", "2"):
        code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--seed", seed, "--out", str(out)],
                                cwd=parent)
        problems += [f"run with seed {seed}: {p}" for p in r.exit_problems(code, 0, err)]
        info = os.stat(out)
        if (info.st_uid, info.st_gid, stat.S_IMODE(info.st_mode)) != (NOBODY, NOBODY, 0o3777):
            problems.append(f"after the run with seed {seed}: owner {info.st_uid}:{info.st_gid} "
                            f"mode {stat.S_IMODE(info.st_mode):o}, not 65534:65534 3777")
        problems += whole_run_problems(r, out)
    if '"seed": "2"' not in (out / "summary.json").read_text() and \
            '"seed": 2' not in (out / "summary.json").read_text():
        problems.append("the second run did not replace the first")
    if sorted(os.listdir(parent)) != ["shared"]:
        problems.append(f"left beside --out: {sorted(os.listdir(parent))}")
    return problems


def case_shared_folder_as_another_user(r, chapters, tmp):
    """The other way round: root's shared folder (3777) in a parent only root may write, given
    as --out to an unprivileged user (nobody, through setpriv): the run cannot stage beside it,
    so it writes into it, twice, and the folder stays root's 3777. None without setpriv."""
    setpriv = shutil.which("setpriv")
    if not setpriv:
        return None
    parent = r.fresh(tmp / "shared_root")
    os.chmod(parent, 0o755)
    os.chmod(tmp, 0o755)
    out = parent / "shared"
    out.mkdir()
    os.chmod(out, 0o3777)
    as_nobody = [setpriv, f"--reuid={NOBODY}", f"--regid={NOBODY}", "--clear-groups"]
    problems = []
    for seed in ("1", "2"):
        code, _, err, _ = r.run(as_nobody + tiny(r, chapters) + ["--quiet", "--seed", seed,
                                                                 "--out", str(out)], cwd=parent)
        problems += [f"run with seed {seed}: {p}" for p in r.exit_problems(code, 0, err)]
        info = os.stat(out)
        if (info.st_uid, stat.S_IMODE(info.st_mode)) != (0, 0o3777):
            problems.append(f"after the run with seed {seed}: owner {info.st_uid} mode "
                            f"{stat.S_IMODE(info.st_mode):o}, not root's 3777")
        if code == 0:
            problems += whole_run_problems(r, out)
    if sorted(os.listdir(parent)) != ["shared"]:
        problems.append(f"left beside --out: {sorted(os.listdir(parent))}")
    return problems


def case_overlayfs(r, chapters, tmp):
    """A previous run in an overlayfs lower layer (a container image): renaming the folder gives
    EXDEV; the run must still replace it whole. None when overlayfs cannot be mounted here."""
    base = r.fresh(tmp / "overlay")
    lower, upper, work, merged = (base / n for n in ("lower", "upper", "work", "merged"))
    for folder in (lower / "parent", upper, work, merged):
        folder.mkdir(parents=True)
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(lower / "parent" / "out")],
                            cwd=base)
    if code != 0:
        return [f"the first run failed: {r.text(err)[:300]!r}"]
    mount = subprocess.run(["mount", "-t", "overlay", "overlay", "-o",
                            f"lowerdir={lower},upperdir={upper},workdir={work}", str(merged)],
                           capture_output=True)
    if mount.returncode != 0:
        return None
    try:
        out = merged / "parent" / "out"
        code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--seed", "5", "--out", str(out)],
                                cwd=merged / "parent")
        problems = r.exit_problems(code, 0, err)
        if code == 0:
            problems += whole_run_problems(r, out)
            if '"5"' not in (out / "summary.json").read_text() and \
                    ": 5" not in (out / "summary.json").read_text():
                problems.append("--out still holds the previous run")
        if sorted(os.listdir(merged / "parent")) != ["out"]:
            problems.append(f"left beside --out: {sorted(os.listdir(merged / 'parent'))}")
        return problems
    finally:
        subprocess.run(["umount", str(merged)], capture_output=True)


def group_out_manifest(r, chapters, tmp, checks):
    if CH01 not in chapters:
        checks.case("out-manifest", [f"{CH01} not built"])
        return
    guarantee = "A run replaces only what runs wrote: "
    shared = "Shared folders keep their owner and mode: "
    checks.case(guarantee + "HOME=H --out ~ with .ssh/ and a copied summary.json",
                case_home(r, chapters, tmp))
    checks.case(guarantee + "notes.txt and my_edits/ added inside a previous run",
                case_added_to_previous_run(r, chapters, tmp))
    checks.case(guarantee + "a folder with a chapter's summary.json alone",
                case_summary_alone(r, chapters, tmp))
    checks.case(guarantee + "a FIFO as a previous run's summary.json", case_fifo(r, chapters, tmp))
    for name in [n for n in r.TINY if n in chapters]:
        checks.case(f"{guarantee}{name}'s manifest lists exactly its folder",
                    case_manifest_lists_everything(r, chapters, tmp, name))
    if os.geteuid() != 0:
        print("SKIP (not root): an empty shared folder of another user keeps owner and mode; "
              "overlayfs")
        return
    checks.case(shared + "an empty shared folder of another user, then a second run",
                case_shared_folder(r, chapters, tmp))
    unprivileged = case_shared_folder_as_another_user(r, chapters, tmp)
    if unprivileged is None:
        print("SKIP: no setpriv (root's shared folder, written by nobody)")
    else:
        checks.case(shared + "root's shared folder, written into by an unprivileged user",
                    unprivileged)
    overlay = case_overlayfs(r, chapters, tmp)
    if overlay is None:
        print("SKIP: overlayfs cannot be mounted here (the EXDEV case)")
    else:
        checks.case(shared + "a previous run on overlayfs (EXDEV) is replaced whole", overlay)


# ---------------------------------------------------------------------------------------------
# "Signals and pipes", "Whole folders"

def case_closed_pipe(r, chapters, tmp, name, args, consumer, previous):
    """`chapter | consumer` where the consumer closes its end: exit 1, one line naming stdout,
    --out the previous run or the new one whole, nothing beside it."""
    parent = r.fresh(tmp / f"pipe_{name}_{consumer.split()[0].strip('(')}_{previous}")
    out = parent / "out"
    if previous:
        code, _, err, _ = r.run([chapters[name]] + args + ["--quiet", "--out", str(out)],
                                cwd=parent)
        if code != 0:
            return [f"the first run failed: {r.text(err)[:300]!r}"]
    before = r.snapshot(out)
    command = [chapters[name]] + args + ["--out", str(out)]
    # The chapter starts a moment after the consumer, so the consumer has closed its end before
    # the first write (0.3 s: a consumer that exits or closes at once needs milliseconds).
    script = f'{{ sleep 0.3; exec "$@"; }} | {consumer}; exit "${{PIPESTATUS[0]}}"'
    p = subprocess.run(["bash", "-c", script, "bash"] + command, cwd=parent,
                       stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                       stderr=subprocess.PIPE, timeout=r.CASE_TIMEOUT)
    problems = r.exit_problems(p.returncode, 1, p.stderr) + r.one_line_problems(p.stderr, [parent])
    if "stdout" not in r.text(p.stderr):
        problems.append(f"message does not name stdout: {r.text(p.stderr)[:300]!r}")
    after = r.snapshot(out)
    if after != before:
        problems += whole_run_problems(r, out)  # swapped in: then whole
    left = r.beside_out(parent, "out") if out.exists() else r.beside_out(parent)
    if left:
        problems.append(f"left beside --out: {left}")
    return problems


def case_signal(r, chapters, tmp, signum):
    """A handled signal beyond INT and TERM mid-render, a previous run in --out: exit 128 +
    signal, one line naming it, the previous run whole, no staging folder, no gnuplot left."""
    exe = chapters["ch05_path_tracer"]
    parent = r.fresh(tmp / f"signal_{signum}")
    out = parent / "out"
    code, _, err, _ = r.run([exe] + r.TINY["ch05_path_tracer"] + ["--quiet", "--out", str(out)],
                            cwd=parent)
    if code != 0:
        return [f"the first run failed: {r.text(err)[:300]!r}"]
    before = r.snapshot(out)
    # Tens of seconds of work: the signal always arrives mid-render.
    long_args = ["--width", "320", "--height", "240", "--spp", "1,4,16,64,256", "--depth", "10",
                 "--reference-spp", "0", "--quiet"]
    code, err = r.interrupted_run(exe, long_args, out, 0.4, signum)
    problems = r.after_interrupt_problems(code, err, parent, before, signum)
    if code == 128 + signum and signal.Signals(signum).name not in r.text(err):
        problems.append(f"the line does not name {signal.Signals(signum).name}: {r.text(err)!r}")
    return problems


def dead_pid():
    """A pid no process has: a child that has exited and been waited for."""
    p = subprocess.Popen(["true"])
    p.wait()
    return p.pid


def case_stale_staging(r, chapters, tmp):
    """The staging folders of runs killed by SIGKILL (pid gone) are removed by the next run in
    the same parent; a look-alike without a manifest, and a living run's, are kept."""
    parent = r.fresh(tmp / "stale")
    out = parent / "out"
    exe = chapters[CH01]
    killed = subprocess.Popen([exe, "--width", "640", "--height", "480", "--spp", "256",
                               "--quiet", "--out", str(out)], cwd=parent,
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    time.sleep(0.5)
    killed.kill()  # SIGKILL: no cleanup possible
    killed.wait()
    stale = [n for n in os.listdir(parent) if ".staging-" in n]
    problems = [] if stale else ["the killed run left no staging folder to clean (case not played)"]
    gone = dead_pid()
    look_alike = parent / f".mine.staging-{gone}"
    look_alike.mkdir()
    (look_alike / "thesis.tex").write_text("precious\n")
    empty = parent / f".other.staging-{gone}-previous"
    empty.mkdir()
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
    problems += r.exit_problems(code, 0, err)
    left = sorted(set(os.listdir(parent)) - {"out"})
    if left != [look_alike.name]:
        problems.append(f"beside --out: {left}, expected only the look-alike {look_alike.name}")
    if not (look_alike / "thesis.tex").exists():
        problems.append("the look-alike without a manifest was removed")
    return problems


def group_out_ends(r, chapters, tmp, checks):
    missing = [n for n in (CH01, "ch05_path_tracer") if n not in chapters]
    if missing:
        checks.case("out-ends", [f"not built: {missing}"])
        return
    guarantee = "Signals and pipes: "
    cases = []
    ch08 = "ch08_next_event_estimation"
    pipe_runs = [(CH01, r.TINY[CH01])]
    if ch08 in chapters:  # its table is longer than a pipe's buffer: it fails mid-print
        pipe_runs.append((ch08, ["--width", "12", "--height", "9", "--spp", "2",
                                 "--reference-spp", "4", "--ray-budgets", "8,16"]))
    for name, args in pipe_runs:
        for consumer in ("head -c0", "(exec 0<&-; sleep 1)"):
            for previous in (False, True):
                cases.append((f"{guarantee}{name} | {consumer}"
                              f"{', a previous run in --out' if previous else ''}",
                              case_closed_pipe, (r, chapters, tmp, name, args, consumer, previous)))
    for signum in (signal.SIGHUP, signal.SIGQUIT, signal.SIGUSR1, signal.SIGUSR2, signal.SIGALRM):
        cases.append((f"{guarantee}{signal.Signals(signum).name} mid-render", case_signal,
                      (r, chapters, tmp, signum)))
    cases.append(("Whole folders: a staging folder whose process is gone", case_stale_staging,
                  (r, chapters, tmp)))
    import concurrent.futures
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {pool.submit(function, *args): name for name, function, args in cases}
        for future in concurrent.futures.as_completed(futures):
            checks.case(futures[future], future.result())


# ---------------------------------------------------------------------------------------------
# "Refused work" (flag values), "Whole folders" (long names)

def case_long_name(r, chapters, tmp, folder_name):
    """A folder name of up to NAME_MAX bytes: two runs, the second replacing the first whole."""
    parent = r.fresh(tmp / f"long{len(folder_name.encode())}")
    out = parent / folder_name
    problems = []
    for seed in ("1", "2"):
        code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--seed", seed, "--out", str(out)],
                                cwd=parent)
        problems += [f"seed {seed}: {p}" for p in r.exit_problems(code, 0, err)]
        if code == 0:
            problems += whole_run_problems(r, out)
        if ".staging-" in r.text(err):
            problems.append(f"the message names the staging folder: {r.text(err)[:300]!r}")
    if sorted(os.listdir(parent)) != [folder_name]:
        problems.append(f"left beside --out: {sorted(os.listdir(parent))}")
    return problems


def group_out_flags(r, chapters, tmp, checks):
    guarantee = "Refused work: "
    cases = []
    for name, exe in chapters.items():
        text_flags = [flag for flag, kind, _ in r.parse_help(exe) if kind == "text"]
        for flag in text_flags:
            # `--flag="$EMPTY"` must not swallow the next flag (it used to make a folder named
            # --quiet, or drop --seed=7).
            cases.append((f"{guarantee}{name} {flag}= --quiet", exe, [flag + "=", "--quiet"], flag))
            cases.append((f"{guarantee}{name} {flag}= --seed=7", exe, [flag + "=", "--seed=7"],
                          flag))
            cases.append((f"{guarantee}{name} {flag} ''", exe, [flag, ""], flag))
            not_utf8 = os.fsdecode(b"not-utf8-\xff\xfe")
            cases.append((f"{guarantee}{name} {flag} (not UTF-8)", exe, [f"{flag}={not_utf8}"],
                          flag))
    import concurrent.futures
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        futures = {pool.submit(r.check_refused, exe, args, flag, tmp / f"flag{i}"): label
                   for i, (label, exe, args, flag) in enumerate(cases)}
        for future in concurrent.futures.as_completed(futures):
            checks.case(futures[future], future.result())
    if CH01 in chapters:
        for folder_name in ("n" * 255, "é" * 127, "x" * 246):
            checks.case(f"Whole folders: a folder name of {len(folder_name.encode())} bytes",
                        case_long_name(r, chapters, tmp, folder_name))


def groups(r):
    """The groups of this module, as robustness.py's GROUPS takes them."""
    return {
        "out-manifest": lambda chapters, tmp, checks: group_out_manifest(r, chapters, tmp, checks),
        "out-ends": lambda chapters, tmp, checks: group_out_ends(r, chapters, tmp, checks),
        "out-flags": lambda chapters, tmp, checks: group_out_flags(r, chapters, tmp, checks),
    }
