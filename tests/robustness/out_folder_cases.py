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


def other_uid():
    """A uid that no account has, for 'another user' (root only): nothing else runs as it, so
    the cases never meet a grading's processes of nobody."""
    import pwd
    import random
    while True:
        uid = random.randrange(3_000_000, 4_000_000)
        try:
            pwd.getpwuid(uid)
        except KeyError:
            return uid


def refused_untouched_problems(r, command, cwd, out, watched):
    """`command` refused before any work (exit 2, one line naming --out and saying to choose a
    folder of one's own), every folder in `watched` as it was."""
    before = {str(w): r.snapshot(w) for w in watched}
    code, _, err, seconds = r.run(command, cwd=cwd)
    problems = refused_problems(r, code, err, seconds, ["--out"], [out])
    if "your own" not in r.text(err):
        problems.append(f"the line does not say to choose a folder of your own: {r.text(err)!r}")
    for w in watched:
        if r.snapshot(w) != before[str(w)]:
            problems.append(f"{w.name} changed")
    return problems


def case_shared_folder(r, chapters, tmp):
    """Root given another user's shared folder (mode 3777) holding a previous run, and a new
    --out inside another user's 0755 home: refused (issue 43: the owner could swap the staging
    folder for links that root then wrote through), nothing made or changed."""
    parent = r.fresh(tmp / "shared")
    os.chmod(parent, 0o755)
    other = other_uid()
    out = parent / "dropbox"
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
    if code != 0:
        return [f"the first run failed: {r.text(err)[:300]!r}"]
    for entry in [out] + list(out.rglob("*")):
        os.lchown(entry, other, other)
    os.chmod(out, 0o3777)
    problems = refused_untouched_problems(r, tiny(r, chapters) + ["--quiet", "--out", str(out)],
                                          parent, out, [parent])
    home = parent / "atkhome"
    home.mkdir(mode=0o755)
    os.chown(home, other, other)
    for new in (home / "out", home / "a" / "b"):
        problems += [f"{new.relative_to(parent)}: {p}" for p in refused_untouched_problems(
            r, tiny(r, chapters) + ["--quiet", "--out", str(new)], parent, new, [parent])]
    return problems


def case_shared_folder_as_another_user(r, chapters, tmp):
    """The other way round: root's shared folder (3777) given as --out to an unprivileged user
    (a uid of this case's own, through setpriv): refused, where it used to be written into.
    None without setpriv."""
    setpriv = shutil.which("setpriv")
    if not setpriv:
        return None
    parent = r.fresh(tmp / "shared_root")
    os.chmod(parent, 0o755)
    os.chmod(tmp, 0o755)
    out = parent / "shared"
    out.mkdir()
    os.chmod(out, 0o3777)
    uid = other_uid()
    as_other = [setpriv, f"--reuid={uid}", f"--regid={uid}", "--clear-groups"]
    return refused_untouched_problems(r, as_other + tiny(r, chapters) + ["--quiet", "--out",
                                                                         str(out)],
                                      parent, out, [parent])


def case_overlayfs(r, chapters, tmp):
    """A previous run in an overlayfs lower layer (a container image): renaming the folder gives
    EXDEV. The run fails with one line (exit 1) saying so, the previous run whole, nothing left
    beside it (it used to move the previous run's files one by one, an undo that could delete
    them). None when overlayfs cannot be mounted here."""
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
        problems = r.exit_problems(code, 1, err) + r.one_line_problems(err, [merged])
        if "layer" not in r.text(err):
            problems.append(f"the line does not say why: {r.text(err)!r}")
        problems += whole_run_problems(r, out)
        if r.snapshot(out) != r.snapshot(lower / "parent" / "out"):
            problems.append("--out no longer holds the previous run")
        if sorted(os.listdir(merged / "parent")) != ["out"]:
            problems.append(f"left beside --out: {sorted(os.listdir(merged / 'parent'))}")
        return problems
    finally:
        subprocess.run(["umount", str(merged)], capture_output=True)


