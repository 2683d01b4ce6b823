# ruff: noqa: E501  (the messages are compared word for word)
"""check.lod, the texture-filtering lesson's checker, judged like those of tests/test_check.py: right answers in
several forms must pass; wrong ones must get exactly the message a teaching assistant would."""

from __future__ import annotations

import math

import numpy as np
import pytest

from interp import check


def _not_written(*args):
    raise NotImplementedError()


def _hypot(dudx, dvdx, dudy, dvdy, size):
    return math.log2(max(math.hypot(dudx, dvdx), math.hypot(dudy, dvdy)) * size)


def _squares(dudx, dvdx, dudy, dvdy, size):
    return 0.5 * math.log2(max(dudx**2 + dvdx**2, dudy**2 + dvdy**2) * size**2)


def _numpy(dudx, dvdx, dudy, dvdy, size):
    jacobian = np.array([[dudx, dvdx], [dudy, dvdy]]) * size
    return np.log2(np.linalg.norm(jacobian, axis=1).max())


def _split_log(dudx, dvdx, dudy, dvdy, size):
    return math.log2(size) + math.log(max(math.hypot(dudx, dvdx), math.hypot(dudy, dvdy)), 2)


def _texels_first(dudx, dvdx, dudy, dvdy, size):
    px, qx, py, qy = (d * size for d in (dudx, dvdx, dudy, dvdy))
    rho = max((px * px + qx * qx) ** 0.5, (py * py + qy * qy) ** 0.5)
    return math.log(rho) / math.log(2)


RIGHT = [
    ("hypot", _hypot),
    ("squares, halved", _squares),
    ("numpy", _numpy),
    ("log2(size) + log", _split_log),
    ("texels first, ln / ln 2", _texels_first),
]


@pytest.mark.parametrize(("label", "answer"), RIGHT, ids=[label for label, _ in RIGHT])
def test_right_answers_pass(label, answer):
    verdict = check.lod(answer)
    assert verdict, (label, verdict)
    assert verdict.message == (
        "lod: right on all 27 cases, among them magnified (λ < 0), negative derivatives, the "
        "footprint turned against the texture and the longer edge along y."
    )


L = math.log2
H = math.hypot

