#!/usr/bin/env python3
"""The pages keep docs/notation.md's one-symbol-one-meaning: every page links the table at its
top, and no maths span brings back a meaning the table moved to another letter.

    notation_test.py REPO_ROOT

Only maths ($...$ and $$...$$) outside code is checked: code keeps the names the program uses
(`k_disk_hit_probability`, a CSV column `k`), and prose words are not symbols. Each rule below
is a letter the lecture uses twice, with the pages where its other meaning must not appear.
And every letter the pages' maths uses is in the table (a subscripted symbol counts by its
letters, so the check is that no letter goes undocumented, not that every subscript is listed).
"""

import os
import re
import sys
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()

CODE = re.compile(r"```.*?```|`[^`\n]+`", re.S)
MATHS = re.compile(r"\$\$.*?\$\$|\$[^$]+?\$", re.S)


def letter(name):
    """A maths token that is the letter alone: not part of a word or a command (\\frac, \\rho),
    not the stem of a subscripted symbol (f_r, I_l, N_{\\mathrm{lights}})."""
    return r"(?<![A-Za-z\\])" + name + r"(?![A-Za-z_])"


CHAPTERS = [f"{name}" for name in ("01_ray_tracing.md", "02_disk_area.md",
                                   "03_trapezoid_vs_mc.md", "04_recursive_nk.md",
                                   "05_path_tracer.md", "06_russian_roulette.md",
                                   "07_importance_sampling.md", "08_next_event_estimation.md",
                                   "09_stratified_qmc.md")]
ALL = CHAPTERS + ["answers.md", "probability-recap.md", "under-the-hood.md"]
# The assignments' handouts and README keep the same symbols (a kit holds one handout only).
HANDOUTS = [f"assignments/{name}" for name in ("README.md", "a1.md", "a2.md", "a3.md", "a4.md",
                                                "a5.md", "a6.md")]

# (pattern, pages, what to write instead)
RULES = [
    (r"(?<![A-Za-z\\])V\s*(?:\\[Bb]ig)?\[", ALL + HANDOUTS,
     "variance is \\mathrm{Var}[...]; V is visibility"),
    (r"(?<![A-Za-z\\])V_", ALL + HANDOUTS, "a ball's volume is \\lvert B_D\\rvert; V is visibility"),
    (r"\\rho", ALL + HANDOUTS, "the albedo is a"),
    (r"T_n", ALL + HANDOUTS, "the trapezoid rule is Q_n; T is the transport operator"),
    (letter("k"), ["02_disk_area.md", "03_trapezoid_vs_mc.md", "09_stratified_qmc.md",
                   "probability-recap.md",
                   "assignments/a1.md"],
     "the dimension is D; k is the depth"),
    (letter("p"), ["02_disk_area.md", "assignments/a1.md"],
     "the disk's hit probability is eta; p is a pdf"),
    (letter("q"), ["02_disk_area.md"], "the ball's fraction of the cube is eta_D; q is roulette's"),
    (letter("T"), ["02_disk_area.md", "03_trapezoid_vs_mc.md"],
     "trials are K, the trapezoid rule Q_n; T is the transport operator"),
    (letter("I"), ["01_ray_tracing.md", "04_recursive_nk.md"],
     "the point light's intensity is I_l, the identity operator 1; I is an integral's value"),
    (letter("A") + "|" + letter("B"), ["04_recursive_nk.md", "05_path_tracer.md",
                                        "07_importance_sampling.md"],
     "two renders are X and X'; A is a light's area"),
    (letter("f"), ["06_russian_roulette.md"], "the throughput floor is q_min; f is an integrand"),
    (letter("M"), ["06_russian_roulette.md"], "roulette's survivals are G; M is the disk's hit count"),
    (r"\\mu", ["07_importance_sampling.md"], "cos(theta) as a variable is z; mu is a mean"),
    (letter("N"), ["08_next_event_estimation.md"],
     "the number of lights is N_lights; N is the samples of one estimate"),
    (letter("R") + "|" + letter("h"), ["08_next_event_estimation.md"],
     "a sphere light's radius is r_light, its cap's depth h_cap"),
]

# Every page of the lessons links the table near its top.
LINKED = CHAPTERS + ["answers.md", "probability-recap.md", "under-the-hood.md", "index.md"]
TOP_LINES = 5


def maths_spans(text):
    """(line number, span) of every maths span outside code."""
    spans = []
    for piece in re.split(r"(```.*?```|`[^`\n]+`)", text, flags=re.S):
        if CODE.fullmatch(piece or "x"):
            continue
        for match in MATHS.finditer(piece):
            spans.append(match.group())
    return spans


