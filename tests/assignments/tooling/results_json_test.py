#!/usr/bin/env python3
"""scripts/grade's results.json follows Gradescope's format (tests/assignments/results.schema.json)
and the course's rules, for a passing, a failing, a timed-out and a non-building submission:
every test listed with its full points (a failed build: each at 0, the compiler's errors once),
hidden tests shown only after publication, no visible total that counts them, a hanging test
costing only its own points, the written answers graded from their file (with the hidden
folder's key) and listed, whatever the build did. The grader runs on a tiny fake kit whose "build" and "tests" are
CMake scripts driven by the submitted file, so each case takes seconds.
Run: results_json_test.py ROOT (CTest label unit)."""

import json
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ left in the tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import schema_subset  # noqa: E402

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))
# The fake tests' time limit: the hanging test sleeps 30 s, far beyond it.
k_fake_timeout = 2

FAKE = {
    ".assignment": '{"assignment": "a9"}\n',
    "CMakeLists.txt": "cmake_minimum_required(VERSION 3.22)\nproject(fake NONE)\nenable_testing()\n"
                      "add_subdirectory(tests)\n",
    "tests/CMakeLists.txt": "add_subdirectory(assignments)\n",
    "tests/assignments/CMakeLists.txt": """
set(mode ${PROJECT_SOURCE_DIR}/src/student.txt)
add_custom_target(assignment_a9 ALL COMMAND ${CMAKE_COMMAND} -DMODE=${mode} -P ${CMAKE_CURRENT_SOURCE_DIR}/compile.cmake)
foreach(t IN ITEMS First Second)
  add_test(NAME a9.A9.${t} COMMAND ${CMAKE_COMMAND} -DMODE=${mode} -DSUITE=A9 -DWHICH=${t} -P ${CMAKE_CURRENT_SOURCE_DIR}/run.cmake)
  set_tests_properties(a9.A9.${t} PROPERTIES LABELS a9)
endforeach()
if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/hidden/CMakeLists.txt)
  include(${CMAKE_CURRENT_SOURCE_DIR}/hidden/CMakeLists.txt)
endif()
""",
    "tests/assignments/compile.cmake": """
file(READ ${MODE} mode)
if(mode MATCHES "broken")
  message(FATAL_ERROR "src/student.cpp:3:7: error: expected ';' before 'return'")
endif()
""",
    "tests/assignments/run.cmake": """
file(READ ${MODE} mode)
if(mode MATCHES "fail" AND WHICH STREQUAL "First")
  message(FATAL_ERROR "DIAGNOSIS: is your pdf off by a factor of 2?")
endif()
if(mode MATCHES "map" AND WHICH STREQUAL "Second")
  # a region test's output, as a4's and a6's print it whether they pass or fail
  message("other output\nregion error map: z = (your mean - reference) / standard error per region\n  y 0-3   +0.0  +30.4!\n  error map image: /tmp/fake-reports/a9/error_map.png\nlater output")
endif()
if(mode MATCHES "hang" AND WHICH STREQUAL "Second")
  execute_process(COMMAND ${CMAKE_COMMAND} -E sleep 30)
endif()
# a test that finished writes its report where GTEST_OUTPUT says, as gtest does; one that
# "leaves early" exits 0 without it
if(NOT (mode MATCHES "early" AND WHICH STREQUAL "First"))
  string(REGEX REPLACE "^xml:" "" dir "$ENV{GTEST_OUTPUT}")
  file(WRITE "${dir}/${SUITE}.${WHICH}.xml" "<testsuites><testsuite name='${SUITE}'><testcase name='${WHICH}' classname='${SUITE}' status='run' result='completed'/></testsuite></testsuites>\\n")
endif()
""",
    "tests/assignments/a9/a9_test.cpp": "TEST(A9, First) {}\nTEST(A9, Second) {}\n",
    "tests/assignments/points.json": '{"a9.A9.First": 2, "a9.A9.Second": 3, "a9-hidden.A9Hidden.Secret": 4}\n',
    "tests/assignments/editable.json": '{"a9": ["src/student.txt"]}\n',
    "src/student.txt": "stub\n",
}
HIDDEN = {
    "CMakeLists.txt": """
add_custom_target(assignment_a9_hidden ALL)
add_test(NAME a9-hidden.A9Hidden.Secret COMMAND ${CMAKE_COMMAND} -DMODE=${mode} -DSUITE=A9Hidden -DWHICH=Secret -P ${CMAKE_CURRENT_SOURCE_DIR}/run.cmake)
set_tests_properties(a9-hidden.A9Hidden.Secret PROPERTIES LABELS a9-hidden)
""",
    "a9_hidden_test.cpp": "TEST(A9Hidden, Secret) {}\n",
    # the written answers' key, as an autograder carries it: a number and a text
    "a9_answers_key.json": json.dumps({"assignment": "a9", "questions": [
        {"id": "x", "kind": "number", "points": 1, "prompt": "x", "answer": 0.5, "rel_tol": 1e-3,
         "hint": "h"},
        {"id": "why", "kind": "text", "points": 2, "prompt": "why", "rubric": ["1: because"]}]}),
}
WRITTEN = {"a9-written.complete": 0, "a9-written.x": 1, "a9-written.why": 0}


def write(folder, files):
    for rel, text in files.items():
        path = os.path.join(folder, rel)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(text)


