"""Grades a written-answers file (tests/assignments/aN/answers.json) against an answer key.

Used by scripts/grade, in the grader's own process: no student code runs here, the file is
only read as data. It is hostile input: a file too large, not UTF-8, not JSON, nested too
deep, or an answer of the wrong type scores 0 for what it spoils, with one line saying why;
nothing in it can raise, crash the grader or change a question's points.

The key (tests/assignments/answers/key.py in the instructor tree, aN_answers_key.json in an
autograder's hidden folder) lists the questions: "number" (within a relative tolerance),
"choice" (one letter), "text" (graded by hand: listed with 0 of 0 points and its rubric, so the
instructor marks it in Gradescope's manual grading). A kit has no key: its self-grading checks
only that every answer is filled in and of the right type.
"""

import json
import math

# A filled-in answers file is under 4 KiB (a few numbers, letters and paragraphs); 64 KiB
# leaves room for long text answers and refuses a file meant to exhaust the grader.
k_max_bytes = 64 * 1024
# One text answer: about a page; the rest is cut (said in the feedback).
k_max_text = 4000


def read_limited(path):
    """The first k_max_bytes + 1 bytes of a regular file, or (None, why)."""
    try:
        with open(path, "rb") as f:
            return f.read(k_max_bytes + 1), None
    except OSError as e:
        return None, f"cannot read the answers file: {e.strerror}"


def parse(data):
    """(answers dict, None) or (None, one line saying why the file is refused)."""
    if data is None:
        return None, "no answers file was submitted"
    if len(data) > k_max_bytes:
        return None, f"the answers file is larger than {k_max_bytes // 1024} KiB"
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:
        return None, "the answers file is not UTF-8 text"
    try:
        value = json.loads(text)
    except RecursionError:
        return None, "the answers file is nested too deep to be an answers file"
    except ValueError as e:  # json.JSONDecodeError, and integers of more than 4300 digits
        return None, f"the answers file is not valid JSON ({str(e).splitlines()[0][:120]})"
    if not isinstance(value, dict):
        return None, "the answers file must be one JSON object of answers (\"id\": answer)"
    return value, None


def typed_answer(question, given):
    """(the answer in its kind's type, None) or (None, why it cannot be graded)."""
    kind = question["kind"]
    if given is None:
        return None, "not answered (null)"
    if kind == "number":
        if isinstance(given, bool) or not isinstance(given, (int, float)):
            return None, f"a number is expected, not {type(given).__name__} (write 0.1234, not \"0.1234\")"
        try:
            value = float(given)
        except OverflowError:
            return None, "the number is too large"
        if not math.isfinite(value):
            return None, "the number is not finite"
        return value, None
    if not isinstance(given, str):
        return None, f"a string is expected, not {type(given).__name__}"
    if kind == "choice":
        letter = given.strip().lower()
        if letter not in question.get("options", {letter: None}):
            return None, f"one of the letters {', '.join(sorted(question['options']))} is expected"
        return letter, None
    if not given.strip():
        return None, "not answered (empty text)"
    return given, None


def written_test(a, question, passed, output, manual=False, answer=None):
    name = f"{a}-written.{question['id']}"
    if manual:
        points = question["points"]
        rubric = question.get("rubric", [])
        shown = (answer or "")[:k_max_text]
        lines = [f"Graded by hand: {points} points, awarded by your instructor after the grades "
                 "are published. Rubric:"] + [f"  {r}" for r in rubric]
        lines += ["Your answer:", shown or "(none)"] + ([output] if output else [])
        return {"name": name, "score": 0, "max_score": 0, "output": "\n".join(lines),
                "visibility": "after_published", "tags": ["manual"],
                "extra_data": {"manual_points": points, "rubric": rubric, "answer": shown}}
    return {"name": name, "score": question["points"] if passed else 0,
            "max_score": question["points"], "output": "" if passed else output,
            "visibility": "after_published"}


def grade(a, data, key):
    """Gradescope tests for every question of `key` (a list of questions), from the answers
    file's bytes `data` (None: not submitted). Numbers and letters score their points when
    right; text is listed for hand grading. Never raises on any `data`."""
    answers, problem = parse(data)
    tests = []
    for q in key:
        given = answers.get(q["id"]) if answers is not None else None
        if problem is None:
            value, why = typed_answer(q, given)
        else:
            value, why = None, problem
        if q["kind"] == "text":
            tests.append(written_test(a, q, False, why and f"({why})", manual=True,
                                      answer=value if isinstance(value, str) else None))
            continue
        if why:
            tests.append(written_test(a, q, False, f"{q['id']}: {why}."))
            continue
        if q["kind"] == "number":
            expected = q["answer"]
            passed = abs(value - expected) <= q["rel_tol"] * abs(expected)
            output = (f"{q['id']} = {value:.8g} is not within {q['rel_tol']:g} (relative) of the "
                      f"answer.\nDIAGNOSIS: {q['hint']}")
        else:
            passed = value == q["answer"]
            output = f"{q['id']} = {value}: not the answer.\nDIAGNOSIS: {q['hint']}"
        tests.append(written_test(a, q, passed, output))
    return tests


def completeness(a, data, ids):
    """The visible check a kit can run without the key: the file parses and every question id
    has a non-null answer. One test worth 0 points (the answers are graded with the key)."""
    answers, problem = parse(data)
    if problem is None:
        missing = [i for i in ids if answers.get(i) is None or answers.get(i) == ""]
        problem = f"not answered yet: {', '.join(missing)}" if missing else None
    return {"name": f"{a}-written.complete", "score": 0, "max_score": 0,
            "status": "failed" if problem else "passed",
            "output": problem or "every written answer is filled in (they are graded with the "
                                 "key after the due date)",
            "visibility": "visible"}


def question_ids(template_data):
    """The question ids of a kit's blank answers file (every key but those starting with _)."""
    answers, _ = parse(template_data)
    return [k for k in (answers or {}) if not k.startswith("_")]


def load_key(path):
    """The questions of an autograder's key file (the instructor's: trusted)."""
    with open(path, encoding="utf-8") as f:
        return json.load(f)["questions"]
