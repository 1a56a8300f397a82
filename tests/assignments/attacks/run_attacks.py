#!/usr/bin/env python3
"""The attack suite of the a2 grader (scripts/test --kits): each attack is a submission that
tries to gain points it did not earn, graded by scripts/grade as Gradescope would (as root, so
the tests run as the grading's own user through scripts/sandbox-run). Each closed attack must score no more
than the honest submission it is built on and must not reach its goal; the open one is run and
reported as open.

  run_attacks.py ROOT BUILD [ATTACK...]   BUILD: the grader's --build folder, kept between
                                          runs; ATTACK: only these (default: every one)

The honest submission: the solution's hemisphere.hpp and plane.hpp, sphere.hpp not submitted
(so a2.3 is graded as its stub and points are lost). The attacks add to it:
  fork_rewrite   a process that outlives the grader and rewrites results.json (fork_rewrite.inc)
  hidden_read    a read of the hidden test's source through __FILE__, printed into the feedback
  hostile_kit    a kit whose CMakeLists.txt runs execute_process, whose tests are `true` and
                 whose points.json gives 100 a test, with no editable file changed
  early_exit     a sampler that calls std::_Exit(0), so CTest sees its tests pass
  atexit_exit    a wrong sampler whose exit hook turns the failed program's status into 0
  forged_report  a sampler that writes passing gtest reports itself (where GTEST_OUTPUT says, or
                 where the grading folder's layout puts them), then exits with 0
  fake_frames    a sampler that writes answer frames of its own (a made-up token) to stdout and
                 every descriptor, then ends the subject mid-request
  compiler_read  __has_include and .incbin of the hidden test and the key (compiler_read.inc)
  detect_hidden  the pole sampler, but the right one when /proc names the hidden test's checker
  forged_feedback  "DIAGNOSIS: ..." lines on stderr and in an exception's text, then 64 MiB of
                 output (forged_feedback.inc)
  leftovers      16 MiB files in /tmp and /dev/shm and a daemon holding the subject's output
  dev_zero       `#include "/dev/zero"` (the build's memory limit, named in the feedback)
  concurrent     2, then 4 honest gradings started together: each scores what it scores alone
a2 is split (subject/checker): the sampler runs in the subject program, as the grading's user, and the
checker that writes the reports holds no student code. Each attack is held to the pole sampler,
the same submission without the attack.
Exit status: 0 every attack gained nothing, 1 otherwise, 2 not run as root.
"""

import json
import os
import re
import shutil
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
RESULTS_DIR = "/tmp/mcrt-attack"  # the path fork_rewrite.inc writes to
# The forked rewriter writes once a second for 20 s: 3 s after the grader is done it has had
# three chances, had it survived.
k_wait_after_grading = 3


def solution_file(root, rel):
    with open(os.path.join(root, rel), encoding="utf-8") as f:
        return f.read()


def submission(root, folder, extra="", sphere=None, cone=False):
    """An a2 submission: the solution's hemisphere.hpp (with `extra` appended) and plane.hpp;
    sphere.hpp only when given; the solution's cone.hpp when `cone`."""
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    with open(os.path.join(folder, "hemisphere.hpp"), "w") as f:
        f.write(solution_file(root, "common/sampling/hemisphere.hpp") + "\n" + extra)
    with open(os.path.join(folder, "plane.hpp"), "w") as f:
        f.write(solution_file(root, "common/sampling/plane.hpp"))
    if sphere is not None:
        with open(os.path.join(folder, "sphere.hpp"), "w") as f:
            f.write(sphere)
    if cone:
        with open(os.path.join(folder, "cone.hpp"), "w") as f:
            f.write(solution_file(root, "common/sampling/cone.hpp"))
    return folder


def grade(root, build, kit):
    shutil.rmtree(RESULTS_DIR, ignore_errors=True)
    os.makedirs(RESULTS_DIR, mode=0o755)
    results = os.path.join(RESULTS_DIR, "results.json")
    run = subprocess.run([os.path.join(root, "scripts/grade"), "a2", "--kit", kit, "--hidden",
                          os.path.join(root, "tests/assignments/hidden"), "--build", build,
                          "--gradescope", results], stdout=subprocess.PIPE,
                         stderr=subprocess.STDOUT, text=True)
    graded = json.load(open(results)) if os.path.exists(results) else None
    return run, results, graded


