"""The checker of the texture-filtering exercise: OpenGL's level of detail.

``interp.check_filtering.lod(my_lod)`` calls the student's ``my_lod(dudx, dvdx, dudy, dvdy,
size)`` on a fixed list of cases, first one to redo by hand, then special ones (magnified,
negative derivatives, a footprint turned against the texture) and random ones, and compares
each answer with :func:`interp.mipmap.level_of_detail`. Like the checkers of
:mod:`interp.check`, it says what is wrong: a known mistake by name, else the first case that
fails.

Examples
--------
>>> import math
>>> def my_lod(dudx, dvdx, dudy, dvdy, size):
...     rho = max(math.hypot(dudx, dvdx), math.hypot(dudy, dvdy)) * size
...     return math.log2(rho)
>>> lod(my_lod)
✓ lod: right on all 27 cases, among them magnified (λ < 0), negative derivatives, the footprint \
turned against the texture and the longer edge along y.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from interp import mipmap
from interp.check import Case, Verdict, _judge, _random

__all__ = ["lod"]


def _edges(dudx: float, dvdx: float, dudy: float, dvdy: float) -> tuple[float, float]:
    """The lengths of the footprint's two edges, in texture coordinates."""
    return math.hypot(dudx, dvdx), math.hypot(dudy, dvdy)


def _taxicab(dudx: float, dvdx: float, dudy: float, dvdy: float) -> tuple[float, float]:
    return abs(dudx) + abs(dvdx), abs(dudy) + abs(dvdy)


def _fwidth(dudx: float, dvdx: float, dudy: float, dvdy: float) -> tuple[float, float]:
    return abs(dudx) + abs(dudy), abs(dvdx) + abs(dvdy)


def _mistake(formula: Callable[[tuple[float, ...], float], float]) -> Callable[..., float]:
    """A wrong answer written in terms of the four derivatives ``d`` and ``size``."""
    return lambda *args: formula(args[:4], args[4])


def _reference(dudx: float, dvdx: float, dudy: float, dvdy: float, size: float) -> float:
    return float(mipmap.level_of_detail(dudx, dvdx, dudy, dvdy, size))


def _draw(rng: np.random.Generator) -> tuple[float, ...]:
    scale = 10.0 ** rng.uniform(-3.5, -1)  # from magnified to far minified
    dudx, dvdx, dudy, dvdy = rng.normal(0, scale, 4)
    return dudx, dvdx, dudy, dvdy, float(2 ** rng.integers(4, 11))


CASES = [
    Case((4 / 256, 0.0, 0.0, 2 / 256, 256.0)),
    Case((0.01, 0.0, 0.0, 0.01, 100.0)),
    Case((1 / 512, 0.0, 0.0, 1 / 1024, 256.0), "magnified (λ < 0)"),
    Case((-2 / 128, 0.0, 0.0, -1 / 128, 128.0), "negative derivatives"),
    Case((3 / 256, 4 / 256, -4 / 256, 3 / 256, 256.0), "the footprint turned against the texture"),
    Case((0.001, 0.0, 0.0, 0.05, 64.0), "the longer edge along y"),
    *_random(11, 21, _draw),
]


