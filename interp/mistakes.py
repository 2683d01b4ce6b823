"""Classic mistakes in perspective-correct interpolation, computed on purpose.

Lesson 5 shows each beside the right answer, :func:`interp.lerp_perspective`. All work along a
segment from A (attribute a1, view depth w1) to B (a2, w2) at screen parameter s, like
:mod:`interp.lerp`; all are wrong unless ``w1 == w2``.
"""

from __future__ import annotations

import numpy as np

from interp import depth, lerp


def lerp_with_window_z(
    a1: object, a2: object, w1: object, w2: object, s: object, near: float, far: float
) -> np.ndarray | float:
    """Dividing by the depth buffer's z instead of w: ``lerp(a/z) / lerp(1/z)``, z = window z.

    Window z is ``A + B/w``, not ``w``, so ``a/z`` is not linear on the screen.

    Examples
    --------
    >>> round(lerp_with_window_z(0.0, 1.0, 2.0, 6.0, 0.5, near=1.0, far=10.0), 3)  # right: 0.25
    0.375
    """
    # On the near plane window z is exactly 0 and the mistaken division has no value; stop z at
    # the smallest depth lerp_perspective takes, which draws its limit there.
    z1, z2 = (np.maximum(depth.window_depth(w, near, far), 1e-12) for w in (w1, w2))
    return lerp.lerp_perspective(a1, a2, z1, z2, s)


def lerp_divided_too_early(
    a1: object, a2: object, w1: object, w2: object, s: object
) -> np.ndarray | float:
    """Dividing too early: interpolate ``a/w``, then multiply by a screen-linear ``w``.

    ``a/w`` is linear on the screen, but ``w`` is not (``1/w`` is): the result must be divided
    by the interpolated ``1/w``, which is not the same as multiplying by the interpolated ``w``.

    Examples
    --------
    >>> round(lerp_divided_too_early(0.0, 1.0, 1.0, 3.0, 0.5), 4)   # the right answer is 0.25
    0.3333
    """
    a_over_w = lerp.lerp_affine(np.divide(a1, w1), np.divide(a2, w2), s)
    return a_over_w * lerp.lerp_affine(w1, w2, s)


def lerp_forgetting_the_clip_vertex(
    a1: object, a2: object, w1: object, w2: object, s: object, near: float
) -> np.ndarray | float:
    """A segment from A (in front) to B (behind the near plane ``w = near``), clipped at the near
    plane, where the new vertex C kept B's attribute instead of getting its own.

    ``s`` runs along the image of the visible part, A to C. The right attribute at C is
    ``a1 + t_c (a2 - a1)`` with ``t_c = (w1 - near) / (w1 - w2)``.

    Examples
    --------
    >>> lerp_forgetting_the_clip_vertex(0.0, 1.0, 3.0, -1.0, 1.0, near=1.0)  # right: 0.5
    1.0
    """
    return lerp.lerp_perspective(a1, a2, w1, near, s)


def clip_vertex_attribute(a1: object, a2: object, w1: object, w2: object, near: float) -> object:
    """The attribute the near-plane vertex C should get: ``a1 + t_c (a2 - a1)``.

    Examples
    --------
    >>> clip_vertex_attribute(0.0, 1.0, 3.0, -1.0, near=1.0)
    0.5
    """
    t_c = (np.asarray(w1, float) - near) / (np.asarray(w1, float) - np.asarray(w2, float))
    value = np.asarray(a1, float) + t_c * (np.asarray(a2, float) - np.asarray(a1, float))
    return value.item() if value.ndim == 0 else value
