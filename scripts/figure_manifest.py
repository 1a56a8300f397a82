#!/usr/bin/env python3
"""docs/figures/manifest.json: what scripts/make-figures made each figure from, and the check
that the figures in docs/figures are still what it makes.

The manifest holds, per figure, the SHA-256 of the PNG and the run and file it was copied from,
and per run the command (as make-figures' runs list gives it) and every flag the run recorded
in its summary.json, defaults included (the seed among them).

    scripts/figure_manifest.py write SCRATCH [LABEL...]   after make-figures' runs: the figures
                                                       of the given runs (all when none) and
                                                       those runs' flags; the rest is kept
    scripts/figure_manifest.py check [BIN_DIR]          the figures against the manifest, the
                                                       manifest against make-figures' runs and,
                                                       given the chapter programs, against the
                                                       flags each program records today

Why not render again: the runs take minutes (the suite must stay fast), so the check proves
the three links that a stale figure breaks instead: the bytes in docs/figures are the bytes
make-figures copied (a hand-edited or half-regenerated figure fails), the runs it copied them
from are the runs make-figures makes now (a changed command fails), and each run's flags with
their defaults are those the chapter program takes today (`--print-flags`, which parses and
prints without running: a changed default fails). A change to the chapter code that keeps its
flags is not seen: that is what the chapter tests, which compare outputs across threads and
against closed forms, are for.
"""

import hashlib
import json
import os
import re
import subprocess
import sys

REPO = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FIGURE = re.compile(r"figures/([0-9][0-9]_[A-Za-z0-9_]*\.png)")


def sha256(path):
    with open(path, "rb") as file:
        return hashlib.sha256(file.read()).hexdigest()


def make_figures_plan(script_text):
    """make-figures' runs {label: command} and its figure sources {figure stem: (label, file)}."""
    runs = dict(re.findall(r'^\s*"([A-Za-z0-9-]+)\|([^"]+)"\s*$', script_text, re.MULTILINE))
    sources = {stem: (label, file) for stem, label, file in
               re.findall(r'^\s*\[([0-9A-Za-z_]+)\]="([A-Za-z0-9-]+):([^"]+)"\s*$', script_text,
                          re.MULTILINE)}
    return runs, sources


def referenced_figures(docs):
    """The figures chapter pages show (figures/NN_stem.png), from {page: text}."""
    return sorted({name for text in docs.values() for name in FIGURE.findall(text)})


def figure_source(figure, sources):
    """(run label, file in its folder) of a figure, as make-figures picks it."""
    stem = figure[:-len(".png")]
    if stem in sources:
        return sources[stem]
    number, rest = stem.split("_", 1)
    return f"ch{number}", rest + ".png"


def read_docs(folder):
    docs = {}
    for name in sorted(os.listdir(folder)):
        if name.endswith(".md"):
            with open(os.path.join(folder, name), encoding="utf-8") as file:
                docs[name] = file.read()
    return docs


def write(scratch, labels, repo=REPO):
    """Updates the manifest for the figures of `labels` (all runs when empty)."""
    path = os.path.join(repo, "docs", "figures", "manifest.json")
    try:
        with open(path, encoding="utf-8") as file:
            manifest = json.load(file)
    except FileNotFoundError:
        manifest = {"figures": {}, "runs": {}}
    with open(os.path.join(repo, "scripts", "make-figures"), encoding="utf-8") as file:
        runs, sources = make_figures_plan(file.read())
    made = {label for label in runs
            if os.path.isfile(os.path.join(scratch, label, "summary.json"))
            and (not labels or label in labels)}
    for label in sorted(made):
        with open(os.path.join(scratch, label, "summary.json"), encoding="utf-8") as file:
            flags = json.load(file)["flags"]
        manifest["runs"][label] = {"command": runs[label], "flags": flags}
    figures = referenced_figures(read_docs(os.path.join(repo, "docs")))
    for figure in figures:
        label, name = figure_source(figure, sources)
        target = os.path.join(repo, "docs", "figures", figure)
        if label in made and os.path.isfile(target):
            manifest["figures"][figure] = {"run": label, "file": name, "sha256": sha256(target)}
    # Only what the pages show and the runs it comes from stay.
    manifest["figures"] = {f: e for f, e in sorted(manifest["figures"].items()) if f in figures}
    used = {entry["run"] for entry in manifest["figures"].values()}
    manifest["runs"] = {r: e for r, e in sorted(manifest["runs"].items()) if r in used}
    temporary = path + ".tmp"
    with open(temporary, "w", encoding="utf-8") as file:
        file.write(json.dumps(manifest, indent=1, sort_keys=True) + "\n")
    os.replace(temporary, path)


