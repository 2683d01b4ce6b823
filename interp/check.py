"""Check a student's function, and say what is wrong with it, like a teaching assistant would.

Each lesson has exercises: write a small function, then call the checker here on it, e.g.
``interp.check.perspective_lerp(my_lerp)``; lesson 7's worked example is a table of numbers
(:func:`worked_example`), and every lesson ends with recap questions (:func:`recap`, one
``recap_N`` per lesson), each wrong answer told why.

A checker calls the function with plain Python floats (no vectorizing needed) on a fixed list of
cases: first one a student can redo by hand, then the endpoints and special cases (s = 0, s = 1,
w1 = w2, ...), then random ones. It compares each answer with the library's own function, and
when they differ it says

- what the function returned, if that was not a number (None, a string, a generator...);
- where it failed, if it raised an error (e.g. divided by zero at s = 0);
- which mistake it made, when the wrong numbers are exactly those of a known mistake; where two
  mistakes give the same numbers, it says so instead of guessing which one the student made;
- otherwise the first case it got wrong, the hand-checkable one if that one is wrong.

A function whose body is still ``raise NotImplementedError()`` (the student edition's stub) is
"not written yet", which is no error. Every checker returns a :class:`Verdict`, which is truthy
when the function is right and shows its message in a notebook.

Examples
--------
>>> t_from_s(lambda s, w1, w2: s * w1 / (s * w1 + (1 - s) * w2))
✓ t_from_s: right on all 30 cases, among them s = 0, s = 1 and w1 = w2.
>>> def t_from_s_unwritten(s, w1, w2):
...     raise NotImplementedError()
>>> t_from_s(t_from_s_unwritten)
… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.
"""

from __future__ import annotations

import math
import types
import warnings
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from interp import barycentric, depth, lerp, mipmap, mistakes, texture

__all__ = [
    "Verdict",
    "affine_error",
    "checker",
    "clip_barycentrics",
    "gap_peak",
    "lod",
    "ndc_depth",
    "near_clip",
    "perspective_lerp",
    "project",
    "recap",
    "recap_1",
    "recap_2",
    "recap_3",
    "recap_4",
    "recap_5",
    "recap_6",
    "recap_7",
    "recap_8",
    "recap_9",
    "recap_10",
    "s_from_t",
    "t_from_s",
    "where_m_lands",
    "worked_example",
]

#: What the student edition's exercise cells hold until the student writes the function.
STUB = "raise NotImplementedError()"

NOT_WRITTEN = f"not written yet: replace `{STUB}` with your code, then run the cell again."


@dataclass(frozen=True)
class Verdict:
    """The outcome of a check: ``ok`` and a message for the student.

    ``pending`` marks a function that is not written yet: not right, but not an error either.

    Examples
    --------
    >>> bool(Verdict(True, "right")), Verdict(False, "wrong")
    (True, ✗ wrong)
    """

    ok: bool
    message: str
    pending: bool = False

    def __bool__(self) -> bool:
        return self.ok

    def _mark(self) -> str:
        return "✓" if self.ok else "…" if self.pending else "✗"

    def __repr__(self) -> str:
        return f"{self._mark()} {self.message}"

    def _repr_markdown_(self) -> str:
        return f"**{self._mark()}** {self.message}"


@dataclass(frozen=True)
class Case:
    """Arguments for the student's function, and what is special about them, if anything."""

    args: tuple[float, ...]
    note: str = ""


class _NotAnAnswerError(Exception):
    """The student's function returned something that is not an answer (None, a string...)."""


def _show(x: float) -> str:
    """A number as a student would write it: 3, 0.5, -0.25, 0.111111."""
    if isinstance(x, float) and x.is_integer():
        return str(int(x))
    return f"{x:.6g}"


def _show_value(value: object) -> str:
    if isinstance(value, tuple):
        return "(" + ", ".join(_show(v) for v in value) + ")"
    return _show(value)


def _random(
    seed: int, n: int, draw: Callable[[np.random.Generator], Sequence[float]]
) -> list[Case]:
    rng = np.random.default_rng(seed)
    return [Case(tuple(float(x) for x in draw(rng))) for _ in range(n)]


def _kind(value: object) -> str:
    if isinstance(value, list):
        return "a list"
    if isinstance(value, tuple):
        return "a tuple"
    return "an array"


def _scalar(value: object) -> float:
    """The student's answer as a float, or :class:`_NotAnAnswerError` saying what it was instead."""
    if value is None:
        raise _NotAnAnswerError("your function returned None: did you forget `return`?")
    if isinstance(value, (str, bytes)):
        text = repr(value) if len(value) < 40 else repr(value[:37]) + "..."
        raise _NotAnAnswerError(
            f"your function returned a string, {text}: return a number, not text."
        )
    if isinstance(value, dict):
        raise _NotAnAnswerError("your function returned a dict: return a number.")
    if isinstance(value, (types.GeneratorType, Iterator)):
        raise _NotAnAnswerError("your function returned a generator: return a number.")
    if isinstance(value, (list, tuple)) or (isinstance(value, np.ndarray) and value.size != 1):
        n = len(value) if isinstance(value, (list, tuple)) else value.size
        raise _NotAnAnswerError(
            f"your function returned {_kind(value)} of {n} value{'s' * (n != 1)}: "
            "return one number."
        )
    if isinstance(value, np.ndarray):
        value = value.reshape(()).item()
    if isinstance(value, (complex, np.complexfloating)):
        if value.imag != 0:
            raise _NotAnAnswerError(
                f"your function returned a complex number, {value:.4g}: is there a square root or "
                "a fractional power of a negative number?"
            )
        value = value.real
    try:
        return float(value)
    except (TypeError, ValueError):
        raise _NotAnAnswerError(
            f"your function returned a {type(value).__name__}: return a number."
        ) from None


def _triple(value: object) -> tuple[float, float, float]:
    """Three floats, or :class:`_NotAnAnswerError` saying what the student's function returned."""
    if value is None:
        raise _NotAnAnswerError("your function returned None: did you forget `return`?")
    if isinstance(value, (str, bytes, dict)):
        _scalar(value)  # raises with the right words
    if isinstance(value, (types.GeneratorType, Iterator)):
        raise _NotAnAnswerError(
            "your function returned a generator: return a list, e.g. `[x / total for x in q]` "
            "or `list(...)`."
        )
    if isinstance(value, (list, tuple, np.ndarray)):
        flat = np.ravel(np.asarray(value, dtype=object))
        if flat.size != 3:
            raise _NotAnAnswerError(
                f"your function returned {_kind(value)} of {flat.size} "
                f"value{'s' * (flat.size != 1)}: return three weights, one per vertex."
            )
        return tuple(_scalar(x) for x in flat)
    _scalar(value)  # a number, or whatever else it is: say what it was
    raise _NotAnAnswerError(
        "your function returned one number: return three weights, one per vertex."
    )


@dataclass
class _Outcome:
    value: object = None  # a float or a tuple of floats
    error: BaseException | None = None
    rejected: str = ""


def _run(student: Callable[..., object], case: Case, convert: Callable) -> _Outcome:
    try:
        with warnings.catch_warnings(), np.errstate(divide="raise", invalid="raise", over="raise"):
            warnings.simplefilter("error")
            returned = student(*case.args)
    except NotImplementedError as error:
        return _Outcome(error=error)
    except Exception as error:  # the student's code: report it, never raise
        return _Outcome(error=error)
    try:
        return _Outcome(value=convert(returned))
    except _NotAnAnswerError as rejected:
        return _Outcome(rejected=str(rejected))


def _close(got: object, expected: object, tolerance: float) -> bool:
    return bool(np.all(np.isclose(got, expected, rtol=tolerance, atol=tolerance, equal_nan=True)))


def _join(notes: list[str]) -> str:
    notes = list(dict.fromkeys(notes))
    return notes[0] if len(notes) == 1 else ", ".join(notes[:-1]) + " and " + notes[-1]


def _where(arguments: str, case: Case) -> str:
    place = f"({arguments}) = {_show_value(case.args)}"
    return f"{place} ({case.note})" if case.note else place


def _error_words(error: BaseException) -> str:
    if isinstance(error, ZeroDivisionError) or (
        isinstance(error, FloatingPointError) and "divide" in str(error)
    ):
        return "divided by zero"
    text = str(error)
    return f"raised {type(error).__name__}" + (f" ({text})" if text else "")


Mistake = tuple[Callable[..., object], str]


