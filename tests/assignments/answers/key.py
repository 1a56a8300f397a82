"""The written questions of a1-a5: each question's kind, points, answer and rubric, and the
parameters its numbers depend on, derived from a course secret (a variant) or the defaults.

Instructor tree only: scripts/make-assignment leaves this folder out of every kit (the leak
check of tests/assignments/tooling/answers_test.py plays it). A kit's answers file is made from
the question list with every answer blank (answers_template); the autograder carries the key
of its variant (key_json) among its hidden files; scripts/grade reads it there, or computes it
here in the instructor tree.

Kinds: "number" (graded within a relative tolerance), "choice" (one letter), "text" (graded by
hand: it appears in results.json with 0 of 0 points and its rubric, for the instructor to mark).
"""

import hashlib
import hmac
import json
import math

# Every numeric answer is graded within this relative tolerance: the handouts ask for 6
# significant digits, whose rounding is at most 5e-6 relative; 1e-5 leaves room for that and
# no room for a wrong formula (the closest wrong answers the questions invite differ by 10% or
# more). It is also what keeps two variants apart: answers within it count as the same answer.
k_rel_tol = 1e-5


def steps(low, high, step, decimals):
    """low, low + step, ..., high, each rounded to `decimals` (so the handout prints it exactly)."""
    return [round(low + step * i, decimals) for i in range(round((high - low) / step) + 1)]


# The parameters of each assignment's questions and hidden tests: the default (no --variant)
# and the values a secret picks from. Defaults are deliberately not the chapter pages' numbers,
# so a key's number found in a kit is a leak, not a coincidence. The lists are long (thousands
# of values at least where a number depends on one parameter alone), so that two secrets rarely
# give one answer within k_rel_tol (answers_test.py measures it over 2000 pairs of secrets).
PARAMS = {
    "a1": {
        "k": (3, [3, 4, 5]),                                       # dimension of the ball
        "s": (1.25, steps(1.05, 1.6, 1e-5, 5)),                    # the cube is [-s, s]^k
        "n": (800, list(range(500, 5001))),                         # points per estimate
    },
    "a2": {
        "r0": (0.35, steps(0.15, 0.85, 1e-5, 5)),                  # a radius in the disk
        "theta0": (35, steps(10, 80, 1e-3, 3)),                     # degrees
        "cone_deg": (20, steps(5, 60, 1e-3, 3)),                    # a cone's half-angle, degrees
    },
    "a3": {
        "branches": (6, [3, 4, 5, 6, 7, 8, 9]),
        "depth": (4, [3, 4, 5, 6]),
        "albedo": (0.55, steps(0.3, 0.8, 1e-4, 4)),
        "width": (320, [160, 200, 240, 320, 400, 480, 640]),
        "height": (240, [120, 160, 200, 240, 300, 360]),
        "spp": (8, list(range(2, 1025))),
        "rate": (2e8, [1e8, 2e8, 3e8, 5e8, 8e8]),                        # rays per second
    },
    "a4": {
        "albedo": (0.65, steps(0.3, 0.85, 1e-5, 5)),
        "depth": (4, [2, 3, 4, 5, 6, 7]),
        "emission": (1.5, steps(0.5, 2.5, 1e-3, 3)),
    },
    "a5": {
        "albedo": (0.45, steps(0.3, 0.7, 1e-5, 5)),
        "min_depth": (2, [1, 2, 3, 4]),
        "q": (0.75, steps(0.5, 0.95, 1e-5, 5)),
        "vertex": (5, [5, 6, 7, 8]),                               # a vertex beyond min_depth
        "height": (1.6, steps(1.0, 3.0, 1e-3, 3)),                 # of the light above x
        "side": (0.4, steps(0.2, 0.7, 1e-3, 3)),                   # of the square light
        "offset": (0.5, steps(0.1, 1.0, 1e-3, 3)),                 # of y from above x
        "lights": (2, [2, 3, 4]),
    },
    "a6": {
        "m": (20000, list(range(1000, 100001))),              # the lobe's exponent
        "p_light": (2.4, steps(0.5, 5.0, 1e-3, 3)),                # per steradian
        "p_bsdf": (0.7, steps(0.1, 2.0, 1e-3, 3)),                 # per steradian
    },
    "a7": {
        "index": (1234, list(range(100, 100001))),                  # i of phi_b(i)
        "base": (5, [3, 5, 7, 11, 13]),                             # b of phi_b(i)
        "slope": (2.5, steps(0.5, 3.0, 1e-4, 4)),                   # f(x) = c x on [0, 1]
        "strata": (12, list(range(4, 65))),                         # jittered strata n
    },
}

