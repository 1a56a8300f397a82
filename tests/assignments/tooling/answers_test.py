#!/usr/bin/env python3
"""The written answers (scripts/written_answers.py, tests/assignments/answers/key.py) and the
course variants (scripts/make-assignment --variant): a correct, a wrong, a blank and a
malformed answers file graded; hand-graded questions listed with their rubric in a results.json
that validates; the key never in a kit (played: a key's answer planted in a kit is found by
make-assignment's check and by leak_check.py); the same secret gives the same autograder byte for byte, two secrets give
different answers to every numeric question and keep the public tests. Run: answers_test.py
ROOT (CTest label unit)."""

import filecmp
import json
import os
import re
import sys
import tempfile
import unittest

sys.dont_write_bytecode = True  # no __pycache__ left in the tree
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import schema_subset  # noqa: E402
import tree_copy  # noqa: E402

ROOT = os.path.abspath(sys.argv.pop(1)) if len(sys.argv) > 1 else os.path.abspath(
    os.path.join(os.path.dirname(__file__), "../../.."))
written = tree_copy.load_script(os.path.join(ROOT, "scripts/written_answers.py"))
key = tree_copy.load_script(os.path.join(ROOT, "tests/assignments/answers/key.py"))
# every assignment the key knows (a new one is covered once its questions are in key.py)
ASSIGNMENTS = sorted(key.QUESTIONS, key=lambda a: int(a[1:]))
grade_script = tree_copy.load_script(os.path.join(ROOT, "scripts/grade"))
with open(os.path.join(ROOT, "tests/assignments/results.schema.json")) as f:
    SCHEMA = json.load(f)


def graded(a, data, secret=None):
    return written.grade(a, data, key.questions(a, secret))


def auto_points(a):
    return sum(q["points"] for q in key.questions(a) if q["kind"] != "text")


