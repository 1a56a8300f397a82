#!/usr/bin/env python3
"""What a kit holds (scripts/make-assignment): the kit of aN stubs every task of aN and of every
later assignment and keeps the earlier ones' solutions; it is made of tracked files only, so a
solution kit or an autograder folder lying untracked in the tree never ships; files that are
near-copies of a stubbed task stay out. Run: kit_contents_test.py ROOT (CTest label unit)."""

import json
import os
import sys
import unittest

sys.dont_write_bytecode = True  # no __pycache__ left in the tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tree_copy  # noqa: E402

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))
ASSIGNMENTS = ["a1", "a2", "a3", "a4", "a5", "a6", "a7"]


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
        # the sequence, with relative paths as the README shows them: a solution kit
        # and an autograder folder left untracked in the tree, then a kit
        cls.sequence = [make(cls.tree, "a4", "--out", "sol4", "--solution"),
                        make(cls.tree, "a2", "--autograder", "ag")]
        with open(os.path.join(cls.tree, "notes.txt"), "w") as f:
            f.write("an instructor's untracked note\n")
        cls.sequence.append(make(cls.tree, "a4", "--out", "kit4"))
        cls.tasks = sorted(line.split(":")[0] for line in listed.splitlines() if line.startswith("a"))

    @classmethod
    def tearDownClass(cls):
        tree_copy.remove(cls.tree)

    def test_untracked_solution_and_autograder_never_ship(self):
        for status, output in self.sequence:
            self.assertEqual(status, 0, output)
        shipped = all_files(os.path.join(self.tree, "kit4"))
        self.assertFalse(sorted(f for f in shipped if f.startswith(("sol4/", "ag/")))[:5])
        self.assertNotIn("notes.txt", shipped)
        self.assertFalse([f for f in shipped if "hidden" in f.split("/")])

    def test_autograder_ships_only_its_own_hidden_test_and_fails_loudly(self):
        folder = os.path.join(self.tree, "ag3")
        status, output = make(self.tree, "a3", "--autograder", folder)
        self.assertEqual(status, 0, output)
        self.assertEqual(sorted(os.listdir(os.path.join(folder, "hidden"))),
                         ["CMakeLists.txt", "a3_answers_key.json", "a3_hidden_test.cpp"])
        self.assertFalse([f for f in all_files(os.path.join(folder, "kit")) if "hidden_test" in f])
        for name in ("setup.sh", "run_autograder"):
            with open(os.path.join(folder, name)) as f:
                text = f.read()
            self.assertIn("set -eu", text)
            self.assertNotIn("|| true", text)
            self.assertNotIn("-DMCRT_KIT", text)  # a -D flag nothing reads
        with open(os.path.join(folder, "run_autograder")) as f:
            text = f.read()
        # a clean copy of set-up's tree for every submission, before anything is copied in
        self.assertLess(text.index("rm -rf /autograder/work"), text.index("cp -a /autograder/base /autograder/work"))
        self.assertLess(text.index("cp -a /autograder/base"), text.index("--kit /autograder/submission"))
        tree_copy.remove(folder)

    def test_kit_stubs_its_own_and_every_later_assignment(self):
        # the generator's own functions (writing five kits would take a minute on a loaded
        # machine; the kit written above and scripts/test --kits write them)
        make = tree_copy.load_script(os.path.join(self.tree, "scripts/make-assignment"))
        files, sources, regions = make.read_tree()
        for a in ASSIGNMENTS:
            with self.subTest(kit=a):
                n = int(a[1:])
                stubbed = make.stubbed_tasks(a, regions)
                self.assertEqual(stubbed, {t for t in self.tasks if int(t[1:].split(".")[0]) >= n})
                withheld = make.withheld_files(files, stubbed)
                # a4.1's loop with a2.1's sampler in it: out of every kit that stubs either
                self.assertEqual("tests/render/path_tracer_plain_layers.hpp" in withheld, n < 5)
                # the closest hit it used to hold stays, and so does every public test
                self.assertNotIn("tests/support/plain_closest_hit.hpp", withheld)
                self.assertFalse([f for f in withheld if f.startswith("tests/assignments/")])
        with open(os.path.join(self.tree, "kit4/.assignment")) as f:
            self.assertEqual(set(json.load(f)["stubbed"]), make.stubbed_tasks("a4", regions))

    def test_kit_ships_no_helper_that_computes_a_task(self):
        # issue #44: an a1 submission scored full marks by calling estimate_disk_area_fast and
        # the Box versions of monte_carlo and trapezoid (a Segment is a 1-D Box); the a1, a2 and
        # a5 kits held a reference tracer with cosine bounces and roulette and a reference
        # renderer with a2.2's and a2.4's samplers written out.
        make = tree_copy.load_script(os.path.join(self.tree, "scripts/make-assignment"))
        files, sources, regions = make.read_tree()
        references = ("tests/render/scene_sphere_box_reference.hpp", "tests/render/path_tracer_checks.cpp")
        for a in ASSIGNMENTS:
            with self.subTest(kit=a):
                n = int(a[1:])
                stubbed = make.stubbed_tasks(a, regions)
                withheld = make.withheld_files(files, stubbed)
                for f in references:
                    # the sphere box's reference also writes the glass's Fresnel choice (a6.4, which
                    # every kit up to a6's stubs): it leaves the a6 kit too, and ships in a7's
                    # (a6's solutions are released by then)
                    self.assertEqual(f in withheld, n <= 5 or (n <= 6 and f.endswith("scene_sphere_box_reference.hpp")), f)

                def kit_text(f):
                    return "\n".join(make.rewrite(sources[f], [r for r in regions if r["file"] == f], stubbed))
                helpers = {  # file: (what its stub says, a line of the answer it must not hold)
                    "common/integration/disk_counter.cpp": ("withheld from this kit: count_in_disk", "inside_unit_disk("),
                    "common/integration/monte_carlo.hpp": ("withheld from this kit: monte_carlo on a Box", "rng.uniform()"),
                    "common/integration/quadrature.hpp": ("withheld from this kit: trapezoid on a Box", "end_weight("),
                }
                for f, (stub, answer) in helpers.items():
                    text = kit_text(f)
                    self.assertEqual(stub in text, n == 1, f)
                    self.assertEqual(answer in text, n > 1, f)
                # the comments above a2's stubs state the contract, not the formula (issue #44:
                # the a2 kit's said z = 1 - 2u0 and r = sqrt(u0))
                formulas = ("1 - 2 u0", "sqrt(u0)", "cos(theta) = u0", "1/(2 pi)", "1/(4 pi)", "cos(theta)/pi", "1/pi")
                for f in ("common/sampling/hemisphere.hpp", "common/sampling/sphere.hpp", "common/sampling/plane.hpp"):
                    found = [x for x in formulas if x in kit_text(f)]
                    self.assertEqual(bool(found), n > 2, f"{f}: {found}")


if __name__ == "__main__":
    unittest.main()