def _judge(
    name: str,
    student: object,
    reference: Callable[..., object],
    cases: Sequence[Case],
    arguments: str,
    mistakes_known: Sequence[Mistake] = (),
    convert: Callable[[object], object] = _scalar,
    tolerance: float = 1e-6,
    numerically: tuple[float, str] | None = None,
) -> Verdict:
    """Run ``student`` on every case and compare with ``reference``; explain the first problem.

    ``mistakes_known`` pairs a wrong function with what to tell a student whose answers are
    exactly its answers; ``numerically`` = (tolerance, message) accepts answers that are right
    only to that tolerance, with that message.
    """
    if not callable(student):
        return Verdict(False, f"pass your function itself, e.g. check.{name}(my_function)")
    outcomes = [_run(student, case, convert) for case in cases]
    expected = [convert(reference(*case.args)) for case in cases]
    if any(isinstance(o.error, NotImplementedError) for o in outcomes):
        return Verdict(False, NOT_WRITTEN, pending=True)
    for outcome in outcomes:
        if outcome.rejected:
            return Verdict(False, outcome.rejected)
    answered = [o.error is None for o in outcomes]
    right = [
        ok and _close(o.value, e, tolerance)
        for ok, o, e in zip(answered, outcomes, expected, strict=True)
    ]
    notes = [case.note for case in cases if case.note]
    if all(right):
        among = f", among them {_join(notes)}" if notes else ""
        return Verdict(True, f"{name}: right on all {len(cases)} cases{among}.")
    if numerically and all(
        ok and _close(o.value, e, numerically[0])
        for ok, o, e in zip(answered, outcomes, expected, strict=True)
    ):
        return Verdict(True, f"{name}: {numerically[1]}")
    if all(answered):
        got = [o.value for o in outcomes]
        for wrong, explanation in mistakes_known:
            if all(
                _close(g, convert(wrong(*case.args)), tolerance)
                for g, case in zip(got, cases, strict=True)
            ):
                return Verdict(False, explanation)
    first = next(i for i, ok in enumerate(right) if not ok)
    case, outcome = cases[first], outcomes[first]
    elsewhere = ""
    wrong_cases = [c for c, ok in zip(cases, right, strict=True) if not ok]
    if all(c.note for c in wrong_cases):
        elsewhere = f" It is right everywhere else: only {_join([c.note for c in wrong_cases])} "
        elsewhere += "go wrong." if len({c.note for c in wrong_cases}) > 1 else "goes wrong."
    answer = _show_value(expected[first])
    if outcome.error is not None:
        return Verdict(
            False,
            f"your function {_error_words(outcome.error)} at {_where(arguments, case)}, where "
            f"the answer is {answer}.{elsewhere}",
        )
    return Verdict(
        False,
        f"for {_where(arguments, case)} the answer is {answer}, your function gave "
        f"{_show_value(outcome.value)}.{elsewhere}",
    )


# --- lesson 1 -------------------------------------------------------------------------------


def project(student: Callable[[float, float, float], float]) -> Verdict:
    """``student(x, z, d)`` is the image coordinate of the view-space point (x, z), z < 0, on
    the image plane at distance d (:func:`interp.project_to_image_plane`).

    Examples
    --------
    >>> project(lambda x, z, d: d * x / -z)
    ✓ project: right on all 24 cases, among them x = 0 and a point on the image plane.
    >>> project(lambda x, z, d: d * x / z)
    ✗ the image is mirrored: divide by the depth w = -z (the camera looks down -z), not by z.
    """
    cases = [
        Case((1.0, -2.0, 1.0)),
        Case((3.0, -2.0, 0.5)),
        Case((0.0, -4.0, 2.0), "x = 0"),
        Case((-1.5, -1.0, 1.0), "a point on the image plane"),
        *_random(1, 20, lambda r: (r.uniform(-5, 5), r.uniform(-9, -0.5), r.uniform(0.2, 3))),
    ]
    return _judge(
        "project",
        student,
        lambda x, z, d: lerp.project_to_image_plane([x, z], d),
        cases,
        "x, z, d",
        [
            (
                lambda x, z, d: -lerp.project_to_image_plane([x, z], d),
                "the image is mirrored: divide by the depth w = -z (the camera looks down -z), "
                "not by z.",
            ),
            (
                lambda x, z, d: lerp.project_to_image_plane([x, z], 1.0),
                "scale by d: the image plane is d away from the eye (your answer is right only "
                "where d = 1).",
            ),
            (
                lambda x, z, d: d * x,
                "divide by the depth: a point twice as far away lands twice as close to the axis.",
            ),
        ],
    )


def where_m_lands(student: Callable[[float, float, float, float, float], float]) -> Verdict:
    """Lesson 1: ``student(x1, z1, x2, z2, d)`` is where the image of M, the middle of the segment
    from A = (x1, z1) to B = (x2, z2), lands along the image from a to b: the fraction s of the way
    from a (s = 0) to b (s = 1).

    Compared with :func:`interp.s_from_t` at t = 1/2 (and :func:`interp.project_to_image_plane`
    for the mistakes).

    Examples
    --------
    >>> def where(x1, z1, x2, z2, d):
    ...     a, b = d * x1 / -z1, d * x2 / -z2
    ...     m = d * (x1 + x2) / 2 / -((z1 + z2) / 2)
    ...     return (m - a) / (b - a)
    >>> where_m_lands(where)
    ✓ where_m_lands: right on all 24 cases, among them A and B equally deep and A on the axis.
    >>> where_m_lands(lambda x1, z1, x2, z2, d: 0.5)
    ✗ 1/2 is where M would land if projection kept ratios along the line. ...
    """

    def draw(r: np.random.Generator) -> tuple[float, ...]:
        x1, z1, z2 = r.uniform(-4, 4), r.uniform(-9, -0.5), r.uniform(-9, -0.5)
        # keep the images of A and B apart: the eye, A and B are never nearly collinear
        x2 = x1 * z2 / z1 + r.choice([-1, 1]) * r.uniform(0.5, 4)
        return x1, z1, x2, z2, r.uniform(0.2, 3)

    cases = [
        Case((-1.0, -1.0, 2.0, -3.0, 1.0)),
        Case((1.0, -3.0, -2.0, -1.0, 2.0)),
        Case((-1.0, -2.0, 3.0, -2.0, 1.0), "A and B equally deep"),
        Case((0.0, -1.0, 1.0, -4.0, 0.5), "A on the axis"),
        *_random(11, 20, draw),
    ]

    def image(x: float, z: float, d: float) -> float:
        return lerp.project_to_image_plane([x, z], d)

    return _judge(
        "where_m_lands",
        student,
        lambda x1, z1, x2, z2, d: lerp.s_from_t(0.5, -z1, -z2),
        cases,
        "x1, z1, x2, z2, d",
        [
            (
                lambda *args: 0.5,
                "1/2 is where M would land if projection kept ratios along the line. It does so "
                "only when A and B are equally deep: project A, B and M, then ask how far m is "
                "from a, as a fraction of the way to b.",
            ),
            (
                lambda x1, z1, x2, z2, d: 1 - lerp.s_from_t(0.5, -z1, -z2),
                "that is measured from b: s is 0 at a, the image of A, and 1 at b.",
            ),
            (
                lambda x1, z1, x2, z2, d: image((x1 + x2) / 2, (z1 + z2) / 2, d),
                "that is m, the image coordinate of M; now say where m lies between a and b, as "
                "a fraction of the way from a to b.",
            ),
        ],
    )


# --- lessons 2 and 3: the s-t mapping --------------------------------------------------------


def _st_cases(first: str) -> list[Case]:
    return [
        Case((0.5, 1.0, 3.0)),
        Case((0.0, 1.0, 3.0), f"{first} = 0"),
        Case((1.0, 1.0, 3.0), f"{first} = 1"),
        Case((0.3, 2.0, 2.0), "w1 = w2"),
        Case((0.75, 4.0, 1.0)),
        *_random(2, 25, lambda r: (r.uniform(0, 1), r.uniform(0.1, 20), r.uniform(0.1, 20))),
    ]


def s_from_t(student: Callable[[float, float, float], float]) -> Verdict:
    """``student(t, w1, w2)`` is the screen parameter of the point at object parameter t
    (:func:`interp.s_from_t`).

    Examples
    --------
    >>> s_from_t(lambda t, w1, w2: t * w2 / ((1 - t) * w1 + t * w2))
    ✓ s_from_t: right on all 30 cases, among them t = 0, t = 1 and w1 = w2.
    >>> s_from_t(lambda t, w1, w2: t * w1 / (t * w1 + (1 - t) * w2))
    ✗ your function gives t w1 / (t w1 + (1-t) w2): that is t_from_s applied to t, ...
    """
    return _judge(
        "s_from_t",
        student,
        lerp.s_from_t,
        _st_cases("t"),
        "t, w1, w2",
        [
            (
                lambda t, w1, w2: t,
                "that is t itself, true only when w1 = w2. Project the point P(t) = (1-t) A + "
                "t B: it is the interpolated position that gets divided by its depth.",
            ),
            (
                lambda t, w1, w2: lerp.t_from_s(t, w1, w2),
                "your function gives t w1 / (t w1 + (1-t) w2): that is t_from_s applied to t, "
                "and also s_from_t with w1 and w2 swapped (the same formula, so either "
                "mistake gives these numbers). At (t, w1, w2) = (0.5, 1, 3) the answer is 0.75: "
                "the middle of AB shows nearer b, the image of the far end.",
            ),
        ],
    )


def t_from_s(student: Callable[[float, float, float], float]) -> Verdict:
    """Lesson 2: ``student(s, w1, w2)`` is the object parameter t of the point seen at screen
    parameter s (:func:`interp.t_from_s`).

    Examples
    --------
    >>> t_from_s(lambda s, w1, w2: s)
    ✗ that is s itself, true only when w1 = w2 ...
    >>> t_from_s(lambda s, w1, w2: s * w2 / (s * w2 + (1 - s) * w1))
    ✗ your function gives s w2 / (s w2 + (1-s) w1): ...
    """
    return _judge(
        "t_from_s",
        student,
        lerp.t_from_s,
        _st_cases("s"),
        "s, w1, w2",
        [
            (
                lambda s, w1, w2: s,
                "that is s itself, true only when w1 = w2 (the segment parallel to the image "
                "plane). The pixel at s shows the point P(t) whose projection lands at p(s): "
                "project P(t) and solve for t.",
            ),
            (
                lambda s, w1, w2: lerp.s_from_t(s, w1, w2),
                "your function gives s w2 / (s w2 + (1-s) w1): that is the forward map s_from_t "
                "applied to s, and also t_from_s with w1 and w2 swapped, or with each end "
                "weighted by its own w where 1/w belongs (all the same formula, so I cannot "
                "tell which you did). At (s, w1, w2) = (0.5, 1, 3) the answer is 0.25: the "
                "middle of the image shows a point nearer A, the near end.",
            ),
            (
                lambda s, w1, w2: 1 - lerp.t_from_s(s, w1, w2),
                "that is 1 - t: t is measured from A (t = 0 at A, 1 at B).",
            ),
        ],
    )


