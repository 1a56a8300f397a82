#!/usr/bin/env python3
"""The chapters as a hostile but realistic user runs them (issue #11, item 8).

Each group below is one CTest test (label "robustness"); CTest passes the chapter executables
as NAME=PATH pairs, so a new chapter is covered as soon as it is built:

  robustness.py --tmp DIR --chapter ch01_ray_tracing=/path/to/ch01_ray_tracing ... GROUP [CHAPTER]

Groups:
  bad-input CHAPTER  a matrix of bad flag values generated from the chapter's --help: exit code 2,
                     one line on stderr under 200 characters naming the flag, nothing written
  work-limits        impossible work refused up front: exit 2 within a second, the estimate in
                     the one-line message
  signals            SIGINT and SIGTERM during a run: exit 130 or 143, one line, no staging folder
                     or temporary file left, no child process left, a previous run kept whole
                     (or, when the signal came after the swap and the line says so, the new
                     run whole)
  full-disk          a real full file system (a small tmpfs, root only; skipped otherwise): exit 1
                     naming a file and "No space left on device", nothing half-written
  paths              quotes, spaces, a leading '-' and non-ASCII characters in --out: exit 0 and
                     every file present and complete
  dev-full           stdout on /dev/full: exit 1, one line with the system's reason
  foreign-out        --out a non-empty folder that no chapter wrote: exit 2, folder untouched
  degenerate         zero emission, 1x1 images, --seed 0 at 8x6, a list of one value: exit 0, no
                     warning, every plot
  leading-zeros      --seed 010 is ten (or refused naming --seed), never octal eight
  out-manifest, out-ends, out-flags
                     --out, the ways a run ends, and flag values (out_folder_cases.py)
  cache-links, cache-integrity, gnuplot-env, divergent, memory-threads
                     the reference cache, temporary files, gnuplot, divergent parameters,
                     memory and threads under attack: see cache_cases.py

Exit status: 0 all cases held, 1 some failed (each failure printed), 77 skipped (CTest
SKIP_RETURN_CODE).
"""

import argparse
import concurrent.futures
import os
import re
import shutil
import signal
import struct
import subprocess
import sys
import time
import zlib
from pathlib import Path

SKIP = 77

# Tiny but complete runs (plots included), without --quiet so that a table reaches stdout.
# A chapter missing here still gets the --help-driven bad-input matrix.
TINY = {
    "ch01_ray_tracing": ["--width", "16", "--height", "12", "--spp", "2"],
    "ch02_disk_area": ["--max-n", "1000", "--trials", "10", "--dims", "2,3", "--ball-n", "500",
                       "--points", "50"],
    "ch03_trapezoid_vs_mc": ["--trials", "4", "--max-evaluations", "3000", "--dims", "1,2"],
    "ch04_recursive_nk": ["--width", "8", "--height", "6", "--spp", "1", "--branching", "2,1",
                          "--max-depth", "2", "--equal-cost-depth", "1", "--budget", "6"],
    "ch05_path_tracer": ["--width", "16", "--height", "12", "--spp", "1,4", "--depth", "3"],
    "ch06_russian_roulette": ["--width", "16", "--height", "12", "--spp", "2", "--depth", "4",
                              "--paths", "2000", "--q", "0.7,0.9"],
    "ch07_importance_sampling": ["--width", "16", "--height", "12", "--spp", "2", "--depth", "3",
                                 "--reference-spp", "4"],
    "ch09_stratified_qmc": ["--trials", "4", "--max-n", "256", "--budget", "256", "--dims", "1,2",
                            "--picture-points", "16"],
}
# Chapters that render an image of a scene (they take --scene, --width, --height, --emission).
RENDERERS = ["ch01_ray_tracing", "ch04_recursive_nk", "ch05_path_tracer",
             "ch06_russian_roulette", "ch07_importance_sampling"]
# The folder of cached reference images (chapters 05 and 08) when a case gives --reference-dir
# beside --out. It may stay only if it holds whole references, each PFM with its JSON (and the
# cache's tag and index).
REFERENCE_CACHE = "reference"


def reference_cache_problems(folder):
    names = sorted(set(os.listdir(folder)) - {"CACHEDIR.TAG", "index.txt"})
    stems = {n.rsplit(".", 1)[0] for n in names}
    whole = all(n.endswith((".pfm", ".json")) and not n.startswith(".") for n in names) \
        and all(f"{s}.pfm" in names and f"{s}.json" in names for s in stems)
    return [] if whole else [f"a reference cache that is not whole: {names}"]


