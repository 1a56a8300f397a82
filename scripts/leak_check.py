#!/usr/bin/env python3
"""The token-level leak check of a student kit: does any file of the kit show a solution it
asks for, or a later one, even with its variables renamed and its comments rewritten?

  scripts/leak_check.py aN KIT      compares KIT (made by scripts/make-assignment aN) against
                                    the solution regions and withheld files of aN and of every
                                    later assignment in the tree this script is in, and searches
                                    it for the written questions' keys of aN and later
                                    (tests/assignments/answers/key.py: make-assignment's
                                    key_leaks)

The C++ of every kit file (and every fenced code block of its Markdown pages) is cut into
tokens with comments and whitespace dropped; identifiers become one symbol, numbers another,
string and character literals a third; keywords and punctuation stay. A window of
k_window_tokens consecutive normalised tokens that also occurs in a reference (a stubbed
region's solution, a withheld file) is a match when its identifiers correspond one to one
(a consistent renaming: `cos_theta` -> `c` everywhere, never two names onto one). Windows that
also occur in a region the kit keeps (an earlier assignment's solution, released) are not
evidence. Each finding names the kit file, its lines and the reference it copies.
Exit status: 0 no leak, 1 leaks found (or a file unreadable), 2 bad arguments.
"""

import importlib.machinery
import importlib.util
import os
import re
import sys

# 25 tokens: about two statements (`beta *= material.brdf() * cos_theta_i / pdf();` alone is
# 14). Measured on the kits a1..a5: at 20, ordinary code (a pixel loop's lambda, the mean of a
# vector) matched answers 3-21 times per kit; at 25 only true near-copies did (a1.1's loop in
# the differential test and the disk benchmark, the cap sampler of light.hpp); at 30 a1.1's
# condensed loop slipped through, at 35 plain_path_tracer.hpp no longer matched a4.1's region
# itself. An answer under 25 tokens (a one-line pdf) is not checked: its copy cannot be told
# from ordinary code.
k_window_tokens = 25

KEYWORDS = set("""alignas alignof and asm auto bool break case catch char char16_t char32_t char8_t
class co_await co_return co_yield concept const consteval constexpr constinit const_cast continue
decltype default delete do double dynamic_cast else enum explicit export extern false float for
friend goto if inline int long mutable namespace new noexcept not nullptr operator or private
protected public register reinterpret_cast requires return short signed sizeof static
static_assert static_cast struct switch template this thread_local throw true try typedef typeid
typename union unsigned using virtual void volatile wchar_t while""".split())

TOKEN = re.compile(r"""
    (?P<comment>//[^\n]*|/\*.*?\*/)
  | (?P<pre>^[ \t]*\#[^\n]*(?:\\\n[^\n]*)*)
  | (?P<string>(?:u8|u|U|L)?R"(?P<delim>[^(\s]*)\(.*?\)(?P=delim)"|(?:u8|u|U|L)?"(?:\\.|[^"\\\n])*")
  | (?P<char>(?:u8|u|U|L)?'(?:\\.|[^'\\\n])+')
  | (?P<number>\.?\d(?:[\w.']|[eEpP][+-])*)
  | (?P<ident>[A-Za-z_]\w*)
  | (?P<punct>::|->\*?|\.\*|\+\+|--|<<=?|>>=?|<=>|[<>=!+\-*/%&|^]=|&&|\|\||\.\.\.|[{}()\[\];,.?:~!<>=+\-*/%&|^])
  | (?P<space>\s+)
  | (?P<other>.)
""", re.S | re.M | re.X)


_tokenized = {}  # (text, first line) -> tokens: a kit's files are mostly the tree's own


def tokenize(text, first_line=1):
    """[(normalised token, identifier or None, line)] of C++ text: comments, whitespace and
    preprocessor lines dropped. Names a copy can rename (variables, parameters) become "$";
    names it must keep to compile against the project (a called function, a member after . or
    ->, a namespace or class before ::, a type: capitalised) stay. The list is shared between
    calls with the same text: callers never change it."""
    known = _tokenized.get((text, first_line))
    if known is None:
        known = _tokenized[(text, first_line)] = _tokenize(text, first_line)
    return known


def _tokenize(text, first_line):
    raw, line = [], first_line
    for m in TOKEN.finditer(text):
        kind, value = m.lastgroup, m.group(0)
        if m.group("string") is not None:
            raw.append(('"', None, line))
        elif kind == "char":
            raw.append(("'", None, line))
        elif kind == "number":
            raw.append(("0", None, line))
        elif kind == "ident":
            raw.append((value, value, line))
        elif kind in ("punct", "other"):
            raw.append((value, None, line))
        line += value.count("\n")
    out = []
    for i, (token, name, at) in enumerate(raw):
        if name is None or name in KEYWORDS:
            out.append((token, None, at))
            continue
        before = raw[i - 1][0] if i else ""
        after = raw[i + 1][0] if i + 1 < len(raw) else ""
        fixed = after in ("(", "::", "<") or before in (".", "->", "::") or name[0].isupper()
        out.append((name, None, at) if fixed else ("$", name, at))
    return out