def gap_peak(student: Callable[[float, float], float]) -> Verdict:
    """Lesson 3: ``student(w1, w2)`` is the screen parameter s where the gap ``|t - s|`` is
    largest, for w1 != w2 (:func:`interp.gap_peak`).

    A peak found numerically (to 1e-3) is accepted, with a nudge towards the closed form.

    Examples
    --------
    >>> gap_peak(lambda w1, w2: w2**0.5 / (w1**0.5 + w2**0.5))
    ✓ gap_peak: right on all 24 cases, among them w2 much larger than w1 and w1 much larger than w2.
    >>> import numpy as np
    >>> def numerically(w1, w2):
    ...     s = np.linspace(0, 1, 100001)
    ...     return s[np.argmax(np.abs(s * w1 / (s * w1 + (1 - s) * w2) - s))]
    >>> gap_peak(numerically)
    ✓ gap_peak: right numerically (to 1e-3 on all 24 cases); now find the closed form.
    """

    def draw(r: np.random.Generator) -> tuple[float, float]:
        w1 = r.uniform(0.2, 20)
        return w1, w1 * r.choice([1 / r.uniform(1.5, 30), r.uniform(1.5, 30)])

    cases = [
        Case((1.0, 9.0)),
        Case((4.0, 1.0)),
        Case((1.0, 400.0), "w2 much larger than w1"),
        Case((100.0, 1.0), "w1 much larger than w2"),
        *_random(3, 20, draw),
    ]

    def peak(w1: float, w2: float) -> float:
        return lerp.gap_peak(w1, w2)[0]

    return _judge(
        "gap_peak",
        student,
        peak,
        cases,
        "w1, w2",
        [
            (
                lambda w1, w2: 0.5,
                "the gap is not symmetric: it peaks nearer the far end's image. Find where "
                "t(s) - s stops growing: where dt/ds = 1.",
            ),
            (
                lambda w1, w2: 1 - peak(w1, w2),
                "that is 1 - s*, the peak with w1 and w2 swapped, which is also where the peak "
                "is in t (t_from_s(s*, w1, w2) = 1 - s*): return the screen parameter s.",
            ),
            (
                lambda w1, w2: lerp.s_from_t(0.5, w1, w2),
                "that is w2 / (w1 + w2), where the middle of AB shows, not where the gap peaks. "
                "dt/ds = w1 w2 / (s w1 + (1-s) w2)^2 equals 1 where s w1 + (1-s) w2 = "
                "sqrt(w1 w2): square roots appear.",
            ),
            (
                lambda w1, w2: lerp.gap_peak(w1, w2)[1],
                "that is the height of the gap at its peak; return where it peaks, s*.",
            ),
        ],
        numerically=(
            1e-3,
            "right numerically (to 1e-3 on all 24 cases); now find the closed form.",
        ),
    )


# --- lesson 4 --------------------------------------------------------------------------------


def ndc_depth(student: Callable[[float, float, float], float]) -> Verdict:
    """Lesson 4: ``student(w, near, far)`` is NDC z at view depth w, for the projection matrix
    of :func:`interp.perspective` (:func:`interp.ndc_depth`).

    Examples
    --------
    >>> ndc_depth(lambda w, n, f: (f + n) / (f - n) - 2 * f * n / ((f - n) * w))
    ✓ ndc_depth: right on all 23 cases, among them w = near and w = far.
    >>> ndc_depth(lambda w, n, f: 2 * (w - n) / (f - n) - 1)
    ✗ that is linear in w, ...
    """
    cases = [
        Case((2.0, 1.0, 3.0)),
        Case((1.0, 1.0, 3.0), "w = near"),
        Case((3.0, 1.0, 3.0), "w = far"),
        *_random(
            4,
            20,
            lambda r: (lambda n, f: (r.uniform(n, f), n, f))(r.uniform(0.01, 2), r.uniform(3, 100)),
        ),
    ]
    return _judge(
        "ndc_depth",
        student,
        depth.ndc_depth,
        cases,
        "w, near, far",
        [
            (
                lambda w, n, f: 2 * (w - n) / (f - n) - 1,
                "that is linear in w, and right only at the near and far planes. NDC z is "
                "z_clip / w, an affine function of 1/w: A + B / w.",
            ),
            (
                lambda w, n, f: depth.ndc_depth(w, n, f) * w,
                "that is z_clip, the third row of the matrix times the point; NDC z is z_clip "
                "divided by w_clip = w.",
            ),
            (
                depth.window_depth,
                "that is window z, (NDC z + 1) / 2, in [0, 1]; NDC z runs from -1 to 1.",
            ),
            (
                lambda w, n, f: -depth.ndc_depth(w, n, f),
                "the sign is flipped: NDC z is -1 at the near plane and +1 at the far plane.",
            ),
        ],
    )


# --- lesson 5 --------------------------------------------------------------------------------


def perspective_lerp(student: Callable[[float, float, float, float, float], float]) -> Verdict:
    """Lesson 5: ``student(a1, a2, w1, w2, s)`` is the attribute seen at screen parameter s,
    interpolated perspective-correctly (:func:`interp.lerp_perspective`).

    The checker sees only a1, a2, w1, w2 and s, so it recognises only mistakes made of those
    (dividing by window z needs near and far, which it does not have).

    Examples
    --------
    >>> perspective_lerp(lambda a1, a2, w1, w2, s: ((1-s) * a1/w1 + s * a2/w2) / ((1-s)/w1 + s/w2))
    ✓ perspective_lerp: right on all 30 cases, among them s = 0, s = 1, w1 = w2 and a1 = a2.
    >>> perspective_lerp(lambda a1, a2, w1, w2, s: (1 - s) * a1 + s * a2)
    ✗ that is affine (screen-space) interpolation, ...
    """
    cases = [
        Case((0.0, 1.0, 1.0, 3.0, 0.5)),
        Case((2.0, -1.0, 4.0, 1.0, 0.25)),
        Case((0.0, 1.0, 1.0, 3.0, 0.0), "s = 0"),
        Case((0.0, 1.0, 1.0, 3.0, 1.0), "s = 1"),
        Case((0.5, 2.0, 2.0, 2.0, 0.5), "w1 = w2"),
        Case((0.7, 0.7, 1.0, 5.0, 0.4), "a1 = a2"),
        *_random(
            5,
            24,
            lambda r: (
                r.uniform(-3, 3),
                r.uniform(-3, 3),
                r.uniform(0.2, 20),
                r.uniform(0.2, 20),
                r.uniform(0, 1),
            ),
        ),
    ]
    return _judge(
        "perspective_lerp",
        student,
        lerp.lerp_perspective,
        cases,
        "a1, a2, w1, w2, s",
        [
            (
                lambda a1, a2, w1, w2, s: lerp.lerp_affine(a1, a2, s),
                "that is affine (screen-space) interpolation, right only when w1 = w2: a/w "
                "and 1/w are what is linear in s. Interpolate both, then divide.",
            ),
            (
                lambda a1, a2, w1, w2, s: lerp.lerp_affine(a1 / w1, a2 / w2, s),
                "that is a/w, interpolated: now divide it by the interpolated 1/w.",
            ),
            (
                mistakes.lerp_divided_too_early,
                "you multiplied the interpolated a/w by a linearly interpolated w; w is not "
                "linear on the screen, 1/w is: divide by the interpolated 1/w instead.",
            ),
            (
                lambda a1, a2, w1, w2, s: lerp.lerp_perspective(a1, a2, w2, w1, s),
                "your function gives ((1-s) a1 w1 + s a2 w2) / ((1-s) w1 + s w2): each end "
                "weighted by its w where 1/w belongs. Swapping w1 and w2, or using s_from_t "
                "where t_from_s belongs, gives these same numbers. The near end (smaller w) "
                "must count more: at (a1, a2, w1, w2, s) = (0, 1, 1, 3, 0.5) the answer is 0.25.",
            ),
        ],
    )


# --- lesson 6 --------------------------------------------------------------------------------