def beside_out(parent, *expected):
    """What a run left in `parent` beyond `expected` (and a whole reference cache)."""
    left = sorted(set(os.listdir(parent)) - set(expected))
    if REFERENCE_CACHE in left and not reference_cache_problems(parent / REFERENCE_CACHE):
        left.remove(REFERENCE_CACHE)
    return left


CASE_TIMEOUT = 20.0  # seconds for a tiny run
REFUSAL_TIMEOUT = 5.0  # seconds for a refusal; a bad input that starts real work is caught by this


class Checks:
    """Collects failures of one group; every case is counted."""

    def __init__(self):
        self.cases = 0
        self.failures = []

    def case(self, name, problems):
        self.cases += 1
        for problem in problems:
            self.failures.append(f"{name}: {problem}")


def run(command, cwd, timeout=CASE_TIMEOUT, stdout=subprocess.PIPE):
    """Runs command (a list, no shell); returns (exit code, stdout, stderr, seconds)."""
    start = time.monotonic()
    try:
        p = subprocess.run(command, cwd=cwd, stdout=stdout, stderr=subprocess.PIPE,
                           stdin=subprocess.DEVNULL, timeout=timeout)
    except subprocess.TimeoutExpired as e:
        return None, e.stdout or b"", e.stderr or b"", time.monotonic() - start
    return p.returncode, p.stdout or b"", p.stderr, time.monotonic() - start


def text(data):
    return data.decode("utf-8", "replace")


def lines_of(data):
    return text(data).splitlines()


def fresh(path):
    path = Path(path)
    if path.exists() or path.is_symlink():
        shutil.rmtree(path)
    path.mkdir(parents=True)
    return path


def snapshot(folder):
    """Every file under folder, by relative path, with its bytes (None for a folder)."""
    folder = Path(folder)
    if not folder.exists():
        return None
    result = {}
    for entry in sorted(folder.rglob("*")):
        result[str(entry.relative_to(folder))] = None if entry.is_dir() else entry.read_bytes()
    return result


def one_line_problems(err, paths=(), limit=200):
    """Exactly one line on stderr, under limit characters once the paths the user gave (whose
    length is the user's) are counted as one character each."""
    lines = lines_of(err)
    problems = []
    if len(lines) != 1:
        problems.append(f"{len(lines)} lines on stderr, not 1: {text(err)[:400]!r}")
        return problems
    line = lines[0]
    for path in sorted((str(p) for p in paths), key=len, reverse=True):
        line = line.replace(path, "P")
    if len(line) >= limit:
        problems.append(f"message of {len(line)} characters besides paths (limit {limit}): "
                        f"{lines[0]!r}")
    return problems


def with_flags(base, *overrides):
    """base arguments with each --flag value pair of overrides replacing the one in base."""
    args = list(base)
    for flag, value in zip(overrides[::2], overrides[1::2]):
        if flag in args:
            args[args.index(flag) + 1] = value
        else:
            args += [flag, value]
    return args


def exit_problems(code, expected, err):
    if code is None:
        return [f"did not finish in time (expected exit {expected})"]
    if code != expected:
        return [f"exit code {code}, expected {expected}; stderr: {text(err)[:300]!r}"]
    return []


# ---------------------------------------------------------------------------------------------
# --help: the chapter's flags, so that the bad-input matrix follows the chapters.

HELP_LINE = re.compile(r"^\s+(?:-\w,)?(--[\w-]+)(.*)$")


def parse_help(exe):
    """[(flag, kind, info)]: kind is int, uint, float, int-list, real-list, choice, text, switch."""
    code, out, err, _ = run([exe, "--help"], cwd="/")
    if code != 0:
        raise RuntimeError(f"{exe} --help exited {code}: {text(err)}")
    flags = []
    for line in lines_of(out):
        m = HELP_LINE.match(line)
        if not m or m.group(1) == "--help":
            continue
        flag = m.group(1)
        spec = re.split(r"\s{2,}", m.group(2).strip())[0] if m.group(2).strip() else ""
        s = re.match(r"^(\w+)(?::(.*?))?(?:=([^=\s]*))?$", spec)
        if not spec or not s:
            flags.append((flag, "switch", {}))
            continue
        type_name, check, default = s.group(1), s.group(2) or "", s.group(3) or ""
        info = {"default": default}
        bounds = re.search(r"\[(\S+) - (\S+)\]", check)
        if type_name in ("INT", "UINT", "FLOAT"):
            if bounds:
                info["lo"], info["hi"] = float(bounds.group(1)), float(bounds.group(2))
            else:
                info["lo"], info["hi"] = 0.0, float(2**64 - 1) if type_name == "UINT" else None
            flags.append((flag, {"INT": "int", "UINT": "uint", "FLOAT": "float"}[type_name], info))
        elif check.startswith("{"):
            info["choices"] = check.strip("{}").split(",")
            flags.append((flag, "choice", info))
        elif re.fullmatch(r"[0-9][0-9.e+,-]*", default) and flag != "--out":
            whole = all(re.fullmatch(r"\d+", item) for item in default.split(","))
            flags.append((flag, "int-list" if whole else "real-list", info))
        else:
            flags.append((flag, "text", info))
    return flags