def line_of(text, span):
    return text[:text.find(span)].count("\n") + 1


def problems(pages):
    """pages: {name: text}. One line per maths span that breaks a rule."""
    found = []
    for pattern, names, instead in RULES:
        for name in names:
            if name not in pages:
                continue
            for span in maths_spans(pages[name]):
                if re.search(pattern, span):
                    found.append(f"{name}:{line_of(pages[name], span)}: {span.strip()} ({instead})")
    return found


def unlinked(pages):
    return [name for name in LINKED if name in pages and
            "(notation.md)" not in "\n".join(pages[name].split("\n")[:TOP_LINES])]


def read_pages():
    pages = {}
    for name in set(ALL + LINKED + HANDOUTS):
        path = os.path.join(REPO, "docs", name)
        if name in HANDOUTS and not os.path.isfile(path):
            continue  # a kit ships its own handout only
        with open(path, encoding="utf-8") as file:
            pages[name] = file.read()
    return pages


# The figures' and the gallery's words: the text of the plots' labels and legends (the string
# literals of chapters/*/plots.hpp, gnuplot's) and of scripts/make-gallery (its captions, checks
# and conclusions) is plain text, not maths, so the moved meanings are matched as written there.
PLAIN_RULES = [
    (r"\bp\s*\(\s*1\s*-\s*p\s*\)", "the disk's hit probability is eta: eta(1-eta)"),
    (r"\|\s*T\s*-\s*I\s*\||\bT_n\b", "the trapezoid rule is Q_n"),
    (r"\bdimension k\b|\bk-ball|-[12]/k\b|\b2\^k\b", "the dimension is D; k is the depth"),
    (r"\bV_(?:k|\{)", "a ball's volume is |B_D|"),
    (r"\\u03c1|\u03c1|\brho\b", "the albedo is a"),
]
STRING = re.compile(r'"(?:[^"\\\n]|\\.)*"')


def text_sources():
    """{path: text}: the string literals of every chapter's plots.hpp (comments left out: they
    name the code's variables) and scripts/make-gallery's source."""
    sources = {}
    chapters = os.path.join(REPO, "chapters")
    for folder in sorted(os.listdir(chapters)) if os.path.isdir(chapters) else []:
        path = os.path.join(chapters, folder, "plots.hpp")
        if os.path.isfile(path):
            with open(path, encoding="utf-8") as file:
                code = "\n".join(line for line in file.read().splitlines()
                                 if not line.lstrip().startswith("//"))
            sources[os.path.relpath(path, REPO)] = "\n".join(STRING.findall(code))
    gallery = os.path.join(REPO, "scripts", "make-gallery")
    if os.path.isfile(gallery):
        with open(gallery, encoding="utf-8") as file:
            sources["scripts/make-gallery"] = "\n".join(STRING.findall(file.read()))
    return sources


def plain_problems(sources):
    found = []
    for path, text in sources.items():
        for pattern, instead in PLAIN_RULES:
            for match in re.finditer(pattern, text):
                found.append(f"{path}: '{match.group(0)}' ({instead})")
    return found


class ThePagesTest(unittest.TestCase):
    def test_no_page_brings_back_a_moved_meaning(self):
        found = problems(read_pages())
        self.assertEqual(found, [], "\n" + "\n".join(found))

    def test_the_handouts_are_checked(self):
        if os.path.isdir(os.path.join(REPO, "docs", "assignments")):
            self.assertTrue(any(name in read_pages() for name in HANDOUTS))

    def test_no_plot_label_or_gallery_text_brings_back_a_moved_meaning(self):
        sources = text_sources()
        self.assertIn("scripts/make-gallery", sources)
        found = plain_problems(sources)
        self.assertEqual(found, [], "\n" + "\n".join(found))

    def test_every_page_links_the_table_at_its_top(self):
        self.assertEqual(unlinked(read_pages()), [])

    def test_the_table_exists_and_names_every_replacement(self):
        with open(os.path.join(REPO, "docs", "notation.md"), encoding="utf-8") as file:
            table = file.read()
        for symbol in ("\\mathrm{Var}", "\\lvert B_D\\rvert", "Q_n", "\\eta_D", "I_l",
                       "X_{\\mathrm{ref}}", "q_{\\min}", "N_{\\mathrm{lights}}", "r_{\\mathrm{light}}",
                       "h_{\\mathrm{cap}}", "$K$", "$G$", "$z$", "$D$"):
            self.assertIn(symbol, table)


