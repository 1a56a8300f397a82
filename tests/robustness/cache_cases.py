"""The reference cache, temporary files, gnuplot and divergent parameters under attack (issue 34).

Groups registered into robustness.py (each one CTest test); every case names, in brackets, the
README guarantee it checks:

  cache-links      [No write through a link] a shared folder where another user (nobody) planted
                   a reference/ full of links named like the cache's temporaries, a `reference`
                   link, a folder anyone may write: refused (exit 2, one line naming
                   --reference-dir) and the file the links point at untouched; links planted in
                   a sticky shared cache or in our own are never followed nor deleted; as root,
                   another user's files in a 1777 cache are never deleted. Root only (the
                   attacker is nobody): skipped with one line otherwise. No pid is predicted.
  cache-integrity  [The reference cache] a cached PFM of NaN, +Inf or negative values (with a
                   matching checksum), of zeros, with trailing bytes, a 30-byte PFM claiming
                   10000x10000, a PFM and a JSON of two writers, a FIFO for the JSON, leftovers
                   of killed writers, two runs with different --reference-spp at once: each run
                   uses the reference it asked for, says why it rendered one again, and leaves a
                   cache that the next run uses as it is. The cache is a folder of its own
                   (issue 43): `cd proj; ch05 --out run` leaves proj/reference/ alone; a user's
                   files planted in the cache stay; an untagged --reference-dir with files, a
                   cache inside --out (or --out inside it), no HOME: refused up front; a HOME
                   where no folder can be made: one line, exit 1; a live writer in another PID
                   namespace (unshare; skipped with a line where not allowed) keeps its file.
  gnuplot-env      [Plots] a ~/.gnuplot that prints and sets decimal commas changes nothing; a
                   hanging gnuplot and one that cannot draw PNG leave the run written with a note.
  divergent        [Refused work] --albedo 1 where a furnace's paths would never end: exit 2,
                   one line naming --albedo, within a second.
  memory-threads   [Memory and threads] every renderer under `ulimit -v` below its predicted
                   peak: exit 2 within a second, one line with the estimate and the flags; no
                   thread for the workers: a run on one thread with a note; no thread at all:
                   one line, exit 1. The thread cases run as an unused uid (root only: the
                   process limit does not bind root), skipped with one line otherwise.
"""

import concurrent.futures
import fcntl
import json
import os
import pwd
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time
from pathlib import Path

base = None  # robustness.py, given by register()

CH05 = "ch05_path_tracer"
# A tiny ch05 run whose reference (16x12 at 16 spp) takes milliseconds, cached in reference/
# of the folder it runs in.
TINY05 = ["--width", "16", "--height", "12", "--spp", "1,4", "--depth", "3",
          "--reference-spp", "16", "--quiet", "--reference-dir", "reference"]
STEM05 = "cornell_ls1_16x12"


def register(robustness):
    """Adds this module's groups to robustness.GROUPS."""
    global base
    base = robustness
    robustness.GROUPS.update({
        "cache-links": group_cache_links,
        "cache-integrity": group_cache_integrity,
        "gnuplot-env": group_gnuplot_env,
        "divergent": group_divergent,
        "memory-threads": group_memory_threads,
    })


def skip(reason):
    print(f"SKIP: {reason}")
    sys.exit(base.SKIP)


def need(chapters, *names):
    missing = [n for n in names if n not in chapters]
    if missing:
        skip(f"not built: {missing}")


# ---------------------------------------------------------------------------------------------
# No write through a link (root runs the chapter, nobody plays the neighbour).

NOBODY = "nobody"


def as_nobody(action, *args):
    """Calls action(*args) in a child process that runs as the unprivileged user nobody (the
    attacker); raises if it fails."""
    user = pwd.getpwnam(NOBODY)
    child = os.fork()
    if child == 0:
        try:
            os.setgroups([])
            os.setgid(user.pw_gid)
            os.setuid(user.pw_uid)
            action(*args)
            os._exit(0)
        except BaseException as e:  # the parent reports it
            print(f"as {NOBODY}: {e!r}", file=sys.stderr)
            os._exit(1)
    _, status = os.waitpid(child, 0)
    if os.waitstatus_to_exitcode(status) != 0:
        raise RuntimeError(f"the attacker's action {action.__name__} failed")


def shared_folder(tmp):
    """A folder like /tmp that both users may write in (mode 1777), reachable by nobody."""
    folder = Path(tempfile.mkdtemp(prefix="mcrt-shared-", dir="/tmp"))
    os.chmod(folder, 0o1777)
    return folder


def victim_file(tmp):
    """A file of root's the attacker wants overwritten, with known bytes."""
    victim = Path(tempfile.mkdtemp(prefix="mcrt-victim-", dir="/tmp")) / "precious"
    victim.write_bytes(b"root's data, never to be overwritten\n")
    os.chmod(victim.parent, 0o755)
    os.chmod(victim, 0o644)
    return victim


def temporary_like_names(stem):
    """Names like the cache's temporaries, old (".NAME.tmp-<pid>-<n>") and new (".NAME.tmp-<16
    hex digits>"): an attacker's guesses. No pid is predicted: the names are drawn."""
    names = []
    for name in (f"{stem}.pfm", f"{stem}.json"):
        names += [f".{name}.tmp-{pid}-0" for pid in range(1, 200)]
        names += [f".{name}.tmp-{os.urandom(8).hex()}" for _ in range(200)]
    return names


