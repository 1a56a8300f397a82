#!/usr/bin/env python3
"""scripts/make-assignment and scripts/grade end in one line and a documented status, never a
traceback: a file given as --out (2), --out beside --autograder (2), an interruption (130,
leaving no kit and no staging folder, so that the same command then succeeds), cmake and git
missing from PATH (1). Run: script_failures_test.py ROOT (CTest label unit)."""

import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))


def run(*command, env=None):
    p = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    return p.returncode, p.stderr


class ScriptFailures(unittest.TestCase):
    def setUp(self):
        self.out = tempfile.mkdtemp(prefix="mcrt-script-failures-")

    def tearDown(self):
        shutil.rmtree(self.out, ignore_errors=True)

    def assertOneLine(self, text):
        self.assertNotIn("Traceback", text)
        self.assertEqual(len(text.strip().splitlines()), 1, text)

    def test_a_file_as_out_is_refused(self):
        path = os.path.join(self.out, "a-file")
        open(path, "w").close()
        status, err = run(os.path.join(ROOT, "scripts/make-assignment"), "a2", "--out", path)
        self.assertEqual(status, 2, err)
        self.assertOneLine(err)
        self.assertIn("--out", err)

    def test_out_beside_autograder_is_refused(self):
        status, err = run(os.path.join(ROOT, "scripts/make-assignment"), "a2", "--out",
                          os.path.join(self.out, "kit"), "--autograder", os.path.join(self.out, "ag"))
        self.assertEqual(status, 2, err)
        self.assertOneLine(err)
        self.assertEqual(os.listdir(self.out), [])

    def test_an_interrupted_kit_leaves_nothing_and_the_rerun_works(self):
        kit = os.path.join(self.out, "kit")
        command = [os.path.join(ROOT, "scripts/make-assignment"), "a2", "--out", kit]
        process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        # interrupted once it has started writing (its staging folder appears), or at 20 s
        for _ in range(400):
            if os.listdir(self.out) or process.poll() is not None:
                break
            time.sleep(0.05)
        process.send_signal(signal.SIGINT)
        err = process.communicate()[1]
        if process.returncode == 0:  # it finished first: a whole kit, which is allowed
            self.assertTrue(os.path.isfile(os.path.join(kit, ".assignment")))
            return
        self.assertEqual(process.returncode, 130, err)
        self.assertOneLine(err)
        self.assertEqual(os.listdir(self.out), [], "an interrupted run left something")
        status, err = run(*command)
        self.assertEqual(status, 0, err)

    def test_missing_tools_are_one_line(self):
        # PATH without git and cmake: python3 started by its full path
        env = dict(os.environ, PATH=self.out)
        status, err = run(sys.executable, os.path.join(ROOT, "scripts/grade"), "a2", "--build",
                          os.path.join(self.out, "grading"), env=env)
        self.assertEqual(status, 1, err)
        self.assertOneLine(err)


if __name__ == "__main__":
    unittest.main()