# The hidden tests' seeds and parameters: scripts/make-assignment --variant writes them into
# the autograder's copy of tests/assignments/hidden/aN_hidden_test.cpp, at its lines
# `inline constexpr T k_hidden_NAME = VALUE;`; the default is the instructor tree's own value.
# The seed is drawn from 2^32 values (None below); the ranges keep every test's premise: a5's
# roulette path has a finite fourth moment, as at the default (each vertex multiplies it by
# E[w^4] / q^3 = (16 a^4 / 5) / q^3, at most 0.571 / 0.614 = 0.93 < 1 over the ranges), so its
# z-test of the mean is as well calibrated as the default's; a furnace albedo below 1.
HIDDEN = {
    "a3": {"seed": (17, None), "branches": (5, [3, 5, 6, 7])},
    "a4": {"seed": (4242, None), "emission": (1.25, [round(0.5 + 0.05 * i, 2) for i in range(31)]),
           "albedo": (0.8, [round(0.6 + 0.01 * i, 2) for i in range(26)])},
    "a5": {"seed": (4243, None), "roulette_q": (0.9, [round(0.85 + 0.01 * i, 2) for i in range(11)]),
           "roulette_albedo": (0.6, [round(0.5 + 0.01 * i, 2) for i in range(16)]),
           "cosine_albedo": (0.8, [round(0.6 + 0.01 * i, 2) for i in range(31)])},
    # a7: the jittered grid's side of the hidden stratification test (n = k^2 points)
    "a7": {"seed": (7331, None), "grid": (11, list(range(5, 17)))},
}


def derived_index(secret, field, size):
    """A number in [0, size) from HMAC-SHA-256(secret, field): the same secret and field always
    give the same index; another secret an independent one."""
    digest = hmac.new(secret.encode("utf-8"), field.encode("utf-8"), hashlib.sha256).digest()
    return int.from_bytes(digest[:8], "big") % size


def params(a, secret=None):
    """{name: value} of assignment `a`'s questions: the defaults, or picked by `secret`."""
    table = PARAMS.get(a, {})
    if secret is None:
        return {name: default for name, (default, _) in table.items()}
    return {name: choices[derived_index(secret, f"{a}.{name}", len(choices))]
            for name, (_, choices) in table.items()}


def hidden_values(a, secret=None):
    """{name: value} of `a`'s hidden tests (empty: none varies). A seed is below 2^32, so that
    seed + a small offset never overflows and every value prints as a plain C++ literal."""
    out = {}
    for name, (default, choices) in HIDDEN.get(a, {}).items():
        if secret is None:
            out[name] = default
        elif choices is None:
            out[name] = 1000 + derived_index(secret, f"{a}.hidden_{name}", 2 ** 32 - 1000)
        else:
            out[name] = choices[derived_index(secret, f"{a}.hidden_{name}", len(choices))]
    return out


def ball_volume(k):
    """|B_k|, the volume of the unit k-ball."""
    return math.pi ** (k / 2) / math.gamma(k / 2 + 1)


def number(qid, points, prompt, answer, hint):
    return {"id": qid, "kind": "number", "points": points, "prompt": prompt, "answer": answer,
            "rel_tol": k_rel_tol, "hint": hint}


def choice(qid, points, prompt, options, answer, hint):
    return {"id": qid, "kind": "choice", "points": points, "prompt": prompt, "options": options,
            "answer": answer, "hint": hint}