def whole(value):
    return str(int(value))


def bad_values(kind, info):
    """Values a flag of this kind must refuse."""
    garbage = ["", "abc", "5x", "1 2", "nan", "inf", "-inf", "1e400", "0x10", "0x1p3", "--",
               "1,2", "١٢"]
    if kind in ("int", "uint"):
        lo, hi = info["lo"], info["hi"]
        values = garbage + ["-1", "-0", "+1", "1.5", "1e3", "18446744073709551616", " 1"]
        values.append(whole(hi + 1) if hi < 2**63 else "18446744073709551616")
        if lo > 0:
            values.append(whole(lo - 1))
        return values
    if kind == "float":
        lo, hi = info["lo"], info["hi"]
        values = garbage + ["1.2.3", "1e", ".", "infinity", "1e999999999999"]
        values.append(repr(hi * 2 + 1))
        values.append(repr(lo / 2) if lo > 0 else "-1")
        if lo <= 0 < hi:
            values.append("-0.5")
        return values
    if kind in ("int-list", "real-list"):
        values = [",", "1,,2", ",1", "1,", "", "abc", "1,x", "-1", "1;2", "0x4", "1e400", "nan",
                  "inf", "1, 2", "99999999999999999999999"]
        if kind == "int-list":
            values += ["1.5", "2,-1"]
        return values
    if kind == "choice":
        first = info["choices"][0]
        return ["no-such-" + first, "", first.upper(), ",".join(info["choices"][:2]),
                first + "x", "-"]
    return []


def bad_input_cases(exe):
    """[(arguments, flag the message must name)] for one chapter."""
    cases = []
    flags = parse_help(exe)
    for flag, kind, info in flags:
        for value in bad_values(kind, info):
            cases.append(([flag, value], flag))
        if kind in ("int", "uint", "float", "int-list", "real-list", "choice"):
            cases.append(([f"{flag}=abc"], flag))  # the --flag=value form
        if kind != "switch":
            cases.append(([flag], flag))  # a missing value at the end of the line
    for unknown in ["--bogus", "--bogus=1", "-x", "--Seed", "---seed", "stray"]:
        cases.append(([unknown], unknown))
    for flag, kind, _ in flags:
        if kind != "switch" and flag != "--out":
            cases.append(([flag + "x", "1"], flag + "x"))  # a misspelt flag
    return cases


def check_refused(exe, arguments, flag, workdir):
    """exit 2, one line under 200 characters naming flag, nothing created at --out or in cwd."""
    workdir = fresh(workdir)
    cwd = workdir / "cwd"
    cwd.mkdir()
    out = workdir / "out"
    command = [exe] + (["--out", str(out)] if "--out" not in arguments[0] else []) + arguments
    code, _, err, _ = run(command, cwd=cwd, timeout=REFUSAL_TIMEOUT)
    problems = exit_problems(code, 2, err) + one_line_problems(err, [workdir])
    if flag not in text(err):
        problems.append(f"message does not name {flag}: {text(err)[:300]!r}")
    if out.exists():
        problems.append("--out was created")
    if any(cwd.iterdir()):
        problems.append(f"files created in the working folder: {os.listdir(cwd)}")
    shutil.rmtree(workdir, ignore_errors=True)
    return problems


def group_bad_input(chapters, tmp, checks, which):
    exe = chapters[which]
    cases = bad_input_cases(exe)
    with concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        futures = {pool.submit(check_refused, exe, args, flag, tmp / f"case{i}"): args
                   for i, (args, flag) in enumerate(cases)}
        for future in concurrent.futures.as_completed(futures):
            checks.case(f"{which} {' '.join(repr(a) for a in futures[future])}", future.result())


# ---------------------------------------------------------------------------------------------
# Work refused before it starts.

def max_out(exe, chapter):
    """Every numeric flag at the top of its range (the image at the largest size allowed)."""
    args = []
    for flag, kind, info in parse_help(exe):
        if flag in ("--threads", "--seed", "--albedo", "--emission") or flag.startswith("--max-rays"):
            continue
        if flag == "--width":
            args += [flag, "8192"]
        elif flag == "--height":
            args += [flag, "4096"]
        elif kind in ("int", "uint"):
            args += [flag, whole(info["hi"])]
    return args