SCRIPTS = Path(__file__).resolve().parents[2] / "scripts"


def case_gallery_fifo(r, tmp):
    """make-gallery with a FIFO as a chapter's summary.json: one line, exit 1, at once (it used
    to wait forever for a writer)."""
    out = r.fresh(tmp / "gallery_fifo")
    (out / CH01).mkdir()
    os.mkfifo(out / CH01 / "summary.json")
    code, _, err, _ = r.run([str(SCRIPTS / "make-gallery"), "--out", str(out)], cwd=out,
                            timeout=r.REFUSAL_TIMEOUT)
    problems = r.exit_problems(code, 1, err) + r.one_line_problems(err, [out])
    return problems + ([] if "summary.json" in r.text(err) else [f"not named: {r.text(err)!r}"])


def case_docs_user_file(r, tmp):
    """A file the user put into out/docs after render-docs wrote it: refused (exit 2, the file
    named), kept (it used to be deleted with the previous pages). None without pandoc."""
    if not shutil.which("pandoc"):
        return None
    out = r.fresh(tmp / "docs_user_file")
    command = [str(SCRIPTS / "render-docs"), "--out", str(out)]
    (out / "docs").mkdir()  # as a render leaves it (its marker lists its files), then the user's
    (out / "docs" / "index.html").write_text("<p>rendered</p>\n")
    (out / "docs" / ".rendered-docs").write_text("index.html\n.rendered-docs\n")
    (out / "docs" / "my-notes.txt").write_text("mine\n")
    before = r.snapshot(out)
    code, _, err, _ = r.run(command, cwd=out, timeout=120)
    problems = r.exit_problems(code, 2, err) + r.one_line_problems(err, [out])
    if "my-notes.txt" not in r.text(err):
        problems.append(f"the line does not name the file: {r.text(err)!r}")
    return problems + (["out/docs changed"] if r.snapshot(out) != before else [])


def case_scripts_refuse_unowned(r, tmp):
    """render-docs and make-gallery given another user's folder (root only): exit 2, one line
    naming --out, nothing written in it."""
    parent = r.fresh(tmp / "scripts_unowned")
    os.chmod(parent, 0o755)
    out = parent / "theirs"
    out.mkdir()
    os.chown(out, other_uid(), other_uid())
    problems = []
    for script in ("render-docs", "make-gallery"):
        code, _, err, seconds = r.run([str(SCRIPTS / script), "--out", str(out)], cwd=parent)
        problems += [f"{script}: {p}" for p in refused_problems(r, code, err, seconds, ["--out"],
                                                                [out])]
        if os.listdir(out):
            problems.append(f"{script} wrote {sorted(os.listdir(out))}")
    return problems


def case_empty_mount_point(r, chapters, tmp):
    """An empty mount point as --out (a tmpfs of mode 0755): the run is written into it whole
    (it can never be swapped: it always failed); a second run is refused (exit 2), the first
    kept. None when a tmpfs cannot be mounted here."""
    parent = r.fresh(tmp / "mount_point")
    out = parent / "mnt"
    out.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=4m,mode=0755", "tmpfs", str(out)],
                      capture_output=True).returncode != 0:
        return None
    try:
        code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)], cwd=parent)
        problems = r.exit_problems(code, 0, err)
        if code == 0:
            problems += whole_run_problems(r, out)
            before = r.snapshot(out)
            code, _, err, seconds = r.run(tiny(r, chapters) + ["--quiet", "--out", str(out)],
                                          cwd=parent)
            problems += [f"second run: {p}" for p in refused_problems(r, code, err, seconds,
                                                                     ["mount point"], [out])]
            if r.snapshot(out) != before:
                problems.append("the second run changed the first")
        return problems + ([f"left beside it: {os.listdir(parent)}"]
                           if os.listdir(parent) != ["mnt"] else [])
    finally:
        subprocess.run(["umount", str(out)], capture_output=True)