def checker(student: Callable[[float, float, float], float]) -> Verdict:
    """``student(u, v, frequency)`` is 1 on white checks and 0 on black ones, with the check at
    the origin black (:func:`interp.texture.checker`).

    Examples
    --------
    >>> import math
    >>> checker(lambda u, v, f: (math.floor(u * f) + math.floor(v * f)) % 2)
    ✓ checker: right on all 36 cases, among them negative u and negative v.
    >>> checker(lambda u, v, f: (int(u * f) + int(v * f)) % 2)
    ✗ int() rounds towards zero, ...
    """

    def reference(u: float, v: float, f: float) -> float:
        return float(texture.checker(np.float64(u * f), np.float64(v * f)))

    cases = [
        Case((0.05, 0.05, 10.0)),
        Case((0.15, 0.05, 10.0)),
        Case((0.3, 0.7, 4.0)),
        Case((-0.05, 0.05, 10.0), "negative u"),
        Case((0.3, -0.4, 4.0), "negative v"),
        Case((-0.3, -0.7, 4.0), "negative u"),
        *_random(6, 30, lambda r: (r.uniform(-1, 1), r.uniform(-1, 1), float(r.integers(1, 12)))),
    ]
    return _judge(
        "checker",
        student,
        reference,
        cases,
        "u, v, frequency",
        [
            (lambda u, v, f: 1 - reference(u, v, f), "black and white are swapped."),
            (lambda u, v, f: reference(u, v, 1), "scale u and v by the frequency first."),
            (
                lambda u, v, f: float((round(u * f) + round(v * f)) % 2),
                "use floor, not round: a check runs from one whole number to the next.",
            ),
            (
                lambda u, v, f: float((int(u * f) + int(v * f)) % 2),
                "int() rounds towards zero, so it is wrong for negative u or v (the checks "
                "either side of 0 come out the same colour): use math.floor.",
            ),
        ],
    )


def affine_error(student: Callable[[float, float, float, float], float]) -> Verdict:
    """Lesson 6: ``student(s, w1, w2, frequency)`` is how far off, in texels, the affine texture
    coordinate is at screen parameter s along an edge whose u runs from 0 at its end at depth w1
    to 1 at its end at depth w2, on a board of ``frequency`` checks per unit of u.

    Compared with ``frequency * |lerp_affine(0, 1, s) - lerp_perspective(0, 1, w1, w2, s)|``,
    the one-dimensional case of :func:`interp.texel_error`.

    Examples
    --------
    >>> affine_error(lambda s, w1, w2, f: f * abs(s - s * w1 / (s * w1 + (1 - s) * w2)))
    ✓ affine_error: right on all 28 cases, among them s = 0, s = 1 and w1 = w2.
    >>> affine_error(lambda s, w1, w2, f: abs(s - s * w1 / (s * w1 + (1 - s) * w2)))
    ✗ that is the error in u; ...
    """

    def error_in_u(s: float, w1: float, w2: float) -> float:
        return abs(lerp.lerp_affine(0.0, 1.0, s) - lerp.lerp_perspective(0.0, 1.0, w1, w2, s))

    def reference(s: float, w1: float, w2: float, f: float) -> float:
        return f * error_in_u(s, w1, w2)

    cases = [
        Case((0.5, 1.0, 3.0, 8.0)),
        Case((0.5, 3.0, 1.0, 8.0)),
        Case((0.0, 1.0, 3.0, 8.0), "s = 0"),
        Case((1.0, 1.0, 3.0, 8.0), "s = 1"),
        Case((0.3, 2.0, 2.0, 8.0), "w1 = w2"),
        *_random(
            8,
            23,
            lambda r: (r.uniform(0, 1), r.uniform(0.2, 20), r.uniform(0.2, 20), r.integers(1, 33)),
        ),
    ]
    signed = "the error is a distance, whichever way the texture slid: take the absolute value."
    return _judge(
        "affine_error",
        student,
        reference,
        cases,
        "s, w1, w2, frequency",
        [
            (
                lambda s, w1, w2, f: error_in_u(s, w1, w2),
                "that is the error in u; one texel is 1/frequency of u, so multiply by the "
                "frequency.",
            ),
            (
                lambda s, w1, w2, f: f * (s - lerp.t_from_s(s, w1, w2)),
                signed,
            ),
            (
                lambda s, w1, w2, f: f * (lerp.t_from_s(s, w1, w2) - s),
                signed,
            ),
            (
                lambda s, w1, w2, f: f * abs(s - lerp.s_from_t(s, w1, w2)),
                "your function gives the error with w1 and w2 swapped, which is also what "
                "using s_from_t(s, ...) where t_from_s(s, ...) belongs gives (the same numbers). "
                "The pixel at s shows the point t = t_from_s(s, w1, w2).",
            ),
        ],
    )


# --- lesson 7 --------------------------------------------------------------------------------


def clip_barycentrics(student: Callable[..., Sequence[float]]) -> Verdict:
    """Lesson 7: ``student(b0, b1, b2, w0, w1, w2)`` turns a pixel's screen-space barycentrics
    into the perspective-correct weights of OpenGL 4.6 eq. 14.9, returning three numbers
    (:func:`interp.perspective_weights`).

    Examples
    --------
    >>> def weights(b0, b1, b2, w0, w1, w2):
    ...     q = (b0 / w0, b1 / w1, b2 / w2)
    ...     return [x / sum(q) for x in q]
    >>> clip_barycentrics(weights)
    ✓ clip_barycentrics: right on all 24 cases, among them a corner and all w equal.
    >>> clip_barycentrics(lambda b0, b1, b2, w0, w1, w2: (x for x in (b0, b1, b2)))
    ✗ your function returned a generator: ...
    """

    def draw(r: np.random.Generator) -> tuple[float, ...]:
        return (*r.dirichlet([1, 1, 1]), *r.uniform(0.2, 20, 3))

    cases = [
        Case((0.5, 0.5, 0.0, 1.0, 3.0, 2.0)),
        Case((0.25, 0.25, 0.5, 1.0, 2.0, 4.0)),
        Case((1.0, 0.0, 0.0, 2.0, 5.0, 1.0), "a corner"),
        Case((0.2, 0.3, 0.5, 3.0, 3.0, 3.0), "all w equal"),
        *_random(7, 20, draw),
    ]

    def reference(b0, b1, b2, w0, w1, w2):
        return tuple(barycentric.perspective_weights([b0, b1, b2], [w0, w1, w2]))

    def weighted(b, w):
        q = np.asarray(b) * np.asarray(w)
        return tuple(q / q.sum())

    return _judge(
        "clip_barycentrics",
        student,
        reference,
        cases,
        "b0, b1, b2, w0, w1, w2",
        [
            (
                lambda b0, b1, b2, *w: (b0, b1, b2),
                "those are the screen-space barycentrics unchanged (noperspective), right only "
                "when w0 = w1 = w2: weight each by 1/w_i.",
            ),
            (
                lambda b0, b1, b2, w0, w1, w2: (b0 / w0, b1 / w1, b2 / w2),
                "those are the b_i / w_i: now divide them by their sum, so that the weights add "
                "up to 1.",
            ),
            (
                lambda b0, b1, b2, w0, w1, w2: weighted((b0, b1, b2), (w0, w1, w2)),
                "you weighted each b_i by w_i; it is 1/w_i that is linear on the screen, so "
                "divide each by its w_i.",
            ),
        ],
        convert=_triple,
    )


# --- lesson 7: the worked example -----------------------------------------------------------

#: The rows of lesson 7's table a student fills in, in order, with a hint for each.
WORKED_ROWS = {
    "w": "w is the clip-space w, the fourth row of P times the point: the view depth -z.",
    "ndc x": "NDC x is clip x divided by clip w.",
    "ndc y": "NDC y is clip y divided by clip w.",
    "window x": "the viewport maps NDC x from [-1, 1] onto [0, 8]: window x = (x + 1) * 8 / 2.",
    "window y": "the viewport maps NDC y from [-1, 1] onto [0, 8]: window y = (y + 1) * 8 / 2, "
    "counted from the bottom, as OpenGL does.",
    "b": "b are the screen-space barycentrics of the pixel centre (3.5, 2.5): the weights of the "
    "three window positions (x, y) that give the centre, summing to 1.",
    "lambda": "lambda_i = (b_i / w_i) / (b_0/w_0 + b_1/w_1 + b_2/w_2).",
    "u": "u = lambda_0 u_0 + lambda_1 u_1 + lambda_2 u_2.",
}


def _worked_value(value: object, length: int) -> tuple[float, ...]:
    """A row of the student's table as floats, or :class:`_NotAnAnswerError` saying what it
    must be."""
    if length == 1:
        try:
            return (_scalar(value),)
        except _NotAnAnswerError:
            raise _NotAnAnswerError("one number") from None
    if isinstance(value, (str, bytes, dict)) or value is None or np.ndim(value) == 0:
        raise _NotAnAnswerError("three numbers, one per corner")
    flat = np.ravel(np.asarray(value, dtype=object))
    if flat.size != length:
        raise _NotAnAnswerError(f"{length} numbers, one per corner")
    try:
        return tuple(_scalar(x) for x in flat)
    except _NotAnAnswerError:
        raise _NotAnAnswerError(f"{length} numbers, one per corner") from None


def _worked_mistake(row: str, got: tuple[float, ...], table: dict[str, object]) -> str:
    """What a student whose row ``row`` is ``got`` most likely did, or ""."""

    def near(values: object) -> bool:
        return _close(np.array(got), np.ravel(np.asarray(values, dtype=float)), 1e-4)

    clip = np.array(table["clip"])
    b, w, u = np.array(table["b"]), np.array(table["w"]), np.array([0.0, 0.5, 1.0])
    if row == "w" and near(clip[:, 2]):
        return "that is clip z; w is the fourth coordinate, -z of the view-space point."
    if row in ("ndc x", "ndc y") and near(clip[:, 0 if row == "ndc x" else 1]):
        return "that is still clip space: divide by w (the perspective divide)."
    if row == "window y" and near(8 - np.array(table["window y"])):
        return (
            "you counted from the top, like image rows; OpenGL's window y counts from the bottom."
        )
    if row == "lambda" and near(b):
        return "those are b unchanged (noperspective): weight each b_i by 1/w_i, then normalise."
    if row == "lambda" and near(b / w):
        return "those are the b_i / w_i: now divide them by their sum, so that they add up to 1."
    if row == "lambda" and near(b * w / np.sum(b * w)):
        return "you weighted each b_i by w_i; it is 1/w_i that is linear on the screen."
    if row == "u" and near(b @ u):
        return "that is the affine (noperspective) value, b_0 u_0 + b_1 u_1 + b_2 u_2: use lambda."
    return ""