def plant_links(folder, target, stem):
    """Links to target under names like the cache's temporaries."""
    os.makedirs(folder, exist_ok=True)
    for name in temporary_like_names(stem):
        os.symlink(target, os.path.join(folder, name))


def plant_link(target, name):
    os.symlink(target, name)


def plant_files(folder, names):
    for name in names:
        Path(folder, name).write_bytes(b"another user's file")


def link_problems(code, err, victim, parent):
    problems = []
    if victim.read_bytes() != b"root's data, never to be overwritten\n":
        problems.append("the file the planted links point at was written")
    return problems


def group_cache_links(chapters, tmp, checks):
    need(chapters, CH05)
    if os.geteuid() != 0:
        skip("the link attacks need root to play another user (nobody); they did not run")
    exe = chapters[CH05]
    guarantee = "[No write through a link]"
    made = []
    try:
        # 1. nobody pre-creates shared/reference/ full of links named like temporaries.
        shared, victim = shared_folder(tmp), victim_file(tmp)
        made += [shared, victim.parent]
        as_nobody(plant_links, shared / "reference", victim, STEM05)
        code, _, err, seconds = base.run([exe] + TINY05 + ["--out", str(shared / "myrun")],
                                         cwd=shared)
        problems = base.exit_problems(code, 2, err) + base.one_line_problems(err, [shared])
        problems += link_problems(code, err, victim, shared)
        if "--reference-dir" not in base.text(err) or "another user" not in base.text(err):
            problems.append(f"message names neither --reference-dir nor the owner: {err!r}")
        if (shared / "myrun").exists():
            problems.append("--out was written although the run was refused")
        if seconds > 1.0:
            problems.append(f"took {seconds:.2f} s to refuse (limit 1 s)")
        checks.case(f"{guarantee} ch05 --out shared/myrun, shared/reference/ another user's, "
                    "full of links named like temporaries", problems)

        # 2. nobody plants shared2/reference -> a folder of root's.
        shared2 = shared_folder(tmp)
        made.append(shared2)
        roots = Path(tempfile.mkdtemp(prefix="mcrt-roots-", dir="/tmp"))
        made.append(roots)
        os.chmod(roots, 0o755)
        as_nobody(plant_link, roots, shared2 / "reference")
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(shared2 / "myrun")],
                                   cwd=shared2)
        problems = base.exit_problems(code, 2, err) + base.one_line_problems(err, [shared2])
        if "symbolic link" not in base.text(err):
            problems.append(f"message does not say the cache is a link: {err!r}")
        if os.listdir(roots):
            problems.append(f"written where the link points: {os.listdir(roots)}")
        checks.case(f"{guarantee} ch05 with a `reference` link planted by another user", problems)

        # 3. A cache folder of ours that anyone may write in, without the sticky bit.
        open_folder = base.fresh(tmp / "open")
        (open_folder / "reference").mkdir()
        os.chmod(open_folder / "reference", 0o777)
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(open_folder / "run")],
                                   cwd=open_folder)
        problems = base.exit_problems(code, 2, err) + base.one_line_problems(err, [open_folder])
        if os.listdir(open_folder / "reference"):
            problems.append("the refused cache was written")
        checks.case(f"{guarantee} ch05 with a reference/ of mode 0777", problems)

        # 4. A sticky cache of ours (mode 1777, tagged by a first run) where nobody planted
        # links under temporary-like names: accepted, the links never followed.
        sticky = shared_folder(tmp)
        made.append(sticky)
        victim2 = victim_file(tmp)
        made.append(victim2.parent)
        os.chown(sticky, 0, 0)
        (sticky / "reference").mkdir()
        os.chmod(sticky / "reference", 0o1777)
        prime_cache(exe, sticky)
        as_nobody(plant_links, sticky / "reference", victim2, STEM05)
        (sticky / "reference" / f"{STEM05}.json").unlink()  # the run renders and writes
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(sticky / "run")], cwd=sticky)
        problems = base.exit_problems(code, 0, err) + link_problems(code, err, victim2, sticky)
        if code == 0 and not (sticky / "reference" / f"{STEM05}.json").is_file():
            problems.append("the cache was not written")
        checks.case(f"{guarantee} ch05 with a sticky reference/ (1777) holding links named like "
                    "temporaries", problems)

        # 5. Root, a 1777 cache of root's: another user's files in it, under names like the
        # cache's own (a PFM without JSON, temporaries whose lock is free), are never deleted
        # (the sticky bit does not stop root; the index does).
        theirs = ["holiday.pfm", ".notes.tmp-draft", "cornell_ls1_16x12_d3.pfm",
                  f".{STEM05}.pfm.tmp-0123456789abcdef", f".{STEM05}.json.tmp-4242-0"]
        as_nobody(plant_files, sticky / "reference", theirs)
        (sticky / "reference" / f"{STEM05}.json").unlink()
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(sticky / "run2")], cwd=sticky)
        problems = base.exit_problems(code, 0, err)
        gone = [n for n in theirs if not (sticky / "reference" / n).is_file()]
        if gone:
            problems.append(f"another user's files deleted from the cache: {gone}")
        checks.case("[The reference cache] root's ch05 with a 1777 cache holding another user's "
                    "files named like leftovers", problems)

        # 6. Links planted in a cache of ours under temporary-like names: never followed, and
        # left where they are (the index does not name them).
        victim3 = victim_file(tmp)
        made.append(victim3.parent)
        own = base.fresh(tmp / "own")
        prime_cache(exe, own)
        planted = temporary_like_names(STEM05)
        for name in planted:
            os.symlink(victim3, own / "reference" / name)
        (own / "reference" / f"{STEM05}.json").unlink()
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(own / "run")], cwd=own)
        problems = base.exit_problems(code, 0, err) + link_problems(code, err, victim3, own)
        left = [n for n in planted if (own / "reference" / n).is_symlink()]
        if len(left) != len(planted):
            problems.append(f"{len(planted) - len(left)} planted names deleted from the cache")
        checks.case(f"{guarantee} ch05 with links named like temporaries in its own cache "
                    "(left, not followed)", problems)

        # 7. scripts/make-gallery in a shared out/ where nobody planted a link under the name it
        # used (.index.html.tmp): refused before writing (issue 43: folders of your own only).
        gallery = Path(__file__).resolve().parents[2] / "scripts" / "make-gallery"
        shared3, victim4 = shared_folder(tmp), victim_file(tmp)
        made += [shared3, victim4.parent]
        as_nobody(plant_link, victim4, shared3 / ".index.html.tmp")
        p = subprocess.run([sys.executable, str(gallery), "--out", str(shared3)],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           stdin=subprocess.DEVNULL, timeout=base.CASE_TIMEOUT)
        problems = base.exit_problems(p.returncode, 2, p.stderr)
        problems += link_problems(p.returncode, p.stderr, victim4, shared3)
        if (shared3 / "index.html").exists():
            problems.append("index.html written in a shared folder")
        checks.case(f"{guarantee} make-gallery refuses a shared out/ with a planted "
                    ".index.html.tmp link", problems)
    finally:
        for folder in made:
            shutil.rmtree(folder, ignore_errors=True)