LARGE_NUMBER = re.compile(r"(\d+(?:\.\d+)?)(?:\s*[eE]\+?(\d+)|\s*(million|billion|trillion))?")


def names_a_large_estimate(message):
    """True if message holds a number of at least a million (the predicted work)."""
    scale = {"million": 1e6, "billion": 1e9, "trillion": 1e12}
    for m in LARGE_NUMBER.finditer(message.replace(",", "").replace("'", "")):
        value = float(m.group(1))
        if m.group(2):
            value *= 10.0 ** int(m.group(2))
        if m.group(3):
            value *= scale[m.group(3)]
        if value >= 1e6:
            return True
    return False


def group_work_limits(chapters, tmp, checks):
    cases = [
        ("ch01_ray_tracing", ["--width", "8192", "--height", "4096", "--spp", "65536"], None),
        ("ch04_recursive_nk", ["--max-rays", "nan", "--max-depth", "30", "--branching", "8"],
         "--max-rays"),
        ("ch04_recursive_nk", ["--max-depth", "30", "--branching", "8"], None),
        ("ch05_path_tracer", ["--width", "8192", "--height", "4096", "--depth", "1000"], None),
        ("ch06_russian_roulette", ["--width", "8192", "--height", "4096", "--spp", "65536"], None),
        ("ch07_importance_sampling", ["--width", "8192", "--height", "4096", "--spp", "65536"],
         None),
    ]
    cases = [c for c in cases if c[0] in chapters]
    cases += [(name, max_out(exe, name), None) for name, exe in chapters.items()]
    for i, (name, args, flag) in enumerate(cases):
        workdir = fresh(tmp / f"work{i}")
        out = workdir / "out"
        code, _, err, seconds = run([chapters[name]] + args + ["--out", str(out)], cwd=workdir)
        problems = exit_problems(code, 2, err) + one_line_problems(err, [workdir])
        if seconds > 1.0:
            problems.append(f"took {seconds:.2f} s to refuse (limit 1 s)")
        if flag and flag not in text(err):
            problems.append(f"message does not name {flag}: {text(err)!r}")
        if not flag and not names_a_large_estimate(text(err)):
            problems.append(f"message gives no estimate of the work: {text(err)!r}")
        if out.exists():
            problems.append("--out was created")
        checks.case(f"{name} {' '.join(args)}", problems)


# ---------------------------------------------------------------------------------------------
# Signals, the staging folder and the swap.

def processes_using(folder):
    """Pids of processes (other than us) whose working folder or command line is under folder."""
    folder = str(folder)
    found = []
    for entry in os.listdir("/proc"):
        if not entry.isdigit() or int(entry) == os.getpid():
            continue
        try:
            cwd = os.readlink(f"/proc/{entry}/cwd")
            with open(f"/proc/{entry}/cmdline", "rb") as f:
                cmdline = f.read().decode("utf-8", "replace")
        except OSError:
            continue
        if cwd.startswith(folder) or folder in cmdline:
            found.append(f"{entry} ({cmdline.replace(chr(0), ' ')[:120]})")
    return found


def interrupted_run(exe, args, out, delay, signum):
    """Starts exe, sends signum after delay seconds; returns (exit code or None, stderr)."""
    p = subprocess.Popen([exe] + args + ["--out", str(out)], cwd=out.parent,
                         stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                         stderr=subprocess.PIPE)
    time.sleep(delay)
    if p.poll() is None:
        p.send_signal(signum)
    try:
        _, err = p.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        p.kill()
        _, err = p.communicate()
        return None, err
    return p.returncode, err


def after_interrupt_problems(code, err, parent, before, signum):
    """What an interrupted run must leave: exit 128+signal, one line, --out as before."""
    problems = []
    expected = 128 + signum
    if code is None:
        problems.append(f"still running 10 s after {signal.Signals(signum).name}")
    elif code < 0:
        problems.append(f"killed by signal {-code} instead of exiting {expected}")
    elif code != expected and code != 0:
        problems.append(f"exit code {code}, expected {expected}: {text(err)[:300]!r}")
    if code == expected:
        problems += one_line_problems(err, [parent])
        if "already written" in text(err):
            # The signal came after the swap: the new run is in --out, and it must be whole.
            # (Its bytes may equal the previous run's: the tiny cases repeat the same flags.)
            problems += [f"said already written, but {p}" for p in output_problems(parent / "out")]
        elif snapshot(parent / "out") != before:
            problems.append("--out changed (an interrupted run must leave the previous one whole)")
    left = beside_out(parent, "out")
    if left:
        problems.append(f"left beside --out: {left}")
    for _ in range(20):  # a child may take a moment to be reaped by the system
        users = processes_using(parent)
        if not users:
            break
        time.sleep(0.05)
    if users:
        problems.append(f"processes still running in the output folder: {users}")
    return problems