def text(qid, points, prompt, rubric):
    return {"id": qid, "kind": "text", "points": points, "prompt": prompt, "rubric": rubric}


def questions_a1(p):
    k, s, n = p["k"], p["s"], p["n"]
    side = (2 * s) ** k
    eta = ball_volume(k) / side
    return [
        number("E_Y", 1, "E[Y_i]", eta, "Y_i is 1 with probability eta = |B_k| / (2s)^k"),
        number("V_Y", 1, "V[Y_i]", eta * (1 - eta), "a Bernoulli variable has E[Y^2] = E[Y]"),
        number("E_M", 1, "E[M]", n * eta, "M is a sum of N of the Y_i: linearity of expectation"),
        number("V_M", 1, "V[M]", n * eta * (1 - eta), "the Y_i are independent: their variances add"),
        number("V_estimate", 1, "V[(2s)^k M / N]", side ** 2 * eta * (1 - eta) / n,
               "V[c X] = c^2 V[X] with c = (2s)^k / N"),
        choice("halve_sd", 1, "To halve the standard deviation of the estimate, N must grow by",
               {"a": "a factor 2", "b": "a factor 4", "c": "a factor sqrt(2)", "d": "a factor 2^k"},
               "b", "the standard deviation falls as N^(-1/2)"),
        text("relative_error_k", 2,
             "Why does the relative error of the k-ball estimate grow with k at fixed N?",
             ["1: relative variance (1 - p_k) / (p_k N) with p_k = |B_k| / 2^k",
              "1: p_k falls fast with k (the ball fills less and less of the cube), so few points hit"]),
        choice("standard_error_unbiased", 1,
               "Is the standard error your monte_carlo returns an unbiased estimate of the true standard deviation of F_N?",
               {"a": "yes", "b": "no: on average it is too small (s is a concave function of s^2)",
                "c": "no: on average it is too large"},
               "b", "E[s^2] = sigma^2, and E[sqrt(X)] <= sqrt(E[X]) (Jensen)"),
        text("trapezoid_dimensions", 2,
             "The trapezoid rule's error falls as n^-2 in 1D. What happens to its error per evaluation in k dimensions, and to Monte Carlo's?",
             ["1: N = n^k evaluations, so the error falls as N^(-2/k)",
              "1: Monte Carlo's stays N^(-1/2) in every dimension; it wins beyond k = 4"]),
    ]


def questions_a2(p):
    r0, theta0 = p["r0"], p["theta0"]
    one_minus_cos = 1 - math.cos(math.radians(p["cone_deg"]))
    return [
        number("density_ratio", 1, "With r = u0, the density at radius r0 divided by the correct 1/pi",
               1 / (2 * r0), "r = u0 puts probability dr on each ring of area 2 pi r dr"),
        number("cosine_pdf", 1, "The cosine hemisphere pdf at theta0 (per steradian)",
               math.cos(math.radians(theta0)) / math.pi, "p = cos(theta) / pi"),
        choice("cosine_cell_counts", 1,
               "The cosine sampler's points binned in the equal (phi, cos theta) cells: its expected count per cell",
               {"a": "is the same in every cell",
                "b": "is larger near the pole, in proportion to the integral of cos(theta) over the cell",
                "c": "is larger near the horizon"},
               "b", "expected count = N times the integral of p = cos(theta) / pi over the cell"),
        text("malley", 2, "Show that Malley's method gives p(omega) = cos(theta) / pi.",
             ["1: the disk point has density 1/pi per unit area",
              "1: projecting up, dA = cos(theta) d omega, so p(omega) = cos(theta) / pi"]),
        choice("wrong_pdf_test", 1,
               "A pdf of 1/pi for the uniform hemisphere passes the sampler's chi-square test. Which test catches it?",
               {"a": "the chi-square test at more samples", "b": "the test that the pdf integrates to 1",
                "c": "the unit-vector test", "d": "none"},
               "b", "the chi-square test of the sampler never sees the pdf's constant"),
        number("cone_pdf", 1, "The pdf per steradian of directions uniform in a cone of half-angle theta_max",
               1 / (2 * math.pi * one_minus_cos), "p = 1 / (2 pi (1 - cos(theta_max))): one over the cap's solid angle"),
        text("cone_derivation", 3,
             "Derive sample_uniform_cone by the inversion method from p(w) = 1 / (2 pi (1 - cos(theta_max))).",
             ["1: the marginal of cos(theta) is uniform on [cos(theta_max), 1] (d omega = d phi d cos(theta), "
              "and phi is uniform on [0, 2 pi) independently)",
              "1: its CDF F(cos theta) = (1 - cos(theta)) / (1 - cos(theta_max)) (or the same from the rim)",
              "1: inverted at u0: cos(theta) = 1 - u0 (1 - cos(theta_max)); phi = 2 pi u1; 1 - u0 in place of u0 "
              "is as good"]),
    ]