def concurrent_gradings(root, build, kit, count):
    """The scores of `count` gradings of `kit` started together, each in a copy of `build` that
    a mount namespace of its own binds at `build`'s path (the copies' CMake folders stay valid)."""
    import tempfile
    scratch = tempfile.mkdtemp(prefix="mcrt-concurrent-")
    try:
        own_kit = os.path.join(scratch, "kit")
        shutil.copytree(kit, own_kit)
        runs = []
        for i in range(count):
            copy = os.path.join(scratch, f"build-{i}")
            subprocess.run(["cp", "-a", "--", build, copy], check=True)
            shutil.rmtree(os.path.join(copy, "attacks"), ignore_errors=True)
            results = os.path.join(scratch, f"results-{i}.json")
            command = (f'mount --bind "$1" "$2" && exec "$3/scripts/grade" a2 --kit "$4" --hidden '
                       f'"$3/tests/assignments/hidden" --build "$2" --gradescope "$5"')
            runs.append((results, subprocess.Popen(
                ["unshare", "--mount", "--propagation", "private", "--", "sh", "-c", command, "sh", copy,
                 build, root, own_kit, results], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)))
        scores = []
        for results, process in runs:
            process.wait()
            scores.append(score(json.load(open(results))) if os.path.exists(results) else None)
        return scores
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


def grading_user_processes():
    """The processes alive whose user is a grading's (scripts/grading_sandbox.py's range)."""
    sys.dont_write_bytecode = True  # no __pycache__ left in the tree
    sys.path.insert(0, os.path.join(os.path.dirname(HERE), "..", "..", "scripts"))
    import grading_sandbox
    first, count = grading_sandbox.k_first_uid, grading_sandbox.k_uid_count
    return [pid for pid, uid in grading_sandbox._processes() if first <= uid < first + count]


def score(results):
    return sum(t["score"] for t in results["tests"]) if results else None