class ResultsJson(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.mkdtemp(prefix="mcrt-results-")
        cls.kit = os.path.join(cls.tmp, "kit")
        write(cls.kit, FAKE)
        os.makedirs(os.path.join(cls.kit, "scripts"))
        for name in ("grade", "written_answers.py", "grading_sandbox.py", "sandbox-run"):
            shutil.copy2(os.path.join(ROOT, "scripts", name), os.path.join(cls.kit, "scripts", name))
        write(os.path.join(cls.tmp, "hidden"), HIDDEN)
        with open(os.path.join(ROOT, "tests/assignments/results.schema.json")) as f:
            cls.schema = json.load(f)

    @classmethod
    def tearDownClass(cls):
        shutil.rmtree(cls.tmp)

    def grade(self, mode):
        submission = os.path.join(self.tmp, f"submission-{mode}")
        write(submission, {"student.txt": mode + "\n", "answers.json": '{"x": 0.5, "why": "because"}\n'})
        results = os.path.join(self.tmp, f"{mode}.json")
        run = subprocess.run([sys.executable, os.path.join(self.kit, "scripts/grade"), "a9", "--kit",
                              submission, "--hidden", os.path.join(self.tmp, "hidden"),
                              "--gradescope", results], stdout=subprocess.PIPE,
                             stderr=subprocess.STDOUT, text=True,
                             env=dict(os.environ, MCRT_GRADE_TIMEOUT=str(k_fake_timeout)))
        with open(results) as f:
            r = json.load(f)
        self.assertEqual(schema_subset.errors(r, self.schema), [], json.dumps(r, indent=1))
        # the course's rules beyond the format
        self.assertNotIn("score", r)       # Gradescope sums the tests: no total of its own
        self.assertEqual(r["visibility"], "after_published")
        self.assertEqual({t["name"]: t["max_score"] for t in r["tests"]},
                         dict({"a9.A9.First": 2, "a9.A9.Second": 3, "a9-hidden.A9Hidden.Secret": 4}, **WRITTEN))
        for t in r["tests"]:
            self.assertEqual(t["visibility"], "visible" if t["name"] in ("a9.A9.First", "a9.A9.Second",
                                                                         "a9-written.complete")
                             else "after_published")
        # the written answers are read as data: graded whatever the build or the tests did
        written = {t["name"]: t for t in r["tests"] if t["name"] in WRITTEN}
        self.assertEqual(written["a9-written.x"]["score"], 1)
        self.assertEqual(written["a9-written.why"]["extra_data"]["rubric"], ["1: because"])
        self.assertIn("2 points of text answers are graded by hand", r["output"])
        return run, r, {t["name"]: t["score"] for t in r["tests"] if t["name"] not in WRITTEN}

    def test_passing(self):
        run, r, scores = self.grade("pass")
        self.assertEqual(run.returncode, 0, run.stdout)
        self.assertEqual(scores, {"a9.A9.First": 2, "a9.A9.Second": 3, "a9-hidden.A9Hidden.Secret": 4})
        self.assertIn("5 / 5", r["output"])  # the public total only: 9 would count the hidden

    def test_failing(self):
        run, r, scores = self.grade("fail")
        self.assertEqual(run.returncode, 1)
        self.assertEqual(scores["a9.A9.First"], 0)
        self.assertEqual(scores["a9.A9.Second"], 3)
        self.assertIn("DIAGNOSIS: is your pdf off by a factor of 2?", r["tests"][0]["output"])
        self.assertIn("3 / 5", r["output"])

    def test_leaving_early(self):
        # status 0 without gtest's report of the test (std::_Exit(0) in a submission): 0 points
        run, r, scores = self.grade("early")
        self.assertEqual(run.returncode, 1)
        self.assertEqual(scores, {"a9.A9.First": 0, "a9.A9.Second": 3, "a9-hidden.A9Hidden.Secret": 4})
        self.assertIn("ended before this test finished", r["tests"][0]["output"])

    def test_error_map_of_a_passing_test(self):
        # a passing region test keeps its error map (the text: always), and the map's image is
        # named on the console of a grading folder that stays, never in results.json (a student
        # on Gradescope cannot open the grader's files)
        run, r, scores = self.grade("map")
        self.assertEqual(scores["a9.A9.Second"], 3)
        second = next(t for t in r["tests"] if t["name"] == "a9.A9.Second")
        self.assertIn("region error map: z =", second["output"])
        self.assertIn("+30.4!", second["output"])
        self.assertNotIn("other output", second["output"])
        self.assertNotIn("later output", second["output"])
        self.assertNotIn("/tmp/fake-reports", json.dumps(r))
        self.assertIn("error map image: /tmp/fake-reports/a9/error_map.png", run.stdout)
        first = next(t for t in r["tests"] if t["name"] == "a9.A9.First")
        self.assertEqual(first["output"], "")  # a passing test without a map says nothing

    def test_timed_out(self):
        run, r, scores = self.grade("hang")
        self.assertEqual(scores, {"a9.A9.First": 2, "a9.A9.Second": 0, "a9-hidden.A9Hidden.Secret": 4})
        second = next(t for t in r["tests"] if t["name"] == "a9.A9.Second")
        self.assertIn(f"limit of {k_fake_timeout} s", second["output"])

    def test_not_building(self):
        run, r, scores = self.grade("broken")
        self.assertEqual(run.returncode, 1)
        self.assertEqual(set(scores.values()), {0})  # the written answer's point is counted above
        text = json.dumps(r)
        self.assertEqual(text.count("expected ';' before"), 1, text)  # the errors, once
        self.assertIn("src/student.cpp:3:7: error", r["output"])


if __name__ == "__main__":
    unittest.main()
