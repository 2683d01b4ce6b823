"""The three ways a rasterizer can fill in an attribute between a triangle's vertices.

Every pixel knows its screen-space barycentric coordinates ``b = (b0, b1, b2)``: how much of
each vertex's image it is made of. They sum to 1 and are linear on the screen.

- ``noperspective`` (affine): ``a = b0 a0 + b1 a1 + b2 a2``. Linear on the screen, so wrong for a
  triangle that is not parallel to the image plane.
- ``smooth`` (perspective-correct, OpenGL 4.6 eq. 14.9): ``a/w`` and ``1/w`` are what is linear
  on the screen. Each vertex hands on ``a_i / w_i`` and ``1 / w_i``; every pixel interpolates
  both linearly and divides::

      a = (b0 a0/w0 + b1 a1/w1 + b2 a2/w2) / (b0/w0 + b1/w1 + b2/w2)

- ``subdivided``: what Quake's span drawer did to save divides: exact (``smooth``) every N pixels
  along a row, affine in between.

The same ``smooth`` result as *weights*: OpenGL's perspective-correct barycentrics
``λ_i = (b_i / w_i) / (b0/w0 + b1/w1 + b2/w2)`` (:func:`perspective_weights`), after which the
attribute is the plain weighted sum ``λ0 a0 + λ1 a1 + λ2 a2``.

Shapes: P pixels, K attributes, vertex index first and pixels last, so that numpy's loops run
over the pixels: ``b`` is (3, P); per-vertex values are (3, K, P) or (3, P).
"""

from __future__ import annotations

import numpy as np

from interp import _checks


def lerp(b: np.ndarray, per_vertex: np.ndarray) -> np.ndarray:
    """``b0 v0 + b1 v1 + b2 v2`` for per-vertex values v of shape (3, K, P) or (3, P).

    Examples
    --------
    >>> b = np.array([[0.25], [0.75], [0.0]])          # one pixel
    >>> lerp(b, np.array([[2.0], [4.0], [8.0]]))
    array([3.5])
    """
    b0, b1, b2 = b
    v0, v1, v2 = per_vertex
    return b0 * v0 + b1 * v1 + b2 * v2


def noperspective(b: np.ndarray, a: np.ndarray) -> np.ndarray:
    """Affine interpolation ``b0 a0 + b1 a1 + b2 a2``, shape (K, P).

    Examples
    --------
    >>> b = np.array([[0.5], [0.5], [0.0]])
    >>> noperspective(b, np.array([[[0.0]], [[1.0]], [[0.0]]]))
    array([[0.5]])
    """
    return lerp(b, a)


def smooth(b: np.ndarray, a_over_w: np.ndarray, one_over_w: np.ndarray) -> np.ndarray:
    """Perspective-correct interpolation from the vertices' ``a/w`` and ``1/w``, shape (K, P).

    Parameters
    ----------
    b : (3, P) array
        Screen-space barycentrics.
    a_over_w : (3, K, P) array
        Each vertex's attributes divided by its clip-space w.
    one_over_w : (3, P) array
        Each vertex's ``1 / w``.

    Examples
    --------
    Half-way on screen between a vertex at depth 1 and one at depth 3 is only a quarter of the
    way along the edge in space:

    >>> a = np.array([[[0.0]], [[1.0]], [[0.0]]])      # vertex, attribute, pixel
    >>> w = np.array([[1.0], [3.0], [1.0]])            # vertex, pixel
    >>> smooth(np.array([[0.5], [0.5], [0.0]]), a / w[:, None], 1 / w)
    array([[0.25]])
    """
    return lerp(b, a_over_w) / lerp(b, one_over_w)  # the per-pixel divide


def _perspective_weights(b: np.ndarray, w: np.ndarray) -> np.ndarray:
    """``λ_i = (b_i / w_i) / Σ_j (b_j / w_j)`` along the first axis."""
    q = b / w
    return q / q.sum(axis=0)


def _screen_weights(weights: np.ndarray, w: np.ndarray) -> np.ndarray:
    """The other way: ``b_i = λ_i w_i / Σ_j λ_j w_j`` along the first axis, the screen-space
    barycentrics of the point whose perspective-correct weights are ``λ``. The sum is the
    point's own w, as w is linear in space; a vertex may have any w (even behind the eye),
    as long as the point is in front.

    Examples
    --------
    >>> _screen_weights(np.array([0.75, 0.25, 0.0]), np.array([1.0, 3.0, 2.0]))
    array([0.5, 0.5, 0. ])
    """
    q = weights * w
    return q / q.sum(axis=0)