def worked_example(student: Callable[[], dict]) -> Verdict:
    """Lesson 7: ``student()`` returns the table of the worked example, a dict with the rows of
    :data:`WORKED_ROWS` (three numbers per row, one per corner, except ``"u"``), which is
    compared with :func:`interp.worked.table`, row by row.

    Examples
    --------
    >>> from interp import worked
    >>> right = {k: v for k, v in worked.table().items() if k in WORKED_ROWS}
    >>> worked_example(lambda: right)
    ✓ worked_example: every row of the table is right, and u = 0.375 is what ...
    >>> worked_example(lambda: {**right, "lambda": right["b"]})
    ✗ row 'lambda' is (0.25, 0.25, 0.5), the answer is (0.5, 0.25, 0.25): those are b ...
    """
    from interp import worked

    if not callable(student):
        return Verdict(False, "pass your function itself, e.g. check.worked_example(my_table)")
    try:
        with warnings.catch_warnings(), np.errstate(divide="raise", invalid="raise"):
            warnings.simplefilter("error")
            answer = student()
    except NotImplementedError:
        return Verdict(False, NOT_WRITTEN, pending=True)
    except Exception as error:  # the student's code: report it, never raise
        return Verdict(False, f"your function {_error_words(error)}.")
    if answer is None:
        return Verdict(False, "your function returned None: did you forget `return`?")
    if not isinstance(answer, dict):
        return Verdict(False, f"return a dict of the table's rows, got {type(answer).__name__}.")
    table = worked.table()
    for row, hint in WORKED_ROWS.items():
        if row not in answer:
            return Verdict(False, f"your table has no row {row!r}; the rows: {list(WORKED_ROWS)}.")
        expected = np.ravel(np.asarray(table[row], dtype=float))
        try:
            got = _worked_value(answer[row], expected.size)
        except _NotAnAnswerError as rejected:
            return Verdict(False, f"row {row!r} must be {rejected}, got {answer[row]!r}.")
        if not _close(np.array(got), expected, 1e-4):
            said = _worked_mistake(row, got, table) or hint
            return Verdict(
                False,
                f"row {row!r} is {_show_value(got) if len(got) > 1 else _show(got[0])}, the "
                f"answer is {_show_value(tuple(expected)) if len(got) > 1 else _show(expected[0])}"
                f": {said}",
            )
    values, _ = worked.drawn()
    drawn = float(values[worked.IMAGE_ROW, worked.COLUMN, 0])
    affine = float(worked.drawn("affine")[0][worked.IMAGE_ROW, worked.COLUMN, 0])
    return Verdict(
        True,
        f"worked_example: every row of the table is right, and u = {_show(round(drawn, 9))} is "
        f"what interp.rasterize draws at that pixel (affine would give {_show(round(affine, 9))}).",
    )


# --- the recap questions at the end of every lesson ------------------------------------------


@dataclass(frozen=True)
class Question:
    """One conceptual question: its options by letter, the right letters, and why.

    ``answer`` holds every right letter ("bd" when two options are right: the question then
    says "choose all that apply"). ``why`` says, for each letter, why that option is right or
    wrong; a student who picks a wrong option, or leaves out a right one, reads it.
    """

    text: str
    options: dict[str, str]
    answer: str
    why: dict[str, str]

    @property
    def several(self) -> bool:
        """Whether more than one option is right ("choose all that apply")."""
        return len(self.answer) > 1

    def markdown(self, number: int) -> str:
        """The question as the lesson prints it."""
        head = f"{number}. {self.text}" + (" *(Choose all that apply.)*" if self.several else "")
        return "\n".join([head, *(f"   - ({k}) {v}" for k, v in self.options.items())])


def _q(text: str, answer: str, **options: tuple[str, str]) -> Question:
    """A question from ``letter=(option, why)`` pairs."""
    return Question(
        text,
        {k: v[0] for k, v in options.items()},
        answer,
        {k: v[1] for k, v in options.items()},
    )