class Grading(unittest.TestCase):
    def assert_valid(self, a, tests):
        results = grade_script.results_json(a, tests, False, "")
        self.assertEqual(schema_subset.errors(results, SCHEMA), [])

    def test_correct_answers_score_every_automatic_point(self):
        for a in ASSIGNMENTS:
            with self.subTest(a):
                tests = graded(a, key.solution_answers(a).encode())
                self.assertEqual(sum(t["score"] for t in tests), auto_points(a))
                self.assertEqual(sum(t["max_score"] for t in tests), auto_points(a))
                self.assert_valid(a, tests)

    def test_hand_graded_questions_are_listed_ungraded_with_their_rubric(self):
        for a in ASSIGNMENTS:
            text_questions = [q for q in key.questions(a) if q["kind"] == "text"]
            self.assertTrue(text_questions, a)  # every handout has one
            tests = {t["name"]: t for t in graded(a, key.solution_answers(a).encode())}
            for q in text_questions:
                t = tests[f"{a}-written.{q['id']}"]
                self.assertEqual((t["score"], t["max_score"]), (0, 0))  # not in the automatic total
                self.assertEqual(t["extra_data"]["manual_points"], q["points"])
                self.assertEqual(t["extra_data"]["rubric"], q["rubric"])
                for line in q["rubric"]:
                    self.assertIn(line, t["output"])
                self.assertEqual(t["visibility"], "after_published")  # the rubric only after grading
            manual = sum(q["points"] for q in text_questions)
            summary = grade_script.results_json(a, list(tests.values()), False, "")["output"]
            self.assertIn(f"{manual} points of text answers are graded by hand", summary)

    def test_wrong_numbers_and_letters_score_zero_with_a_diagnosis(self):
        for a in ASSIGNMENTS:
            answers = json.loads(key.solution_answers(a))
            for q in key.questions(a):
                if q["kind"] == "number":
                    answers[q["id"]] *= 1 + 10 * q["rel_tol"]  # 10 times the tolerance
                elif q["kind"] == "choice":
                    answers[q["id"]] = next(o for o in sorted(q["options"]) if o != q["answer"])
            tests = graded(a, json.dumps(answers).encode())
            self.assertEqual(sum(t["score"] for t in tests), 0, a)
            for t in tests:
                if t["max_score"]:
                    self.assertIn("DIAGNOSIS:", t["output"])
            # within the tolerance still scores (a 6-digit rounding is 5e-6 at most)
            near = json.loads(key.solution_answers(a))
            for q in key.questions(a):
                if q["kind"] == "number":
                    near[q["id"]] = float(f"{q['answer']:.6g}")
            self.assertEqual(sum(t["score"] for t in graded(a, json.dumps(near).encode())), auto_points(a))

    def test_blank_file_scores_zero_and_says_not_answered(self):
        for a in ASSIGNMENTS:
            with open(os.path.join(ROOT, f"tests/assignments/{a}/answers.json"), "rb") as f:
                blank = f.read()
            tests = graded(a, blank)
            self.assertEqual(sum(t["score"] for t in tests), 0)
            self.assertTrue(all("not answered" in t["output"] for t in tests), a)
            ids = [q["id"] for q in key.questions(a)]
            complete = written.completeness(a, blank, ids)
            self.assertEqual(complete["status"], "failed")
            self.assertIn(ids[0], complete["output"])
            self.assertEqual(written.completeness(a, key.solution_answers(a).encode(), ids)["status"], "passed")

    def test_malformed_files_score_zero_without_a_crash_or_a_forged_score(self):
        a = "a1"
        ids = [q["id"] for q in key.questions(a)]
        first_number = next(q["id"] for q in key.questions(a) if q["kind"] == "number")
        first_choice = next(q["id"] for q in key.questions(a) if q["kind"] == "choice")
        right = json.loads(key.solution_answers(a))
        cases = {
            "not JSON": b"{\"E_Y\": 0.26,",
            "not UTF-8": b"{\"E_Y\": \"\xff\xfe\"}",
            "a list": json.dumps([right]).encode(),
            "nested too deep": b"[" * 30000 + b"]" * 30000,
            "too large": json.dumps(dict(right, pad="x" * (written.k_max_bytes + 1))).encode(),
            "a 5000-digit integer": ("{\"E_Y\": " + "9" * 5000 + "}").encode(),
            "NaN and infinity": b"{\"E_Y\": NaN, \"V_Y\": Infinity, \"E_M\": 1e999}",
            "a number as a string": json.dumps(dict(right, **{first_number: str(right[first_number])})).encode(),
            "a boolean": json.dumps(dict(right, **{first_number: True})).encode(),
            "a letter as a number": json.dumps(dict(right, **{first_choice: 2})).encode(),
            "a score of its own": json.dumps({"score": 100, "tests": [{"score": 100}], "E_Y": "100"}).encode(),
            "nothing submitted": None,
        }
        for name, data in cases.items():
            with self.subTest(name):
                tests = graded(a, data)  # must not raise
                self.assertEqual([t["name"] for t in tests], [f"{a}-written.{i}" for i in ids])
                self.assertEqual(sum(t["max_score"] for t in tests), auto_points(a))
                self.assertLess(sum(t["score"] for t in tests), auto_points(a))
                self.assertTrue(all(t["score"] in (0, t["max_score"]) for t in tests))
                self.assertTrue(all(len(t["output"]) < 2000 for t in tests))  # one clear line, not the file
                self.assert_valid(a, tests)
        # a wrong type spoils only its own question
        tests = graded(a, cases["a number as a string"])
        spoiled = [t for t in tests if t["max_score"] and not t["score"]]
        self.assertEqual([t["name"] for t in spoiled], [f"{a}-written.{first_number}"])
        self.assertIn("a number is expected", spoiled[0]["output"])

    def test_the_grader_takes_the_submitted_file_and_the_hidden_key(self):
        with tempfile.TemporaryDirectory() as submission, tempfile.TemporaryDirectory() as hidden:
            with open(os.path.join(submission, "answers.json"), "w") as f:  # found by its name
                f.write(key.solution_answers("a3", "course-2027"))
            with open(os.path.join(hidden, "a3_answers_key.json"), "w") as f:
                f.write(key.key_json("a3", "course-2027"))
            inputs = grade_script.written_inputs("a3", submission, hidden)
            tests = grade_script.written_tests("a3", inputs)
            self.assertEqual(sum(t["score"] for t in tests), auto_points("a3"))
            # graded with the default key instead, the variant's numbers are wrong
            os.remove(os.path.join(hidden, "a3_answers_key.json"))
            tests = grade_script.written_tests("a3", grade_script.written_inputs("a3", submission, hidden))
            self.assertLess(sum(t["score"] for t in tests), auto_points("a3"))