def group_out_manifest(r, chapters, tmp, checks):
    if CH01 not in chapters:
        checks.case("out-manifest", [f"{CH01} not built"])
        return
    guarantee = "A run replaces only what runs wrote: "
    shared = "Folders of your own: "
    checks.case(guarantee + "HOME=H --out ~ with .ssh/ and a copied summary.json",
                case_home(r, chapters, tmp))
    checks.case(guarantee + "notes.txt and my_edits/ added inside a previous run",
                case_added_to_previous_run(r, chapters, tmp))
    checks.case(guarantee + "a folder with a chapter's summary.json alone",
                case_summary_alone(r, chapters, tmp))
    checks.case(guarantee + "a FIFO as a previous run's summary.json", case_fifo(r, chapters, tmp))
    checks.case("Regular files only: make-gallery and a FIFO as summary.json",
                case_gallery_fifo(r, tmp))
    docs = case_docs_user_file(r, tmp)
    if docs is None:
        print("SKIP: no pandoc (a file of the user's in out/docs)")
    else:
        checks.case(guarantee + "render-docs and a file of the user's in out/docs", docs)
    for name in [n for n in r.TINY if n in chapters]:
        checks.case(f"{guarantee}{name}'s manifest lists exactly its folder",
                    case_manifest_lists_everything(r, chapters, tmp, name))
    if os.geteuid() != 0:
        print("SKIP (not root): an empty shared folder of another user keeps owner and mode; "
              "overlayfs")
        return
    checks.case(shared + "another user's 3777 folder, a new --out in another user's home (root)",
                case_shared_folder(r, chapters, tmp))
    checks.case(shared + "render-docs and make-gallery given another user's folder",
                case_scripts_refuse_unowned(r, tmp))
    unprivileged = case_shared_folder_as_another_user(r, chapters, tmp)
    if unprivileged is None:
        print("SKIP: no setpriv (root's shared folder, given to another user)")
    else:
        checks.case(shared + "root's shared folder, given to an unprivileged user",
                    unprivileged)
    mounted = case_empty_mount_point(r, chapters, tmp)
    if mounted is None:
        print("SKIP: a tmpfs cannot be mounted here (an empty mount point as --out)")
    else:
        checks.case(shared + "an empty mount point is written into, then kept", mounted)
    overlay = case_overlayfs(r, chapters, tmp)
    if overlay is None:
        print("SKIP: overlayfs cannot be mounted here (the EXDEV case)")
    else:
        checks.case(shared + "a previous run on overlayfs (EXDEV) is kept, one line", overlay)


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
    # Tens of seconds of work: the signal always arrives mid-render. One thread: these cases
    # are about the signal's number and name; a render on every core interrupted by SIGINT and
    # SIGTERM is the signals group's, so a second core here would only burn 0.4 s more a case.
    long_args = ["--width", "320", "--height", "240", "--spp", "1,4,16,64,256", "--depth", "10",
                 "--reference-spp", "0", "--threads", "1", "--quiet"]
    code, err = r.interrupted_run(exe, long_args, out, 0.4, signum)
    problems = r.after_interrupt_problems(code, err, parent, before, signum)
    if code == 128 + signum and signal.Signals(signum).name not in r.text(err):
        problems.append(f"the line does not name {signal.Signals(signum).name}: {r.text(err)!r}")
    return problems


def wait_for(predicate, seconds=10.0):
    """Polls predicate until it holds or `seconds` pass; its last value."""
    deadline = time.monotonic() + seconds
    while not predicate() and time.monotonic() < deadline:
        time.sleep(0.05)
    return predicate()