#: The recap questions of each lesson (10 is the cheat sheet's review), numbered from 1.
QUIZZES: dict[int, list[Question]] = {
    1: [
        _q(
            "A is at depth 2 and B at depth 8. Where on the image does M, the middle of AB, show?",
            "b",
            a=("At s = 0.5, the middle of the image.", "only when A and B are equally deep."),
            b=(
                "At s = 0.8, nearer b, the image of the far end.",
                "s = w_B / (w_A + w_B) = 8/10: the near half of AB fills most of the image.",
            ),
            c=(
                "At s = 0.2, nearer a, the image of the near end.",
                "the near half is drawn larger, so M is pushed towards b, not a.",
            ),
        ),
        _q(
            "When does M show exactly at the middle of the image?",
            "a",
            a=(
                "When A and B are equally deep.",
                "then AB is parallel to the image plane and projection only scales it.",
            ),
            b=(
                "When A and B are equally far from the axis (x_A = -x_B).",
                "x does not matter: only the depths w_A and w_B decide where M shows.",
            ),
            c=(
                "When the image plane is at distance d = 1.",
                "d scales the whole image and leaves every fraction s as it is.",
            ),
        ),
        _q(
            "Moving the image plane (changing d) changes where M shows, as a fraction s of the "
            "image:",
            "b",
            a=("Yes: s grows with d.", "every image coordinate is multiplied by d alike."),
            b=(
                "No: every image coordinate is scaled by the same factor.",
                "a fraction of the way from a to b does not change under scaling.",
            ),
            c=(
                "Only when the plane passes A.",
                "nothing special happens there: the image is still scaled by d.",
            ),
        ),
        _q(
            "The line through A and B passes through the eye (Lengyel's c = 0). The image of AB "
            "is:",
            "b",
            a=(
                "A segment, with M at its middle.",
                "all of AB lies on one ray from the eye: it is seen end-on.",
            ),
            b=(
                "A single point, so s is undefined.",
                "a and b coincide, and a fraction of the way from a to b means nothing.",
            ),
            c=(
                "Nothing at all.",
                "the segment is in front of the eye: it is seen, as a point.",
            ),
        ),
    ],
    2: [
        _q(
            "Rays through equally spaced pixels hit the segment AB (A near, B far):",
            "b",
            a=("Equally spaced along AB.", "only when A and B are equally deep."),
            b=(
                "Crowded towards the near end A.",
                "the near part of AB covers more of the screen, so more pixels land there.",
            ),
            c=(
                "Crowded towards the far end B.",
                "the far part covers less screen: fewer pixels, spread further apart on AB.",
            ),
        ),
        _q(
            "An attribute is 0 at A (near) and 1 at B (far). At the middle of the image its "
            "right value is:",
            "b",
            a=("0.5.", "that is the affine value, right only at equal depths."),
            b=(
                "Less than 0.5.",
                "the middle of the image shows a point nearer A: t(1/2) = w_1 / (w_1 + w_2).",
            ),
            c=("More than 0.5.", "that would need A to be the far end."),
        ),
        _q(
            "Interpolating an attribute linearly on the screen uses, in place of the object "
            "parameter t:",
            "a",
            a=("The screen parameter s.", "a = (1-s) a_1 + s a_2 uses s where t belongs."),
            b=("1/w.", "1/w is interpolated by the right method, not by the affine one."),
            c=("Nothing: it is right.", "it is right only when w_1 = w_2."),
        ),
        _q(
            "A and B are equally deep. Then:",
            "a",
            a=("t = s everywhere.", "the s-t curve is the diagonal."),
            b=("t = s only at the two ends.", "with equal depths they agree everywhere."),
            c=("t = 1 - s.", "t and s both run from A (0) to B (1)."),
        ),
    ],
    3: [
        _q(
            "The screen parameter s(t) of the point P(t) depends on:",
            "ab",
            a=("t.", "of course: s = t w_2 / ((1-t) w_1 + t w_2)."),
            b=("The depths w_1 and w_2 (in fact only their ratio).", "they weight the mix."),
            c=(
                "The screen positions x'_1 and x'_2 of A and B.",
                "they drop out of the CS5500 derivation: s depends only on t and the depths.",
            ),
            d=(
                "The first row of the projection matrix M.",
                "only the w row matters: M's other rows move the image, not the fraction s.",
            ),
        ),
        _q(
            "Where is the gap |t - s| largest?",
            "b",
            a=("At s = 1/2, always.", "the gap is not symmetric unless w_1 = w_2."),
            b=(
                "At s* = sqrt(w_2) / (sqrt(w_1) + sqrt(w_2)).",
                "where dt/ds = 1, i.e. s w_1 + (1-s) w_2 = sqrt(w_1 w_2).",
            ),
            c=(
                "At s = w_2 / (w_1 + w_2).",
                "that is where the middle of AB shows, not where the gap peaks.",
            ),
        ),
        _q(
            "As w_2 / w_1 grows without bound, the largest gap:",
            "a",
            a=(
                "Tends to 1.",
                "(r - 1) / (r + 1) with r = sqrt(w_2 / w_1) tends to 1, never reaching it.",
            ),
            b=("Tends to 1/2.", "1/2 is its value at w_2 = 9 w_1; it keeps growing."),
            c=("Grows without bound.", "t and s both lie in [0, 1]: the gap is below 1."),
        ),
        _q(
            "'Interpolate first, then project' works because:",
            "a",
            a=(
                "M is linear, so M P(t) is the same mix of MA and MB as P(t) is of A and B.",
                "the divide by w comes only after the mixing.",
            ),
            b=(
                "Projection keeps ratios along a line.",
                "the divide by w does not: that is the whole problem.",
            ),
            c=(
                "The screen is flat.",
                "the screen being flat is not what makes the mix carry over; linearity of M is.",
            ),
        ),
    ],
    4: [
        _q(
            "Along the image of a segment, which are linear in the screen parameter s?",
            "bcd",
            a=("w, the view depth.", "w bends: 1/w is the straight one."),
            b=("1/w.", "1/w(s) = (1-s)/w_1 + s/w_2."),
            c=("NDC z.", "NDC z = alpha + beta/w is an affine function of 1/w."),
            d=("Window z, what the depth buffer stores.", "it is (NDC z + 1)/2, affine again."),
            e=("The object parameter t.", "t(s) is a curve unless w_1 = w_2."),
        ),
        _q(
            "With a 24-bit fixed-point depth buffer, halving the near plane:",
            "a",
            a=(
                "About doubles the smallest depth step, at every depth.",
                "steps grow like w^2 / near in fixed point.",
            ),
            b=("Halves every depth step.", "the opposite: a smaller near plane costs precision."),
            c=(
                "Changes nothing far away.",
                "far away the step still grows like w^2 / near: it doubles.",
            ),
        ),
        _q(
            "A float32 depth buffer storing window z, compared with a 24-bit fixed-point one:",
            "b",
            a=(
                "Is finer everywhere.",
                "in [1/2, 1) float32 numbers are exactly 2^-24 apart, like 24-bit fixed point.",
            ),
            b=(
                "Is the same wherever window z >= 1/2, finer only very near the near plane.",
                "window z passes 1/2 at w = 2 far near / (far + near), about twice the near plane.",
            ),
            c=("Is coarser far away.", "it is the same there: 2^-24 in both."),
        ),
        _q(
            "Reversed Z (storing 1 at the near plane and 0 at the far one, in float32):",
            "a",
            a=(
                "Puts float's fine spacing far away, where 1/w changes least.",
                "floats are finest near 0, and reversed depth is near 0 far away.",
            ),
            b=(
                "Helps a 24-bit fixed-point buffer just as much.",
                "fixed-point numbers are evenly spaced: reversing them changes nothing.",
            ),
            c=(
                "Needs no change to the depth test.",
                "nearer is now larger: the test becomes GL_GREATER, the buffer cleared to 0.",
            ),
        ),
    ],
    5: [
        _q(
            "Along the image of a segment, which are linear in s?",
            "bc",
            a=("The attribute a.", "a is linear in t, not in s."),
            b=("a/w.", "Low's eq. 16: a/w is linear on the screen."),
            c=("1/w.", "Low's eq. 12."),
            d=("a times w.", "a w is neither: only quantities divided by w are."),
        ),
        _q(
            "Having interpolated a/w, you get a by dividing by:",
            "a",
            a=("The interpolated 1/w.", "both are linear on the screen; their quotient is a."),
            b=(
                "Window z, from the depth buffer.",
                "window z is alpha' + beta'/w, not 1/w: the classic mistake.",
            ),
            c=(
                "Nothing: multiply by a linearly interpolated w instead.",
                "w is not linear on the screen: that is dividing too early.",
            ),
        ),
        _q(
            "When does affine (screen-space) interpolation give the right attribute along a "
            "segment?",
            "ab",
            a=("When w_1 = w_2.", "then t = s."),
            b=("When a_1 = a_2.", "a constant is right whichever way it is interpolated."),
            c=(
                "When the segment is short on the screen.",
                "shorter means smaller errors, not none: the error depends on w_2 / w_1.",
            ),
        ),
        _q(
            "A segment from A (in front) to B (behind the near plane) is clipped at C. C's "
            "attribute is:",
            "a",
            a=(
                "a_1 + t_C (a_2 - a_1), with t_C where the segment meets the near plane.",
                "clipping happens in clip space, where everything is still linear in t.",
            ),
            b=("B's attribute.", "C is not B: the whole visible part would come out wrong."),
            c=("(a_1 + a_2) / 2.", "only if the near plane cuts AB at its middle."),
        ),
    ],
    6: [
        _q(
            "Looking straight down at the ground quad, the affine error is:",
            "a",
            a=("Zero.", "every corner is at the same depth, so affine is exact."),
            b=("At its largest.", "it is large seen low and flat, and zero from above."),
            c=("The same as at the default camera.", "the depths no longer differ."),
        ),
        _q(
            "Why do the affine checkerboard's lines bend differently in the quad's two triangles?",
            "a",
            a=(
                "Each triangle is interpolated affinely from its own three corners.",
                "on the shared diagonal both agree, but the slopes differ on either side: a kink.",
            ),
            b=(
                "The rasterizer skips pixels on the diagonal.",
                "the fill rule draws each pixel once: no gap, no overlap.",
            ),
            c=("The texture has a line there.", "the texture is a plain checkerboard."),
        ),
        _q(
            "Cutting the quad into 8 x 8 smaller quads, all drawn affinely:",
            "a",
            a=(
                "Lowers the largest error a lot.",
                "each small triangle spans a small range of depths (at the lesson's default "
                "camera the largest error falls from 3.86 to 0.12 texels).",
            ),
            b=("Removes the error completely.", "the error shrinks but stays above 0."),
            c=("Makes the error worse.", "more, smaller triangles are each nearly exact."),
        ),
        _q(
            "With no roll, Quake-style spans on a level floor are exact because:",
            "a",
            a=("Every image row is at one depth.", "and with equal depths affine is exact."),
            b=("The spans are short.", "even 64-pixel spans are exact without roll."),
            c=("The floor is far away.", "distance does not matter, equal depth does."),
        ),
    ],
    7: [
        _q(
            "Across a triangle, which are planes over the screen (affine in a pixel's x and y)?",
            "bdef",
            a=("w.", "its contours are straight but not evenly spaced: not a plane."),
            b=("1/w.", "the triangle's plane equation makes 1/w affine in NDC x and y."),
            c=("A texture coordinate u.", "u is affine in space, not on the screen."),
            d=("u/w.", "the same argument as 1/w, for a quantity affine on the triangle."),
            e=("NDC z.", "alpha + beta/w, affine in 1/w."),
            f=("Window z.", "affine in NDC z, so the depth buffer may interpolate it."),
        ),
        _q(
            "Why does the 1D result carry over to triangles?",
            "a",
            a=(
                "The triangle lies in a plane, on which 1/w is affine in NDC (x, y); the "
                "viewport is affine too.",
                "so 1/w, and a/w, are planes over the pixels.",
            ),
            b=("Triangles are small.", "the result is exact at every size."),
            c=("The GPU cuts triangles into lines.", "it needs no such thing: planes suffice."),
        ),
        _q(
            "OpenGL's perspective-correct weights are lambda_i =",
            "a",
            a=("(b_i / w_i) / (b_0/w_0 + b_1/w_1 + b_2/w_2).", "eq. 14.9."),
            b=("(b_i w_i) / (b_0 w_0 + b_1 w_1 + b_2 w_2).", "1/w is linear, not w."),
            c=("b_i.", "that is noperspective."),
        ),
        _q(
            "On the edge from vertex 0 to vertex 1 (b_2 = 0), lambda_1 reduces to:",
            "a",
            a=(
                "t(s) of lesson 3, with s = b_1 and the edge's depths w_0, w_1.",
                "b_1 w_0 / (b_1 w_0 + b_0 w_1) with b_0 = 1 - s.",
            ),
            b=("b_1.", "only if w_0 = w_1."),
            c=("1/2.", "only at one point, if at all."),
        ),
    ],
    8: [
        _q(
            "A vertex shader writes gl_Position = vec4(p.xyz / p.w, 1.0). A smooth output is then:",
            "a",
            a=(
                "Interpolated like noperspective.",
                "every vertex has w = 1: there is nothing left to correct with.",
            ),
            b=("Still perspective-correct.", "the w that made it correct is gone."),
            c=("Flat.", "it is still interpolated, just not perspective-correctly."),
        ),
        _q(
            "A flat output takes, across a whole triangle, the value of:",
            "a",
            a=(
                "Its provoking vertex: by default the last vertex of the triangle.",
                "glProvokingVertex can make it the first.",
            ),
            b=("The average of its three vertices.", "flat does not interpolate or average."),
            c=(
                "The vertex nearest the camera.",
                "the provoking vertex is fixed by the order, not by depth.",
            ),
        ),
        _q(
            "Why is a triangle clipped before dividing by w?",
            "a",
            a=(
                "A vertex behind the camera has w <= 0: dividing would mirror it or divide by 0.",
                "in clip space everything is still linear, so the cut is exact.",
            ),
            b=("It is faster.", "that is not the reason: it is about correctness."),
            c=("The divide needs positive numbers.", "w is not required to be positive: w != 0."),
        ),
        _q(
            "On long rows (hundreds of pixels), Quake's spans of 16 pixels cost about how many "
            "divides per pixel?",
            "a",
            a=(
                "About 1/16.",
                "one exact value every 16 pixels along a row, plus one to close the row: on "
                "short rows, like the lab's, that last one counts (0.13 per pixel there).",
            ),
            b=("16.", "that is the span length, not the cost."),
            c=("None.", "each span starts with a divide."),
        ),
    ],
    9: [
        _q(
            "One pixel's footprint in the texture is the parallelogram spanned by:",
            "b",
            a=(
                "(du/dx, du/dy) and (dv/dx, dv/dy).",
                "that pairs the two derivatives of one coordinate; an edge is where one "
                "screen step takes (u, v): (du/dx, dv/dx) along x, (du/dy, dv/dy) along y.",
            ),
            b=(
                "(du/dx, dv/dx) and (du/dy, dv/dy).",
                "one pixel step right moves (u, v) by the first, one step up by the second.",
            ),
            c=(
                "(u, v) and (1/w, 1/w).",
                "those are values at the pixel, not how they change from pixel to pixel.",
            ),
        ),
        _q(
            "Where the level of detail λ <= 0, the texture is:",
            "c",
            a=(
                "Minified: several texels fall in one pixel.",
                "that is λ > 0, a footprint longer than one texel.",
            ),
            b=("Not drawn.", "λ only chooses how the texture is read, not whether."),
            c=(
                "Magnified: a texel covers a pixel or more, and level 0 is read.",
                "the footprint is at most one texel long.",
            ),
        ),
        _q(
            "At λ = 2.3, trilinear filtering (GL_LINEAR_MIPMAP_LINEAR) reads:",
            "a",
            a=(
                "Levels 2 and 3, each bilinearly, blended 70% and 30%.",
                "the two levels around λ, weighted by its fraction 0.3.",
            ),
            b=(
                "Level 2 alone.",
                "one level is GL_LINEAR_MIPMAP_NEAREST (the nearest level, 2); trilinear "
                "blends the two levels around λ.",
            ),
            c=(
                "Levels 0 to 3, averaged.",
                "only the two levels around λ are read.",
            ),
        ),
        _q(
            "With affine interpolation, λ across one triangle is:",
            "b",
            a=(
                "The same as with perspective-correct interpolation.",
                "perspective-correct derivatives change from pixel to pixel, as the footprints "
                "do; affine ones cannot.",
            ),
            b=(
                "Constant: u and v are linear on the screen, so their derivatives are constants.",
                "so one mip level serves the whole triangle, near part and far part alike.",
            ),
            c=(
                "Always 0.",
                "λ is the log2 of the footprint in texels: constant on the triangle, but "
                "not 0 unless the footprint is exactly one texel long.",
            ),
        ),
    ],
    10: [
        _q(
            "Which is the perspective-correct attribute at screen parameter s?",
            "a",
            a=(
                "((1-s) a_1/w_1 + s a_2/w_2) / ((1-s)/w_1 + s/w_2)",
                "interpolate a/w and 1/w, then divide.",
            ),
            b=("(1-s) a_1 + s a_2", "that is affine (noperspective)."),
            c=(
                "((1-s) a_1 w_1 + s a_2 w_2) / ((1-s) w_1 + s w_2)",
                "each end weighted by its w where 1/w belongs.",
            ),
        ),
        _q(
            "The object parameter seen at screen parameter s is t(s) =",
            "a",
            a=("s w_1 / (s w_1 + (1-s) w_2)", "CS5500's result."),
            b=("s w_2 / (s w_2 + (1-s) w_1)", "that is s(t), the forward map, applied to s."),
            c=("s", "only when w_1 = w_2."),
        ),
        _q(
            "Which are linear on the screen?",
            "bcf",
            a=("w", "1/w is."),
            b=("1/w", "the heart of the matter."),
            c=("window z", "affine in 1/w."),
            d=("u", "u is linear in space, not on the screen."),
            e=("t", "t(s) is a curve."),
            f=("u/w", "like 1/w."),
        ),
        _q(
            "Which GLSL qualifier interpolates linearly in screen space?",
            "a",
            a=("noperspective", "the screen-space barycentrics b."),
            b=("smooth", "smooth is perspective-correct, the default."),
            c=("flat", "flat does not interpolate."),
        ),
    ],
}


