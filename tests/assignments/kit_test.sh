#!/bin/sh
# One assignment's kit, generated into a temporary folder, built and graded (scripts/test
# --kits runs the stub kit of every assignment; CTest assignments.a2_kit_* with
# -DMCRT_ASSIGNMENT_KIT_TESTS=ON). Each builds the common libraries from scratch.
#   kit_test.sh ROOT stub [aN]      the stub kit (default a2): no marker, no hidden test, no
#                                   other handout, none of the leaks below; it builds, and its
#                                   grader scores 0, every test failing, with NOT IMPLEMENTED
#                                   feedback naming every task of aN
#   kit_test.sh ROOT solution [aN]  the solution kit, graded with the hidden tests: full marks
#   kit_test.sh ROOT variant aN SECRET  the solution kit of the course variant SECRET, graded
#                                   by that variant's autograder (its hidden tests and answer
#                                   key, make-assignment --autograder --variant): full marks;
#                                   graded with the default hidden folder instead, its written
#                                   answers lose points (the variant's numbers are its own)
# With KIT_TEST_REUSE=DIR (scripts/test --kits), the stub kit is synced into DIR/kit, only the
# files whose content changed being rewritten, and built in DIR/build: one kit after another
# recompiles only what their stubs change, not the whole project. A variant's gradings use
# DIR/variant-build, the grader's --build folder kept from one assignment to the next (as
# Gradescope keeps /autograder/base): each rebuilds only what its grading tree changes.
set -eu
root=$1 mode=$2 a=${3:-a2}
tmp=$(mktemp -d /tmp/mcrt-kit-test.XXXXXX)
# The grading runs the subject as a user of its own (as root): it must reach the grading tree
# below this folder, as it reaches /autograder/work on Gradescope (mktemp makes it 0700).
chmod 755 "$tmp"
trap 'rm -rf "$tmp"' EXIT
fail() { echo "kit_test $a: $*" >&2; exit 1; }

if [ "$mode" = variant ]; then
  secret=${4:?kit_test.sh ROOT variant aN SECRET}
  build=$tmp/build
  if [ -n "${KIT_TEST_REUSE:-}" ]; then build=$KIT_TEST_REUSE/variant-build; fi
  "$root/scripts/make-assignment" "$a" --out "$tmp/kit" --solution --variant "$secret"
  "$root/scripts/make-assignment" "$a" --autograder "$tmp/autograder" --variant "$secret"
  "$root/scripts/grade" "$a" --kit "$tmp/kit" --hidden "$tmp/autograder/hidden" --build "$build" \
      --gradescope "$tmp/results.json" > "$tmp/grade.txt" 2>&1 || { cat "$tmp/grade.txt"; fail "the variant's solution kit lost points"; }
  cat "$tmp/grade.txt"
  grep -q '"visibility": "after_published"' "$tmp/results.json" || fail "no hidden test was graded"
  if "$root/scripts/grade" "$a" --kit "$tmp/kit" --hidden "$root/tests/assignments/hidden" --build "$build" \
      > "$tmp/default.txt" 2>&1; then
    fail "the variant's answers scored full marks against the default key"
  fi
  exit 0
fi

if [ "$mode" = solution ]; then
  "$root/scripts/make-assignment" "$a" --out "$tmp/kit" --solution
  "$root/scripts/grade" "$a" --kit "$tmp/kit" --hidden "$root/tests/assignments/hidden" \
      --gradescope "$tmp/results.json" > "$tmp/grade.txt" 2>&1 || { cat "$tmp/grade.txt"; fail "the solution kit lost points"; }
  cat "$tmp/grade.txt"
  grep -q '"visibility": "after_published"' "$tmp/results.json" || fail "no hidden test was graded"
  exit 0
fi

"$root/scripts/make-assignment" "$a" --out "$tmp/kit"
kit=$tmp/kit
build=$tmp/kit/build-grade
if [ -n "${KIT_TEST_REUSE:-}" ]; then
  python3 - "$tmp/kit" "$KIT_TEST_REUSE/kit" <<'PY'
import filecmp, os, shutil, sys
new, kit = sys.argv[1], sys.argv[2]
wanted = set()
for d, _, fs in os.walk(new):
    for f in fs:
        rel = os.path.relpath(os.path.join(d, f), new)
        wanted.add(rel)
        target = os.path.join(kit, rel)
        if not (os.path.isfile(target) and filecmp.cmp(os.path.join(new, rel), target, shallow=False)):
            os.makedirs(os.path.dirname(target), exist_ok=True)
            shutil.copyfile(os.path.join(new, rel), target)
            shutil.copymode(os.path.join(new, rel), target)
for d, _, fs in os.walk(kit):
    for f in fs:
        if os.path.relpath(os.path.join(d, f), kit) not in wanted:
            os.remove(os.path.join(d, f))
PY
  kit=$KIT_TEST_REUSE/kit
  build=$KIT_TEST_REUSE/build
