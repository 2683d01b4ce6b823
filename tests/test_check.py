# ruff: noqa: E501  (the messages are compared word for word)
"""The exercise checkers, judged on a table of student answers: right ones, each in several
algebraically equivalent forms (scalar Python and numpy), must pass; wrong ones must get exactly
the message a good teaching assistant would give."""

from __future__ import annotations

import math

import numpy as np
import pytest

from interp import check


def _not_written(*args):
    raise NotImplementedError()


def _numeric_peak(w1, w2):
    s = np.linspace(0, 1, 100001)
    t = s * w1 / (s * w1 + (1 - s) * w2)
    return s[np.argmax(np.abs(t - s))]


def _t_forgets_w1_equals_w2(s, w1, w2):
    # solved for t by a route that divides by w1 - w2
    return s * w1 / (w2 + s * (w1 - w2)) if w1 != w2 else float("nan")


def _t_divides_by_s(s, w1, w2):
    return 1 / (1 + (1 - s) * w2 / (s * w1))


def _lerp_via_t(a1, a2, w1, w2, s):
    t = s * w1 / (s * w1 + (1 - s) * w2)
    return (1 - t) * a1 + t * a2


def _lerp_ek_first_form(a1, a2, w1, w2, s):
    return (w1 * s * a2 + w2 * (1 - s) * a1) / (w2 * (1 - s) + w1 * s)


def _lerp_ek_second_form(a1, a2, w1, w2, s):
    z = 1 / ((1 - s) / w1 + s / w2)
    return z * (a1 / w1 * (1 - s) + a2 / w2 * s)


def _lerp_numpy(a1, a2, w1, w2, s):
    a, w, b = np.array([a1, a2]), np.array([w1, w2]), np.array([1 - s, s])
    return np.sum(b * a / w) / np.sum(b / w)


def _weights_numpy(b0, b1, b2, w0, w1, w2):
    q = np.array([b0, b1, b2]) / np.array([w0, w1, w2])
    return q / q.sum()


def _weights_tuple(b0, b1, b2, w0, w1, w2):
    d = b0 * w1 * w2 + b1 * w0 * w2 + b2 * w0 * w1
    return (b0 * w1 * w2 / d, b1 * w0 * w2 / d, b2 * w0 * w1 / d)


def _where_closed_form(x1, z1, x2, z2, d):
    return z2 / (z1 + z2)


def _where_projected(x1, z1, x2, z2, d):
    a, b = d * x1 / -z1, d * x2 / -z2
    m = d * (x1 + x2) / -(z1 + z2)
    return (m - a) / (b - a)


def _where_numpy(x1, z1, x2, z2, d):
    P = np.array([[x1, z1], [(x1 + x2) / 2, (z1 + z2) / 2], [x2, z2]])
    a, m, b = d * P[:, 0] / -P[:, 1]
    return (m - a) / (b - a)


def _where_mirrored(x1, z1, x2, z2, d):  # dividing by z instead of -z mirrors all three alike
    a, b, m = d * x1 / z1, d * x2 / z2, d * (x1 + x2) / (z1 + z2)
    return (m - a) / (b - a)


def _table(**rows):
    """Lesson 7's worked-example table, right, with some rows changed."""
    from interp import worked

    right = {k: v for k, v in worked.table().items() if k in check.WORKED_ROWS}
    return lambda: {**right, **rows}


def _table_by_hand():
    # typed in as a student would, in plain Python numbers and lists
    return {
        "w": [1, 2, 4],
        "ndc x": [-3 / 4, 3 / 4, -1 / 4],
        "ndc y": [-0.75, -0.75, 0],
        "window x": [1, 7, 3],
        "window y": [1, 1, 4],
        "b": [1 / 4, 1 / 4, 1 / 2],
        "lambda": np.array([0.5, 0.25, 0.25]),
        "u": 3 / 8,
    }


def _near_clip_one_minus(z1, w1, z2, w2):
    return 1 - (z1 + w1) / ((z1 + w1) - (z2 + w2))