def signal_case(exe, tiny, long_args, parent, delay, signum, previous):
    parent = fresh(parent)
    out = parent / "out"
    if previous:
        code, _, err, _ = run([exe] + tiny + ["--quiet", "--out", str(out)], cwd=parent)
        if code != 0:
            return [f"the first, complete run failed with exit {code}: {text(err)[:300]!r}"]
    before = snapshot(out)
    code, err = interrupted_run(exe, long_args, out, delay, signum)
    problems = after_interrupt_problems(code, err, parent, before, signum)
    if code == 0:  # finished before the signal arrived: then it must be whole
        problems += output_problems(out)
    if previous:  # the previous output is still accepted as --out: a third run replaces it
        code, _, err, _ = run([exe] + tiny + ["--quiet", "--seed", "7", "--out", str(out)],
                              cwd=parent)
        problems += [f"third run: {p}" for p in exit_problems(code, 0, err)]
        if code == 0 and snapshot(out) == before:
            problems.append("third run: --out not replaced")
        if beside_out(parent, "out"):
            problems.append(f"third run left {beside_out(parent, 'out')}")
    return problems


def group_signals(chapters, tmp, checks):
    exe = chapters.get("ch05_path_tracer")
    if not exe:
        checks.case("signals", ["ch05_path_tracer not built"])
        return
    tiny = TINY["ch05_path_tracer"]
    # About a minute of work on 2 cores: the signal always arrives mid-render.
    long_args = ["--width", "320", "--height", "240", "--spp", "1,4,16,64,256", "--depth", "10",
                 "--quiet"]
    cases = []
    for signum, previous, delay in [(signal.SIGINT, False, 0.3), (signal.SIGTERM, True, 0.3),
                                    (signal.SIGINT, True, 1.0), (signal.SIGTERM, False, 1.0)]:
        cases.append((f"ch05 {signal.Signals(signum).name} after {delay} s, "
                      f"{'a previous run in --out' if previous else 'no previous run'}",
                      (exe, tiny, long_args, tmp / f"sig{len(cases)}", delay, signum, previous)))
    # Signals while the plots are drawn: a tiny run of each chapter, interrupted at fractions of
    # its own running time (a run that finishes first must simply be whole).
    for name in ("ch03_trapezoid_vs_mc", "ch05_path_tracer"):
        if name not in chapters:
            continue
        probe = fresh(tmp / f"probe_{name}")
        start = time.monotonic()
        run([chapters[name]] + TINY[name] + ["--quiet", "--out", str(probe / "out")], cwd=probe)
        duration = time.monotonic() - start
        shutil.rmtree(probe, ignore_errors=True)
        for fraction in (0.5, 0.9):
            signum = signal.SIGTERM if fraction == 0.5 else signal.SIGINT
            cases.append((f"{name} tiny run, {signal.Signals(signum).name} at {fraction:.0%} of "
                          f"its {duration:.2f} s", (chapters[name], TINY[name],
                                                    TINY[name] + ["--quiet"],
                                                    tmp / f"sig{len(cases)}",
                                                    duration * fraction, signum, True)))
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {pool.submit(signal_case, *args): name for name, args in cases}
        for future in concurrent.futures.as_completed(futures):
            checks.case(futures[future], future.result())


# ---------------------------------------------------------------------------------------------
# Complete files: PNG decoded chunk by chunk, SVG closed, every plot present.

