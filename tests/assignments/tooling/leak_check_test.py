#!/usr/bin/env python3
"""scripts/leak_check.py finds a copied answer whatever its names and comments, finds
render/path_tracer_plain_layers.hpp (a4.1's loop on other helpers) against a4.1's region itself, and
flags no ordinary code. Run: leak_check_test.py ROOT (CTest label unit, about a second)."""

import functools
import os
import re
import shutil
import sys
import tempfile
import unittest

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))
sys.dont_write_bytecode = True  # no __pycache__ left in the tree
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import leak_check  # noqa: E402

MAKE = leak_check.load_make_assignment(ROOT)
TREE = MAKE.read_tree()


def region_text(task):
    files, sources, regions = TREE
    r = next(r for r in regions if r["task"] == task and not r["withheld"] and r["end"] - r["begin"] > 3)
    return "\n".join(sources[r["file"]][r["begin"] + 1:r["end"]])


@functools.lru_cache(maxsize=None)
def references_of(assignment):
    return leak_check.kit_references(assignment, TREE, MAKE)


def leaks_in(assignment, files, drop=()):
    """Findings of the check of `assignment` on a folder holding `files` (path -> text),
    without the references whose names contain one of `drop`."""
    references = {k: v for k, v in references_of(assignment).items()
                  if not any(d in k for d in drop)}
    folder = tempfile.mkdtemp(prefix="mcrt-leak-")
    try:
        for rel, text in files.items():
            os.makedirs(os.path.dirname(os.path.join(folder, rel)), exist_ok=True)
            with open(os.path.join(folder, rel), "w") as f:
                f.write(text)
        return leak_check.find_leaks(folder, leak_check.build_index(references))
    finally:
        shutil.rmtree(folder)


class LeakCheck(unittest.TestCase):
    def test_renamed_copy_with_new_comments_is_caught(self):
        text = region_text("a4.1")
        for old, new in (("radiance", "acc"), ("beta", "throughput"), ("bounce", "k"),
                         ("material", "m"), ("cos_theta_i", "c"), ("local", "dir_local"),
                         ("hit", "h"), ("wi", "w_in")):
            text = re.sub(rf"\b{old}\b", new, text)
        text = re.sub(r"//.*", "// my own words", text).replace("  ", "\t")
        self.assertNotIn("beta", text)
        copy = ("#pragma once\nnamespace mine {\ninline Color trace(const Scene& scene, Ray ray, "
                "int max_depth, Rng& rng, RayCount& count) {\n" + text + "\n}\n}\n")
        found = leaks_in("a4", {"tests/mine.hpp": copy})
        self.assertIn("a4.1", {ref.split()[0] for _, _, _, ref in found}, found)
        # the same text in a Markdown page's code block too
        found = leaks_in("a4", {"docs/page.md": "Text.\n```cpp\n" + copy + "```\n"})
        self.assertTrue(found)

    def test_plain_path_tracer_is_caught_against_a4_1_itself(self):
        with open(os.path.join(ROOT, "tests/render/path_tracer_plain_layers.hpp")) as f:
            text = f.read()
        # without its own withheld-file entry: the answer's region alone must find it
        for kit in ("a2", "a4"):
            found = leaks_in(kit, {"tests/render/path_tracer_plain_layers.hpp": text},
                             drop=("plain_path_tracer",))
            self.assertIn("a4.1", {ref.split()[0] for _, _, _, ref in found}, (kit, found))
        # a5 releases a4.1: the same file is no leak there
        self.assertEqual(leaks_in("a5", {"tests/render/path_tracer_plain_layers.hpp": text}), [])

    def test_ordinary_code_is_not_flagged(self):
        files = {}
        for rel in ("common/geometry/sphere.hpp", "common/render/scene.hpp", "common/io/table.cpp",
                    "tests/geometry/camera_test.cpp", "chapters/05_path_tracer/main.cpp",
                    "common/render/render.hpp", "docs/architecture.md", "docs/01_ray_tracing.md"):
            with open(os.path.join(ROOT, rel)) as f:
                files[rel] = f.read()
        for kit in ("a1", "a4"):
            self.assertEqual(leaks_in(kit, files), [], kit)

    def test_comments_strings_and_names_are_normalised(self):
        a = leak_check.tokenize('x = f(y) + 2.5; // note\n/* block */ s = "text";')
        b = leak_check.tokenize('u = f(v) + 7;\ns = "other";')
        self.assertEqual([t[0] for t in a], [t[0] for t in b])
        self.assertTrue(leak_check.renaming_is_consistent(a, b))
        # two names onto one is no renaming
        c = leak_check.tokenize('x = f(x) + 7;\ns = "other";')
        self.assertFalse(leak_check.renaming_is_consistent(a, c))


if __name__ == "__main__":
    unittest.main()