fi
grep -rq "// ASSIGNMENT" "$kit/common" "$kit/chapters" "$kit/tests" && fail "a marker is left in the kit"
[ -e "$kit/tests/assignments/hidden" ] && fail "hidden tests are in the kit"
[ -e "$kit/docs/assignments/$a.md" ] || fail "the handout is missing"
[ "$(ls "$kit/docs/assignments")" = "$a.md" ] || fail "another handout is in the kit: $(ls "$kit/docs/assignments")"
[ -e "$kit/tests/render/recursive_estimator_known_bugs_a3.hpp" ] && fail "a3's known-wrong recursions are in the kit"
[ -e "$kit/tests/render/mis_known_bugs_a6.hpp" ] && fail "a6's known-wrong variants are in the kit"

# The token-level check: no window of the answers of aN and later (names and comments aside)
python3 "$root/scripts/leak_check.py" "$a" "$kit" || fail "the token-level leak check found a copy"
# The leaks: a solution of the kit's own or a later assignment anywhere in it (the grep -F
# strings are lines of the solutions, or of near-copies of them); scripts/leak_check.py compares
# token sequences, these lines are the ones a human reviewer would look for.
leak() {  # leak FILE-OR-DIR STRING WHAT
  if grep -rqF -- "$2" "$kit/$1" 2>/dev/null; then fail "leak: $3 ($1: $2)"; fi
}
case "$a" in
  a1|a2)
    grep -q 'throw std::logic_error("not implemented: a2.1 sample_uniform_hemisphere")' \
        "$kit/common/sampling/hemisphere.hpp" || fail "the a2.1 stub is not in the kit"
    leak common/sampling/hemisphere.hpp 'const double cos_theta = u.x;' "a2.1's sampler"
    # cos^m at m = 0 is a2.1's sampler, at m = 1 a2.2's (by inversion); its pdf both pdfs
    leak common/sampling/cosine_power.hpp 'std::pow(u.x, 1.0 / (m + 1.0))' "the cosine-power sampler"
    leak common/sampling/cosine_power.hpp '(m + 1.0) * k_inv_two_pi' "the cosine-power pdf"
    leak tests 'inline Vec2 disk_with_radius_u' "sampling/sampling_known_bugs.hpp (a2.4 but for one line)"
    # a2.5's inversion, in its own file and in the sphere light's cone sampler
    leak common/sampling/cone.hpp 'u.x * (1.0 - cos_theta_max)' "a2.5's sampler"
    leak common/sampling/light.hpp 'const double cos_theta = 1.0 - u.x * one_minus_cos_max;' "the sphere light's cone (a2.5)"
    # every later assignment is stubbed; an earlier one keeps its solution
    grep -q 'not implemented: a4.1 estimate_path_radiance' "$kit/common/render/path_tracer.hpp" || fail "a4.1 is not stubbed"
    if [ "$a" = a2 ] && grep -q 'not implemented: a1' "$kit/common/integration/disk_area.hpp"; then
      fail "a1 is stubbed in the a2 kit"
    fi
    ;;
esac
case "$a" in
  a1|a2|a3)
    leak common/render/recursive_estimator.hpp 'incident_radiance(scene, spawn_ray(' "a3.1's recursion"
    leak common/render/recursive_estimator.hpp 'if (total > k_max - level) return k_max;' "a3.2's prediction"
    ;;
esac
case "$a" in
  a1|a2|a3|a4)  # a4.1's path loop, and the near-copies of it
    leak common/render/path_tracer.hpp 'beta *= material.brdf() * cos_theta_i / uniform_hemisphere_pdf();' "a4.1's loop"
    leak common/render/importance_path_tracer.hpp 'beta *= material.brdf() * cos_theta_i / p_wi;' "the importance-sampled path tracer"
    leak common/render/russian_roulette.hpp 'beta *= material.brdf() * cos_theta_i / uniform_hemisphere_pdf();' "the roulette path tracer"
    leak tests 'path_radiance_with(' "render/path_tracer_known_bugs.hpp's path loop"
    leak tests 'roulette_path_with(' "render/russian_roulette_known_bugs.hpp's path loop"
    leak tests 'reference_radiance(const ReferenceQuadBox' "render/scene_quad_box_reference.hpp's path tracer"
    leak tests 'plain_path_radiance(' "render/path_tracer_plain_layers.hpp (a4.1's loop, a2.1's sampler)"
    leak common/engine/path_tracer_lanes.cpp 'path.radiance += beta(l) * material.emission;' "the four-lane path loop"
    leak common/engine/bounce_lanes.cpp 'sub(one, mul(cos_theta, cos_theta))' "the four-lane hemisphere sample"
    leak common/engine/bounce_lanes.cpp 'brdf * cos_theta_i / uniform_hemisphere_pdf()' "the four-lane weight update"
    ;;
