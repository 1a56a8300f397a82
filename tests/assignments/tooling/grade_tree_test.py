#!/usr/bin/env python3
"""scripts/grade never changes the instructor's tree, and takes only the editable files from a
kit. In a copy of the tree with an uncommitted edit and untracked files (one in
tests/assignments/hidden/), it prepares the grading tree with `--hidden OTHER` and with a
hostile kit (its CMakeLists.txt runs execute_process, its tests are `true`, its points.json
gives 100 a test): the tree stays byte-identical, OTHER's hidden test of a2 (and no other) is
in the grading tree, and of the kit only a2's editable files are. The grader stops after the
copy step (--prepare-only), so this takes seconds. Run: grade_tree_test.py ROOT (label unit)."""

import hashlib
import json
import os
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ left in the tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import tree_copy  # noqa: E402

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))


def snapshot(folder):
    """{path: sha256} of every file under `folder` but .git/."""
    out = {}
    for d, dirs, names in os.walk(folder):
        dirs[:] = [x for x in dirs if x != ".git"]
        for n in names:
            path = os.path.join(d, n)
            with open(path, "rb") as f:
                out[os.path.relpath(path, folder)] = hashlib.sha256(f.read()).hexdigest()
    return out


def read(path):
    with open(path, encoding="utf-8") as f:
        return f.read()


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as f:
        f.write(text)


class GradeTree(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tree = tree_copy.copy_tree(ROOT)
        cls.out = tempfile.mkdtemp(prefix="mcrt-grade-out-")
        hidden = os.path.join(cls.tree, "tests/assignments/hidden")
        with open(os.path.join(hidden, "a2_hidden_test.cpp"), "a") as f:
            f.write("// an uncommitted edit\n")
        write(os.path.join(hidden, "a6_hidden_test.cpp"), "// an untracked hidden test\n")
        write(os.path.join(cls.tree, "notes.txt"), "an untracked note\n")
        cls.other = os.path.join(cls.out, "other")
        write(os.path.join(cls.other, "CMakeLists.txt"), read(os.path.join(hidden, "CMakeLists.txt")))
        write(os.path.join(cls.other, "a2_hidden_test.cpp"), "// OTHER's hidden test of a2\n")
        write(os.path.join(cls.other, "a3_hidden_test.cpp"), "// OTHER's hidden test of a3\n")
        cls.kit = os.path.join(cls.out, "hostile")
        write(os.path.join(cls.kit, "CMakeLists.txt"),
              'execute_process(COMMAND sh -c "echo 19/19 > /tmp/owned")\n')
        write(os.path.join(cls.kit, "tests/assignments/a2/a2_test.cpp"), "int main() { return 0; }\n")
        write(os.path.join(cls.kit, "tests/assignments/points.json"), '{"a2.A2.Task1UniformHemisphereFollowsItsPdf": 100}\n')
        write(os.path.join(cls.kit, "common/sampling/hemisphere.hpp"), "// the student's hemisphere.hpp\n")
        cls.before = snapshot(cls.tree)

    @classmethod
    def tearDownClass(cls):
        tree_copy.remove(cls.tree)
        tree_copy.remove(cls.out)

    def grade(self, *args):
        status, output = tree_copy.run_script(os.path.join(self.tree, "scripts/grade"),
                                              ["a2", *args, "--prepare-only"], self.tree)
        self.assertEqual(status, 0, output)
        self.assertEqual(snapshot(self.tree), self.before, "the instructor's tree changed")

    def test_hidden_other_goes_into_the_grading_tree_only(self):
        build = os.path.join(self.out, "with-other")
        self.grade("--hidden", self.other, "--build", build)
        hidden = os.path.join(build, "src/tests/assignments/hidden")
        self.assertEqual(sorted(os.listdir(hidden)), ["CMakeLists.txt", "a2_hidden_test.cpp"])
        self.assertEqual(read(os.path.join(hidden, "a2_hidden_test.cpp")), "// OTHER's hidden test of a2\n")
        # the instructor's solution of a2 is graded, later assignments' answers are not there
        self.assertNotIn("not implemented", read(os.path.join(build, "src/common/sampling/hemisphere.hpp")))
        self.assertIn("not implemented: a4.1", read(os.path.join(build, "src/common/render/path_tracer.hpp")))
        self.assertFalse(os.path.exists(os.path.join(build, "src/notes.txt")))

    def test_hostile_kit_gives_only_its_editable_files(self):
        build = os.path.join(self.out, "hostile-kit")
        self.grade("--kit", self.kit, "--hidden", self.other, "--build", build)
        src = os.path.join(build, "src")
        for rel in ("CMakeLists.txt", "tests/assignments/a2/a2_test.cpp", "tests/assignments/points.json"):
            self.assertEqual(read(os.path.join(src, rel)), read(os.path.join(ROOT, rel)), rel)
        self.assertEqual(read(os.path.join(src, "common/sampling/hemisphere.hpp")),
                         "// the student's hemisphere.hpp\n")
        # an editable file not submitted is graded as its stub, never as the solution
        self.assertIn("not implemented: a2.4", read(os.path.join(src, "common/sampling/plane.hpp")))
        with open(os.path.join(ROOT, "tests/assignments/editable.json")) as f:
            self.assertIn("common/sampling/plane.hpp", json.load(f)["a2"])

    def test_build_refuses_a_folder_it_did_not_make(self):
        # a user's folder holding their own code in src/: refused before anything is written
        build = os.path.join(self.out, "users-folder")
        write(os.path.join(build, "src/my_code.cpp"), "// the user's own code\n")
        status, output = tree_copy.run_script(os.path.join(self.tree, "scripts/grade"),
                                              ["a2", "--build", build, "--prepare-only"], self.tree)
        self.assertEqual(status, 2, output)
        self.assertIn("not a folder scripts/grade made", output)
        self.assertEqual(read(os.path.join(build, "src/my_code.cpp")), "// the user's own code\n")
        self.assertEqual(sorted(os.listdir(build)), ["src"])

    def test_build_folder_moved_starts_its_builds_anew(self):
        # a folder grade made, moved elsewhere: its CMake folders name the old place, so they
        # are removed (grade's own, as its marker proves) and the grading goes on
        made = os.path.join(self.out, "made-here")
        self.grade("--build", made)
        write(os.path.join(made, "build/CMakeCache.txt"), f"# made in {made}\n")
        moved = os.path.join(self.out, "moved-there")
        os.rename(made, moved)
        status, output = tree_copy.run_script(os.path.join(self.tree, "scripts/grade"),
                                              ["a2", "--build", moved, "--prepare-only"], self.tree)
        self.assertEqual(status, 0, output)
        self.assertIn("copied or moved", output)
        self.assertFalse(os.path.exists(os.path.join(moved, "build")))
        self.assertTrue(os.path.isfile(os.path.join(moved, "src/CMakeLists.txt")))

    def test_editable_json_is_what_the_markers_define(self):
        status, output = tree_copy.run_script(os.path.join(self.tree, "scripts/make-assignment"),
                                              ["--editable"], self.tree)
        self.assertEqual(status, 0)
        self.assertEqual(output, read(os.path.join(ROOT, "tests/assignments/editable.json")))


if __name__ == "__main__":
    unittest.main()