def furnace_recursion_variance(a, n, k):
    """Var[L_k] of the recursion in the furnace (Le = 1): V_j = a^2 / (3N) (4 V_(j-1) + m_(j-1)^2)."""
    v, m = 0.0, 1.0
    for _ in range(k):
        v, m = a * a / (3 * n) * (4 * v + m * m), 1 + a * m
    return v


def questions_a3(p):
    n, k = p["branches"], p["depth"]
    rays = sum(n ** j for j in range(k + 1))
    seconds = p["width"] * p["height"] * p["spp"] * rays / p["rate"]
    return [
        number("rays_per_pixel", 1, "Rays of one pixel at spp samples, N branches, depth k, in the furnace",
               p["spp"] * rays, "spp x (1 + N + N^2 + ... + N^k): the camera ray, then N rays per vertex"),
        number("image_seconds", 1, "Seconds for the image at the given size, spp and rate", seconds,
               "pixels x spp x rays per sample / rays per second"),
        text("variance_and_cost", 2,
             "Why does the variance fall with N but the cost grow as N^k? Compare with N = 1 and N times more samples per pixel.",
             ["1: branching averages only the first bounce's estimate over N; deeper levels multiply the rays",
              "1: N = 1 with N times the samples buys the same or more variance reduction for far fewer rays"]),
        number("furnace_variance", 1, "The variance of one camera sample's estimate in the furnace (Le = 1)",
               furnace_recursion_variance(p["albedo"], n, k),
               "Var[w L] = E[w^2] E[L^2] - (E[w] E[L])^2 at every level, divided by N"),
    ]


def questions_a4(p):
    a, k, le = p["albedo"], p["depth"], p["emission"]
    return [
        number("furnace_mean", 1, "The furnace mean at albedo a, depth k, emission Le",
               le * (1 - a ** (k + 1)) / (1 - a), "Le (1 + a + ... + a^k)"),
        number("furnace_limit", 1, "The furnace mean as k -> infinity", le / (1 - a), "a geometric series"),
        number("third_moment", 1, "E[w^3] of one bounce's weight w = 2a cos(theta), uniform hemisphere sampling",
               2 * a ** 3, "cos(theta) is uniform on [0, 1] under uniform hemisphere sampling"),
        choice("stop_at_zero", 1, "Why may a path stop when beta = 0 without bias?",
               {"a": "every later term is multiplied by beta = 0", "b": "it is biased, but little",
                "c": "the emission is counted at the next vertex"},
               "a", "the rest of the sum has the factor beta"),
        text("independent_reference", 2,
             "Why is comparing with an independent implementation at another seed stronger than with your own tracer at more samples?",
             ["1: your own tracer shares your bug, so it agrees with itself whatever the bug",
              "1: another seed makes the two estimates independent, so the standard errors are honest"]),
    ]