def _letters(value: object) -> str | None:
    """The letters a student chose, sorted, or None if ``value`` is not a choice."""
    if isinstance(value, str):
        text = value
    elif isinstance(value, (list, tuple, set, frozenset)) and all(
        isinstance(v, str) for v in value
    ):
        text = "".join(value)
    else:
        return None
    letters = [c for c in text.lower() if c.isalpha()]
    return "".join(sorted(set(letters)))


def recap(lesson: int, student: Callable[[], dict]) -> Verdict:
    """Check the answers to lesson ``lesson``'s recap questions (:data:`QUIZZES`).

    ``student()`` returns a dict from question number (1, 2, ...) to the letter or letters
    chosen, e.g. ``{1: "b", 2: "bd"}``. Each wrong answer gets its reason: why a chosen option
    is wrong, or why a missing one is right.

    Examples
    --------
    >>> recap(1, lambda: {1: "b", 2: "a", 3: "b", 4: "b"})
    ✓ recap 1: all 4 answers right.
    >>> print(repr(recap(1, lambda: {1: "a", 2: "a", 3: "b", 4: "b"})))
    ✗ recap 1: 3 of 4 right.
    <BLANKLINE>
    - question 1: (a) is not right: only when A and B are equally deep.
    """
    questions = QUIZZES[lesson]
    name = f"recap {lesson}"
    if not callable(student):
        return Verdict(False, f"pass your function itself, e.g. check.recap_{lesson}(my_answers)")
    try:
        answers = student()
    except NotImplementedError:
        return Verdict(False, NOT_WRITTEN, pending=True)
    except Exception as error:  # the student's code: report it, never raise
        return Verdict(False, f"your function {_error_words(error)}.")
    if answers is None:
        return Verdict(False, "your function returned None: did you forget `return`?")
    if not isinstance(answers, dict):
        return Verdict(
            False,
            f"return a dict from question number to letters, e.g. {{1: 'a', 2: 'bc'}}; got "
            f"{type(answers).__name__}.",
        )
    notes, right = [], 0
    for number, question in enumerate(questions, start=1):
        chosen = _letters(answers.get(number, answers.get(str(number))))
        if chosen is None or not chosen:
            notes.append(f'- question {number}: no answer: give its letter as a string, e.g. "b".')
            continue
        unknown = [c for c in chosen if c not in question.options]
        if unknown:
            notes.append(
                f"- question {number}: there is no option ({unknown[0]}); the options are "
                f"{', '.join(question.options)}."
            )
            continue
        if chosen == question.answer:
            right += 1
            continue
        if len(chosen) > 1 and not question.several:
            notes.append(f"- question {number}: it has one right answer: choose one letter.")
            continue
        wrong = [c for c in chosen if c not in question.answer]
        missing = [c for c in question.answer if c not in chosen]
        said = [f"({c}) is not right: {question.why[c]}" for c in wrong]
        if missing and question.several:  # say how many, not which: let the student find them
            count = (
                "one right option is" if len(missing) == 1 else f"{len(missing)} right options are"
            )
            said.append(f"{'And ' if wrong else ''}{count} missing.")
        notes.append(f"- question {number}: " + " ".join(said))
    extra = [k for k in answers if str(k) not in {str(n) for n in range(1, len(questions) + 1)}]
    if extra:
        notes.append(f"- there is no question {extra[0]}; the questions are 1 to {len(questions)}.")
    if right == len(questions) and not extra:
        return Verdict(True, f"{name}: all {len(questions)} answers right.")
    return Verdict(False, f"{name}: {right} of {len(questions)} right.\n\n" + "\n".join(notes))


def _recap_checker(lesson: int) -> Callable[[Callable[[], dict]], Verdict]:
    def checker(student: Callable[[], dict]) -> Verdict:
        return recap(lesson, student)

    checker.__name__ = checker.__qualname__ = f"recap_{lesson}"
    checker.__doc__ = (
        f"Lesson {lesson}'s recap questions: ``student()`` returns a dict from question number "
        "to the letter(s) chosen (see :func:`recap`)."
    )
    return checker


recap_1, recap_2, recap_3, recap_4, recap_5, recap_6, recap_7, recap_8, recap_9, recap_10 = (
    _recap_checker(k) for k in range(1, 11)
)


# --- lesson 8: clipping ----------------------------------------------------------------------


def _near_t(z1: float, w1: float, z2: float, w2: float) -> float:
    """Where the edge from clip-space (z1, w1) to (z2, w2) meets the near plane z = -w."""
    d1, d2 = z1 + w1, z2 + w2  # >= 0 inside the near plane
    return d1 / (d1 - d2)