RIGHT = [
    (check.project, "d x / -z", lambda x, z, d: d * x / -z),
    (check.project, "d x / |z|", lambda x, z, d: d * x / abs(z)),
    (check.project, "numpy", lambda x, z, d: np.divide(d * x, -z)),
    (check.where_m_lands, "project three points", _where_projected),
    (check.where_m_lands, "closed form w2 / (w1 + w2)", _where_closed_form),
    (check.where_m_lands, "numpy", _where_numpy),
    (check.where_m_lands, "mirrored projection", _where_mirrored),
    (check.s_from_t, "CS5500", lambda t, w1, w2: t * w2 / ((1 - t) * w1 + t * w2)),
    (check.s_from_t, "1/w form", lambda t, w1, w2: (t / w1) / ((1 - t) / w2 + t / w1)),
    (
        check.s_from_t,
        "numpy",
        lambda t, w1, w2: np.float64(t) * w2 / np.interp(t, [0, 1], [w1, w2]),
    ),
    (check.t_from_s, "CS5500", lambda s, w1, w2: s * w1 / (s * w1 + (1 - s) * w2)),
    (check.t_from_s, "1/w form", lambda s, w1, w2: (s / w2) / ((1 - s) / w1 + s / w2)),
    (
        check.t_from_s,
        "numpy",
        lambda s, w1, w2: np.true_divide(s * w1, np.dot([s, 1 - s], [w1, w2])),
    ),
    (check.gap_peak, "sqrt form", lambda w1, w2: math.sqrt(w2) / (math.sqrt(w1) + math.sqrt(w2))),
    (check.gap_peak, "ratio form", lambda w1, w2: 1 / (1 + (w1 / w2) ** 0.5)),
    (check.gap_peak, "solved quadratic", lambda w1, w2: (w2 - math.sqrt(w1 * w2)) / (w2 - w1)),
    (check.gap_peak, "numpy", lambda w1, w2: np.sqrt(w2) / np.sqrt([w1, w2]).sum()),
    (check.ndc_depth, "matrix", lambda w, n, f: (f + n) / (f - n) - 2 * f * n / ((f - n) * w)),
    (check.ndc_depth, "one fraction", lambda w, n, f: ((f + n) * w - 2 * f * n) / ((f - n) * w)),
    (
        check.ndc_depth,
        "numpy matrix",
        lambda w, n, f: (
            np.array([0, 0, -(f + n) / (f - n), -2 * f * n / (f - n)]) @ [0, 0, -w, 1] / w
        ),
    ),
    (
        check.perspective_lerp,
        "lerp(a/w) / lerp(1/w)",
        lambda a1, a2, w1, w2, s: ((1 - s) * a1 / w1 + s * a2 / w2) / ((1 - s) / w1 + s / w2),
    ),
    (check.perspective_lerp, "via t", _lerp_via_t),
    (check.perspective_lerp, "Ek's first form", _lerp_ek_first_form),
    (check.perspective_lerp, "Ek's second form", _lerp_ek_second_form),
    (check.perspective_lerp, "numpy", _lerp_numpy),
    (check.checker, "floor", lambda u, v, f: (math.floor(u * f) + math.floor(v * f)) % 2),
    (check.checker, "numpy, bool", lambda u, v, f: np.floor(u * f) % 2 != np.floor(v * f) % 2),
    (check.checker, "xor", lambda u, v, f: (math.floor(u * f) % 2) ^ (math.floor(v * f) % 2)),
    (
        check.affine_error,
        "f |s - t|",
        lambda s, w1, w2, f: f * abs(s - s * w1 / (s * w1 + (1 - s) * w2)),
    ),
    (
        check.affine_error,
        "one fraction",
        lambda s, w1, w2, f: f * abs(s * (1 - s) * (w2 - w1)) / (s * w1 + (1 - s) * w2),
    ),
    (
        check.affine_error,
        "numpy",
        lambda s, w1, w2, f: np.abs(np.float64(s) - s * w1 / (s * w1 + (1 - s) * w2)) * f,
    ),
    (
        check.clip_barycentrics,
        "list",
        lambda b0, b1, b2, w0, w1, w2: [
            x / (b0 / w0 + b1 / w1 + b2 / w2) for x in (b0 / w0, b1 / w1, b2 / w2)
        ],
    ),
    (check.clip_barycentrics, "numpy array", _weights_numpy),
    (check.clip_barycentrics, "tuple, cleared of fractions", _weights_tuple),
    (check.worked_example, "the library's numbers", _table()),
    (check.worked_example, "typed in by hand", _table_by_hand),
    (
        check.near_clip,
        "distances to the plane",
        lambda z1, w1, z2, w2: (z1 + w1) / ((z1 + w1) - (z2 + w2)),
    ),
    (check.near_clip, "solved for t", lambda z1, w1, z2, w2: -(z1 + w1) / (z2 - z1 + w2 - w1)),
    (check.recap_1, "letters", lambda: {1: "b", 2: "a", 3: "b", 4: "b"}),
    (
        check.recap_4,
        "upper case, lists, string keys",
        lambda: {1: ["D", "b", "c"], "2": "A", 3: "b", 4: "a"},
    ),
    (check.recap_7, "letters in any order", lambda: {1: "fedb", 2: "a", 3: "a", 4: "a"}),
    (check.recap_9, "letters", lambda: {1: "b", 2: "c", 3: "a", 4: "b"}),
    (check.recap_10, "with commas", lambda: {1: "a", 2: "a", 3: "b, c, f", 4: "a"}),
]


@pytest.mark.parametrize(
    ("checker", "label", "answer"), RIGHT, ids=[f"{c.__name__}: {label}" for c, label, _ in RIGHT]
)
def test_right_answers_pass(checker, label, answer):
    verdict = checker(answer)
    assert verdict, (label, verdict)