def lod(student: Callable[[float, float, float, float, float], float]) -> Verdict:
    """``student(dudx, dvdx, dudy, dvdy, size)`` is OpenGL's level of detail
    ``λ = log2(max(sqrt(dudx² + dvdx²), sqrt(dudy² + dvdy²)) * size)`` for a texture of
    ``size x size`` texels (:func:`interp.mipmap.level_of_detail`).

    Examples
    --------
    >>> import math
    >>> lod(lambda dudx, dvdx, dudy, dvdy, size: math.log2(
    ...     max(abs(dudx), abs(dvdx), abs(dudy), abs(dvdy)) * size))
    ✗ that is the shortcut OpenGL allows (the largest single derivative, ...
    >>> lod(lambda dudx, dvdx, dudy, dvdy, size: math.log2(
    ...     max(math.hypot(dudx, dvdx), math.hypot(dudy, dvdy))))
    ✗ that is λ for a texture one texel wide: ...
    """

    def longer(*d: float) -> float:
        return max(_edges(*d))

    def shorter(*d: float) -> float:
        return min(_edges(*d))

    return _judge(
        "lod",
        student,
        _reference,
        CASES,
        "dudx, dvdx, dudy, dvdy, size",
        [
            (
                _mistake(lambda d, size: math.log2(longer(*d))),
                "that is λ for a texture one texel wide: (u, v) run from 0 to 1 across the "
                "texture, so multiply the footprint by size to count texels.",
            ),
            (
                _mistake(lambda d, size: math.log(longer(*d) * size)),
                "that is the natural logarithm; λ is the logarithm base 2 (math.log2): each "
                "mipmap level halves the texture.",
            ),
            (
                _mistake(lambda d, size: math.log10(longer(*d) * size)),
                "that is the logarithm base 10; λ is the logarithm base 2 (math.log2): each "
                "mipmap level halves the texture.",
            ),
            (
                _mistake(lambda d, size: longer(*d) * size),
                "that is rho, the longer footprint edge in texels; λ = log2(rho), the mipmap level "
                "whose texels are that large.",
            ),
            (
                _mistake(lambda d, size: math.log2(shorter(*d) * size)),
                "you took the shorter footprint edge; OpenGL takes the longer one, so that the "
                "texture never aliases (it blurs along the short edge instead).",
            ),
            (
                _mistake(lambda d, size: math.log2(sum(_edges(*d)) * size)),
                "you added the two edge lengths; rho is the longer of the two.",
            ),
            (
                _mistake(lambda d, size: math.log2(max(_taxicab(*d)) * size)),
                "you measured each footprint edge as |du| + |dv|; its length is "
                "sqrt(du² + dv²) (math.hypot).",
            ),
            (
                _mistake(lambda d, size: math.log2(max(_fwidth(*d)) * size)),
                "that is the larger of GLSL's fwidth(u) = |du/dx| + |du/dy| and fwidth(v): a "
                "box around the footprint. OpenGL's rho is the longer edge: the larger of "
                "sqrt(du/dx² + dv/dx²) and sqrt(du/dy² + dv/dy²).",
            ),
            (
                _mistake(lambda d, size: math.log2(sum(_edges(*d)) / 2 * size)),
                "you averaged the two edge lengths; rho is the longer of the two.",
            ),
            (
                _mistake(lambda d, size: 2 * _reference(*d, size)),
                "that is twice λ: the log2 of a squared length. Take the square root of "
                "du² + dv² first (or halve the logarithm).",
            ),
            (
                _mistake(lambda d, size: math.log2(max(map(abs, d)) * size)),
                "that is the shortcut OpenGL allows (the largest single derivative, which some "
                "GPUs use), not the lengths of the footprint's edges: write "
                "sqrt(du/dx² + dv/dx²) and sqrt(du/dy² + dv/dy²).",
            ),
            (
                lambda dudx, dvdx, dudy, dvdy, size: _reference(dudx, dudy, dvdx, dvdy, size),
                "you paired du/dx with du/dy. One footprint edge is where one step along x "
                "takes (u, v): (du/dx, dv/dx); the other is (du/dy, dv/dy).",
            ),
            (
                _mistake(lambda d, size: max(_reference(*d, size), 0.0)),
                "λ is negative where the texture is magnified (a texel larger than a pixel): "
                "do not clamp it at 0; OpenGL reads its sign to choose the magnification filter.",
            ),
            (
                _mistake(lambda d, size: math.floor(_reference(*d, size))),
                "λ is not rounded down: trilinear filtering blends the two levels around it "
                "by its fraction.",
            ),
            (
                _mistake(lambda d, size: round(_reference(*d, size))),
                "λ is not rounded: trilinear filtering blends the two levels around it by its "
                "fraction.",
            ),
        ],
    )