def perspective_weights(b: object, w: object) -> np.ndarray:
    """OpenGL's perspective-correct barycentric weights (OpenGL 4.6, eq. 14.9).

    ``λ_i = (b_i / w_i) / (b0/w0 + b1/w1 + b2/w2)``: each screen-space weight divided by its
    vertex's clip-space w, then all three scaled to sum to 1. The perspective-correct attribute
    at the pixel is then ``λ0 a0 + λ1 a1 + λ2 a2``, the same number :func:`smooth` computes as
    ``lerp(b, a/w) / lerp(b, 1/w)``.

    Parameters
    ----------
    b : (3,) or (3, ...) array_like
        Screen-space barycentric coordinates of one or more pixels, vertex first; each set
        sums to 1 inside the triangle. Values in [-1e12, 1e12].
    w : (3,) or (3, ...) array_like
        The three vertices' clip-space w (view depths), in [1e-12, 1e12]; broadcasts against
        ``b``.

    Returns
    -------
    (3,) or (3, ...) float array
        The weights λ, summing to 1 along the first axis.

    Examples
    --------
    Half-way along the screen edge from a vertex at depth 1 to one at depth 3 is a quarter of
    the way in space:

    >>> perspective_weights([0.5, 0.5, 0.0], [1.0, 3.0, 2.0])
    array([0.75, 0.25, 0.  ])
    """
    b = _checks.number_array(b, "b")
    w = _checks.depth_array(w, "w")
    if b.ndim == 0 or b.shape[0] != 3:
        raise ValueError(f"b must have shape (3,) or (3, ...), one row per vertex, got {b.shape}")
    if w.ndim == 0 or w.shape[0] != 3:
        raise ValueError(f"w must have shape (3,) or (3, ...): one w per vertex, got {w.shape}")
    b, w = _checks.broadcast(b=b, w=w)
    q = b / w
    if np.any(np.abs(q.sum(axis=0)) <= 1e-12 * np.abs(q).sum(axis=0)):
        raise ValueError("b must not make b0/w0 + b1/w1 + b2/w2 zero (nothing to divide by)")
    return _perspective_weights(b, w)


def subdivided(
    b_left: np.ndarray,
    b_right: np.ndarray,
    fraction: np.ndarray,
    a_over_w: np.ndarray,
    one_over_w: np.ndarray,
) -> np.ndarray:
    """Exact at two anchor pixels on the row, affine in between.

    Parameters
    ----------
    b_left, b_right : (3, P) arrays
        Barycentrics of each pixel's left and right anchor (pixels N apart on its row).
    fraction : (P,) array
        Where the pixel lies between its anchors, from 0 (left) to 1 (right).
    a_over_w, one_over_w : (3, K, P) and (3, P) arrays
        As for :func:`smooth`.

    Examples
    --------
    >>> a, w = np.array([[[0.0]], [[1.0]], [[0.0]]]), np.array([[1.0], [3.0], [1.0]])
    >>> left, right = np.array([[1.0], [0], [0]]), np.array([[0.0], [1], [0]])
    >>> subdivided(left, right, np.array([0.5]), a / w[:, None], 1 / w)   # no longer 0.25
    array([[0.5]])
    """
    at_left = smooth(b_left, a_over_w, one_over_w)
    at_right = smooth(b_right, a_over_w, one_over_w)
    return at_left + fraction * (at_right - at_left)


def smooth_derivative(
    a: np.ndarray, one_over_w: np.ndarray, dN: np.ndarray, dD: np.ndarray
) -> np.ndarray:
    """How a perspective-correct attribute changes per pixel step, exactly, shape (K, P).

    ``a = N / D`` with ``N = lerp(b, a/w)`` and ``D = lerp(b, 1/w)``. Both are linear on the
    screen, so on each triangle their steps ``dN`` and ``dD`` are constants, and the quotient
    rule gives ``da = (dN - a dD) / D``. (A GPU estimates the same from neighbouring pixels,
    ``dFdx``, to choose how much to blur a texture.)

    Parameters
    ----------
    a : (K, P) array
        The interpolated attribute.
    one_over_w : (P,) array
        ``D``, the interpolated ``1/w``.
    dN, dD : (K, P) and (P,) arrays
        The steps of ``N`` and ``D`` for one pixel.

    Examples
    --------
    Next to a vertex with a = 0 at depth 1, a tenth of the way towards one with a = 1 at depth
    3 is only a thirtieth of the way in space:

    >>> smooth_derivative(np.array([[0.0]]), np.array([1.0]), np.array([[0.1 / 3]]),
    ...                   np.array([0.1 / 3 - 0.1]))
    array([[0.03333333]])
    """
    return (dN - a * dD) / one_over_w