WRONG = [
    # every checker: what it returned is not an answer, or it is not written yet
    (check.t_from_s, "not written yet", _not_written),
    (check.t_from_s, "forgot return", lambda s, w1, w2: None),
    (check.t_from_s, "a string", lambda s, w1, w2: "s*w1/(s*w1+(1-s)*w2)"),
    (check.t_from_s, "a dict", lambda s, w1, w2: {"t": s}),
    (check.t_from_s, "a generator", lambda s, w1, w2: (x for x in [s])),
    (check.t_from_s, "a list of 2", lambda s, w1, w2: [s, 1 - s]),
    (check.t_from_s, "not a function", 0.25),
    (check.gap_peak, "complex", lambda w1, w2: (w1 - w2) ** 0.5),
    (check.gap_peak, "both s* and the gap", lambda w1, w2: (0.5, 0.5)),
    (
        check.clip_barycentrics,
        "a generator",
        lambda b0, b1, b2, w0, w1, w2: (b for b in (b0, b1, b2)),
    ),
    (check.clip_barycentrics, "two weights", lambda b0, b1, b2, w0, w1, w2: [b0, b1]),
    (check.clip_barycentrics, "one number", lambda b0, b1, b2, w0, w1, w2: b0),
    (check.clip_barycentrics, "forgot return", lambda *args: None),
    (check.clip_barycentrics, "not written yet", _not_written),
    (check.worked_example, "not written yet", _not_written),
    (check.worked_example, "forgot return", lambda: None),
    (check.worked_example, "a list", lambda: [1, 2, 4]),
    (check.worked_example, "raises", lambda: 1 / 0),
    (check.recap_4, "not written yet", _not_written),
    (check.recap_4, "forgot return", lambda: None),
    (check.recap_4, "a string", lambda: "bcd a b a"),
    (check.near_clip, "not written yet", _not_written),
    # project
    (check.project, "mirrored", lambda x, z, d: d * x / z),
    (check.project, "no d", lambda x, z, d: x / -z),
    (check.project, "no divide", lambda x, z, d: d * x),
    (check.project, "wrong", lambda x, z, d: d * x / (1 - z)),
    # where_m_lands
    (check.where_m_lands, "one half", lambda *args: 0.5),
    (check.where_m_lands, "from b", lambda x1, z1, x2, z2, d: z1 / (z1 + z2)),
    (check.where_m_lands, "m itself", lambda x1, z1, x2, z2, d: d * (x1 + x2) / -(z1 + z2)),
    (check.where_m_lands, "ratio of depths", lambda x1, z1, x2, z2, d: z2 / z1),
    # s_from_t
    (check.s_from_t, "t itself", lambda t, w1, w2: t),
    (check.s_from_t, "t_from_s instead", lambda t, w1, w2: t * w1 / (t * w1 + (1 - t) * w2)),
    # t_from_s
    (check.t_from_s, "s itself", lambda s, w1, w2: s),
    (check.t_from_s, "forward map", lambda s, w1, w2: s * w2 / ((1 - s) * w1 + s * w2)),
    (check.t_from_s, "swapped w", lambda s, w1, w2: s * w2 / (s * w2 + (1 - s) * w1)),
    (check.t_from_s, "weights w, not 1/w", lambda s, w1, w2: (s * w2) / ((1 - s) * w1 + s * w2)),
    (check.t_from_s, "from B", lambda s, w1, w2: (1 - s) * w2 / (s * w1 + (1 - s) * w2)),
    (check.t_from_s, "divides by zero at s = 0", _t_divides_by_s),
    (
        check.t_from_s,
        "numpy divides by zero at s = 0",
        lambda s, w1, w2: 1 / (1 + (1 - s) * w2 / (np.float64(s) * w1)),
    ),
    (check.t_from_s, "wrong only at w1 = w2", _t_forgets_w1_equals_w2),
    (
        check.t_from_s,
        "divides by zero at w1 = w2",
        lambda s, w1, w2: s * w1 * (w1 - w2) / (s * w1 * (w1 - w2) + (1 - s) * w2 * (w1 - w2)),
    ),
    (check.t_from_s, "wrong", lambda s, w1, w2: s * w1 / (s * w1 + w2)),
    # gap_peak
    (check.gap_peak, "one half", lambda w1, w2: 0.5),
    (check.gap_peak, "swapped", lambda w1, w2: w1**0.5 / (w1**0.5 + w2**0.5)),
    (check.gap_peak, "no square roots", lambda w1, w2: w2 / (w1 + w2)),
    (check.gap_peak, "the height", lambda w1, w2: abs(w2**0.5 - w1**0.5) / (w1**0.5 + w2**0.5)),
    (check.gap_peak, "coarse numerics", lambda w1, w2: float(np.round(_numeric_peak(w1, w2), 1))),
    # ndc_depth
    (check.ndc_depth, "linear in w", lambda w, n, f: 2 * (w - n) / (f - n) - 1),
    (check.ndc_depth, "z_clip", lambda w, n, f: (f + n) / (f - n) * w - 2 * f * n / (f - n)),
    (check.ndc_depth, "window z", lambda w, n, f: f / (f - n) - f * n / ((f - n) * w)),
    (check.ndc_depth, "sign", lambda w, n, f: 2 * f * n / ((f - n) * w) - (f + n) / (f - n)),
    (check.ndc_depth, "no factor 2", lambda w, n, f: (f + n) / (f - n) - f * n / ((f - n) * w)),
    # perspective_lerp
    (check.perspective_lerp, "affine", lambda a1, a2, w1, w2, s: (1 - s) * a1 + s * a2),
    (
        check.perspective_lerp,
        "no divide",
        lambda a1, a2, w1, w2, s: (1 - s) * a1 / w1 + s * a2 / w2,
    ),
    (
        check.perspective_lerp,
        "times lerp w",
        lambda a1, a2, w1, w2, s: ((1 - s) * a1 / w1 + s * a2 / w2) * ((1 - s) * w1 + s * w2),
    ),
    (
        check.perspective_lerp,
        "weights w",
        lambda a1, a2, w1, w2, s: ((1 - s) * a1 * w1 + s * a2 * w2) / ((1 - s) * w1 + s * w2),
    ),
    (
        check.perspective_lerp,
        "swapped w",
        lambda a1, a2, w1, w2, s: _lerp_via_t(a1, a2, w2, w1, s),
    ),
    (
        check.perspective_lerp,
        "t from s_from_t",
        lambda a1, a2, w1, w2, s: a1 + (a2 - a1) * s * w2 / ((1 - s) * w1 + s * w2),
    ),
    (
        check.perspective_lerp,
        "a2 - a1 slip",
        lambda a1, a2, w1, w2, s: _lerp_via_t(0, a2, w1, w2, s),
    ),
    # checker
    (
        check.checker,
        "swapped colours",
        lambda u, v, f: 1 - (math.floor(u * f) + math.floor(v * f)) % 2,
    ),
    (check.checker, "no frequency", lambda u, v, f: (math.floor(u) + math.floor(v)) % 2),
    (check.checker, "round", lambda u, v, f: (round(u * f) + round(v * f)) % 2),
    (check.checker, "int", lambda u, v, f: (int(u * f) + int(v * f)) % 2),
    # affine_error
    (check.affine_error, "in u", lambda s, w1, w2, f: abs(s - s * w1 / (s * w1 + (1 - s) * w2))),
    (check.affine_error, "signed", lambda s, w1, w2, f: f * (s - s * w1 / (s * w1 + (1 - s) * w2))),
    (
        check.affine_error,
        "s_from_t",
        lambda s, w1, w2, f: f * abs(s - s * w2 / ((1 - s) * w1 + s * w2)),
    ),
    (
        check.affine_error,
        "the gap",
        lambda s, w1, w2, f: f * abs(w2**0.5 - w1**0.5) / (w1**0.5 + w2**0.5),
    ),
    # clip_barycentrics
    (check.clip_barycentrics, "unchanged", lambda b0, b1, b2, w0, w1, w2: [b0, b1, b2]),
    (
        check.clip_barycentrics,
        "not normalised",
        lambda b0, b1, b2, w0, w1, w2: [b0 / w0, b1 / w1, b2 / w2],
    ),
    (
        check.clip_barycentrics,
        "times w",
        lambda b0, b1, b2, w0, w1, w2: [
            x / (b0 * w0 + b1 * w1 + b2 * w2) for x in (b0 * w0, b1 * w1, b2 * w2)
        ],
    ),
    (
        check.clip_barycentrics,
        "normalised by the sum of b",
        lambda b0, b1, b2, w0, w1, w2: [b0 / w0, b1 / w1, b2 / w2 * 0],
    ),
    # worked_example
    (check.worked_example, "a row missing", lambda: {"w": (1, 2, 4)}),
    (check.worked_example, "clip z for w", _table(w=(0.125, 1.375, 3.875))),
    (check.worked_example, "no divide", _table(**{"ndc x": (-0.75, 1.5, -1.0)})),
    (check.worked_example, "rows from the top", _table(**{"window y": (7, 7, 4)})),
    (check.worked_example, "window x slip", _table(**{"window x": (1, 7, 4)})),
    (check.worked_example, "lambda = b", _table(**{"lambda": (0.25, 0.25, 0.5)})),
    (check.worked_example, "lambda not normalised", _table(**{"lambda": (0.25, 0.125, 0.125)})),
    (check.worked_example, "lambda weighted by w", _table(**{"lambda": (1 / 11, 2 / 11, 8 / 11)})),
    (check.worked_example, "affine u", _table(u=0.625)),
    (check.worked_example, "two weights", _table(**{"lambda": (0.5, 0.25)})),
    (check.worked_example, "u as text", _table(u="0.375")),
    # recap
    (check.recap_4, "a wrong option", lambda: {1: "bcde", 2: "a", 3: "b", 4: "a"}),
    (check.recap_4, "one missing", lambda: {1: "bc", 2: "a", 3: "b", 4: "a"}),
    (check.recap_4, "two for one", lambda: {1: "bcd", 2: "ab", 3: "b", 4: "z"}),
    (check.recap_4, "unanswered", lambda: {1: "bcd", 2: "a", 3: "b", 4: 2}),
    (check.recap_4, "a question too many", lambda: {1: "bcd", 2: "a", 3: "b", 4: "a", 5: "a"}),
    # near_clip
    (check.near_clip, "from the outside vertex", _near_clip_one_minus),
    (check.near_clip, "the far plane", lambda z1, w1, z2, w2: (z1 - w1) / ((z1 - w1) - (z2 - w2))),
    (check.near_clip, "in NDC", lambda z1, w1, z2, w2: (-1 - z1 / w1) / (z2 / w2 - z1 / w1)),
    (check.near_clip, "z only", lambda z1, w1, z2, w2: (z1 + w1) / (z1 - z2)),
]