class KitsAndVariants(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tree = tree_copy.copy_tree(ROOT)

    @classmethod
    def tearDownClass(cls):
        tree_copy.remove(cls.tree)

    def make(self, *args):
        return tree_copy.run_script(os.path.join(self.tree, "scripts/make-assignment"), list(args), self.tree)

    def test_tree_answers_files_are_the_blank_templates(self):
        for a in ASSIGNMENTS:
            with open(os.path.join(ROOT, f"tests/assignments/{a}/answers.json")) as f:
                self.assertEqual(f.read(), key.answers_template(a), a)

    def test_the_key_is_never_in_a_kit(self):
        out = os.path.join(self.tree, "kit-a4")
        status, output = self.make("a4", "--out", out)
        self.assertEqual(status, 0, output)
        files = [os.path.join(d, n) for d, _, ns in os.walk(out) for n in ns]
        self.assertFalse([f for f in files if "/tests/assignments/answers/" in f])
        texts = []
        for path in files:
            with open(path, encoding="utf-8", errors="replace") as f:
                texts.append(f.read())
        text = "\n".join(texts)  # a separator: no number is made of two files' ends
        for a in ("a4", "a5"):  # its own key and every later one
            for q in key.questions(a):
                for line in q.get("rubric", []):
                    self.assertNotIn(line, text)
                for digits in (4, 5, 6) if q["kind"] == "number" else ():
                    written_out = f"{q['answer']:.{digits}g}"
                    # the literal first: the pattern (a lookbehind at every position of
                    # megabytes) is searched only where the digits occur at all
                    if len(written_out.replace(".", "").lstrip("0")) >= 4 and written_out in text:
                        # as a number of its own (0.6 or 8 are in any code: not evidence)
                        self.assertIsNone(re.search(r"(?<![\d.])" + re.escape(written_out) + r"(?!\d)", text),
                                          f"{a} {q['id']}")
        with open(os.path.join(out, "tests/assignments/a4/answers.json")) as f:
            self.assertTrue(all(v is None for k, v in json.load(f).items() if not k.startswith("_")))
        # Played: a key's answer in a kit file (as if a tracked page quoted it) is found by
        # make-assignment's check, which refuses such a kit, and by the kit check of
        # scripts/test --kits (leak_check.py); an earlier assignment's key is not asked for.
        make = tree_copy.load_script(os.path.join(self.tree, "scripts/make-assignment"))
        self.assertEqual(make.key_leaks("a4", out), [])
        planted = {a: next(q for q in key.questions(a) if q["kind"] == "number") for a in ("a3", "a5")}
        with open(os.path.join(out, "docs/answers.md"), "a") as f:
            f.write("".join(f"\nThe answer is {q['answer']:.4g}.\n" for q in planted.values()))
        found = make.key_leaks("a4", out)
        self.assertEqual(found, [f"docs/answers.md: a5 {planted['a5']['id']} ({planted['a5']['answer']:.4g})"])
        status, output = tree_copy.run_script(os.path.join(self.tree, "scripts/leak_check.py"), ["a4", out], self.tree)
        self.assertEqual(status, 1, output)
        self.assertIn(f"docs/answers.md: a5 {planted['a5']['id']}", output)
        tree_copy.remove(out)

    def test_same_secret_same_autograder_and_two_secrets_differ(self):
        folders = {}
        for name, secret in (("x1", "course-2027"), ("x2", "course-2027"), ("y", "course-2028")):
            folders[name] = os.path.join(self.tree, f"ag-{name}")
            status, output = self.make("a5", "--autograder", folders[name], "--variant", secret)
            self.assertEqual(status, 0, output)

        def listing(folder):
            return sorted(os.path.relpath(os.path.join(d, n), folder) for d, _, ns in os.walk(folder) for n in ns)
        x1, x2, y = folders["x1"], folders["x2"], folders["y"]
        self.assertEqual(listing(x1), listing(x2))
        match, mismatch, errors = filecmp.cmpfiles(x1, x2, listing(x1), shallow=False)
        self.assertEqual((mismatch, errors), ([], []))

        def key_of(folder):
            with open(os.path.join(folder, "hidden/a5_answers_key.json")) as f:
                return {q["id"]: q for q in json.load(f)["questions"]}
        kx, ky = key_of(x1), key_of(y)
        for qid, q in kx.items():
            if q["kind"] == "number":
                self.assertNotAlmostEqual(q["answer"], ky[qid]["answer"], msg=qid)

        def read(folder, rel):
            with open(os.path.join(folder, rel)) as f:
                return f.read()
        # the handout's numbers and the hidden seed change; the public tests do not
        self.assertNotEqual(read(x1, "kit/docs/assignments/a5.md"), read(y, "kit/docs/assignments/a5.md"))
        self.assertNotIn("<!--v:", read(x1, "kit/docs/assignments/a5.md"))
        self.assertNotEqual(read(x1, "hidden/a5_hidden_test.cpp"), read(y, "hidden/a5_hidden_test.cpp"))
        for name, value in key.hidden_values("a5", "course-2028").items():
            self.assertIn(f"k_hidden_{name} = {value!r};", read(y, "hidden/a5_hidden_test.cpp"))
        for rel in ("kit/tests/assignments/a5/a5_test.cpp", "kit/tests/assignments/a5/a5_checks.hpp"):
            self.assertEqual(read(x1, rel), read(y, rel))
        for folder in folders.values():
            tree_copy.remove(folder)

    def test_every_numeric_answer_depends_on_the_secret(self):
        # two secrets: every numeric answer of every assignment differs (the parameters a
        # number depends on are all drawn from the secret)
        for a in ASSIGNMENTS:
            one = {q["id"]: q for q in key.questions(a, "course-2027")}
            two = {q["id"]: q for q in key.questions(a, "course-2028")}
            for qid, q in one.items():
                if q["kind"] == "number":  # apart by more than the grading tolerance
                    x, y = q["answer"], two[qid]["answer"]
                    self.assertGreater(abs(x - y), q["rel_tol"] * max(abs(x), abs(y)),
                                       msg=f"{a} {qid}: {x} and {y}")
            if key.hidden_values(a):  # the hidden tests' seed too
                self.assertNotEqual(key.hidden_values(a, "course-2027")["seed"],
                                    key.hidden_values(a, "course-2028")["seed"])

    def test_two_secrets_rarely_share_a_numeric_answer(self):
        # Over 10,000 fixed pairs of secrets (5 s), fewer than 1 pair in 1000 gives one numeric
        # answer of any assignment within the grading tolerance (100,000 pairs measured 0.034%:
        # 3.4 expected here). A parameter drawn from a short list fails this: a6's lobe exponent
        # from 7 values made 14% of pairs share an answer, and the 1e-3 tolerance with lists in
        # steps of 0.001 made 2.5% share one.
        shared = []
        pairs = 10000
        for i in range(pairs):
            shared += [(i, (a, qid)) for a in ASSIGNMENTS for qid in key.shared_answers(a, f"pair-{i}-one", f"pair-{i}-two")]
        self.assertLess(len({i for i, _ in shared}), pairs / 1000, shared)

    def test_a_variant_sharing_an_answer_with_last_years_is_refused(self):
        # a pair of secrets that shares a numeric answer (about 1 pair in 3000). The search
        # starts at the first such pair of today's key (6369, a4): any sharing pair proves the
        # refusal, and starting there spares 2 s of search; if key.py changes, it goes on.
        first = 6369
        pair = next((a, f"unlike-{i}-new", f"unlike-{i}-old") for i in range(first, first + 100000)
                    for a in ASSIGNMENTS if key.shared_answers(a, f"unlike-{i}-new", f"unlike-{i}-old"))
        a, new, old = pair
        out = tempfile.mkdtemp(prefix="mcrt-unlike-")
        status, output = self.make(a, "--out", os.path.join(out, "kit"), "--variant", new, "--unlike", "other", "--unlike", old)
        self.assertEqual(status, 1, output)
        self.assertIn("choose another secret", output)
        self.assertFalse(os.path.exists(os.path.join(out, "kit")))  # refused before writing
        status, output = self.make(a, "--out", os.path.join(out, "kit"), "--variant", new, "--unlike", f"{old}-not")
        self.assertEqual(status, 0, output)
        status, output = self.make(a, "--out", os.path.join(out, "kit2"), "--unlike", old)
        self.assertEqual(status, 2, output)  # --unlike without --variant
        tree_copy.remove(out)

    def test_handout_placeholders_name_parameters(self):
        make = tree_copy.load_script(os.path.join(self.tree, "scripts/make-assignment"))
        for a in ASSIGNMENTS:
            with open(os.path.join(ROOT, f"docs/assignments/{a}.md")) as f:
                text = f.read()
            names = set(n for _, n in make.VARIANT_NUMBER.findall(text))
            self.assertEqual(names, set(key.params(a)), a)  # every parameter shown, none unknown
            # the tree's handout shows the defaults
            for value, name in make.VARIANT_NUMBER.findall(text):
                self.assertEqual(value, make.format_param(key.params(a)[name]), f"{a} {name}")


if __name__ == "__main__":
    unittest.main()