def markdown_code(text):
    """The tokens of the fenced code blocks of a Markdown page, with their lines in the page."""
    out, block, start = [], None, 0
    for number, line in enumerate(text.split("\n"), 1):
        if line.lstrip().startswith("```"):
            if block is None:
                block, start = [], number + 1
            else:
                out += tokenize("\n".join(block), start)
                block = None
        elif block is not None:
            block.append(line)
    return out


def file_tokens(path):
    with open(path, encoding="utf-8", errors="replace") as handle:
        text = handle.read()
    return markdown_code(text) if path.endswith(".md") else tokenize(text)


def renaming_is_consistent(a, b):
    """True when the identifiers of two windows of equal shape map one to one."""
    forward, backward = {}, {}
    for (_, x, _), (_, y, _) in zip(a, b):
        if x is None:
            continue
        if forward.setdefault(x, y) != y or backward.setdefault(y, x) != x:
            return False
    return True


def window_shapes(tokens):
    """The shape (normalised tokens) of every window of `tokens`, in order."""
    w, kinds = k_window_tokens, [t[0] for t in tokens]
    return [tuple(kinds[i:i + w]) for i in range(len(kinds) - w + 1)]


def shapes(texts):
    return {shape for tokens in texts for shape in window_shapes(tokens)}


def build_index(references):
    """{window shape: [(reference name, tokens, start)]} of every window of the references
    (name -> (tokens, kept shapes)) that is not among that reference's kept shapes."""
    index = {}
    for name, (tokens, kept_shapes) in references.items():
        for i, shape in enumerate(window_shapes(tokens)):
            if shape not in kept_shapes:
                index.setdefault(shape, []).append((name, tokens, i))
    return index


def find_in_tokens(tokens, index):
    """[(first line, last line, reference name)] of the stretches of `tokens` that copy a
    reference window, overlapping windows of the same reference merged."""
    w = k_window_tokens
    found = []
    for i, shape in enumerate(window_shapes(tokens)):
        window = tokens[i:i + w]
        for name, ref, j in index.get(shape, ()):
            if renaming_is_consistent(window, ref[j:j + w]):
                last = found[-1] if found else None
                if last and last[2] == name and last[3] >= i - 1:
                    found[-1] = (last[0], window[-1][2], name, i)
                else:
                    found.append((window[0][2], window[-1][2], name, i))
                break
    return [(a, b, name) for a, b, name, _ in found]


def scanned(rel):
    return rel.endswith((".hpp", ".cpp", ".h", ".cc", ".md"))


def find_leaks(kit, index):
    """[(kit-relative path, first line, last line, reference)] of every copy in the kit."""
    leaks = []
    for folder, dirs, names in os.walk(kit):
        dirs[:] = sorted(d for d in dirs if not d.startswith(("build", ".git")))
        for name in sorted(names):
            rel = os.path.relpath(os.path.join(folder, name), kit)
            if scanned(rel):
                for a, b, ref in find_in_tokens(file_tokens(os.path.join(kit, rel)), index):
                    leaks.append((rel, a, b, ref))
    return leaks


def region_tokens(region, sources):
    lines = sources[region["file"]]
    return tokenize("\n".join(lines[region["begin"] + 1:region["end"]]), region["begin"] + 2)