def manifest_unlocked(folder):
    """Whether the lock on a staging folder's manifest is free (its run is gone)."""
    import fcntl
    try:
        with open(folder / MANIFEST, "rb") as f:
            fcntl.flock(f, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return True
    except OSError:
        return False


def case_stale_staging(r, chapters, tmp):
    """Liveness by lock (issue 43): a live run's staging folder is kept by a run beside it, even
    from another PID namespace where its pid means nothing here (it used to be deleted as
    stale); once that run is killed (SIGKILL), the next run removes its folder. Folders the user
    named like ours (`.draft.staging-999999`) are never touched. Returns (problems, note)."""
    parent = r.fresh(tmp / "stale")
    exe = chapters[CH01]
    # One thread: the live run only has to hold its lock while the other runs; on every core it
    # would take CPU from them and from the tests beside this one.
    long_run = [exe, "--width", "640", "--height", "480", "--spp", "256", "--threads", "1",
                "--quiet", "--out", str(parent / "live")]
    # In a PID namespace of its own the run gets pid 999991 (set through ns_last_pid): a pid the
    # host does not have, as a container's run on a shared volume would.
    namespaced = ["unshare", "--pid", "--fork", "--mount-proc", "--kill-child=SIGKILL", "sh", "-c",
                  'echo 999990 > /proc/sys/kernel/ns_last_pid && "$@"', "sh"] + long_run
    note = None
    probe = subprocess.run(namespaced[:5] + ["true"], capture_output=True) \
        if os.geteuid() == 0 and shutil.which("unshare") else None
    if probe is None or probe.returncode != 0:
        namespaced, note = long_run, "no PID namespace here: the live run shares ours"
    live = subprocess.Popen(namespaced, cwd=parent, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    try:
        staging = lambda: [n for n in os.listdir(parent) if n.startswith(".live.staging-")]
        if not wait_for(staging):
            return ["the live run made no staging folder (case not played)"], note
        live_staging = parent / staging()[0]
        draft = parent / ".draft.staging-999999"
        draft.mkdir()
        (draft / "notes.txt").write_text("mine\n")
        (parent / ".empty.staging-999998").mkdir()
        copied = parent / ".copy.staging-999997"
        copied.mkdir()
        (copied / MANIFEST).write_text(MANIFEST + "\n")
        users = {draft.name, ".empty.staging-999998", copied.name}
        code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(parent / "out")],
                                cwd=parent)
        problems = r.exit_problems(code, 0, err)
        if not (live_staging / MANIFEST).exists():
            problems.append("a live run's staging folder was removed")
    finally:
        live.kill()  # SIGKILL: with --kill-child the namespace goes with it
        live.wait()
    if not wait_for(lambda: manifest_unlocked(live_staging)):
        return problems + ["the killed run's lock is still held 10 s later"], note
    code, _, err, _ = r.run(tiny(r, chapters) + ["--quiet", "--out", str(parent / "out")],
                            cwd=parent)
    problems += r.exit_problems(code, 0, err)
    left = set(os.listdir(parent)) - {"out"}
    if left != users:
        problems.append(f"beside --out: {sorted(left)}, expected only the user's {sorted(users)}")
    if (draft / "notes.txt").read_text() != "mine\n":
        problems.append("the user's .draft.staging-999999 changed")
    return problems, note


def case_file_size_limit(r, chapters, tmp):
    """Under `ulimit -f 4` a file cannot grow past 4 KiB: exit 1 with one line (the system's
    "File too large"), nothing left beside --out (it was killed by SIGXFSZ, exit 153, its
    staging folder left)."""
    parent = r.fresh(tmp / "file_size")
    name = "ch05_path_tracer"
    command = [chapters[name]] + r.TINY[name] + ["--quiet", "--out", str(parent / "out")]
    p = subprocess.run(["bash", "-c", 'ulimit -f 4 && exec "$@"', "bash"] + command, cwd=parent,
                       stdin=subprocess.DEVNULL, capture_output=True, timeout=r.CASE_TIMEOUT)
    problems = r.exit_problems(p.returncode, 1, p.stderr) + r.one_line_problems(p.stderr, [parent])
    if "File too large" not in r.text(p.stderr):
        problems.append(f"the line lacks the system's reason: {r.text(p.stderr)!r}")
    if r.beside_out(parent):
        problems.append(f"left: {r.beside_out(parent)}")
    return problems


