"""The three ways a rasterizer can fill in an attribute between a triangle's vertices.

Every pixel knows its screen-space barycentric coordinates ``b = (b0, b1, b2)``: how much of
each vertex's image it is made of. They sum to 1 and are linear on the screen.

- ``noperspective`` (affine): ``a = sum(b_i a_i)``. Linear on the screen, so wrong for a
  triangle that is not parallel to the image plane.
- ``smooth`` (perspective-correct, OpenGL 4.6 eq. 14.9): ``a/w`` and ``1/w`` are what is linear
  on the screen, so interpolate those and divide per pixel::

      a = sum(b_i a_i / w_i) / sum(b_i / w_i)

- ``subdivided``: what Quake's span drawer did to save divides: exact (``smooth``) every N pixels
  along a row, affine in between.

Shapes: P pixels, K attributes. ``b`` is (P, 3); per-vertex ``a`` is (P, 3, K); ``w`` is (P, 3).
"""

from __future__ import annotations

import numpy as np


def noperspective(b: np.ndarray, a: np.ndarray) -> np.ndarray:
    """Affine interpolation: ``sum(b_i a_i)``, shape (P, K).

    Examples
    --------
    >>> b = np.array([[0.5, 0.5, 0.0]])
    >>> noperspective(b, np.array([[[0.0], [1.0], [0.0]]]))
    array([[0.5]])
    """
    return np.einsum("pi,pik->pk", b, a)


def smooth(b: np.ndarray, a: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Perspective-correct interpolation: ``sum(b_i a_i / w_i) / sum(b_i / w_i)``, shape (P, K).

    Examples
    --------
    Half-way on screen between a vertex at depth 1 and one at depth 3 is only a quarter of the
    way along the edge in space:

    >>> b = np.array([[0.5, 0.5, 0.0]])
    >>> smooth(b, np.array([[[0.0], [1.0], [0.0]]]), np.array([[1.0, 3.0, 1.0]]))
    array([[0.25]])
    """
    a_over_w = np.einsum("pi,pik->pk", b / w, a)  # linear on the screen
    one_over_w = np.sum(b / w, axis=1, keepdims=True)  # linear on the screen
    return a_over_w / one_over_w  # the per-pixel divide


def subdivided(
    b_left: np.ndarray,
    b_right: np.ndarray,
    fraction: np.ndarray,
    a: np.ndarray,
    w: np.ndarray,
) -> np.ndarray:
    """Exact at two anchor pixels on the row, affine in between.

    Parameters
    ----------
    b_left, b_right : (P, 3) arrays
        Barycentrics of each pixel's left and right anchor (pixels N apart on its row).
    fraction : (P,) array
        Where the pixel lies between its anchors, from 0 (left) to 1 (right).
    a : (P, 3, K) array
        Vertex attributes.
    w : (P, 3) array
        Vertex clip-space w.

    Examples
    --------
    >>> a, w = np.array([[[0.0], [1.0], [0.0]]]), np.array([[1.0, 3.0, 1.0]])
    >>> left, right = np.array([[1.0, 0, 0]]), np.array([[0.0, 1, 0]])
    >>> subdivided(left, right, np.array([0.5]), a, w)   # affine between exact endpoints
    array([[0.5]])
    """
    at_left = smooth(b_left, a, w)
    at_right = smooth(b_right, a, w)
    return at_left + fraction[:, None] * (at_right - at_left)