# ---------------------------------------------------------------------------------------------
# The cache is one verified unit.

def pfm_header(width, height):
    return f"PF\n{width} {height}\n-1.0\n".encode()


def prime_cache(exe, parent, extra=()):
    """A run that leaves a whole cache in parent/reference; returns its JSON."""
    code, _, err, _ = base.run([exe] + TINY05 + list(extra) + ["--out", str(parent / "first")],
                               cwd=parent)
    if code != 0:
        raise RuntimeError(f"the priming run failed: exit {code}: {base.text(err)[:300]!r}")
    return json.loads((parent / "reference" / f"{STEM05}.json").read_text())


def fnv1a64(data):
    """FNV-1a, 64 bits: the checksum the cache records."""
    value = 0xcbf29ce484222325
    for byte in data:
        value = ((value ^ byte) * 0x100000001b3) & 0xFFFFFFFFFFFFFFFF
    return value


def rehash(parent, pfm_bytes):
    """Writes pfm_bytes as the cached PFM and records its size and hash in the JSON, as a
    writer would: only the value checks can then find it wrong."""
    folder = parent / "reference"
    (folder / f"{STEM05}.pfm").write_bytes(pfm_bytes)
    description = json.loads((folder / f"{STEM05}.json").read_text())
    description["pfm"] = {"bytes": len(pfm_bytes), "fnv1a64": f"{fnv1a64(pfm_bytes):016x}"}
    (folder / f"{STEM05}.json").write_text(json.dumps(description, indent=2) + "\n")


def rmse_column(out):
    lines = (out / "rmse_vs_spp.csv").read_text().splitlines()
    header = lines[0].split(",")
    index = header.index("rmse_vs_reference")
    return [line.split(",")[index] for line in lines[1:]]


def cache_problems(parent):
    """The cache holds whole references only, nothing hidden or temporary."""
    return base.reference_cache_problems(parent / "reference")


def integrity_case(exe, parent, spoil, expected_rmse, expect_note, what):
    """Primes a cache, spoils it, runs: exit 0, one note line (or none), the rmse against the
    reference its own spp gives, a whole cache, then a third run that uses it silently."""
    parent = base.fresh(parent)
    prime_cache(exe, parent)
    spoil(parent)
    code, _, err, seconds = base.run([exe] + TINY05 + ["--out", str(parent / "run")], cwd=parent)
    problems = base.exit_problems(code, 0, err)
    lines = base.lines_of(err)
    if expect_note:
        if len(lines) != 1 or "again" not in lines[0]:
            problems.append(f"expected one line saying why it rendered again: {base.text(err)!r}")
        elif expect_note not in lines[0]:
            problems.append(f"the note does not say {expect_note!r}: {lines[0]!r}")
    elif lines:
        problems.append(f"unexpected stderr: {base.text(err)!r}")
    if code == 0 and rmse_column(parent / "run") != expected_rmse:
        problems.append(f"rmse_vs_reference {rmse_column(parent / 'run')} differs from a clean "
                        f"run's {expected_rmse}: it used another reference")
    if seconds > 5.0:  # a tiny run; the 10000x10000 header must not make it allocate 1.2 GB
        problems.append(f"took {seconds:.1f} s")
    problems += cache_problems(parent)
    code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(parent / "run")], cwd=parent)
    if code != 0 or err:
        problems.append(f"the next run did not use the repaired cache silently: exit {code}, "
                        f"{base.text(err)!r}")
    return [f"{what}: {p}" for p in problems]