def png_problems(path):
    data = Path(path).read_bytes()
    if not data.startswith(b"\x89PNG\r\n\x1a\n"):
        return [f"{path.name}: not a PNG"]
    pos, idat, header, chunks = 8, b"", None, []
    while pos + 8 <= len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        crc = data[pos + 8 + length:pos + 12 + length]
        if len(body) != length or len(crc) != 4:
            return [f"{path.name}: truncated in chunk {kind!r}"]
        if struct.unpack(">I", crc)[0] != zlib.crc32(kind + body) & 0xFFFFFFFF:
            return [f"{path.name}: bad CRC in chunk {kind!r}"]
        chunks.append(kind)
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    if not chunks or chunks[-1] != b"IEND" or header is None:
        return [f"{path.name}: no IHDR or no IEND"]
    width, height, depth, colour, _, _, interlace = header
    try:
        pixels = zlib.decompress(idat)
    except zlib.error as e:
        return [f"{path.name}: image data does not inflate ({e})"]
    channels = {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}.get(colour, 0)
    if interlace == 0 and len(pixels) != height * (1 + (width * channels * depth + 7) // 8):
        return [f"{path.name}: {len(pixels)} bytes of pixels for {width}x{height}"]
    return []


def output_problems(out, reference=None):
    """Every PNG decodes, every SVG is closed, every plot script has its pictures (when gnuplot
    is installed), and the same file names as the reference run, if one is given."""
    out = Path(out)
    if not out.is_dir():
        return [f"no output folder {out}"]
    names = sorted(p.name for p in out.iterdir())
    problems = []
    for name in names:
        if name.startswith(".") and name != ".mcrt-manifest":  # the run's list of its files
            problems.append(f"hidden or temporary file left: {name}")
        path = out / name
        if name.endswith(".png"):
            problems += png_problems(path)
        elif name.endswith(".svg"):
            if not path.read_bytes().rstrip().endswith(b"</svg>"):
                problems.append(f"{name}: SVG not closed")
        elif path.is_file() and path.stat().st_size == 0:
            problems.append(f"{name}: empty")
    if shutil.which("gnuplot"):
        for name in names:
            if name.endswith(".gp"):
                stem = name[:-3]
                for picture in (stem + ".png", stem + ".svg"):
                    if picture not in names:
                        problems.append(f"plot {picture} missing")
    if reference is not None and names != reference:
        problems.append(f"files differ from the plain run: missing "
                        f"{sorted(set(reference) - set(names))}, extra "
                        f"{sorted(set(names) - set(reference))}")
    return problems


# ---------------------------------------------------------------------------------------------

def group_paths(chapters, tmp, checks):
    tmp = fresh(tmp)
    weird = "it's a \"dir\" with  spaces, ünïcødé 日本 $HOME `true`; & (x) #1 back\\slash"
    plain_names = {}

    def plain(name):
        parent = fresh(tmp / f"plain_{name}")
        code, _, err, _ = run([chapters[name]] + TINY[name] + ["--quiet", "--out",
                                                             str(parent / "out")], cwd=parent)
        if code != 0:
            return None, [f"the plain run failed with exit {code}: {text(err)[:300]!r}"]
        return sorted(p.name for p in (parent / "out").iterdir()), []

    def weird_run(index, name, folder_name, out_argument, reference):
        parent = fresh(tmp / f"weird{index}")
        code, _, err, _ = run([chapters[name]] + TINY[name] + ["--quiet"] + out_argument,
                              cwd=parent)
        problems = exit_problems(code, 0, err)
        if code == 0:
            problems += output_problems(parent / folder_name, reference)
            left = beside_out(parent, folder_name)
            if left:
                problems.append(f"left beside --out: {left}")
        return problems

    names = [n for n in TINY if n in chapters]
    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        for name, (listing, problems) in zip(names, pool.map(plain, names)):
            plain_names[name] = listing
            checks.case(f"{name} plain run", problems)
        cases = [(name, weird, [f"--out={weird}"]) for name in names if plain_names[name]]
        if "ch05_path_tracer" in names and plain_names["ch05_path_tracer"]:
            for folder, argument in [("it's here", ["--out", "it's here"]),
                                     ("-weird", ["--out=-weird"]),
                                     ("-dash", ["--out", "./-dash"])]:
                cases.append(("ch05_path_tracer", folder, argument))
        futures = {pool.submit(weird_run, i, name, folder, argument, plain_names[name]):
                   f"{name} --out {folder!r}" for i, (name, folder, argument) in enumerate(cases)}
        for future in concurrent.futures.as_completed(futures):
            checks.case(futures[future], future.result())


def group_dev_full(chapters, tmp, checks):
    if not os.path.exists("/dev/full"):
        print("SKIP: no /dev/full on this system")
        sys.exit(SKIP)
    for name in [n for n in TINY if n in chapters]:
        parent = fresh(tmp / name)
        with open("/dev/full", "wb") as full:
            code, _, err, _ = run([chapters[name]] + TINY[name] + ["--out", str(parent / "out")],
                                  cwd=parent, stdout=full)
        problems = exit_problems(code, 1, err) + one_line_problems(err, [parent])
        if "No space left on device" not in text(err):
            problems.append(f"message does not give the system's reason: {text(err)!r}")
        checks.case(f"{name} >/dev/full", problems)


def group_foreign_out(chapters, tmp, checks):
    for name, exe in chapters.items():
        parent = fresh(tmp / name)
        out = parent / "mine"
        (out / "sub").mkdir(parents=True)
        (out / "notes.txt").write_text("my thesis, not a chapter's output\n")
        (out / "sub" / "data.bin").write_bytes(bytes(range(256)))
        before = snapshot(out)
        code, _, err, seconds = run([exe] + TINY.get(name, []) + ["--quiet", "--out", str(out)],
                                    cwd=parent)
        problems = exit_problems(code, 2, err) + one_line_problems(err, [out])
        if "--out" not in text(err) and str(out) not in text(err):
            problems.append(f"message names neither --out nor the folder: {text(err)!r}")
        if snapshot(out) != before:
            problems.append("the folder's contents changed")
        if sorted(os.listdir(parent)) != ["mine"]:
            problems.append(f"left beside --out: {sorted(os.listdir(parent))}")
        if seconds > 1.0:
            problems.append(f"took {seconds:.2f} s to refuse (limit 1 s)")
        checks.case(f"{name} --out a foreign folder", problems)


def group_degenerate(chapters, tmp, checks):
    cases = []
    for name in [n for n in RENDERERS if n in chapters]:
        tiny = TINY[name]
        cases.append((name, with_flags(tiny, "--scene", "furnace", "--emission", "0"),
                      "zero emission"))
        cases.append((name, with_flags(tiny, "--width", "1", "--height", "1"), "a 1x1 image"))
        cases.append((name, with_flags(tiny, "--width", "8", "--height", "6", "--seed", "0"),
                      "--seed 0 at 8x6"))
    for name in ("ch02_disk_area", "ch03_trapezoid_vs_mc"):
        if name in chapters:
            cases.append((name, with_flags(TINY[name], "--seed", "0"), "--seed 0"))
    # A list of one value: plots of a single point.
    for name, flag, value in [("ch02_disk_area", "--dims", "2"),
                              ("ch03_trapezoid_vs_mc", "--dims", "1"),
                              ("ch04_recursive_nk", "--branching", "1"),
                              ("ch05_path_tracer", "--spp", "1"),
                              ("ch06_russian_roulette", "--q", "0.7")]:
        if name in chapters:
            cases.append((name, with_flags(TINY[name], flag, value), f"{flag} {value} alone"))

    def one(i, name, args):
        parent = fresh(tmp / f"deg{i}")
        code, _, err, _ = run([chapters[name]] + args + ["--quiet", "--out",
                                                        str(parent / "out")], cwd=parent)
        problems = exit_problems(code, 0, err)
        if "warning" in text(err).lower():
            problems.append(f"a warning on stderr: {text(err)[:400]!r}")
        if code == 0:
            problems += output_problems(parent / "out")
        return problems

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = {pool.submit(one, i, name, args): f"{name} {what} ({' '.join(args)})"
                   for i, (name, args, what) in enumerate(cases)}
        for future in concurrent.futures.as_completed(futures):
            checks.case(futures[future], future.result())


def group_full_disk(chapters, tmp, checks):
    name = "ch05_path_tracer"
    if name not in chapters:
        checks.case("full disk", [f"{name} not built"])
        return
    if os.geteuid() != 0:
        print("SKIP: mounting a small tmpfs needs root; the full-disk cases did not run")
        sys.exit(SKIP)
    tmp = fresh(tmp)
    mount = tmp / "disk"
    mount.mkdir()
    probe = subprocess.run(["mount", "-t", "tmpfs", "-o", "size=64k", "tmpfs", str(mount)],
                           stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if probe.returncode != 0:
        print(f"SKIP: cannot mount a tmpfs here ({text(probe.stderr).strip()})")
        sys.exit(SKIP)
    subprocess.run(["umount", str(mount)], check=True)
    exe, tiny = chapters[name], TINY[name] + ["--quiet"]
    reference = fresh(tmp / "plain")
    code, _, err, _ = run([exe] + tiny + ["--out", str(reference / "out")], cwd=reference)
    if code != 0:
        checks.case("plain run", [f"exit {code}: {text(err)[:300]!r}"])
        return
    listing = sorted(p.name for p in (reference / "out").iterdir())
    size = sum(p.stat().st_size for p in (reference / "out").iterdir())
    failed = 0
    # From far too small to just enough: each run is whole (exit 0) or leaves nothing (exit 1).
    for kib in (4, 16, 64, 128, max(256, 2 * size // 1024 + 64)):
        subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={kib}k", "tmpfs", str(mount)],
                       check=True)
        try:
            out = mount / "out"
            code, _, err, _ = run([exe] + tiny + ["--out", str(out)], cwd=tmp)
            problems = []
            if code == 1:
                failed += 1
                problems += one_line_problems(err, [mount])
                if "No space left on device" not in text(err):
                    problems.append(f"message lacks the system's reason: {text(err)!r}")
                if str(mount) not in text(err):
                    problems.append(f"message names no file under the full disk: {text(err)!r}")
                if beside_out(mount):
                    problems.append(f"left on the full disk: {beside_out(mount)}")
            elif code == 0:
                problems += output_problems(out, listing)
                if beside_out(mount, "out"):
                    problems.append(f"left beside --out: {beside_out(mount, 'out')}")
            else:
                problems += exit_problems(code, 1, err)
            if kib == 64 and code != 1:
                problems.append(f"a 64 KiB disk holds a {size // 1024} KiB run?")
            checks.case(f"{name} on a {kib} KiB tmpfs", problems)
        finally:
            subprocess.run(["umount", str(mount)], check=True)
    if failed == 0:
        checks.case("full disk", ["no run met a full disk"])


def group_leading_zeros(chapters, tmp, checks):
    """010 is ten, never octal eight: --seed 010 renders what --seed 10 renders, not --seed 8."""
    name = "ch05_path_tracer"
    if name not in chapters:
        checks.case("leading zeros", [f"{name} not built"])
        return
    images = {}
    for seed in ("010", "10", "8"):
        parent = fresh(tmp / f"seed{seed}")
        code, _, err, _ = run([chapters[name]] + with_flags(TINY[name], "--seed", seed) +
                              ["--quiet", "--out", str(parent / "out")], cwd=parent)
        if code == 2 and seed == "010":
            problems = one_line_problems(err)
            if "--seed" not in text(err):
                problems.append(f"refused without naming --seed: {text(err)!r}")
            checks.case(f"{name} --seed 010 refused", problems)
            return
        checks.case(f"{name} --seed {seed}", exit_problems(code, 0, err))
        if code == 0:
            images[seed] = (parent / "out" / "spp_0001.pfm").read_bytes()
    if len(images) == 3:
        problems = []
        if images["010"] != images["10"]:
            problems.append("--seed 010 differs from --seed 10")
        if images["010"] == images["8"]:
            problems.append("--seed 010 is read as octal 8")
        checks.case(f"{name} --seed 010 is ten", problems)


GROUPS = {
    "leading-zeros": group_leading_zeros,
    "work-limits": group_work_limits,
    "signals": group_signals,
    "full-disk": group_full_disk,
    "paths": group_paths,
    "dev-full": group_dev_full,
    "foreign-out": group_foreign_out,
    "degenerate": group_degenerate,
}

# The groups of out_folder_cases.py, given this module for its helpers.
sys.path.insert(0, str(Path(__file__).resolve().parent))
import out_folder_cases  # noqa: E402  (after the helpers it uses are defined)

GROUPS.update(out_folder_cases.groups(sys.modules[__name__]))

# The reference cache, temporary files, gnuplot's environment and divergent parameters: their
# groups live in cache_cases.py and use the helpers above.
import cache_cases  # noqa: E402

cache_cases.register(sys.modules[__name__])

# Renames that fail with EIO part-way through a run: io_error_cases.py.
import io_error_cases  # noqa: E402

GROUPS.update(io_error_cases.groups(sys.modules[__name__]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--tmp", required=True, help="scratch folder (emptied first)")
    parser.add_argument("--chapter", action="append", default=[], help="NAME=PATH")
    parser.add_argument("group", choices=["bad-input"] + sorted(GROUPS))
    parser.add_argument("which", nargs="?", help="the chapter, for bad-input")
    options = parser.parse_args()
    chapters = {name: str(Path(path).resolve())
                for name, path in (item.split("=", 1) for item in options.chapter)}
    tmp = fresh(Path(options.tmp).resolve())
    # The chapters' default reference cache: this group's, never the user's ~/.cache.
    os.environ["XDG_CACHE_HOME"] = str(fresh(Path(f"{tmp}-xdg-cache")))
    checks = Checks()
    for name, path in list(chapters.items()):
        if not os.access(path, os.X_OK):  # a failure, but the other chapters still run
            checks.case(name, [f"not built: no executable {path}"])
            del chapters[name]
    start = time.monotonic()
    if options.group == "bad-input" and options.which not in chapters:
        pass
    elif options.group == "bad-input":
        group_bad_input(chapters, tmp, checks, options.which)
    else:
        GROUPS[options.group](chapters, tmp, checks)
    for failure in checks.failures:
        print("FAIL", failure)
    print(f"{options.group} {options.which or ''}: {checks.cases} cases, "
          f"{len(checks.failures)} failures, {time.monotonic() - start:.1f} s")
    shutil.rmtree(tmp, ignore_errors=True)
    shutil.rmtree(os.environ["XDG_CACHE_HOME"], ignore_errors=True)
    return 1 if checks.failures else 0


if __name__ == "__main__":
    sys.exit(main())