GREEK = re.compile(r"\\(alpha|beta|gamma|delta|epsilon|varepsilon|zeta|eta|theta|vartheta|iota|"
                   r"kappa|lambda|mu|nu|xi|pi|rho|sigma|tau|upsilon|phi|varphi|chi|psi|omega|"
                   r"Gamma|Delta|Theta|Lambda|Xi|Pi|Sigma|Phi|Psi|Omega)(?![A-Za-z])")


def letters(text):
    """The letters (Latin, and Greek commands) that a text's maths uses as symbols."""
    found = set()
    for span in maths_spans(text):
        span = re.sub(r"\\(?:mathrm|text|operatorname|mathbb)\{[^}]*\}", " ", span)
        found |= {"\\" + name for name in GREEK.findall(span)}
        span = re.sub(r"\\[A-Za-z]+", " ", span)
        found |= set(re.findall(r"(?<![A-Za-z])[A-Za-z](?![A-Za-z])", span))
    return found


class TheTableTest(unittest.TestCase):
    def test_every_letter_a_page_uses_is_in_the_table(self):
        with open(os.path.join(REPO, "docs", "notation.md"), encoding="utf-8") as file:
            table = letters(file.read())
        pages = read_pages()
        missing = {name: sorted(letters(pages[name]) - table) for name in ALL}
        self.assertEqual({name: found for name, found in missing.items() if found}, {})


class TheCheckTest(unittest.TestCase):
    def test_a_moved_meaning_is_caught(self):
        pages = {"02_disk_area.md": "the $k$-ball fills $q = V_k/2^k$ and $V[M] = Np(1-p)$"}
        found = problems(pages)
        self.assertTrue(any("D; k is the depth" in line for line in found), found)
        self.assertTrue(any("eta_D" in line for line in found), found)
        self.assertTrue(any("\\mathrm{Var}" in line for line in found), found)
        self.assertTrue(any("B_D" in line for line in found), found)

    def test_a_moved_meaning_in_a_handout_is_caught(self):
        # the old a1 handout
        found = problems({"assignments/a1.md": "$V[4M/N] = 16 p(1-p)/N$, $T_n = h$, "
                                               "$p_k = V_k/2^k$",
                          "assignments/a5.md": "the albedo $\\rho$"})
        for expected in ("\\mathrm{Var}", "Q_n", "eta; p is a pdf", "D; k is the depth",
                         "B_D", "albedo is a"):
            self.assertTrue(any(expected in line for line in found), (expected, found))

    def test_a_moved_meaning_in_a_label_or_caption_is_caught(self):
        # the old legends and gallery texts, as string literals
        sources = {"plots.hpp": "\"title 'theory 4 sqrt(p(1-p)/N)'\" \"trapezoid |T - I|\" "
                                "\"dimension k\" \"rmse / V_{{{1}}}\"",
                   "make-gallery": "\"(\\u03c1/\\u03c0) Le A\" \"the k-ball\""}
        found = plain_problems(sources)
        self.assertEqual(len(found), 6, found)
        self.assertEqual(plain_problems({"x": "\"4 sqrt(\\u03b7(1-\\u03b7)/N) |Q_n - I| "
                                              "dimension D, depth k, |B_D|, 2^D\""}), [])

    def test_code_subscripts_and_commands_are_not_symbols(self):
        pages = {
            "02_disk_area.md": "`k_disk_hit_probability` and ```\nk = 1\n``` and $\\eta_D$",
            "06_russian_roulette.md": "$f_r \\cos\\theta / p$ and $\\frac{a}{b}$ and $\\max \\beta_j$",
            "01_ray_tracing.md": "$I_l(\\theta_l)$ and $\\int f$",
            "08_next_event_estimation.md": "$1/N_{\\mathrm{lights}}$, $h_{\\mathrm{cap}}$, $r^2$",
        }
        self.assertEqual(problems(pages), [])

    def test_the_line_of_a_problem_is_named(self):
        found = problems({"04_recursive_nk.md": "one\ntwo $(I - T)^{-1}$"})
        self.assertEqual(len(found), 1)
        self.assertTrue(found[0].startswith("04_recursive_nk.md:2: "), found)

    def test_letters_are_symbols_not_words_or_commands(self):
        self.assertEqual(letters("$\\frac{a}{\\rho} + \\mathrm{Var}[X]$ and `$k$`"),
                         {"a", "\\rho", "X"})

    def test_a_page_without_the_link_is_named(self):
        pages = {"index.md": "# Pages\n\ntext\n", "01_ray_tracing.md": "# 01\n\nSymbols: [notation](notation.md).\n"}
        self.assertEqual(unlinked(pages), ["index.md"])


if __name__ == "__main__":
    unittest.main()