def group_cache_integrity(chapters, tmp, checks):
    need(chapters, CH05)
    exe = chapters[CH05]
    guarantee = "[The reference cache]"
    # The rmse against the reference that a clean cache gives, per --reference-spp.
    clean = {}
    for spp in ("16", "32"):
        parent = base.fresh(tmp / f"clean{spp}")
        code, _, err, _ = base.run([exe] + base.with_flags(TINY05, "--reference-spp", spp) +
                                   ["--out", str(parent / "run")], cwd=parent)
        if code != 0:
            checks.case(f"clean run at reference spp {spp}", base.exit_problems(code, 0, err))
            return
        clean[spp] = rmse_column(parent / "run")
    pixels = 16 * 12 * 3
    folder = lambda parent: parent / "reference"  # noqa: E731
    pfm = lambda parent: folder(parent) / f"{STEM05}.pfm"  # noqa: E731

    def values(value):
        return lambda parent: rehash(parent, pfm_header(16, 12) + struct.pack("<f", value) * pixels)

    def append_bytes(parent):
        with open(pfm(parent), "ab") as f:
            f.write(b"\0" * 12)

    def zeros(parent):  # the JSON left as it was: only the hash can tell
        pfm(parent).write_bytes(pfm_header(16, 12) + b"\0" * (4 * pixels))

    def huge_header(parent):
        pfm(parent).write_bytes(b"PF\n10000 10000\n-1.0\n" + b"\0" * 10)

    def other_writers_pfm(parent):
        # A writer of 32 spp killed between its two renames: its PFM beside the 16-spp JSON.
        other = base.fresh(parent / "other")
        code, _, _, _ = base.run([exe] + base.with_flags(TINY05, "--reference-spp", "32") +
                                 ["--out", str(other / "run")], cwd=other)
        shutil.copy(other / "reference" / f"{STEM05}.pfm", pfm(parent))
        shutil.rmtree(other)

    def fifo_json(parent):
        (folder(parent) / f"{STEM05}.json").unlink()
        os.mkfifo(folder(parent) / f"{STEM05}.json")

    def killed_writers(parent):
        # What killed writers leave, named in the index as they named it: temporaries, and a
        # PFM without its JSON.
        names = [f".{STEM05}.pfm.tmp-0123456789abcdef", f".{STEM05}.json.tmp-fedcba9876543210",
                 f".{STEM05}_d3.pfm.tmp-00112233445566aa"]
        for name in names:
            (folder(parent) / name).write_bytes(b"half a reference")
        shutil.copy(pfm(parent), folder(parent) / "cornell_ls1_16x12_d3.pfm")
        with open(folder(parent) / "index.txt", "a") as index:
            index.write("".join(f"{n}\n" for n in names + ["cornell_ls1_16x12_d3.pfm"]))

    cases = [
        (values(float("nan")), "finite", "a PFM of NaN with a matching hash"),
        (values(float("inf")), "finite", "a PFM of +Inf with a matching hash"),
        (values(-0.25), "non-negative", "a PFM of negative values with a matching hash"),
        (zeros, "checksum", "a PFM of zeros its JSON does not describe"),
        (append_bytes, "bytes", "a PFM with trailing bytes"),
        (huge_header, "bytes", "a 30-byte PFM whose header claims 10000x10000"),
        (other_writers_pfm, "checksum", "another writer's 32-spp PFM beside the 16-spp JSON"),
        (fifo_json, "not a regular file", "a FIFO in place of the JSON"),
        (killed_writers, None, "leftovers of killed writers (temporaries, a PFM without JSON)"),
    ]
    # Two at a time, each in a parent of its own (the machine has at least 2 cores).
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {pool.submit(integrity_case, exe, tmp / f"case{i}", spoil, clean["16"], note,
                               what): what for i, (spoil, note, what) in enumerate(cases)}
        for future in concurrent.futures.as_completed(futures):
            checks.case(f"{guarantee} ch05 with {futures[future]}", future.result())

    # A live writer's temporary (its lock held) is not a leftover: it stays.
    parent = base.fresh(tmp / "live")
    prime_cache(exe, parent)
    live = folder(parent) / f".{STEM05}.pfm.tmp-00000000000000aa"
    with open(live, "wb") as held:
        fcntl.flock(held, fcntl.LOCK_EX)
        (folder(parent) / f"{STEM05}.json").unlink()  # the next run renders and writes
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(parent / "run")], cwd=parent)
        problems = base.exit_problems(code, 0, err)
        if not live.exists():
            problems.append("a live writer's temporary file was removed")
    checks.case(f"{guarantee} ch05 beside a live writer's temporary file", problems)

    # Two runs at once in one parent with different --reference-spp, repeated: each uses the
    # reference of the spp it asked for (its rmse column equals the clean run's).
    parent = base.fresh(tmp / "concurrent")
    rounds = 8  # each round two tiny runs, about 0.3 s: enough crossings to mix a weak cache

    def one(index, spp):
        code, _, err, _ = base.run([exe] + base.with_flags(TINY05, "--reference-spp", spp) +
                                   ["--out", str(parent / f"run{index}_{spp}")], cwd=parent)
        if code != 0:
            return [f"round {index}, spp {spp}: exit {code}: {base.text(err)[:200]!r}"]
        got = rmse_column(parent / f"run{index}_{spp}")
        return [] if got == clean[spp] else [
            f"round {index}, spp {spp}: rmse_vs_reference {got}, its own reference gives "
            f"{clean[spp]}"]

    problems = []
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for index in range(rounds):
            for result in pool.map(lambda spp: one(index, spp), ["16", "32"]):
                problems += result
    problems += cache_problems(parent)
    checks.case(f"{guarantee} two ch05 runs at once with --reference-spp 16 and 32, "
                f"{rounds} rounds", problems)
    own_folder_cases(exe, tmp, checks, guarantee)