def near_clip(student: Callable[[float, float, float, float], float]) -> Verdict:
    """Lesson 8: ``student(z1, w1, z2, w2)`` is the parameter t at which the edge from a vertex
    inside the near plane (clip z1, w1, with ``z1 >= -w1``) to one outside it (``z2 < -w2``)
    crosses the near plane ``z = -w``, found in clip space as :mod:`interp.clipping` does.

    Examples
    --------
    >>> near_clip(lambda z1, w1, z2, w2: (z1 + w1) / ((z1 + w1) - (z2 + w2)))
    ✓ near_clip: right on all 24 cases, among them the inside vertex on the near plane and ...
    >>> near_clip(lambda z1, w1, z2, w2: (-1 - z1 / w1) / (z2 / w2 - z1 / w1))
    ✗ that interpolates NDC z = z/w, ...
    """

    def draw(r: np.random.Generator) -> tuple[float, ...]:
        # an edge from a point in front of the near plane to one in front of the eye but
        # before the near plane, both made with interp.perspective's near = n, far = f
        n, f = r.uniform(0.1, 2), r.uniform(5, 100)
        w1, w2 = r.uniform(n * 1.2, f), r.uniform(0.05 * n, 0.9 * n)

        def z(w):
            return (f + n) / (f - n) * w - 2 * f * n / (f - n)

        return z(w1), w1, z(w2), w2

    cases = [
        Case((0.0, 2.0, -3.0, 1.0)),
        Case((1.0, 3.0, -1.5, 0.8)),
        Case((-1.0, 1.0, -4.0, 2.0), "the inside vertex on the near plane"),
        Case((2.0, 4.0, -1.0, -1.0), "the outside vertex behind the eye"),
        *_random(9, 20, draw),
    ]
    return _judge(
        "near_clip",
        student,
        _near_t,
        cases,
        "z1, w1, z2, w2",
        [
            (
                lambda z1, w1, z2, w2: (-1 - z1 / w1) / (z2 / w2 - z1 / w1),
                "that interpolates NDC z = z/w, which is not linear along the edge in space "
                "(and has no meaning behind the eye): clip first, in clip space, where the "
                "distance z + w to the near plane is linear in t.",
            ),
            (
                lambda z1, w1, z2, w2: 1 - _near_t(z1, w1, z2, w2),
                "that is measured from the outside vertex: t is 0 at the inside vertex (z1, w1).",
            ),
            (
                lambda z1, w1, z2, w2: (z1 - w1) / ((z1 - w1) - (z2 - w2)),
                "that is where the edge meets the far plane z = w; the near plane is z = -w, "
                "where z + w = 0.",
            ),
        ],
    )


# --- lesson 9: the level of detail ----------------------------------------------------------
#
# ``lod(my_lod)`` calls the student's ``my_lod(dudx, dvdx, dudy, dvdy, size)`` on a fixed list of
# cases, first one to redo by hand, then special ones (magnified, negative derivatives, a
# footprint turned against the texture) and random ones, and compares each answer with
# :func:`interp.mipmap.level_of_detail`.


def _lod_edges(dudx: float, dvdx: float, dudy: float, dvdy: float) -> tuple[float, float]:
    """The lengths of the footprint's two edges, in texture coordinates."""
    return math.hypot(dudx, dvdx), math.hypot(dudy, dvdy)


def _lod_taxicab(dudx: float, dvdx: float, dudy: float, dvdy: float) -> tuple[float, float]:
    return abs(dudx) + abs(dvdx), abs(dudy) + abs(dvdy)


def _lod_fwidth(dudx: float, dvdx: float, dudy: float, dvdy: float) -> tuple[float, float]:
    return abs(dudx) + abs(dudy), abs(dvdx) + abs(dvdy)


def _lod_mistake(formula: Callable[[tuple[float, ...], float], float]) -> Callable[..., float]:
    """A wrong answer written in terms of the four derivatives ``d`` and ``size``."""
    return lambda *args: formula(args[:4], args[4])


def _lod_reference(dudx: float, dvdx: float, dudy: float, dvdy: float, size: float) -> float:
    return float(mipmap.level_of_detail(dudx, dvdx, dudy, dvdy, size))


def _lod_draw(rng: np.random.Generator) -> tuple[float, ...]:
    scale = 10.0 ** rng.uniform(-3.5, -1)  # from magnified to far minified
    dudx, dvdx, dudy, dvdy = rng.normal(0, scale, 4)
    return dudx, dvdx, dudy, dvdy, float(2 ** rng.integers(4, 11))


_LOD_CASES = [
    Case((4 / 256, 0.0, 0.0, 2 / 256, 256.0)),
    Case((0.01, 0.0, 0.0, 0.01, 100.0)),
    Case((1 / 512, 0.0, 0.0, 1 / 1024, 256.0), "magnified (λ < 0)"),
    Case((-2 / 128, 0.0, 0.0, -1 / 128, 128.0), "negative derivatives"),
    Case((3 / 256, 4 / 256, -4 / 256, 3 / 256, 256.0), "the footprint turned against the texture"),
    Case((0.001, 0.0, 0.0, 0.05, 64.0), "the longer edge along y"),
    *_random(11, 21, _lod_draw),
]


def lod(student: Callable[[float, float, float, float, float], float]) -> Verdict:
    """Lesson 9: ``student(dudx, dvdx, dudy, dvdy, size)`` is OpenGL's level of detail
    ``λ = log2(max(sqrt(dudx² + dvdx²), sqrt(dudy² + dvdy²)) * size)`` for a texture of
    ``size x size`` texels (:func:`interp.mipmap.level_of_detail`).

    Examples
    --------
    >>> import math
    >>> def my_lod(dudx, dvdx, dudy, dvdy, size):
    ...     rho = max(math.hypot(dudx, dvdx), math.hypot(dudy, dvdy)) * size
    ...     return math.log2(rho)
    >>> lod(my_lod)
    ✓ lod: right on all 27 cases, among them magnified (λ < 0), negative derivatives, the \
footprint turned against the texture and the longer edge along y.
    >>> lod(lambda dudx, dvdx, dudy, dvdy, size: math.log2(
    ...     max(abs(dudx), abs(dvdx), abs(dudy), abs(dvdy)) * size))
    ✗ that is the shortcut OpenGL allows (the largest single derivative, ...
    >>> lod(lambda dudx, dvdx, dudy, dvdy, size: math.log2(
    ...     max(math.hypot(dudx, dvdx), math.hypot(dudy, dvdy))))
    ✗ that is λ for a texture one texel wide: ...
    """

    def longer(*d: float) -> float:
        return max(_lod_edges(*d))

    def shorter(*d: float) -> float:
        return min(_lod_edges(*d))

    return _judge(
        "lod",
        student,
        _lod_reference,
        _LOD_CASES,
        "dudx, dvdx, dudy, dvdy, size",
        [
            (
                _lod_mistake(lambda d, size: math.log2(longer(*d))),
                "that is λ for a texture one texel wide: (u, v) run from 0 to 1 across the "
                "texture, so multiply the footprint by size to count texels.",
            ),
            (
                _lod_mistake(lambda d, size: math.log(longer(*d) * size)),
                "that is the natural logarithm; λ is the logarithm base 2 (math.log2): each "
                "mipmap level halves the texture.",
            ),
            (
                _lod_mistake(lambda d, size: math.log10(longer(*d) * size)),
                "that is the logarithm base 10; λ is the logarithm base 2 (math.log2): each "
                "mipmap level halves the texture.",
            ),
            (
                _lod_mistake(lambda d, size: longer(*d) * size),
                "that is rho, the longer footprint edge in texels; λ = log2(rho), the mipmap level "
                "whose texels are that large.",
            ),
            (
                _lod_mistake(lambda d, size: math.log2(shorter(*d) * size)),
                "you took the shorter footprint edge; OpenGL takes the longer one, so that the "
                "texture never aliases (it blurs along the short edge instead).",
            ),
            (
                _lod_mistake(lambda d, size: math.log2(sum(_lod_edges(*d)) * size)),
                "you added the two edge lengths; rho is the longer of the two.",
            ),
            (
                _lod_mistake(lambda d, size: math.log2(max(_lod_taxicab(*d)) * size)),
                "you measured each footprint edge as |du| + |dv|; its length is "
                "sqrt(du² + dv²) (math.hypot).",
            ),
            (
                _lod_mistake(lambda d, size: math.log2(max(_lod_fwidth(*d)) * size)),
                "that is the larger of GLSL's fwidth(u) = |du/dx| + |du/dy| and fwidth(v): a "
                "box around the footprint. OpenGL's rho is the longer edge: the larger of "
                "sqrt(du/dx² + dv/dx²) and sqrt(du/dy² + dv/dy²).",
            ),
            (
                _lod_mistake(lambda d, size: math.log2(sum(_lod_edges(*d)) / 2 * size)),
                "you averaged the two edge lengths; rho is the longer of the two.",
            ),
            (
                _lod_mistake(lambda d, size: 2 * _lod_reference(*d, size)),
                "that is twice λ: the log2 of a squared length. Take the square root of "
                "du² + dv² first (or halve the logarithm).",
            ),
            (
                _lod_mistake(lambda d, size: math.log2(max(map(abs, d)) * size)),
                "that is the shortcut OpenGL allows (the largest single derivative, which some "
                "GPUs use), not the lengths of the footprint's edges: write "
                "sqrt(du/dx² + dv/dx²) and sqrt(du/dy² + dv/dy²).",
            ),
            (
                lambda dudx, dvdx, dudy, dvdy, size: _lod_reference(dudx, dudy, dvdx, dvdy, size),
                "you paired du/dx with du/dy. One footprint edge is where one step along x "
                "takes (u, v): (du/dx, dv/dx); the other is (du/dy, dv/dy).",
            ),
            (
                _lod_mistake(lambda d, size: max(_lod_reference(*d, size), 0.0)),
                "λ is negative where the texture is magnified (a texel larger than a pixel): "
                "do not clamp it at 0; OpenGL reads its sign to choose the magnification filter.",
            ),
            (
                _lod_mistake(lambda d, size: math.floor(_lod_reference(*d, size))),
                "λ is not rounded down: trilinear filtering blends the two levels around it "
                "by its fraction.",
            ),
            (
                _lod_mistake(lambda d, size: round(_lod_reference(*d, size))),
                "λ is not rounded: trilinear filtering blends the two levels around it by its "
                "fraction.",
            ),
        ],
    )