def kit_references(assignment, tree, make):
    """{reference name: (tokens, kept shapes)} for the kit of `assignment`.

    The references: every region the kit stubs (the answers themselves) and every withheld file
    of its stubbed tasks (with a3's known-wrong recursions, never in a kit). Not evidence
    against an answer: a window of a region the kit keeps (an earlier assignment's, released),
    of a stub, or of a withheld file of released tasks only that the kit ships
    (render/path_tracer_plain_layers.hpp in a5). Not evidence against a withheld region or file
    either: a window of a file that ships in every kit (regions cut out): such files are
    scaffolding the lanes engines and reference tracers share with the rest of the project."""
    files, sources, regions = tree
    stubbed = make.stubbed_tasks(assignment, regions)
    first = int(assignment[1:])
    released = [f for f, tasks in make.WITHHELD_FILES.items()
                if all(int(t[1:].split(".")[0]) < first for t in tasks)]
    kept = [region_tokens(r, sources) for r in regions if not make.is_stubbed(r, stubbed)]
    kept += [tokenize(make.expand_stub(r)) for r in regions if make.is_stubbed(r, stubbed)]
    kept += [file_tokens(os.path.join(make.ROOT, f)) for f in released]
    # the marked files as this kit has them: their answers replaced, their other code shipped
    kept += [tokenize("\n".join(make.rewrite(lines, [r for r in regions if r["file"] == f], stubbed)))
             for f, lines in sources.items()]
    answer_kept = shapes(kept)
    always = set(make.WITHHELD_FILES) | {"tests/render/recursive_estimator_known_bugs_a3.hpp"}
    scaffolding = []
    for f in files:
        if f.endswith(make.SOURCE_EXT) and f.startswith(("common/", "chapters/", "tests/")) \
                and f not in always and not f.startswith(make.EXCLUDED):
            if f in sources:
                lines, cut = list(sources[f]), [r for r in regions if r["file"] == f]
                for r in cut:
                    lines[r["begin"]:r["end"] + 1] = [""] * (r["end"] + 1 - r["begin"])
                scaffolding.append(tokenize("\n".join(lines)))
            else:
                scaffolding.append(file_tokens(os.path.join(make.ROOT, f)))
    counts = {}
    for tokens in scaffolding:
        for shape in shapes([tokens]):
            counts[shape] = counts.get(shape, 0) + 1
    # an idiom two files of every kit share (a signature, the closest-hit preamble) is no answer
    answer_kept |= {shape for shape, n in counts.items() if n >= 2}
    support_kept = answer_kept | set(counts)

    references = {}
    for r in regions:
        if make.is_stubbed(r, stubbed):
            name = f"{r['task']}{' (withheld)' if r['withheld'] else ''} {r['file']}:{r['begin'] + 2}"
            references[name] = (region_tokens(r, sources), support_kept if r["withheld"] else answer_kept)
    withheld = [f for f, tasks in make.WITHHELD_FILES.items() if tasks & stubbed]
    if "a3.1" in stubbed:
        withheld.append("tests/render/recursive_estimator_known_bugs_a3.hpp")  # a3's recursion but for one line
    for f in withheld:
        path = os.path.join(make.ROOT, f)
        if os.path.isfile(path):
            references[f"withheld file {f}"] = (file_tokens(path), support_kept)
    return references


def load_make_assignment(root):
    path = os.path.join(root, "scripts", "make-assignment")
    loader = importlib.machinery.SourceFileLoader("make_assignment", path)
    module = importlib.util.module_from_spec(importlib.util.spec_from_loader(loader.name, loader))
    loader.exec_module(module)
    return module


# Copies known and not yet removed: (kit file, task) -> why it still ships. Each is printed
# on every run, so that it stays in view until a `withheld` region removes it.
KNOWN_OPEN = {}  # none: sample_sphere_cap (a2.1 and a2.3 at other heights) is withheld


def split_known(leaks):
    """(leaks, known open copies) by KNOWN_OPEN."""
    known = [l for l in leaks if (l[0], l[3].split()[0]) in KNOWN_OPEN]
    return [l for l in leaks if l not in known], known


def report(leaks):
    return "\n".join(f"{rel}:{a}-{b}: copies {ref}" for rel, a, b, ref in leaks)


def main():
    args = sys.argv[1:]
    if len(args) != 2 or not re.fullmatch(r"a\d+", args[0]):
        print("leak_check: usage: leak_check.py aN KIT", file=sys.stderr)
        sys.exit(2)
    assignment, kit = args
    if not os.path.isdir(kit):
        print(f"leak_check: {kit}: not a folder", file=sys.stderr)
        sys.exit(1)
    make = load_make_assignment(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    tree = make.read_tree()
    if assignment not in {r["assignment"] for r in tree[2]}:
        print(f"leak_check: no markers of {assignment} in the tree", file=sys.stderr)
        sys.exit(2)
    references = kit_references(assignment, tree, make)
    leaks, known = split_known(find_leaks(kit, build_index(references)))
    for rel, a, b, ref in known:
        print(f"leak_check {assignment}: known, still open: {rel}:{a}-{b} copies {ref} "
              f"({KNOWN_OPEN[(rel, ref.split()[0])]})")
    keys = make.key_leaks(assignment, kit)
    if keys:
        print(f"leak_check {assignment}: {len(keys)} answers of the written questions' key in {kit}:\n  "
              + "\n  ".join(keys))
    if leaks:
        print(f"leak_check {assignment}: {len(leaks)} copies of a solution in {kit}:\n{report(leaks)}")
    if leaks or keys:
        sys.exit(1)
    print(f"leak_check {assignment}: no window of {k_window_tokens} tokens of {len(references)} "
          f"solutions and withheld files in {kit}, and no answer of the key")


if __name__ == "__main__":
    main()