def case_gnuplot_wrapper_child(r, chapters, tmp):
    """A gnuplot wrapper that starts a child of its own, and SIGINT while it runs: exit 130 and
    the child ended with it (it used to keep running: only the wrapper was killed)."""
    import random
    parent = r.fresh(tmp / "wrapper")
    folder = parent / "bin"
    folder.mkdir()
    marker = f"1000.{random.randrange(10**9):09d}"  # a sleep no one else runs
    wrapper = folder / "gnuplot"
    wrapper.write_text(f"#!/bin/sh\nsleep {marker} &\nwait\n")
    wrapper.chmod(0o755)
    environment = dict(os.environ, PATH=f"{folder}:{os.environ.get('PATH', '/usr/bin:/bin')}")
    child_running = lambda: any(marker in c for c in command_lines().values())
    run = subprocess.Popen(tiny(r, chapters, "ch05_path_tracer") + ["--quiet", "--out",
                                                                    str(parent / "out")],
                           cwd=parent, env=environment, stdin=subprocess.DEVNULL,
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    try:
        if not wait_for(child_running):
            return ["the wrapper's child never started (case not played)"]
        run.send_signal(signal.SIGINT)
        _, err = run.communicate(timeout=10)
    finally:
        run.kill()
        run.wait()
    problems = r.exit_problems(run.returncode, 130, err)
    if not wait_for(lambda: not child_running(), 2.0):
        problems.append("the gnuplot wrapper's child is still running")
        for pid, line in command_lines().items():  # this case's own child, found by its marker
            if marker in line:
                os.kill(pid, signal.SIGKILL)
    return problems


def command_lines():
    """The command line of every process that can be read, by pid."""
    lines = {}
    for pid in os.listdir("/proc"):
        if pid.isdigit():
            try:
                with open(f"/proc/{pid}/cmdline", "rb") as f:
                    lines[int(pid)] = f.read().replace(b"\0", b" ").decode(errors="replace")
            except OSError:
                pass
    return lines


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
        # Both consumers leave the chapter a pipe with no reader (one exits, one closes its end
        # and lives on): the same failed write for the chapter, which ch01 meets both ways.
        # ch08 (a second of CPU a run) meets the first only: its own matter is the long table.
        consumers = ("head -c0", "(exec 0<&-; sleep 1)") if name == CH01 else ("head -c0",)
        for consumer in consumers:
            for previous in (False, True):
                cases.append((f"{guarantee}{name} | {consumer}"
                              f"{', a previous run in --out' if previous else ''}",
                              case_closed_pipe, (r, chapters, tmp, name, args, consumer, previous)))
    for signum in (signal.SIGHUP, signal.SIGQUIT, signal.SIGUSR1, signal.SIGUSR2, signal.SIGALRM):
        cases.append((f"{guarantee}{signal.Signals(signum).name} mid-render", case_signal,
                      (r, chapters, tmp, signum)))
    cases.append(("Signals and pipes: ulimit -f 4", case_file_size_limit, (r, chapters, tmp)))
    cases.append(("Signals and pipes: SIGINT ends a gnuplot wrapper's child",
                  case_gnuplot_wrapper_child, (r, chapters, tmp)))
    import concurrent.futures
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {pool.submit(function, *args): name for name, function, args in cases}
        for future in concurrent.futures.as_completed(futures):
            checks.case(futures[future], future.result())
    problems, note = case_stale_staging(r, chapters, tmp)
    if note:
        print(f"SKIP: {note}")
    checks.case("Whole folders: a live run's staging folder (another PID namespace), a killed "
                "one's, the user's look-alikes", problems)


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