WRONG = {
    "not written yet": (
        _not_written,
        "… not written yet: replace `raise NotImplementedError()` with your code, then run the cell again.",
    ),
    "forgot return": (lambda *a: None, "✗ your function returned None: did you forget `return`?"),
    "text": (
        lambda *a: "log2(rho)",
        "✗ your function returned a string, 'log2(rho)': return a number, not text.",
    ),
    "rho and lambda": (
        lambda *a: (1.0, 0.0),
        "✗ your function returned a tuple of 2 values: return one number.",
    ),
    "no size": (
        lambda a, b, c, d, s: L(max(H(a, b), H(c, d))),
        "✗ that is λ for a texture one texel wide: (u, v) run from 0 to 1 across the texture, so multiply the footprint by size to count texels.",
    ),
    "natural log": (
        lambda a, b, c, d, s: math.log(max(H(a, b), H(c, d)) * s),
        "✗ that is the natural logarithm; λ is the logarithm base 2 (math.log2): each mipmap level halves the texture.",
    ),
    "log10": (
        lambda a, b, c, d, s: math.log10(max(H(a, b), H(c, d)) * s),
        "✗ that is the logarithm base 10; λ is the logarithm base 2 (math.log2): each mipmap level halves the texture.",
    ),
    "no log": (
        lambda a, b, c, d, s: max(H(a, b), H(c, d)) * s,
        "✗ that is rho, the longer footprint edge in texels; λ = log2(rho), the mipmap level whose texels are that large.",
    ),
    "shorter edge": (
        lambda a, b, c, d, s: L(min(H(a, b), H(c, d)) * s),
        "✗ you took the shorter footprint edge; OpenGL takes the longer one, so that the texture never aliases (it blurs along the short edge instead).",
    ),
    "sum of edges": (
        lambda a, b, c, d, s: L((H(a, b) + H(c, d)) * s),
        "✗ you added the two edge lengths; rho is the longer of the two.",
    ),
    "taxicab": (
        lambda a, b, c, d, s: L(max(abs(a) + abs(b), abs(c) + abs(d)) * s),
        "✗ you measured each footprint edge as |du| + |dv|; its length is sqrt(du² + dv²) (math.hypot).",
    ),
    "fwidth": (
        lambda a, b, c, d, s: L(max(abs(a) + abs(c), abs(b) + abs(d)) * s),
        "✗ that is the larger of GLSL's fwidth(u) = |du/dx| + |du/dy| and fwidth(v): a box around the footprint. OpenGL's rho is the longer edge: the larger of sqrt(du/dx² + dv/dx²) and sqrt(du/dy² + dv/dy²).",
    ),
    "mean of edges": (
        lambda a, b, c, d, s: L((H(a, b) + H(c, d)) / 2 * s),
        "✗ you averaged the two edge lengths; rho is the longer of the two.",
    ),
    "no square root": (
        lambda a, b, c, d, s: L(max(a * a + b * b, c * c + d * d) * s * s),
        "✗ that is twice λ: the log2 of a squared length. Take the square root of du² + dv² first (or halve the logarithm).",
    ),
    "max of components": (
        lambda a, b, c, d, s: L(max(abs(a), abs(b), abs(c), abs(d)) * s),
        "✗ that is the shortcut OpenGL allows (the largest single derivative, which some GPUs use), not the lengths of the footprint's edges: write sqrt(du/dx² + dv/dx²) and sqrt(du/dy² + dv/dy²).",
    ),
    "paired by coordinate": (
        lambda a, b, c, d, s: L(max(H(a, c), H(b, d)) * s),
        "✗ you paired du/dx with du/dy. One footprint edge is where one step along x takes (u, v): (du/dx, dv/dx); the other is (du/dy, dv/dy).",
    ),
    "clamped at 0": (
        lambda a, b, c, d, s: max(0.0, _hypot(a, b, c, d, s)),
        "✗ λ is negative where the texture is magnified (a texel larger than a pixel): do not clamp it at 0; OpenGL reads its sign to choose the magnification filter.",
    ),
    "rounded down": (
        lambda a, b, c, d, s: math.floor(_hypot(a, b, c, d, s)),
        "✗ λ is not rounded down: trilinear filtering blends the two levels around it by its fraction.",
    ),
    "rounded": (
        lambda a, b, c, d, s: round(_hypot(a, b, c, d, s)),
        "✗ λ is not rounded: trilinear filtering blends the two levels around it by its fraction.",
    ),
    "size squared under the root": (
        lambda a, b, c, d, s: 0.5 * L(max(a * a + b * b, c * c + d * d) * s),
        "✗ for (dudx, dvdx, dudy, dvdy, size) = (0.015625, 0, 0, 0.0078125, 256) the answer is 2, your function gave -2.",
    ),
    "y edge from dv/dy alone": (
        lambda a, b, c, d, s: L(max(H(a, b), abs(d)) * s),
        "✗ for (dudx, dvdx, dudy, dvdy, size) = (-2.65913e-05, 0.000354246, -0.000876183, 0.000743011, 1024) the answer is 0.234355, your function gave -0.394328.",
    ),
    "not a function": (0.5, "✗ pass your function itself, e.g. check.lod(my_function)"),
}


@pytest.mark.parametrize("label", WRONG)
def test_wrong_answers_get_their_message(label):
    answer, message = WRONG[label]
    assert repr(check.lod(answer)) == message


def test_every_known_mistake_is_reachable():
    # Each explanation the checker knows is given for some answer in the table above.
    verdicts = {repr(check.lod(answer)) for answer, _ in WRONG.values()}
    assert sum(v.startswith("✗ that is") or v.startswith("✗ you") for v in verdicts) >= 12
    assert sum("λ is not rounded" in v for v in verdicts) == 2