#: The message each wrong answer must get, word for word.
EXPECTED = {
    (
        "t_from_s",
        "not written yet",
    ): "… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.",
    ("t_from_s", "forgot return"): "✗ your function returned None: did you forget `return`?",
    (
        "t_from_s",
        "a string",
    ): "✗ your function returned a string, 's*w1/(s*w1+(1-s)*w2)': return a number, not text.",
    ("t_from_s", "a dict"): "✗ your function returned a dict: return a number.",
    ("t_from_s", "a generator"): "✗ your function returned a generator: return a number.",
    ("t_from_s", "a list of 2"): "✗ your function returned a list of 2 values: return one number.",
    ("t_from_s", "not a function"): "✗ pass your function itself, e.g. check.t_from_s(my_function)",
    (
        "gap_peak",
        "complex",
    ): "✗ your function returned a complex number, 1.732e-16+2.828j: is there a square root or a fractional power of a negative number?",
    (
        "gap_peak",
        "both s* and the gap",
    ): "✗ your function returned a tuple of 2 values: return one number.",
    (
        "clip_barycentrics",
        "a generator",
    ): "✗ your function returned a generator: return a list, e.g. `[x / total for x in q]` or `list(...)`.",
    (
        "clip_barycentrics",
        "two weights",
    ): "✗ your function returned a list of 2 values: return three weights, one per vertex.",
    (
        "clip_barycentrics",
        "one number",
    ): "✗ your function returned one number: return three weights, one per vertex.",
    (
        "clip_barycentrics",
        "forgot return",
    ): "✗ your function returned None: did you forget `return`?",
    (
        "clip_barycentrics",
        "not written yet",
    ): "… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.",
    (
        "project",
        "mirrored",
    ): "✗ the image is mirrored: divide by the depth w = -z (the camera looks down -z), not by z.",
    (
        "project",
        "no d",
    ): "✗ scale by d: the image plane is d away from the eye (your answer is right only where d = 1).",
    (
        "project",
        "no divide",
    ): "✗ divide by the depth: a point twice as far away lands twice as close to the axis.",
    (
        "project",
        "wrong",
    ): "✗ for (x, z, d) = (1, -2, 1) the answer is 0.5, your function gave 0.333333.",
    (
        "where_m_lands",
        "one half",
    ): "✗ 1/2 is where M would land if projection kept ratios along the line. It does so only when A and B are equally deep: project A, B and M, then ask how far m is from a, as a fraction of the way to b.",
    (
        "where_m_lands",
        "from b",
    ): "✗ that is measured from b: s is 0 at a, the image of A, and 1 at b.",
    (
        "where_m_lands",
        "m itself",
    ): "✗ that is m, the image coordinate of M; now say where m lies between a and b, as a fraction of the way from a to b.",
    (
        "where_m_lands",
        "ratio of depths",
    ): "✗ for (x1, z1, x2, z2, d) = (-1, -1, 2, -3, 1) the answer is 0.75, your function gave 3.",
    (
        "s_from_t",
        "t itself",
    ): "✗ that is t itself, true only when w1 = w2. Project the point P(t) = (1-t) A + t B: it is the interpolated position that gets divided by its depth.",
    (
        "s_from_t",
        "t_from_s instead",
    ): "✗ your function gives t w1 / (t w1 + (1-t) w2): that is t_from_s applied to t, and also s_from_t with w1 and w2 swapped (the same formula, so either mistake gives these numbers). At (t, w1, w2) = (0.5, 1, 3) the answer is 0.75: the middle of AB shows nearer b, the image of the far end.",
    (
        "t_from_s",
        "s itself",
    ): "✗ that is s itself, true only when w1 = w2 (the segment parallel to the image plane). The pixel at s shows the point P(t) whose projection lands at p(s): project P(t) and solve for t.",
    (
        "t_from_s",
        "forward map",
    ): "✗ your function gives s w2 / (s w2 + (1-s) w1): that is the forward map s_from_t applied to s, and also t_from_s with w1 and w2 swapped, or with each end weighted by its own w where 1/w belongs (all the same formula, so I cannot tell which you did). At (s, w1, w2) = (0.5, 1, 3) the answer is 0.25: the middle of the image shows a point nearer A, the near end.",
    (
        "t_from_s",
        "swapped w",
    ): "✗ your function gives s w2 / (s w2 + (1-s) w1): that is the forward map s_from_t applied to s, and also t_from_s with w1 and w2 swapped, or with each end weighted by its own w where 1/w belongs (all the same formula, so I cannot tell which you did). At (s, w1, w2) = (0.5, 1, 3) the answer is 0.25: the middle of the image shows a point nearer A, the near end.",
    (
        "t_from_s",
        "weights w, not 1/w",
    ): "✗ your function gives s w2 / (s w2 + (1-s) w1): that is the forward map s_from_t applied to s, and also t_from_s with w1 and w2 swapped, or with each end weighted by its own w where 1/w belongs (all the same formula, so I cannot tell which you did). At (s, w1, w2) = (0.5, 1, 3) the answer is 0.25: the middle of the image shows a point nearer A, the near end.",
    ("t_from_s", "from B"): "✗ that is 1 - t: t is measured from A (t = 0 at A, 1 at B).",
    (
        "t_from_s",
        "numpy divides by zero at s = 0",
    ): "✗ your function divided by zero at (s, w1, w2) = (0, 1, 3) (s = 0), where the answer is 0. It is right everywhere else: only s = 0 goes wrong.",
    (
        "t_from_s",
        "divides by zero at s = 0",
    ): "✗ your function divided by zero at (s, w1, w2) = (0, 1, 3) (s = 0), where the answer is 0. It is right everywhere else: only s = 0 goes wrong.",
    (
        "t_from_s",
        "wrong only at w1 = w2",
    ): "✗ for (s, w1, w2) = (0.3, 2, 2) (w1 = w2) the answer is 0.3, your function gave nan. It is right everywhere else: only w1 = w2 goes wrong.",
    (
        "t_from_s",
        "divides by zero at w1 = w2",
    ): "✗ your function divided by zero at (s, w1, w2) = (0.3, 2, 2) (w1 = w2), where the answer is 0.3. It is right everywhere else: only w1 = w2 goes wrong.",
    (
        "t_from_s",
        "wrong",
    ): "✗ for (s, w1, w2) = (0.5, 1, 3) the answer is 0.25, your function gave 0.142857.",
    (
        "gap_peak",
        "one half",
    ): "✗ the gap is not symmetric: it peaks nearer the far end's image. Find where t(s) - s stops growing: where dt/ds = 1.",
    (
        "gap_peak",
        "swapped",
    ): "✗ that is 1 - s*, the peak with w1 and w2 swapped, which is also where the peak is in t (t_from_s(s*, w1, w2) = 1 - s*): return the screen parameter s.",
    (
        "gap_peak",
        "no square roots",
    ): "✗ that is w2 / (w1 + w2), where the middle of AB shows, not where the gap peaks. dt/ds = w1 w2 / (s w1 + (1-s) w2)^2 equals 1 where s w1 + (1-s) w2 = sqrt(w1 w2): square roots appear.",
    (
        "gap_peak",
        "the height",
    ): "✗ that is the height of the gap at its peak; return where it peaks, s*.",
    (
        "gap_peak",
        "coarse numerics",
    ): "✗ for (w1, w2) = (1, 9) the answer is 0.75, your function gave 0.8.",
    (
        "ndc_depth",
        "linear in w",
    ): "✗ that is linear in w, and right only at the near and far planes. NDC z is z_clip / w, an affine function of 1/w: A + B / w.",
    (
        "ndc_depth",
        "z_clip",
    ): "✗ that is z_clip, the third row of the matrix times the point; NDC z is z_clip divided by w_clip = w.",
    (
        "ndc_depth",
        "window z",
    ): "✗ that is window z, (NDC z + 1) / 2, in [0, 1]; NDC z runs from -1 to 1.",
    (
        "ndc_depth",
        "sign",
    ): "✗ the sign is flipped: NDC z is -1 at the near plane and +1 at the far plane.",
    (
        "ndc_depth",
        "no factor 2",
    ): "✗ for (w, near, far) = (2, 1, 3) the answer is 0.5, your function gave 1.25.",
    (
        "perspective_lerp",
        "affine",
    ): "✗ that is affine (screen-space) interpolation, right only when w1 = w2: a/w and 1/w are what is linear in s. Interpolate both, then divide.",
    (
        "perspective_lerp",
        "no divide",
    ): "✗ that is a/w, interpolated: now divide it by the interpolated 1/w.",
    (
        "perspective_lerp",
        "times lerp w",
    ): "✗ you multiplied the interpolated a/w by a linearly interpolated w; w is not linear on the screen, 1/w is: divide by the interpolated 1/w instead.",
    (
        "perspective_lerp",
        "weights w",
    ): "✗ your function gives ((1-s) a1 w1 + s a2 w2) / ((1-s) w1 + s w2): each end weighted by its w where 1/w belongs. Swapping w1 and w2, or using s_from_t where t_from_s belongs, gives these same numbers. The near end (smaller w) must count more: at (a1, a2, w1, w2, s) = (0, 1, 1, 3, 0.5) the answer is 0.25.",
    (
        "perspective_lerp",
        "swapped w",
    ): "✗ your function gives ((1-s) a1 w1 + s a2 w2) / ((1-s) w1 + s w2): each end weighted by its w where 1/w belongs. Swapping w1 and w2, or using s_from_t where t_from_s belongs, gives these same numbers. The near end (smaller w) must count more: at (a1, a2, w1, w2, s) = (0, 1, 1, 3, 0.5) the answer is 0.25.",
    (
        "perspective_lerp",
        "t from s_from_t",
    ): "✗ your function gives ((1-s) a1 w1 + s a2 w2) / ((1-s) w1 + s w2): each end weighted by its w where 1/w belongs. Swapping w1 and w2, or using s_from_t where t_from_s belongs, gives these same numbers. The near end (smaller w) must count more: at (a1, a2, w1, w2, s) = (0, 1, 1, 3, 0.5) the answer is 0.25.",
    (
        "perspective_lerp",
        "a2 - a1 slip",
    ): "✗ for (a1, a2, w1, w2, s) = (2, -1, 4, 1, 0.25) the answer is 0.285714, your function gave -0.571429.",
    ("checker", "swapped colours"): "✗ black and white are swapped.",
    ("checker", "no frequency"): "✗ scale u and v by the frequency first.",
    ("checker", "round"): "✗ use floor, not round: a check runs from one whole number to the next.",
    (
        "checker",
        "int",
    ): "✗ int() rounds towards zero, so it is wrong for negative u or v (the checks either side of 0 come out the same colour): use math.floor.",
    (
        "affine_error",
        "in u",
    ): "✗ that is the error in u; one texel is 1/frequency of u, so multiply by the frequency.",
    (
        "affine_error",
        "signed",
    ): "✗ the error is a distance, whichever way the texture slid: take the absolute value.",
    (
        "affine_error",
        "s_from_t",
    ): "✗ your function gives the error with w1 and w2 swapped, which is also what using s_from_t(s, ...) where t_from_s(s, ...) belongs gives (the same numbers). The pixel at s shows the point t = t_from_s(s, w1, w2).",
    (
        "affine_error",
        "the gap",
    ): "✗ for (s, w1, w2, frequency) = (0.5, 1, 3, 8) the answer is 2, your function gave 2.14359.",
    (
        "clip_barycentrics",
        "unchanged",
    ): "✗ those are the screen-space barycentrics unchanged (noperspective), right only when w0 = w1 = w2: weight each by 1/w_i.",
    (
        "clip_barycentrics",
        "not normalised",
    ): "✗ those are the b_i / w_i: now divide them by their sum, so that the weights add up to 1.",
    (
        "clip_barycentrics",
        "times w",
    ): "✗ you weighted each b_i by w_i; it is 1/w_i that is linear on the screen, so divide each by its w_i.",
    (
        "clip_barycentrics",
        "normalised by the sum of b",
    ): "✗ for (b0, b1, b2, w0, w1, w2) = (0.5, 0.5, 0, 1, 3, 2) the answer is (0.75, 0.25, 0), your function gave (0.5, 0.166667, 0).",
    (
        "worked_example",
        "not written yet",
    ): "… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.",
    ("worked_example", "forgot return"): "✗ your function returned None: did you forget `return`?",
    ("worked_example", "a list"): "✗ return a dict of the table's rows, got list.",
    ("worked_example", "raises"): "✗ your function divided by zero.",
    (
        "recap_4",
        "not written yet",
    ): "… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.",
    ("recap_4", "forgot return"): "✗ your function returned None: did you forget `return`?",
    (
        "recap_4",
        "a string",
    ): "✗ return a dict from question number to letters, e.g. {1: 'a', 2: 'bc'}; got str.",
    (
        "near_clip",
        "not written yet",
    ): "… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.",
    (
        "worked_example",
        "a row missing",
    ): "✗ your table has no row 'ndc x'; the rows: ['w', 'ndc x', 'ndc y', 'window x', 'window y', 'b', 'lambda', 'u'].",
    (
        "worked_example",
        "clip z for w",
    ): "✗ row 'w' is (0.125, 1.375, 3.875), the answer is (1, 2, 4): that is clip z; w is the fourth coordinate, -z of the view-space point.",
    (
        "worked_example",
        "no divide",
    ): "✗ row 'ndc x' is (-0.75, 1.5, -1), the answer is (-0.75, 0.75, -0.25): that is still clip space: divide by w (the perspective divide).",
    (
        "worked_example",
        "rows from the top",
    ): "✗ row 'window y' is (7, 7, 4), the answer is (1, 1, 4): you counted from the top, like image rows; OpenGL's window y counts from the bottom.",
    (
        "worked_example",
        "window x slip",
    ): "✗ row 'window x' is (1, 7, 4), the answer is (1, 7, 3): the viewport maps NDC x from [-1, 1] onto [0, 8]: window x = (x + 1) * 8 / 2.",
    (
        "worked_example",
        "lambda = b",
    ): "✗ row 'lambda' is (0.25, 0.25, 0.5), the answer is (0.5, 0.25, 0.25): those are b unchanged (noperspective): weight each b_i by 1/w_i, then normalise.",
    (
        "worked_example",
        "lambda not normalised",
    ): "✗ row 'lambda' is (0.25, 0.125, 0.125), the answer is (0.5, 0.25, 0.25): those are the b_i / w_i: now divide them by their sum, so that they add up to 1.",
    (
        "worked_example",
        "lambda weighted by w",
    ): "✗ row 'lambda' is (0.0909091, 0.181818, 0.727273), the answer is (0.5, 0.25, 0.25): you weighted each b_i by w_i; it is 1/w_i that is linear on the screen.",
    (
        "worked_example",
        "affine u",
    ): "✗ row 'u' is 0.625, the answer is 0.375: that is the affine (noperspective) value, b_0 u_0 + b_1 u_1 + b_2 u_2: use lambda.",
    (
        "worked_example",
        "two weights",
    ): "✗ row 'lambda' must be 3 numbers, one per corner, got (0.5, 0.25).",
    ("worked_example", "u as text"): "✗ row 'u' must be one number, got '0.375'.",
    (
        "recap_4",
        "a wrong option",
    ): "✗ recap 4: 3 of 4 right.\n\n- question 1: (e) is not right: t(s) is a curve unless w_1 = w_2.",
    (
        "recap_4",
        "one missing",
    ): "✗ recap 4: 3 of 4 right.\n\n- question 1: one right option is missing.",
    (
        "recap_4",
        "two for one",
    ): "✗ recap 4: 2 of 4 right.\n\n- question 2: it has one right answer: choose one letter.\n- question 4: there is no option (z); the options are a, b, c.",
    (
        "recap_4",
        "unanswered",
    ): '✗ recap 4: 3 of 4 right.\n\n- question 4: no answer: give its letter as a string, e.g. "b".',
    (
        "recap_4",
        "a question too many",
    ): "✗ recap 4: 4 of 4 right.\n\n- there is no question 5; the questions are 1 to 4.",
    (
        "near_clip",
        "from the outside vertex",
    ): "✗ that is measured from the outside vertex: t is 0 at the inside vertex (z1, w1).",
    (
        "near_clip",
        "the far plane",
    ): "✗ that is where the edge meets the far plane z = w; the near plane is z = -w, where z + w = 0.",
    (
        "near_clip",
        "in NDC",
    ): "✗ that interpolates NDC z = z/w, which is not linear along the edge in space (and has no meaning behind the eye): clip first, in clip space, where the distance z + w to the near plane is linear in t.",
    (
        "near_clip",
        "z only",
    ): "✗ for (z1, w1, z2, w2) = (0, 2, -3, 1) the answer is 0.5, your function gave 0.666667.",
}