def print_flags(bin_dir, command):
    """The flags the chapter program of `command` records today, from --print-flags."""
    words = command.split()
    program = os.path.join(bin_dir, os.path.basename(words[0]))
    done = subprocess.run([program, *words[1:], "--print-flags"], capture_output=True,
                          text=True, timeout=60, check=False)  # a parse, not a run: seconds
    if done.returncode != 0:
        return None, f"{program} --print-flags: exit {done.returncode}: {done.stderr.strip()}"
    return json.loads(done.stdout), None


def check(repo, manifest, script_text, docs, bin_dir=None):
    """Every way docs/figures has drifted from what make-figures makes, one line each."""
    problems = []
    runs, sources = make_figures_plan(script_text)
    for figure in referenced_figures(docs):
        entry = manifest["figures"].get(figure)
        path = os.path.join(repo, "docs", "figures", figure)
        if entry is None:
            problems.append(f"{figure}: a page shows it, the manifest does not list it "
                            "(run scripts/make-figures)")
            continue
        if not os.path.isfile(path):
            problems.append(f"{figure}: missing from docs/figures")
        elif sha256(path) != entry["sha256"]:
            problems.append(f"{figure}: its bytes are not those scripts/make-figures copied "
                            "(edited or copied by hand? run scripts/make-figures)")
        if (entry["run"], entry["file"]) != figure_source(figure, sources):
            problems.append(f"{figure}: made from {entry['run']}:{entry['file']}, but "
                            "make-figures now takes it from "
                            + ":".join(figure_source(figure, sources)))
    # A chapter figure no page shows is a leftover: nothing remakes it, and nobody reads it.
    shown = set(referenced_figures(docs))
    folder = os.path.join(repo, "docs", "figures")
    for name in sorted(os.listdir(folder)):
        if FIGURE.fullmatch("figures/" + name) and name not in shown:
            problems.append(f"{name}: no docs page shows it (remove it, or show it on a page)")
    for label, run in sorted(manifest["runs"].items()):
        if runs.get(label) != run["command"]:
            problems.append(f"run {label}: made with '{run['command']}', make-figures now runs "
                            f"'{runs.get(label)}'")
            continue
        if bin_dir is None:
            continue
        flags, error = print_flags(bin_dir, run["command"])
        if error:
            problems.append(f"run {label}: {error}")
        elif flags != run["flags"]:
            changed = sorted(set(flags.items()) ^ set(run["flags"].items()))
            problems.append(f"run {label}: its flags changed since the figures were made "
                            f"(now vs then: {changed}); run scripts/make-figures")
    return problems


def main(argv):
    if len(argv) >= 3 and argv[1] == "write":
        write(argv[2], set(argv[3:]))
        return 0
    if len(argv) in (2, 3) and argv[1] == "check":
        with open(os.path.join(REPO, "docs", "figures", "manifest.json"), encoding="utf-8") as f:
            manifest = json.load(f)
        with open(os.path.join(REPO, "scripts", "make-figures"), encoding="utf-8") as f:
            script_text = f.read()
        problems = check(REPO, manifest, script_text, read_docs(os.path.join(REPO, "docs")),
                         argv[2] if len(argv) == 3 else None)
        for line in problems:
            print(line)
        return 1 if problems else 0
    print("usage: scripts/figure_manifest.py write SCRATCH [LABEL...] | check [BIN_DIR]",
          file=sys.stderr)
    return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv))
