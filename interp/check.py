"""Check a student's function, and say what is wrong with it.

Each lesson ends with an exercise: write a small function, then call the checker here on it,
e.g. ``interp.check.perspective_lerp(my_lerp)``. The checker calls the function on a set of
cases with plain Python floats (no vectorizing needed), compares with the library, and if the
answers differ, recognises the usual mistakes and explains them.

Every checker returns a :class:`Verdict`, which is truthy when the function is right and shows
its message in a notebook.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np

from interp import depth, lerp, mistakes


@dataclass(frozen=True)
class Verdict:
    """The outcome of a check: ``ok`` and a message for the student."""

    ok: bool
    message: str

    def __bool__(self) -> bool:
        return self.ok

    def __repr__(self) -> str:
        return ("✓ " if self.ok else "✗ ") + self.message

    def _repr_markdown_(self) -> str:
        return ("**✓** " if self.ok else "**✗** ") + self.message


Case = tuple[float, ...]


def _cases(rng: np.random.Generator, n: int, draw: Callable[[np.random.Generator], Case]):
    return [tuple(float(x) for x in draw(rng)) for _ in range(n)]


def _judge(
    name: str,
    student: Callable[..., object],
    reference: Callable[..., object],
    cases: Sequence[Case],
    argument_names: str,
    mistakes_known: Sequence[tuple[Callable[..., object], str]] = (),
) -> Verdict:
    if not callable(student):
        return Verdict(False, f"pass your function itself, e.g. check.{name}(my_function)")
    got, expected = [], []
    for case in cases:
        try:
            value = np.asarray(student(*case), dtype=float)
        except Exception as error:  # the student's code: report, never raise
            return Verdict(
                False,
                f"your function raised {type(error).__name__}: {error} "
                f"for ({argument_names}) = {case}",
            )
        got.append(value)
        expected.append(np.asarray(reference(*case), dtype=float))
    if all(
        g.shape == e.shape and np.allclose(g, e, rtol=1e-6, atol=1e-9)
        for g, e in zip(got, expected, strict=True)
    ):
        return Verdict(True, f"{name}: right on all {len(cases)} cases.")
    for wrong, explanation in mistakes_known:
        answers = [np.asarray(wrong(*case), dtype=float) for case in cases]
        if all(
            g.shape == a.shape and np.allclose(g, a, rtol=1e-6, atol=1e-9)
            for g, a in zip(got, answers, strict=True)
        ):
            return Verdict(False, explanation)
    for case, g, e in zip(cases, got, expected, strict=True):
        if g.shape != e.shape or not np.allclose(g, e, rtol=1e-6, atol=1e-9):
            return Verdict(
                False,
                f"for ({argument_names}) = {tuple(round(c, 4) for c in case)} the answer is "
                f"{np.round(e, 6).tolist()}, your function gave {np.round(g, 6).tolist()}",
            )
    raise AssertionError("unreachable")  # pragma: no cover


def project(student: Callable[[float, float, float], float]) -> Verdict:
    """Lesson 1: ``student(x, z, d)`` is the image of the view-space point (x, z), z < 0, on the
    image plane at distance d.

    Examples
    --------
    >>> project(lambda x, z, d: d * x / -z)
    ✓ project: right on all 20 cases.
    >>> project(lambda x, z, d: d * x / z)
    ✗ the image is mirrored: divide by the depth w = -z (the camera looks down -z), not by z
    """
    cases = _cases(
        np.random.default_rng(1),
        20,
        lambda r: (r.uniform(-5, 5), r.uniform(-9, -0.5), r.uniform(0.2, 3)),
    )
    return _judge(
        "project",
        student,
        lambda x, z, d: lerp.project_to_image_plane([x, z], d),
        cases,
        "x, z, d",
        [
            (
                lambda x, z, d: d * x / z,
                "the image is mirrored: divide by the depth w = -z (the camera looks down -z), "
                "not by z",
            ),
            (lambda x, z, d: x / -z, "scale by d: the image plane is d away from the eye"),
            (lambda x, z, d: d * x, "divide by the depth: further points land nearer the axis"),
        ],
    )


def _st_cases() -> list[Case]:
    return _cases(
        np.random.default_rng(2),
        30,
        lambda r: (r.uniform(0, 1), r.uniform(0.1, 20), r.uniform(0.1, 20)),
    )


def s_from_t(student: Callable[[float, float, float], float]) -> Verdict:
    """``student(t, w1, w2)`` is the screen parameter of the point at object parameter t.

    Examples
    --------
    >>> s_from_t(lambda t, w1, w2: t * w2 / ((1 - t) * w1 + t * w2))
    ✓ s_from_t: right on all 30 cases.
    """
    return _judge(
        "s_from_t",
        student,
        lerp.s_from_t,
        _st_cases(),
        "t, w1, w2",
        [
            (
                lambda t, w1, w2: t,
                "that is t itself: true only when w1 = w2; project the point "
                "P(t) = (1-t) A + t B, it is the interpolated position that gets divided by w",
            ),
            (lambda t, w1, w2: lerp.s_from_t(t, w2, w1), "w1 and w2 are swapped"),
            (lambda t, w1, w2: lerp.t_from_s(t, w1, w2), "that is the inverse mapping, t_from_s"),
        ],
    )


def t_from_s(student: Callable[[float, float, float], float]) -> Verdict:
    """Lesson 2: ``student(s, w1, w2)`` is the object parameter of the point seen at s.

    Examples
    --------
    >>> t_from_s(lambda s, w1, w2: s)
    ✗ that is s itself: true only when w1 = w2 (an orthographic camera); ...
    """
    return _judge(
        "t_from_s",
        student,
        lerp.t_from_s,
        _st_cases(),
        "s, w1, w2",
        [
            (
                lambda s, w1, w2: s,
                "that is s itself: true only when w1 = w2 (an orthographic "
                "camera); solve s = t w2 / ((1-t) w1 + t w2) for t",
            ),
            (lambda s, w1, w2: lerp.t_from_s(s, w2, w1), "w1 and w2 are swapped"),
            (lambda s, w1, w2: lerp.s_from_t(s, w1, w2), "that is the forward mapping, s_from_t"),
        ],
    )


def gap_peak(student: Callable[[float, float], float]) -> Verdict:
    """Lesson 3: ``student(w1, w2)`` is the screen parameter s where ``|t - s|`` is largest.

    Examples
    --------
    >>> gap_peak(lambda w1, w2: w2**0.5 / (w1**0.5 + w2**0.5))
    ✓ gap_peak: right on all 30 cases.
    """
    cases = [
        c
        for c in _cases(
            np.random.default_rng(3), 40, lambda r: (r.uniform(0.1, 20), r.uniform(0.1, 20))
        )
        if abs(c[0] - c[1]) > 1e-3
    ][:30]

    def peak(w1: float, w2: float) -> float:
        return np.sqrt(w2) / (np.sqrt(w1) + np.sqrt(w2))

    return _judge(
        "gap_peak",
        student,
        peak,
        cases,
        "w1, w2",
        [
            (
                lambda w1, w2: 0.5,
                "the gap is not symmetric: set d(t - s)/ds = 0 with "
                "t = t_from_s(s, w1, w2) and solve for s",
            ),
            (lambda w1, w2: peak(w2, w1), "w1 and w2 are swapped"),
            (
                lambda w1, w2: w2 / (w1 + w2),
                "close: the derivative dt/ds = w1 w2 / (s w1 + "
                "(1-s) w2)^2 equals 1 where s w1 + (1-s) w2 = sqrt(w1 w2): square roots appear",
            ),
        ],
    )


def ndc_depth(student: Callable[[float, float, float], float]) -> Verdict:
    """Lesson 4: ``student(w, near, far)`` is NDC z for view depth w.

    Examples
    --------
    >>> ndc_depth(lambda w, n, f: (f + n) / (f - n) - 2 * f * n / ((f - n) * w))
    ✓ ndc_depth: right on all 30 cases.
    """
    cases = _cases(
        np.random.default_rng(4),
        30,
        lambda r: (lambda n, f: (r.uniform(n, f), n, f))(r.uniform(0.01, 2), r.uniform(3, 100)),
    )
    return _judge(
        "ndc_depth",
        student,
        depth.ndc_depth,
        cases,
        "w, near, far",
        [
            (
                lambda w, n, f: 2 * (w - n) / (f - n) - 1,
                "that is linear in w; NDC z is z_clip / w, which is linear in 1/w: A + B / w",
            ),
            (lambda w, n, f: depth.window_depth(w, n, f), "that is window z, (NDC z + 1) / 2"),
            (
                lambda w, n, f: -depth.ndc_depth(w, n, f),
                "the sign is flipped: the near plane is at NDC z = -1",
            ),
        ],
    )


def perspective_lerp(student: Callable[[float, float, float, float, float], float]) -> Verdict:
    """Lesson 5: ``student(a1, a2, w1, w2, s)`` interpolates an attribute perspective-correctly.

    Examples
    --------
    >>> perspective_lerp(lambda a1, a2, w1, w2, s: (1 - s) * a1 + s * a2)
    ✗ that is affine (screen-space) interpolation: ...
    """
    cases = _cases(
        np.random.default_rng(5),
        30,
        lambda r: (
            r.uniform(-3, 3),
            r.uniform(-3, 3),
            r.uniform(0.2, 20),
            r.uniform(0.2, 20),
            r.uniform(0, 1),
        ),
    )
    return _judge(
        "perspective_lerp",
        student,
        lerp.lerp_perspective,
        cases,
        "a1, a2, w1, w2, s",
        [
            (
                lambda a1, a2, w1, w2, s: lerp.lerp_affine(a1, a2, s),
                "that is affine (screen-space) interpolation: interpolate a/w and 1/w "
                "linearly in s, then divide one by the other",
            ),
            (
                lambda a1, a2, w1, w2, s: lerp.lerp_affine(a1 / w1, a2 / w2, s),
                "you interpolated a/w but did not divide by the interpolated 1/w",
            ),
            (
                mistakes.lerp_divided_too_early,
                "you multiplied by a linearly interpolated w; w is not linear on the screen, "
                "1/w is: divide by the interpolated 1/w instead",
            ),
            (
                lambda a1, a2, w1, w2, s: lerp.lerp_perspective(a1, a2, w2, w1, s),
                "w1 and w2 are swapped",
            ),
        ],
    )


def checker(student: Callable[[float, float, float], float]) -> Verdict:
    """Lesson 6: ``student(u, v, frequency)`` is 1 on white checks and 0 on black ones, with
    the check at the origin black.

    Examples
    --------
    >>> import math
    >>> checker(lambda u, v, f: (math.floor(u * f) + math.floor(v * f)) % 2)
    ✓ checker: right on all 40 cases.
    """
    cases = _cases(
        np.random.default_rng(6),
        40,
        lambda r: (r.uniform(0, 1), r.uniform(0, 1), float(r.integers(1, 12))),
    )

    def reference(u: float, v: float, f: float) -> float:
        return float((np.floor(u * f) + np.floor(v * f)) % 2)

    return _judge(
        "checker",
        student,
        reference,
        cases,
        "u, v, frequency",
        [
            (lambda u, v, f: 1 - reference(u, v, f), "black and white are swapped"),
            (lambda u, v, f: reference(u, v, 1), "scale u and v by the frequency first"),
            (
                lambda u, v, f: float((round(u * f) + round(v * f)) % 2),
                "use floor, not round: a check runs from one whole number to the next",
            ),
        ],
    )


def clip_barycentrics(student: Callable[..., Sequence[float]]) -> Verdict:
    """Lesson 7: ``student(b0, b1, b2, w0, w1, w2)`` turns screen-space barycentrics into the
    perspective-correct ones (OpenGL 4.6 eq. 14.9), returning three numbers.

    Examples
    --------
    >>> def fix(b0, b1, b2, w0, w1, w2):
    ...     q = (b0 / w0, b1 / w1, b2 / w2)
    ...     return [x / sum(q) for x in q]
    >>> clip_barycentrics(fix)
    ✓ clip_barycentrics: right on all 30 cases.
    """

    def draw(r: np.random.Generator) -> Case:
        b = r.dirichlet([1, 1, 1])
        return (*b, *r.uniform(0.2, 20, 3))

    cases = _cases(np.random.default_rng(7), 30, draw)

    def reference(b0, b1, b2, w0, w1, w2):
        q = np.array([b0 / w0, b1 / w1, b2 / w2])
        return q / q.sum()

    def times_w(b0, b1, b2, w0, w1, w2):
        q = np.array([b0 * w0, b1 * w1, b2 * w2])
        return q / q.sum()

    return _judge(
        "clip_barycentrics",
        student,
        reference,
        cases,
        "b0, b1, b2, w0, w1, w2",
        [
            (
                lambda b0, b1, b2, *w: [b0, b1, b2],
                "those are the screen-space barycentrics unchanged: weight each by 1/w_i",
            ),
            (
                lambda b0, b1, b2, w0, w1, w2: [b0 / w0, b1 / w1, b2 / w2],
                "divide by their sum, so that the weights add up to 1",
            ),
            (times_w, "divide each by its w_i, do not multiply"),
        ],
    )
