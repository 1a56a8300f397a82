#!/usr/bin/env python3
"""What a kit holds (scripts/make-assignment): the kit of aN stubs every task of aN and of every
later assignment and keeps the earlier ones' solutions; it is made of tracked files only, so a
solution kit or an autograder folder lying untracked in the tree never ships; files that are
near-copies of a stubbed task stay out. Run: kit_contents_test.py ROOT (CTest label unit)."""

import json
import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tree_copy  # noqa: E402

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))
ASSIGNMENTS = ["a1", "a2", "a3", "a4", "a5"]


def make(tree, *args):
    """(exit status, output) of the tree's make-assignment, run in `tree`."""
    return tree_copy.run_script(os.path.join(tree, "scripts/make-assignment"), list(args), tree)


def all_files(folder):
    return {os.path.relpath(os.path.join(d, f), folder) for d, _, fs in os.walk(folder) for f in fs}


class KitContents(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tree = tree_copy.copy_tree(ROOT)
        listed = make(cls.tree, "--list")[1]
        cls.tasks = sorted(line.split(":")[0] for line in listed.splitlines() if line.startswith("a"))

    @classmethod
    def tearDownClass(cls):
        tree_copy.remove(cls.tree)

    def test_untracked_solution_and_autograder_never_ship(self):
        # The sequence, with relative paths as the README shows them.
        self.assertEqual(make(self.tree, "a4", "--out", "sol4", "--solution")[0], 0)
        self.assertEqual(make(self.tree, "a2", "--autograder", "ag")[0], 0)
        with open(os.path.join(self.tree, "notes.txt"), "w") as f:
            f.write("an instructor's untracked note\n")
        status, output = make(self.tree, "a4", "--out", "kit4")
        self.assertEqual(status, 0, output)
        shipped = all_files(os.path.join(self.tree, "kit4"))
        self.assertFalse(sorted(f for f in shipped if f.startswith(("sol4/", "ag/")))[:5])
        self.assertNotIn("notes.txt", shipped)
        self.assertFalse([f for f in shipped if "hidden" in f.split("/")])

    def test_kit_stubs_its_own_and_every_later_assignment(self):
        for a in ASSIGNMENTS:
            with self.subTest(kit=a):
                out = os.path.join(self.tree, f"stubs-{a}")
                status, output = make(self.tree, a, "--out", out)
                self.assertEqual(status, 0, output)
                with open(os.path.join(out, ".assignment")) as f:
                    stubbed = set(json.load(f)["stubbed"])
                n = int(a[1:])
                self.assertEqual(stubbed, {t for t in self.tasks if int(t[1:].split(".")[0]) >= n})
                # a4.1's loop with a2.1's sampler in it: out of every kit that stubs either
                near_copy = os.path.exists(os.path.join(out, "tests/support/plain_path_tracer.hpp"))
                self.assertEqual(near_copy, n == 5)
                # the closest hit it used to hold stays, and so does the public test of aN
                self.assertTrue(os.path.exists(os.path.join(out, "tests/support/plain_closest_hit.hpp")))
                self.assertTrue(os.path.exists(os.path.join(out, f"tests/assignments/{a}/{a}_test.cpp")))
                tree_copy.remove(out)


if __name__ == "__main__":
    unittest.main()
