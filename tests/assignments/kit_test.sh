#!/bin/sh
# The a2 kit, generated into a temporary folder, built and graded (CTest assignments.a2_kit_*,
# registered with -DMCRT_ASSIGNMENT_KIT_TESTS=ON; each builds the common libraries from
# scratch: about 2 minutes of CPU, more on a busy machine).
#   kit_test.sh ROOT stub       the stub kit: its stub throws "not implemented: a2.1 ...", no
#                               marker and no hidden test is in it, and its grader fails a2.1 to
#                               a2.4 with NOT IMPLEMENTED feedback
#   kit_test.sh ROOT solution   the solution kit, graded with the hidden tests: full marks
set -eu
root=$1 mode=$2
tmp=$(mktemp -d /tmp/mcrt-kit-test.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "kit_test: $*" >&2; exit 1; }

if [ "$mode" = solution ]; then
  "$root/scripts/make-assignment" a2 --out "$tmp/kit" --solution
  "$root/scripts/grade" a2 --kit "$tmp/kit" --hidden "$root/tests/assignments/hidden" \
      --gradescope "$tmp/results.json" > "$tmp/grade.txt" 2>&1 || { cat "$tmp/grade.txt"; fail "the solution kit lost points"; }
  cat "$tmp/grade.txt"
  grep -q '"visibility": "after_published"' "$tmp/results.json" || fail "no hidden test was graded"
  exit 0
fi

"$root/scripts/make-assignment" a2 --out "$tmp/kit"
kit=$tmp/kit
grep -q 'throw std::logic_error("not implemented: a2.1 sample_uniform_hemisphere")' \
    "$kit/common/sampling/hemisphere.hpp" || fail "the a2.1 stub is not in the kit"
grep -q 'const double cos_theta = u.x;' "$kit/common/sampling/hemisphere.hpp" && fail "the a2.1 solution is in the kit"
grep -rq "// ASSIGNMENT" "$kit/common" "$kit/chapters" "$kit/tests" && fail "a marker is left in the kit"
[ -e "$kit/tests/assignments/hidden" ] && fail "hidden tests are in the kit"
[ -e "$kit/docs/assignments/a2.md" ] || fail "the handout is missing"
[ -e "$kit/docs/assignments/a1.md" ] && fail "another assignment's handout is in the kit"
# The later assignments that need a2.1 are stubbed too; a1 keeps its solution.
grep -q 'not implemented: a4.1 estimate_path_radiance' "$kit/common/render/path_tracer.hpp" || fail "a4.1 is not stubbed"
grep -q 'not implemented: a1' "$kit/common/integration/disk_area.hpp" && fail "a1 is stubbed in the a2 kit"

if "$kit/scripts/grade" a2 --gradescope "$tmp/results.json" > "$tmp/grade.txt" 2>&1; then
  cat "$tmp/grade.txt"; fail "the stub kit got full marks"
fi
cat "$tmp/grade.txt"
for task in a2.1 a2.2 a2.3 a2.4; do
  grep -qF "NOT IMPLEMENTED: task $task (" "$tmp/grade.txt" || fail "no feedback names task $task"
done
grep -q '^a2: 0 / ' "$tmp/grade.txt" || fail "the stub kit scored points"
python3 -c "import json,sys; r=json.load(open(sys.argv[1])); assert r['score']==0 and r['tests'] and all({'name','score','max_score','output','visibility'} <= set(t) for t in r['tests'])" \
    "$tmp/results.json" || fail "results.json is not in Gradescope's format"