def questions_a5(p):
    a, d, q, j = p["albedo"], p["min_depth"], p["q"], p["vertex"]
    h, s, dx, lights = p["height"], p["side"], p["offset"], p["lights"]
    r2 = h * h + dx * dx
    return [
        number("no_division_mean", 1,
               "Fixed q after d, survivors keep their weight (no division by q): the furnace mean (Le = 1)",
               (1 - a ** (d + 1)) / (1 - a) + a ** d * a * q / (1 - a * q),
               "vertex j > d is reached with probability q^(j - d) and then adds a^j on average"),
        number("survivor_weight", 1, "E[beta_j] over the paths that reach vertex j (furnace, uniform sampling)",
               a ** j / q ** (j - d), "each survival divides beta by q; each bounce multiplies its mean by a"),
        number("wrong_pdf_mean", 1,
               "Cosine directions divided by the uniform pdf 1/(2 pi): the mean weight of one furnace bounce",
               4 * a / 3, "w = 2a cos(theta), and E[cos(theta)] = 2/3 under the cosine pdf"),
        number("light_pdf", 1, "p_omega of the light point straight above x (per steradian, every light counted)",
               h * h / (lights * s * s), "p_omega = p_A r^2 / cos(theta_y), p_A = 1 / (N_lights s^2)"),
        number("light_term", 1, "The NEE term f_r Le cos(theta_x) / p_omega for the point at the offset (Le = 1, V = 1)",
               a / math.pi * h * h / (r2 * r2) * lights * s * s,
               "cos(theta_x) = cos(theta_y) = h / r, r^2 = h^2 + offset^2"),
        choice("missing_one_over_n", 1, "NEE without the 1/N_lights in p_omega, in a scene of N_lights equal lights: the direct light is",
               {"a": "N_lights times too bright", "b": "N_lights times too dark", "c": "unbiased"},
               "b", "the pdf is N_lights times too large, so each term is N_lights times too small"),
        text("furnace_blind_spot", 2,
             "Name one bug of sample_direct_light that the exact furnace test of a5.3 cannot catch, and the test of the handout that catches it.",
             ["1: a bug the furnace hides: its one light is the whole sphere and nothing occludes (a missing 1/N_lights, "
              "a visibility test that never blocks, sampling only the visible cap)",
              "1: the test that sees it: two lights (1/N_lights), the Cornell box regions (shadows), the strip above the ceiling (the cap)"]),
    ]


def questions_a6(p):
    m, pl, pb = p["m"], p["p_light"], p["p_bsdf"]
    return [
        number("one_minus_cos", 1, "1 - cos(alpha) of the lobe's sample at m and u0 = 1 - 1e-9",
               -math.expm1(math.log1p(-1e-9) / (m + 1)), "cos(alpha) = u0^(1/(m + 1)): invert the CDF c^(m+1)"),
        number("balance_weight", 1, "The balance heuristic's weight of the light sample, p_l and p_b given",
               pl / (pl + pb), "w_l = p_l / (p_l + p_b)"),
        number("power_weight", 1, "The power heuristic's weight of the light sample, p_l and p_b given",
               pl * pl / (pl * pl + pb * pb), "w_l = p_l^2 / (p_l^2 + p_b^2)"),
        choice("weights_sum", 1,
               "One sample of each strategy, weights with w_l + w_b = 1 wherever f Le cos > 0 and w_s = 0 wherever p_s = 0: the estimator is",
               {"a": "unbiased, whatever such weights", "b": "unbiased only with the balance heuristic",
                "c": "unbiased only if both pdfs are positive wherever f Le cos > 0"},
               "a", "E[w_s f Le cos / p_s] is the integral of w_s f Le cos where p_s > 0; add the two"),
        text("light_sampling_wins", 2,
             "On which plate x light region does light sampling alone beat MIS at equal rays, and why can MIS not win there?",
             ["1: a region where the light's pdf follows the integrand much better than the lobe's: "
              "a rough plate under a small light",
              "1: at equal rays MIS spends half its rays on BSDF samples that there almost never reach "
              "the light: weighting keeps it unbiased and robust, but cannot make those rays useful"]),
    ]


def radical_inverse(i, b):
    """phi_b(i): i's base-b digits mirrored about the point, as an exact fraction's float."""
    mirrored, scale = 0, 1
    while i:
        i, d = divmod(i, b)
        mirrored, scale = mirrored * b + d, scale * b
    return mirrored / scale