@pytest.mark.parametrize(
    ("checker", "label", "answer"), WRONG, ids=[f"{c.__name__}: {label}" for c, label, _ in WRONG]
)
def test_wrong_answers_get_their_message(checker, label, answer):
    verdict = checker(answer)
    assert not verdict
    assert repr(verdict) == EXPECTED[checker.__name__, label]


def test_every_wrong_answer_has_its_message():
    assert sorted(EXPECTED) == sorted((c.__name__, label) for c, label, _ in WRONG)


def test_recap_questions_are_well_formed():
    for lesson, questions in check.QUIZZES.items():
        assert 3 <= len(questions) <= 4, lesson
        for question in questions:
            assert question.answer and set(question.answer) <= set(question.options)
            assert question.answer == "".join(sorted(question.answer))
            assert set(question.why) == set(question.options), question.text
            assert list(question.options) == [
                chr(ord("a") + k) for k in range(len(question.options))
            ]


def test_the_right_answers_of_every_recap_pass_and_every_single_wrong_option_is_explained():
    for lesson, questions in check.QUIZZES.items():
        key = {k: q.answer for k, q in enumerate(questions, start=1)}
        assert check.recap(lesson, lambda key=key: key), lesson
        for k, question in enumerate(questions, start=1):
            for letter in question.options:
                if letter in question.answer:
                    continue
                wrong = {**key, k: question.answer + letter if question.several else letter}
                verdict = check.recap(lesson, lambda wrong=wrong: wrong)
                assert not verdict and question.why[letter] in verdict.message


def test_each_lesson_asks_its_recap_questions_word_for_word():
    """The questions a lesson prints are the ones its checker marks, options included."""
    from pathlib import Path

    import nbformat

    sources = sorted((Path(__file__).parent.parent / "source" / "lessons").glob("*.ipynb"))
    for lesson, questions in check.QUIZZES.items():
        (path,) = [p for p in sources if p.name.startswith(f"{lesson:02d}_")]
        cells = nbformat.read(path, as_version=4).cells
        (text,) = [
            c.source
            for c in cells
            if c.cell_type == "markdown"
            and "1. " in c.source
            and f"check.recap_{lesson}" not in c.source
            and questions[0].text in c.source
        ]
        for k, question in enumerate(questions, start=1):
            assert f"{k}. {question.text}" in text, (lesson, question.text)
            for letter, option in question.options.items():
                assert f"({letter}) {option}" in text, (lesson, k, option)
