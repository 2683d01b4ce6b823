"""An exact reference for small images: a ray cast in integer (rational) arithmetic.

Every float is a rational number; scaling all clip coordinates by one power of two makes them
integers without changing the scene (clip coordinates are homogeneous), and Python's integers
never round or overflow. So this answers exactly, for any finite input however tiny or large,
which triangle is seen at a point of the screen, and where on it.

For a point ``(xn, yn)`` in NDC let ``m = (xn, yn, 1)`` (scaled to integers). With the
triangle's vertices ``V_i = (x_i, y_i, w_i)``, the clip-space point seen there is ``P = sum l_i
P_i`` with ``l_i = e_i / sum(e)`` and ``e_i = (V_j x V_k) . m`` (Cramer's rule for ``P.x = xn
P.w``, ``P.y = yn P.w``, ``sum(l) = 1``), and ``P.w = det / sum(e)`` with ``det = V_0 . (V_1 x
V_2)``. The point is on the triangle and in front of the eye when every ``e_i`` has the sign of
``det`` (or is 0) and ``sum(e) != 0``; its NDC depth is ``sum(e_i z_i) / det``, which must lie in
``[-1, 1]``. Screen-space (``noperspective``) barycentrics are ``b_i = l_i w_i / P.w = e_i w_i /
det``. Nothing here is shared with ``interp``.
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

import numpy as np

#: Samples are placed on a grid of 1/NUDGE pixel; ambiguous pixels are those whose answer
#: changes when the sample moves by one step of this grid in x or y.
NUDGE = 64


@dataclass
class Exact:
    triangle: np.ndarray  # (H, W) visible triangle, -1 where none
    depth: np.ndarray  # (H, W) window depth, 1 where none
    weights: np.ndarray  # (H, W, 3) clip-space barycentrics l of the visible point
    screen: np.ndarray  # (H, W, 3) screen-space barycentrics b = l w / P.w of that point
    ambiguous: np.ndarray  # (H, W) bool: the answer changes within 1/NUDGE pixel, or a near tie

    def values(self, attributes: np.ndarray, triangles: np.ndarray, mode: str) -> np.ndarray:
        """``smooth`` attributes ``sum(l_i a_i)`` of the seen point ("perspective"), or
        ``noperspective`` ones ``sum(b_i a_i)`` ("affine")."""
        seen = self.triangle >= 0
        out = np.zeros((*self.triangle.shape, attributes.shape[1]))
        a = attributes[np.asarray(triangles)[self.triangle[seen]]]  # (P, 3, K)
        weights = self.weights if mode == "perspective" else self.screen
        out[seen] = np.einsum("pi,pik->pk", weights[seen], a)
        return out


def _integers(clip: np.ndarray) -> list[list[int]]:
    """The clip coordinates times one common power of two, as exact Python integers."""
    fractions = [[Fraction(float(c)) for c in row] for row in clip]
    scale = 1
    for row in fractions:
        for c in row:
            scale = max(scale, c.denominator)  # denominators are powers of two
    return [[int(c * scale) for c in row] for row in fractions]


def _cross(a: tuple[int, int, int], b: tuple[int, int, int]) -> tuple[int, int, int]:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _dot(a: tuple[int, ...], b: tuple[int, ...]) -> int:
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


class _Triangle:
    def __init__(self, vertices: list[list[int]]) -> None:
        V = [(v[0], v[1], v[3]) for v in vertices]  # (x, y, w)
        self.z = [v[2] for v in vertices]
        self.w = [v[3] for v in vertices]
        self.E = [_cross(V[(i + 1) % 3], V[(i + 2) % 3]) for i in range(3)]
        self.det = _dot(V[0], self.E[0])

    def hit(self, m: tuple[int, int, int]) -> tuple[Fraction, list[int], int] | None:
        """NDC depth, (e_0, e_1, e_2) and their sum where the triangle is seen at m, else None."""
        if self.det == 0:
            return None
        e = [_dot(E, m) for E in self.E]
        total = e[0] + e[1] + e[2]
        if total == 0 or any(ei * self.det < 0 for ei in e):
            return None
        depth = Fraction(e[0] * self.z[0] + e[1] * self.z[1] + e[2] * self.z[2], self.det * m[2])
        if not -1 <= depth <= 1:
            return None
        return depth, e, total


def _nearest(tris: list[_Triangle], m: tuple[int, int, int]):
    """(triangle, depth, e, sum, gap to the runner-up); the first drawn wins ties."""
    best = None
    second = None
    for k, tri in enumerate(tris):
        hit = tri.hit(m)
        if hit is None:
            continue
        if best is None or hit[0] < best[1]:
            second = best[1] if best is not None else None
            best = (k, *hit)
        elif second is None or hit[0] < second:
            second = hit[0]
    if best is None:
        return -1, None, None, None, None
    gap = None if second is None else second - best[1]
    return (*best, gap)


def render(clip, triangles, width: int, height: int, tie: float = 1e-9) -> Exact:
    """Cast exact rays through every pixel centre of a ``width x height`` image."""
    V = _integers(np.asarray(clip, dtype=np.float64))
    tris = [_Triangle([V[i] for i in t]) for t in np.asarray(triangles)]
    shape = (height, width)
    triangle = np.full(shape, -1)
    depth = np.ones(shape)
    weights = np.zeros((*shape, 3))
    screen = np.zeros((*shape, 3))
    ambiguous = np.zeros(shape, dtype=bool)

    def ray(X: int, Y: int) -> tuple[int, int, int]:
        # sample at window (X / NUDGE, Y / NUDGE): m = (xn, yn, 1) times NUDGE W H > 0
        return (
            (2 * X - NUDGE * width) * height,
            (2 * Y - NUDGE * height) * width,
            NUDGE * width * height,
        )

    for row in range(height):
        for col in range(width):
            X = NUDGE * col + NUDGE // 2
            Y = NUDGE * (height - 1 - row) + NUDGE // 2
            k, d, e, total, gap = _nearest(tris, ray(X, Y))
            triangle[row, col] = k
            if k >= 0:
                depth[row, col] = float((d + 1) / 2)
                weights[row, col] = [float(Fraction(ei, total)) for ei in e]
                scale = tris[k].det * ray(X, Y)[2]
                screen[row, col] = [
                    float(Fraction(ei * wi, scale)) for ei, wi in zip(e, tris[k].w, strict=True)
                ]
                ambiguous[row, col] = gap is not None and gap < 2 * tie
            for dx, dy in ((1, 0), (-1, 0), (0, 1), (0, -1)):
                if _nearest(tris, ray(X + dx, Y + dy))[0] != k:
                    ambiguous[row, col] = True
                    break
    return Exact(triangle, depth, weights, screen, ambiguous)