USER_FILES = {"ground_truth_4096spp.pfm": b"PF\n1 1\n-1.0\n" + b"\0" * 12,
              "measured.pfm": b"a user's measurement", ".notes.tmp-draft": b"a user's draft",
              f".{STEM05}.pfm.tmp-0123456789abcdef": b"a user's file under a cache-like name"}


def plant_user_files(folder):
    os.makedirs(folder, exist_ok=True)
    for name, data in USER_FILES.items():
        (Path(folder) / name).write_bytes(data)


def user_files_problems(folder):
    gone = [n for n, data in USER_FILES.items()
            if not (Path(folder) / n).is_file() or (Path(folder) / n).read_bytes() != data]
    return [f"a user's files deleted or changed: {gone}"] if gone else []


def refusal_problems(code, err, seconds, parent, *words):
    problems = base.exit_problems(code, 2, err) + base.one_line_problems(err, [parent])
    for word in words:
        if word not in base.text(err):
            problems.append(f"the line does not say {word!r}: {base.text(err)!r}")
    if seconds > 1.0:
        problems.append(f"took {seconds:.2f} s to refuse (limit 1 s)")
    return problems


def own_folder_cases(exe, tmp, checks, guarantee):
    """The cache is a folder of its own and deletes only what its index names (issue 43)."""
    tiny = [a for a in TINY05 if a not in ("--reference-dir", "reference")]

    # `cd proj; ch05 --out run` where proj/reference/ is the user's folder of pictures: the
    # default cache is elsewhere ($XDG_CACHE_HOME), proj/reference/ untouched.
    parent = base.fresh(tmp / "proj")
    plant_user_files(parent / "reference")
    code, _, err, _ = base.run([exe] + tiny + ["--out", "run"], cwd=parent)
    problems = base.exit_problems(code, 0, err) + user_files_problems(parent / "reference")
    if sorted(os.listdir(parent / "reference")) != sorted(USER_FILES):
        problems.append(f"written into the user's reference/: {os.listdir(parent / 'reference')}")
    xdg = Path(os.environ["XDG_CACHE_HOME"]) / "mcrt-companion"
    if code == 0 and not (xdg / "CACHEDIR.TAG").is_file():
        problems.append(f"no tagged cache in $XDG_CACHE_HOME/mcrt-companion: {xdg}")
    checks.case(f"{guarantee} cd proj; ch05 --out run, proj/reference/ a user's pictures",
                problems)

    # The user's files planted in the cache itself (a tagged folder): never deleted.
    parent = base.fresh(tmp / "planted")
    prime_cache(exe, parent)
    plant_user_files(parent / "reference")
    (parent / "reference" / f"{STEM05}.json").unlink()  # the run renders and writes
    code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(parent / "run")], cwd=parent)
    problems = base.exit_problems(code, 0, err) + user_files_problems(parent / "reference")
    checks.case(f"{guarantee} ch05 with a user's files planted in its cache", problems)

    # --reference-dir mypics: a non-empty folder without CACHEDIR.TAG is refused up front.
    parent = base.fresh(tmp / "mypics")
    plant_user_files(parent / "mypics")
    code, _, err, seconds = base.run([exe] + tiny + ["--reference-dir", "mypics", "--out", "run"],
                                     cwd=parent)
    problems = refusal_problems(code, err, seconds, parent, "--reference-dir", "CACHEDIR.TAG")
    problems += user_files_problems(parent / "mypics")
    if sorted(os.listdir(parent / "mypics")) != sorted(USER_FILES) or (parent / "run").exists():
        problems.append(f"written: {sorted(os.listdir(parent))}, {os.listdir(parent / 'mypics')}")
    checks.case(f"{guarantee} ch05 --reference-dir mypics (a user's files, no tag)", problems)

    # A cache inside --out (which each run replaces): refused before any work.
    parent = base.fresh(tmp / "inside")
    for flags in (["--out", "run", "--reference-dir", "run/cache"],
                  ["--out", "cache/run", "--reference-dir", "cache"]):
        code, _, err, seconds = base.run([exe] + tiny + flags, cwd=parent)
        problems = refusal_problems(code, err, seconds, parent, "--reference-dir", "--out")
        if os.listdir(parent):
            problems.append(f"left: {os.listdir(parent)}")
        checks.case(f"{guarantee} ch05 {' '.join(flags)}", problems)

    # No HOME, no XDG_CACHE_HOME: refused with a line; a HOME where no folder can be made: one
    # line, exit 1; both before any work.
    parent = base.fresh(tmp / "nohome")
    env = {k: v for k, v in os.environ.items() if k not in ("HOME", "XDG_CACHE_HOME")}
    code, _, err, seconds = run_env([exe] + tiny + ["--out", "run"], parent, env)
    problems = refusal_problems(code, err, seconds, parent, "--reference-dir", "HOME")
    checks.case(f"{guarantee} ch05 without HOME nor XDG_CACHE_HOME", problems)
    (parent / "home").write_text("a file, not a folder\n")
    env["HOME"] = str(parent / "home")
    code, _, err, seconds = run_env([exe] + tiny + ["--out", "run"], parent, env)
    problems = base.exit_problems(code, 1, err) + base.one_line_problems(err, [parent])
    if "--reference-dir" not in base.text(err) or seconds > 1.0:
        problems.append(f"not one prompt line naming --reference-dir: {base.text(err)!r}, "
                        f"{seconds:.2f} s")
    if sorted(os.listdir(parent)) != ["home"]:
        problems.append(f"left: {os.listdir(parent)}")
    checks.case(f"{guarantee} ch05 with a HOME where no cache folder can be made", problems)

    # A live writer in another PID namespace (a container sharing the folder): its temporary,
    # named in the index, holds its lock and stays; once it is gone, the next run removes it.
    if not shutil.which("unshare") or subprocess.run(
            ["unshare", "--pid", "--fork", "true"], stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL).returncode != 0:
        print("SKIP: unshare --pid is not allowed here; the other-namespace writer did not run")
        return
    parent = base.fresh(tmp / "namespace")
    prime_cache(exe, parent)
    name = f".{STEM05}.pfm.tmp-{os.urandom(8).hex()}"
    writer_code = ("import fcntl, sys\n"
                   f"f = open({str(parent / 'reference' / name)!r}, 'wb')\n"
                   "fcntl.flock(f, fcntl.LOCK_EX)\n"
                   f"open({str(parent / 'reference' / 'index.txt')!r}, 'a').write({name!r} + '\\n')\n"
                   "print('ready', flush=True)\n"
                   "sys.stdin.read()\n")
    writer = subprocess.Popen(["unshare", "--pid", "--fork", "--kill-child", sys.executable, "-c",
                               writer_code], stdin=subprocess.PIPE, stdout=subprocess.PIPE)
    problems = []
    try:
        if writer.stdout.readline().strip() != b"ready":
            problems.append("the writer in another PID namespace did not start")
        (parent / "reference" / f"{STEM05}.json").unlink()
        code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(parent / "run")], cwd=parent)
        problems += base.exit_problems(code, 0, err)
        if not (parent / "reference" / name).exists():
            problems.append("a live writer's temporary (another PID namespace) was removed")
    finally:
        writer.stdin.close()
        writer.wait(timeout=10)
    code, _, err, _ = base.run([exe] + TINY05 + ["--out", str(parent / "run2")], cwd=parent)
    problems += base.exit_problems(code, 0, err)
    if (parent / "reference" / name).exists():
        problems.append("a dead writer's temporary, named in the index, was left")
    checks.case(f"{guarantee} ch05 beside a live writer in another PID namespace", problems)