def questions_a7(p):
    i, b, c, n = p["index"], p["base"], p["slope"], p["strata"]
    return [
        number("radical_inverse", 1, "phi_b(i), the radical inverse of i in base b (i and b given)",
               radical_inverse(i, b), "write i in base b and mirror its digits about the point"),
        number("jittered_variance", 1,
               "The variance of the jittered estimate of the integral of f(x) = c x over [0, 1] with n strata",
               c * c / (12.0 * n ** 3),
               "each stratum's point is uniform on an interval of width 1/n: c^2 / (12 n^2) each, "
               "and the estimate is the mean of n of them"),
        choice("unscrambled_halton", 1,
               "The plain (unscrambled) Halton points, used as an estimator (1/n) sum f(x_i), give an estimate that is",
               {"a": "unbiased, since the points are evenly spread",
                "b": "deterministic, so biased for most f: its error is a fixed number",
                "c": "unbiased when n is a power of the base"},
               "b", "an estimate is unbiased when each point is uniform; a fixed point is not random"),
        text("never_worse", 2,
             "Why is the variance of a jittered estimate never above that of independent points at equal n?",
             ["1: Var = (1/n^2) sum_k sigma_k^2, the variances within the equal-probability strata",
              "1: sigma^2 = (1/n) sum_k sigma_k^2 + (1/n) sum_k (mu_k - mu)^2: stratifying removes the "
              "variance between the strata' means, which is never negative"]),
    ]


QUESTIONS = {"a1": questions_a1, "a2": questions_a2, "a3": questions_a3, "a4": questions_a4,
             "a5": questions_a5, "a6": questions_a6, "a7": questions_a7}


def questions(a, secret=None):
    """The questions of assignment `a` with their answers, for the variant of `secret`."""
    return QUESTIONS[a](params(a, secret)) if a in QUESTIONS else []


def shared_answers(a, secret, other):
    """The numeric questions of `a` that the variants `secret` and `other` answer alike (within
    the grading tolerance): one variant's answer would score in the other."""
    theirs = {q["id"]: q["answer"] for q in questions(a, other) if q["kind"] == "number"}
    return [q["id"] for q in questions(a, secret) if q["kind"] == "number" and
            abs(q["answer"] - theirs[q["id"]]) <= q["rel_tol"] * max(abs(q["answer"]), abs(theirs[q["id"]]))]


def key_json(a, secret=None):
    """The answer key and rubric of `a` as the autograder carries it (its hidden folder)."""
    return json.dumps({"assignment": a, "questions": questions(a, secret)}, indent=2) + "\n"


def answers_template(a):
    """The answers file a kit holds: every answer null (the prompts are in the handout)."""
    out = {"_instructions": f"Assignment {a}'s written answers (docs/assignments/{a}.md, "
                            "'Written answers'): replace each null by a number, a letter, or "
                            "your text, as the handout asks."}
    for q in questions(a):
        out[q["id"]] = None
    return json.dumps(out, indent=2) + "\n"


def solution_answers(a, secret=None):
    """The answers file filled with the key's answers (text: the rubric's points)."""
    out = {}
    for q in questions(a, secret):
        out[q["id"]] = q["answer"] if q["kind"] != "text" else " ".join(q["rubric"])
    return json.dumps(out, indent=2) + "\n"


def hidden_grid():
    """Every value a variant may draw for the hidden tests' varied parameters (no seeds): what
    measure_assignment_fairness --variants measures at every point of."""
    return {a: {name: choices for name, (_, choices) in table.items() if choices is not None}
            for a, table in HIDDEN.items()}


if __name__ == "__main__":
    import sys
    if sys.argv[1:] != ["--hidden-grid"]:
        print("usage: key.py --hidden-grid   (the hidden tests' variant grid as JSON)", file=sys.stderr)
        sys.exit(2)
    print(json.dumps(hidden_grid(), indent=1))
