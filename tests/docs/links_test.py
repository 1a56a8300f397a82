#!/usr/bin/env python3
"""Every relative link of the docs pages, chapters and assignments alike (docs/*.md,
docs/assignments/*.md), still works once scripts/render-docs has rendered them into OUT/docs/:

  - a link to a page (NAME.md, rendered NAME.html beside it) reaches a page that exists, and its
    #anchor is a heading of that page (GitHub's identifiers, as pandoc's gfm reader makes them);
  - a link or image into figures/ reaches a file there (render-docs copies figures/);
  - no other relative link: render-docs would point it back into the source tree, out of OUT,
    where a gallery copied or served on its own cannot follow (the assignments README linked
    fairness.json so).

    links_test.py REPO_ROOT
"""

import os
import re
import sys
import unittest

REPO = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.getcwd()
DOCS = os.path.join(REPO, "docs")

CODE = re.compile(r"```.*?```|`[^`\n]+`", re.S)
MATHS = re.compile(r"\$\$.*?\$\$|\$[^$]+?\$", re.S)  # [a](b) in maths is no link
# [text](target) and ![alt](target), the target up to a space or the closing bracket
LINK = re.compile(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^#{1,6}\s+(.+?)\s*#*\s*$", re.M)
HTML_ID = re.compile(r"\bid=\"([^\"]+)\"")


def pages():
    found = []
    for folder in (DOCS, os.path.join(DOCS, "assignments")):
        if os.path.isdir(folder):
            found += [os.path.join(folder, name) for name in sorted(os.listdir(folder))
                      if name.endswith(".md")]
    return found


def anchor(heading):
    """GitHub's identifier of a heading: formatting marks dropped, lower case, punctuation
    other than - and _ removed, spaces to hyphens."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link keeps its text
    text = re.sub(r"[`*$\\]", "", text).lower()
    text = re.sub(r"[^\w\- ]", "", text)
    return text.replace(" ", "-")


def anchors_of(path, cache):
    if path not in cache:
        with open(path, encoding="utf-8") as file:
            text = CODE.sub("", file.read())
        names, seen = set(), {}
        for heading in HEADING.findall(text):
            name = anchor(heading)
            count = seen.get(name, 0)
            names.add(name if count == 0 else f"{name}-{count}")  # repeated headings: -1, -2
            seen[name] = count + 1
        cache[path] = names | set(HTML_ID.findall(text))
    return cache[path]


def problems_of(path, text, cache):
    rel = os.path.relpath(path, REPO)
    out = []
    blank = lambda m: re.sub(r"[^\n]", " ", m.group(0))  # lines keep their numbers
    for match in LINK.finditer(MATHS.sub(blank, CODE.sub(blank, text))):
        target = match.group(1)
        line = text.count("\n", 0, match.start()) + 1
        if re.match(r"^[A-Za-z][\w+.-]*:", target) or target.startswith("//"):
            continue  # a URL: not this test's
        where, _, fragment = target.partition("#")
        if not where:
            resolved = path
        else:
            resolved = os.path.normpath(os.path.join(os.path.dirname(path), where))
            inside_docs = resolved.startswith(DOCS + os.sep)
            figure = inside_docs and os.path.relpath(resolved, DOCS).startswith("figures" + os.sep)
            if not (where.endswith(".md") and inside_docs) and not figure:
                out.append(f"{rel}:{line}: link {target!r} is neither a docs page nor a figure: "
                           "rendered, it would point out of the output folder")
                continue
            if not os.path.isfile(resolved):
                out.append(f"{rel}:{line}: link {target!r} reaches no file")
                continue
        if fragment and resolved.endswith(".md") and fragment not in anchors_of(resolved, cache):
            out.append(f"{rel}:{line}: link {target!r}: no heading #{fragment} in "
                       f"{os.path.relpath(resolved, REPO)}")
    return out


class TheLinksTest(unittest.TestCase):
    def test_every_relative_link_works_rendered(self):
        cache, problems = {}, []
        for path in pages():
            with open(path, encoding="utf-8") as file:
                problems += problems_of(path, file.read(), cache)
        self.assertEqual(problems, [], "\n" + "\n".join(problems))

    def test_the_assignments_pages_are_checked(self):
        names = [os.path.relpath(p, DOCS) for p in pages()]
        if os.path.isdir(os.path.join(DOCS, "assignments")):
            self.assertTrue(any(n.startswith("assignments" + os.sep) for n in names))


class TheCheckTest(unittest.TestCase):
    def check(self, text, name="assignments/x.md"):
        return problems_of(os.path.join(DOCS, name), text, {})

    def test_a_link_into_the_source_tree_fails(self):
        # the old assignments README's link, rendered ../../../docs/assignments/fairness.json
        found = self.check("the file [fairness.json](fairness.json) holds")
        self.assertEqual(len(found), 1)
        self.assertIn("neither a docs page nor a figure", found[0])

    def test_a_missing_page_and_a_missing_anchor_fail(self):
        self.assertIn("reaches no file", self.check("[a](../99_nothing.md)")[0])
        found = self.check("[a](../07_importance_sampling.md#no-such-heading)")
        self.assertIn("no heading #no-such-heading", found[0])

    def test_a_page_heading_and_a_figure_pass(self):
        self.assertEqual(self.check(
            "[a](../07_importance_sampling.md#building-a-sampler-from-a-pdf-the-inversion-method) "
            "and [b](README.md)", "assignments/a2.md"), [])
        self.assertEqual(self.check("![c](figures/02_points.png) `[d](nowhere.json)`",
                                    "02_disk_area.md"), [])

    def test_urls_are_left_alone(self):
        self.assertEqual(self.check("[pbrt](https://pbrt.org/)"), [])


if __name__ == "__main__":
    unittest.main(verbosity=2)