# ---------------------------------------------------------------------------------------------
# gnuplot under control.

PLOTTER = "ch02_disk_area"


def group_gnuplot_env(chapters, tmp, checks):
    need(chapters, PLOTTER)
    real = shutil.which("gnuplot")
    if not real:
        skip("gnuplot is not installed; its environment cannot be tried")
    exe, tiny = chapters[PLOTTER], base.TINY[PLOTTER] + ["--quiet"]
    guarantee = "[Plots]"

    def run_with(name, env):
        parent = base.fresh(tmp / name)
        start = time.monotonic()
        code, _, err, _ = run_env([exe] + tiny + ["--out", str(parent / "out")], parent, env)
        return parent, code, err, time.monotonic() - start

    plain, code, err, _ = run_with("plain", dict(os.environ))
    if code != 0:
        checks.case("plain run", base.exit_problems(code, 0, err))
        return
    plain_files = base.snapshot(plain / "out")

    # A ~/.gnuplot that prints a line and sets decimal commas.
    home = base.fresh(tmp / "home")
    (home / ".gnuplot").write_text('print "hello: from ~/.gnuplot"\nset decimalsign ","\n'
                                   'set format y "%.3f"\n')
    env = dict(os.environ, HOME=str(home))
    parent, code, err, _ = run_with("rc", env)
    problems = base.exit_problems(code, 0, err)
    if err:
        problems.append(f"stderr: {base.text(err)[:300]!r}")
    if code == 0:
        files = base.snapshot(parent / "out")
        changed = sorted(k for k in files if k != "timings.json" and
                         files.get(k) != plain_files.get(k))
        if changed:
            problems.append(f"files differ from a run without ~/.gnuplot: {changed}")
    checks.case(f"{guarantee} {PLOTTER} with a ~/.gnuplot that prints and sets decimal commas",
                problems)

    # Fake gnuplots first on the PATH: one that hangs, one that cannot draw PNG.
    fakes = {
        "hanging": "#!/bin/sh\nexec sleep 300\n",
        "no-png": "#!/bin/sh\necho 'gnuplot: unknown or ambiguous terminal type: pngcairo' >&2\n"
                  "exit 1\n",
    }
    for name, script in fakes.items():
        bin_dir = base.fresh(tmp / f"bin-{name}")
        (bin_dir / "gnuplot").write_text(script)
        os.chmod(bin_dir / "gnuplot", 0o755)
        # 1 s per gnuplot: the hanging one is stopped quickly (the default limit is 30 s).
        env = dict(os.environ, PATH=f"{bin_dir}:{os.environ.get('PATH', '')}",
                   MCRT_GNUPLOT_TIMEOUT="1")
        parent, code, err, seconds = run_with(name, env)
        problems = base.exit_problems(code, 0, err)
        lines = base.lines_of(err)
        if len(lines) != 1 or not lines[0].startswith("note: gnuplot"):
            problems.append(f"expected one note about gnuplot: {base.text(err)!r}")
        if code == 0:
            names = sorted(os.listdir(parent / "out"))
            expected = sorted(n for n in plain_files if not n.endswith((".png", ".svg")) or
                              not (n[:-4] + ".gp") in plain_files)
            if names != expected:
                problems.append(f"files {names}, expected every file but the plots' {expected}")
        if seconds > 10.0:  # one probe of 1 s at most, then no gnuplot at all
            problems.append(f"took {seconds:.1f} s")
        left = base.processes_using(bin_dir) + base.processes_using(parent)
        if left:
            problems.append(f"gnuplot's processes left running: {left}")
            for entry in left:
                os.kill(int(entry.split()[0]), signal.SIGKILL)
        what = "hangs" if name == "hanging" else "cannot draw PNG"
        checks.case(f"{guarantee} {PLOTTER} with a gnuplot that {what}", problems)

    # MCRT_GNUPLOT_TIMEOUT is read strictly: anything but 1 to 3600 seconds is refused up front
    # (exit 2, one line naming the variable and what it accepts), never ignored.
    for value in ["abc", "0", "3601", "1.5", " 5", "-1", ""]:
        parent, code, err, _ = run_with(f"timeout-{value.strip() or 'empty'}",
                                        dict(os.environ, MCRT_GNUPLOT_TIMEOUT=value))
        problems = base.exit_problems(code, 2, err)
        lines = base.lines_of(err)
        if len(lines) != 1 or "MCRT_GNUPLOT_TIMEOUT: give a whole number of seconds from 1 to 3600" \
                not in lines[0]:
            problems.append(f"expected one line naming MCRT_GNUPLOT_TIMEOUT: {base.text(err)!r}")
        if os.path.exists(parent / "out"):
            problems.append("--out was written")
        checks.case(f"{guarantee} {PLOTTER} with MCRT_GNUPLOT_TIMEOUT={value!r} is refused",
                    problems)