esac
case "$a" in
  a1|a2|a3|a4|a5)  # a5's estimators, their copies in chapter 08's baselines and MIS, the known bugs
    leak common 'beta /= q;' "Russian roulette's 1/q"
    leak common 'beta *= material.albedo;' "the cosine-sampled weight f_r cos / p = rho"
    leak common/render/light_sampling.hpp 'area_to_solid_angle_pdf(y.pdf_area' "the light sample's change of measure"
    leak tests 'wrong_nee_radiance(' "render/next_event_estimation_known_bugs.hpp's NEE loop"
    leak tests 'path_radiance_cosine_pdf_without_inv_pi' "render/importance_path_tracer_known_bugs.hpp"
    # the chapter pages quote the loops: their code blocks are left out too
    leak docs 'beta /= q;' "chapter 06's page quoting the roulette"
    leak docs 'if (bounce == 0) radiance += material.emission;' "chapter 08's page quoting NEE"
    leak docs 'const double p_wi = hemisphere_pdf(pdf, cos_theta_i);' "chapter 07's page quoting its loop"
    ;;
esac

case "$a" in
  a1|a2|a3|a4|a5|a6)  # a6's lobe, heuristics and MIS (every kit up to a6's stubs them)
    grep -q 'not implemented: a6.1 sample_phong_lobe_local' "$kit/common/sampling/phong.hpp" || fail "a6.1 is not stubbed"
    leak common/sampling/phong.hpp 'const double one_minus_cos = -std::expm1(log_cos_alpha);' "a6.1's lobe sampler"
    leak common/sampling/phong.hpp '(m + 1.0) * k_inv_two_pi * phong_cos_power(' "a6.1's lobe pdf"
    leak common/render/mis.hpp 'return sum > 0.0 ? p_s2 / sum : 0.0;' "a6.2's power heuristic"
    leak common/render/glossy_direct.hpp 'mis_weight(heuristic, b.pdf_bsdf, b.pdf_light)' "a6.3's MIS"
    leak common/render/glossy_direct.hpp 's.pdf_light = plates_light_pdf(scene, hit.point, w, j);' "a6.3's light sample"
    leak tests 'mis_weight(MisHeuristic::balance, b.pdf_bsdf, n * b.pdf_light)' "render/glossy_direct_test.cpp's known-wrong MIS"
    leak docs 'mis_weight(heuristic, b.pdf_bsdf, b.pdf_light)' "chapter 08's page quoting the plates' MIS"
    leak tests 'inline Vec3 sample_phong_lobe_cos_u_to_one_over_m' "sampling/sampling_known_bugs.hpp (a naive a6.1 lobe sampler)"
    ;;
esac

case "$a" in
  a1|a2|a3|a4|a5|a6|a7)  # a7's point sets and radical inverse (every kit stubs them: a7 is the last)
    grep -q 'not implemented: a7.1 JitteredPoints' "$kit/common/sampling/point_sets.hpp" || fail "a7.1 is not stubbed"
    grep -q 'not implemented: a7.3 radical_inverse' "$kit/common/sampling/radical_inverse.hpp" || fail "a7.3 is not stubbed"
    leak common/sampling/point_sets.hpp '(cell % columns + jitter) / columns' "a7.1's jitter"
    leak common/sampling/point_sets.hpp 'return (slab + hash_uniform(key, i, j)) / n;' "a7.2's Latin hypercube"
    leak common/sampling/radical_inverse.hpp 'mirrored = mirrored * base + rest % base;' "a7.3's radical inverse"
    leak common/sampling/point_sets.hpp 'permutation_element(digits % base, base, dimension_key + k)' "a7.4's scrambled digits"
    leak tests 'struct LatinHypercubeOnePermutation' "sampling/point_sets_known_bugs_a7.hpp (a7's sets but for one line)"
    ;;
esac

# Every task's tests fail: the grader scores 0, with NOT IMPLEMENTED feedback for each task.
if "$kit/scripts/grade" "$a" --build "$build" --gradescope "$tmp/results.json" > "$tmp/grade.txt" 2>&1; then
  cat "$tmp/grade.txt"; fail "the stub kit got full marks"
fi
cat "$tmp/grade.txt"
grep -q "(the build failed)" "$tmp/grade.txt" && fail "the stub kit does not build"
for task in $(python3 -c "import json,sys; print(' '.join(t for t in json.load(open(sys.argv[1]))['stubbed'] if t.startswith(sys.argv[2] + '.')))" "$kit/.assignment" "$a"); do
  grep -qF "NOT IMPLEMENTED: task $task (" "$tmp/grade.txt" || fail "no feedback names task $task"
done
grep -q "^$a: 0 / " "$tmp/grade.txt" || fail "the stub kit scored points"
python3 - "$tmp/results.json" "$root/tests/assignments/results.schema.json" "$root/tests/assignments/tooling" <<'PY' || fail "results.json is not in Gradescope's format"
import json, sys
sys.path.insert(0, sys.argv[3])
import schema_subset
r, schema = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert not schema_subset.errors(r, schema), schema_subset.errors(r, schema)
assert r["tests"] and sum(t["score"] for t in r["tests"]) == 0
PY
echo "kit_test $a: the stub kit builds, scores 0 with NOT IMPLEMENTED for every task, and leaks none of the checked solutions"