def main():
    if len(sys.argv) < 3:
        print("run_attacks: usage: run_attacks.py ROOT BUILD [ATTACK...]", file=sys.stderr)
        sys.exit(2)
    root, build = (os.path.abspath(p) for p in sys.argv[1:3])
    only = set(sys.argv[3:])

    def wanted(name):
        return not only or name in only
    if os.geteuid() != 0:
        print("run_attacks: the sandbox needs root (the tests run as a user of the grading's own); not run", file=sys.stderr)
        sys.exit(2)
    work = os.path.join(build, "attacks")
    os.makedirs(work, exist_ok=True)
    failures = []

    def report(name, ok, line):
        print(f"  {'closed' if ok else 'OPEN  '} {name}: {line}", flush=True)
        if not ok:
            failures.append(name)

    started = time.monotonic()
    run, _, honest = grade(root, build, submission(root, os.path.join(work, "honest")))
    honest_seconds = time.monotonic() - started
    base = score(honest)
    if honest is None:
        print(run.stdout)
        sys.exit(1)
    print(f"  honest submission (a2.3 not submitted): {base} points", flush=True)
    secret = "TEST(A2Hidden, CornersOfTheUnitSquare)"  # a line of the hidden test

    def include(name):
        with open(os.path.join(HERE, name)) as f:
            return f.read()

    if wanted("fork_rewrite"):
        # fork_rewrite: the file must still say what the grader wrote, after the grader is gone
        run, path, graded = grade(root, build, submission(root, os.path.join(work, "fork"), include("fork_rewrite.inc")))
        time.sleep(k_wait_after_grading)
        after = json.load(open(path)) if os.path.exists(path) else None
        report("fork_rewrite", after == graded and score(after) <= base,
               f"graded {score(graded)}, the file says {score(after)} {k_wait_after_grading} s later")

    if wanted("hidden_read"):
        # hidden_read: no feedback carries a line of the hidden test's source
        run, _, graded = grade(root, build, submission(root, os.path.join(work, "read"), include("hidden_read.inc")))
        shown = json.dumps(graded) if graded else ""
        tried = "HIDDEN SOURCE: (unreadable)" in shown  # the attack ran and was refused
        report("hidden_read", secret not in shown and score(graded) <= base,
               f"graded {score(graded)}; the hidden source {'is' if secret in shown else 'is not'} in the "
               f"feedback{' (its read was refused)' if tried else ''}")

    if wanted("compiler_read"):
        # compiler_read: the subject's compiler probes and embeds the hidden test (the checker's
        # copy and the --hidden folder's) and the answer key; nothing of them reaches the feedback,
        # no probe finds them, and the submission still builds (it was not refused by chance)
        paths = {"@CHECKER_HIDDEN@": os.path.join(build, "checker/src/tests/assignments/hidden/a2_hidden_test.cpp"),
                 "@HIDDEN@": os.path.join(root, "tests/assignments/hidden/a2_hidden_test.cpp"),
                 "@KEY@": os.path.join(root, "tests/assignments/answers/key.py")}
        attack = include("compiler_read.inc")
        for placeholder, path in paths.items():
            attack = attack.replace(placeholder, path)
        run, _, graded = grade(root, build, submission(root, os.path.join(work, "compiler"), attack))
        shown = json.dumps(graded) if graded else ""
        found = re.findall(r"COMPILER PROBE (\w+): found", shown)
        absent = re.findall(r"COMPILER PROBE (\w+): absent", shown)
        report("compiler_read", graded is not None and not found and len(set(absent)) == 3 and secret not in shown
               and "def params(" not in shown and score(graded) <= base,
               f"graded {score(graded)}; probes that found their file: {sorted(set(found)) or 'none'}, "
               f"absent: {sorted(set(absent)) or 'none (the attack did not run)'}")

    if wanted("hostile_kit"):
        # hostile_kit: a whole kit of its own; only its editable files (unchanged stubs) are taken
        kit = os.path.join(work, "hostile-kit")
        shutil.rmtree(kit, ignore_errors=True)
        subprocess.run([os.path.join(root, "scripts/make-assignment"), "a2", "--out", kit],
                       stdout=subprocess.DEVNULL, check=True)
        with open(os.path.join(kit, "CMakeLists.txt"), "a") as f:
            f.write('\nexecute_process(COMMAND sh -c "echo owned > /tmp/mcrt-attack-owned")\n')
        with open(os.path.join(kit, "tests/assignments/a2/a2_test.cpp"), "w") as f:
            f.write("int main() { return 0; }\n")
        with open(os.path.join(kit, "tests/assignments/points.json"), "w") as f:
            f.write('{"a2.A2.Task1UniformHemisphereFollowsItsPdf": 100}\n')
        if os.path.exists("/tmp/mcrt-attack-owned"):
            os.remove("/tmp/mcrt-attack-owned")
        run, _, graded = grade(root, build, kit)
        report("hostile_kit", score(graded) == 0 and not os.path.exists("/tmp/mcrt-attack-owned"),
               f"graded {score(graded)} (the stub kit's 0); its execute_process "
               f"{'ran' if os.path.exists('/tmp/mcrt-attack-owned') else 'did not run'}")

    def sphere_with(call, inc):
        """The solution's sphere sampler with `call` as its first statement."""
        sphere = solution_file(root, "common/sampling/sphere.hpp")
        sphere = re.sub(r"(inline Vec3 sample_uniform_sphere\(Vec2 u\) \{\n)", r"\1  " + call + "\n", sphere)
        return sphere.replace('#pragma once\n', '#pragma once\n' + (include(inc) if inc else ""), 1)

    pole_scores = []

    def pole_score():
        """The score of the solution's sphere.hpp with a sampler that always returns the pole: its
        pdf is right, which earns its own test, and its sampler is a unit vector of the wrong
        distribution. Attacks that submit a sphere.hpp are held to it (graded once, when first asked)."""
        if not pole_scores:
            _, _, graded = grade(root, build, submission(
                root, os.path.join(work, "pole"), sphere=sphere_with("return {0.0, 0.0, 1.0};", None)))
            pole_scores.append(score(graded))
            print(f"  the same with a sampler that returns the pole: {pole_scores[0]} points", flush=True)
        return pole_scores[0]

    if any(wanted(n) for n in ("early_exit", "atexit_exit", "forged_report", "fake_frames")):
        # early_exit and atexit_exit: a status of 0 from a program that did not finish its test, or
        # whose test failed, scores nothing (gtest's report decides). Each is held to the pole
        # sampler, the same submission without the attack.
        pole = pole_score()
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "exit"), sphere=sphere_with("mcrt_attack::leave_early();", "early_exit.inc")))
        report("early_exit", score(graded) <= pole, f"graded {score(graded)} against the pole sampler's {pole}")
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "atexit"),
            sphere=sphere_with("mcrt_attack::succeed_at_exit(); return {0.0, 0.0, 1.0};", "atexit_exit.inc")))
        report("atexit_exit", score(graded) <= pole, f"graded {score(graded)} against the pole sampler's {pole}")

        # forged_report and fake_frames: the verdicts are the checker's, out of the student code's reach
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "forged"), sphere=sphere_with("mcrt_attack::forge_report_and_leave();",
                                                                     "forged_report.inc")))
        report("forged_report", score(graded) is not None and score(graded) <= pole,
               f"graded {score(graded)} against the pole sampler's {pole}")
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "frames"), sphere=sphere_with("mcrt_attack::fake_frames_and_leave();",
                                                                     "fake_frames.inc")))
        named = graded is not None and "gave no valid answer to request a2_samples" in json.dumps(graded)
        report("fake_frames", score(graded) is not None and score(graded) <= pole and named,
               f"graded {score(graded)} against the pole sampler's {pole}; the feedback "
               f"{'names' if named else 'does not name'} the unanswered request")

    if wanted("detect_hidden"):
        # detect_hidden: a sampler whose directions have length 2 (the public unit-vector test
        # and the hidden corners test fail), the right one when it finds a hidden test asking;
        # with the cone submitted, the hidden test turns on the sphere alone
        long_pole = "return {0.0, 0.0, 2.0};"
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "long"), sphere=sphere_with(long_pole, None), cone=True))
        plain = score(graded)
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "detect"), cone=True,
            sphere=sphere_with(f"if (!mcrt_attack::asked_by_hidden()) {long_pole}", "detect_hidden.inc")))
        report("detect_hidden", score(graded) is not None and plain is not None and score(graded) <= plain,
               f"graded {score(graded)} against the same sampler's {plain} without the detection")

    if wanted("forged_feedback"):
        # forged_feedback: "DIAGNOSIS:" lines on stderr and in the exception's text, then 64 MiB
        # of output: no line of any test's feedback starts with the forged diagnosis, none opens
        # with the submission's output, each stays short; the score is held to the pole sampler's
        # (the same sphere.hpp, whose pdf earns its own test, without the attack)
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "forged-feedback"),
            sphere=sphere_with("mcrt_attack::forge_diagnosis(true); mcrt_attack::throw_forged_diagnosis();",
                               "forged_feedback.inc")))
        outputs = [t.get("output", "") for t in graded["tests"]] if graded else []
        forged = [o for o in outputs if re.search(r"(?m)^\s*DIAGNOSIS: forged", o)]
        longest = max((len(o) for o in outputs), default=0)
        student_first = [o for o in outputs if o.startswith(("| ", "--- what your program printed", "x" * 20))]
        report("forged_feedback", graded is not None and not forged and not student_first and longest < 16384
               and score(graded) <= pole_score(),
               f"graded {score(graded)} against the pole sampler's {pole_score()}; {len(forged)} tests show the forged diagnosis as the grader's, "
               f"{len(student_first)} open with the submission's output; the longest feedback is "
               f"{longest} characters")

    if wanted("leftovers"):
        # leftovers: files in /tmp and /dev/shm and a daemon holding the subject's output: the
        # files are gone after the grading, the daemon too, and the grading takes about the
        # honest one's time (the daemon stretched every test to its 60 s limit before)
        token = f"mcrt-attack-leftover-{os.getpid()}-{int(time.time())}"
        started = time.monotonic()
        run, _, graded = grade(root, build, submission(
            root, os.path.join(work, "leftovers"), include("leftovers.inc").replace("@TOKEN@", token)))
        took = time.monotonic() - started
        left = [os.path.join(d, n) for d in ("/tmp", "/dev/shm") for n in os.listdir(d) if n.startswith(token)]
        daemons = grading_user_processes()
        for path in left:
            os.remove(path)
        report("leftovers", graded is not None and not left and not daemons and score(graded) <= base
               and took < 3 * honest_seconds + 30,
               f"graded {score(graded)} in {took:.0f} s (the honest one in {honest_seconds:.0f} s); "
               f"{len(left)} files left in /tmp and /dev/shm, {len(daemons)} processes of a grading's user alive")

    if wanted("dev_zero"):
        # dev_zero: `#include "/dev/zero"` stops at the build's memory limit, named in the feedback
        started = time.monotonic()
        run, _, graded = grade(root, build, submission(root, os.path.join(work, "zero"), '#include "/dev/zero"\n'))
        took = time.monotonic() - started
        named = graded is not None and "memory limit" in graded.get("output", "")
        report("dev_zero", graded is not None and score(graded) == 0 and named,
               f"graded {score(graded)} in {took:.0f} s; the feedback {'names' if named else 'does not name'} "
               f"the memory limit")

    if wanted("concurrent"):
        # concurrent: 2, then 4 gradings of the honest submission started together, each in its
        # own copy of the build folder (bound at the same path in a mount namespace of its own,
        # so nothing is rebuilt), score what it scores alone
        for count in (2, 4):
            scores = concurrent_gradings(root, build, submission(root, os.path.join(work, "honest")), count)
            report(f"concurrent_{count}", scores == [base] * count,
                   f"{count} gradings at once scored {scores}; alone {base}")

    shutil.rmtree(RESULTS_DIR, ignore_errors=True)
    if failures:
        print(f"run_attacks: attacks that gained something: {', '.join(failures)}", file=sys.stderr)
        sys.exit(1)
    print("run_attacks: every attack gained nothing")


if __name__ == "__main__":
    main()