def run_with(command, cwd, timeout=20.0, **options):
    """robustness.run with subprocess.run's other options (env, preexec_fn): (exit code or
    None on time-out, stdout, stderr, seconds)."""
    start = time.monotonic()
    try:
        p = subprocess.run(command, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           stdin=subprocess.DEVNULL, timeout=timeout, **options)
    except subprocess.TimeoutExpired as e:
        return None, e.stdout or b"", e.stderr or b"", time.monotonic() - start
    return p.returncode, p.stdout, p.stderr, time.monotonic() - start


def run_env(command, cwd, env, timeout=20.0):
    """robustness.run with an environment."""
    return run_with(command, cwd, timeout, env=env)


# ---------------------------------------------------------------------------------------------
# Divergent parameters refused up front.

def group_divergent(chapters, tmp, checks):
    cases = [
        ("ch05_path_tracer", ["--scene", "furnace", "--albedo", "1"]),
        ("ch06_russian_roulette", ["--scene", "furnace", "--albedo", "1"]),
        ("ch07_importance_sampling", ["--albedo", "1"]),
        ("ch07_importance_sampling", ["--scene", "furnace", "--albedo", "1.0"]),
        ("ch08_next_event_estimation", ["--scene", "furnace", "--albedo", "1"]),
        ("ch08_next_event_estimation", ["--albedo", "1"]),
    ]
    cases = [c for c in cases if c[0] in chapters]
    if not cases:
        skip("no chapter that renders a furnace is built")
    for i, (name, args) in enumerate(cases):
        parent = base.fresh(tmp / f"div{i}")
        out = parent / "out"
        code, _, err, seconds = base.run([chapters[name]] + args + ["--out", str(out)],
                                         cwd=parent, timeout=base.REFUSAL_TIMEOUT)
        problems = base.exit_problems(code, 2, err) + base.one_line_problems(err, [parent])
        if "--albedo" not in base.text(err):
            problems.append(f"message does not name --albedo: {base.text(err)!r}")
        if seconds > 1.0:
            problems.append(f"took {seconds:.2f} s to refuse (limit 1 s)")
        if os.listdir(parent):
            problems.append(f"left: {os.listdir(parent)}")
        checks.case(f"[Refused work] {name} {' '.join(args)}", problems)


# ---------------------------------------------------------------------------------------------
# Memory and threads are work too.

def limited(limits, uid=None):
    """A preexec_fn that sets resource limits (and then drops to uid: the process limit counts
    the processes of a user, and binds only one that is not root)."""
    import resource

    def apply():
        for which, value in limits:
            resource.setrlimit(which, (value, value))
        if uid is not None:
            os.setgroups([])
            os.setgid(uid)
            os.setuid(uid)
    return apply


def run_limited(command, cwd, preexec, timeout=20.0):
    """robustness.run with `preexec` (limits, a user) applied in the child."""
    return run_with(command, cwd, timeout, preexec_fn=preexec)


# A uid no account uses: its process count is this suite's alone (other suites on the machine
# may run as nobody at the same time).
UNUSED_UID = 64917


def group_memory_threads(chapters, tmp, checks):
    import resource
    gigabyte = 1 << 30
    # Each renderer at a size whose images alone exceed the address space allowed, with work
    # small enough that the ray limits pass: the memory estimate must refuse it.
    cases = [
        ("ch01_ray_tracing", ["--width", "8192", "--height", "4096", "--spp", "1"]),
        ("ch04_recursive_nk", ["--width", "4096", "--height", "2048", "--spp", "1",
                               "--branching", "1", "--max-depth", "1", "--equal-cost-depth",
                               "1", "--max-rays", "1e12"]),
        ("ch05_path_tracer", ["--width", "8192", "--height", "4096", "--spp", "1", "--depth",
                              "0", "--reference-spp", "0"]),
        ("ch06_russian_roulette", ["--width", "8192", "--height", "4096", "--spp", "1",
                                   "--depth", "0", "--paths", "100", "--q", "0.5"]),
        ("ch07_importance_sampling", ["--width", "8192", "--height", "4096", "--spp", "1",
                                      "--depth", "0", "--reference-spp", "1"]),
        ("ch08_next_event_estimation", ["--width", "2048", "--height", "1024", "--spp", "1",
                                        "--reference-spp", "2"]),
    ]
    cases = [c for c in cases if c[0] in chapters]
    for i, (name, args) in enumerate(cases):
        parent = base.fresh(tmp / f"mem{i}")
        # 1 GB of address space: less than any of these runs' images, more than the program.
        code, _, err, seconds = run_limited(
            [chapters[name]] + args + ["--quiet", "--out", str(parent / "out")], parent,
            limited([(resource.RLIMIT_AS, gigabyte)]))
        problems = base.exit_problems(code, 2, err) + base.one_line_problems(err, [parent])
        message = base.text(err)
        if "memory" not in message or not base.names_a_large_estimate(message):
            problems.append(f"message gives no memory estimate: {message!r}")
        if "--width" not in message:
            problems.append(f"message does not name --width: {message!r}")
        if seconds > 1.0:
            problems.append(f"took {seconds:.2f} s to refuse (limit 1 s)")
        if (parent / "out").exists():
            problems.append("--out was created")
        checks.case(f"[Memory and threads] {name} {' '.join(args)} under ulimit -v 1 GB",
                    problems)

    if os.geteuid() != 0:
        print("SKIP: the thread cases need root to run as an unused uid; they did not run")
        return
    name = "ch02_disk_area"
    if name not in chapters:
        return
    tiny = base.TINY[name] + ["--threads", "4", "--quiet"]
    # Threads and processes of the uid: 1, the process alone (its interruption watcher cannot
    # start); 2, that watcher and no worker (nor gnuplot).
    for limit in (1, 2):
        shared = shared_folder(tmp)
        try:
            out = shared / "out"
            code, _, err, _ = run_limited(
                [chapters[name]] + tiny + ["--out", str(out)], shared,
                limited([(resource.RLIMIT_NPROC, limit)], UNUSED_UID))
            lines = base.lines_of(err)
            if limit == 1:
                problems = base.exit_problems(code, 1, err) + base.one_line_problems(err, [shared])
                if "thread" not in base.text(err):
                    problems.append(f"the line does not say a thread failed: {err!r}")
                if out.exists():
                    problems.append("--out was created")
                what = "no thread at all: one line, exit 1"
            else:
                problems = base.exit_problems(code, 0, err)
                if not any("threads could be started" in line for line in lines):
                    problems.append(f"no note about the threads: {base.text(err)!r}")
                if any(not line.startswith("note:") for line in lines):
                    problems.append(f"stderr beyond notes: {base.text(err)!r}")
                if code == 0 and not (out / "disk_area.csv").is_file():
                    problems.append("the run's tables are missing")
                what = "no worker thread: the run on one thread, with a note"
            checks.case(f"[Memory and threads] {name} --threads 4 under ulimit -u {limit} "
                        f"({what})", problems)
        finally:
            shutil.rmtree(shared, ignore_errors=True)
