"""The 1D story: a segment in the plane, seen by a camera with a 1D image plane.

A 2D point ``(x, z)`` is in view space: the camera sits at the origin and looks down -z, as in
OpenGL (Low's report looks down +z; only the sign of z differs). The image plane is the line
``z = -d``; the point projects to the image coordinate ``x_img = d * x / w`` where ``w = -z`` is
its view depth, the same number as clip-space w.

Glossary
--------
t      : object-space parameter along the segment: ``P(t) = (1 - t) A + t B``.
s      : screen-space parameter along its image: ``p(s) = (1 - s) a + s b``.
w1, w2 : view depths of the endpoints A and B (clip-space w), > 0 in front of the camera.
a1, a2 : an attribute's values at A and B (intensity, colour, texture coordinate...).

The result the lessons derive (CS5500 handout; Low, eq. 12 and 16): "interpolate first, then
project" gives ``s = t w2 / ((1 - t) w1 + t w2)``; equivalently ``1/w`` and ``a/w`` vary
linearly in s, so the right attribute is ``lerp(a/w) / lerp(1/w)``.

Ranges: parameters (t, s) and attributes lie in [-1e12, 1e12], depths (w1, w2, d) in
[1e-12, 1e12]; outside, a ValueError names the argument. Within them every result is finite.

One home per formula: each public function checks its arguments, then calls an unchecked kernel
of the same name with a leading underscore (``s_from_t`` calls ``_s_from_t``). The rest of the
package (clipping, the plots, the exercise checkers) calls the kernels, so every formula is
written exactly once, here.
"""

from __future__ import annotations

import numpy as np

from interp import _checks


def _depths(w1: object, w2: object) -> tuple[np.ndarray, np.ndarray]:
    """View depths: in [1e-12, 1e12] (> 0: a point at or behind the camera has w <= 0)."""
    return _checks.depth_array(w1, "w1"), _checks.depth_array(w2, "w2")


def _fraction(x: object, name: str) -> np.ndarray:
    """A parameter (t, s) or attribute value: in [-1e12, 1e12]."""
    return _checks.number_array(x, name)


def _result(x: np.ndarray) -> np.ndarray | float:
    return x.item() if x.ndim == 0 else x


def _s_from_t(t: np.ndarray, w1: np.ndarray, w2: np.ndarray) -> np.ndarray:
    """Interpolate first, then project: ``t w2 / ((1 - t) w1 + t w2)``."""
    return t * w2 / ((1 - t) * w1 + t * w2)


def _t_from_s(s: np.ndarray, w1: np.ndarray, w2: np.ndarray) -> np.ndarray:
    """The inverse of :func:`_s_from_t`: ``s w1 / (s w1 + (1 - s) w2)``."""
    return s * w1 / (s * w1 + (1 - s) * w2)


def _lerp(a1: np.ndarray, a2: np.ndarray, s: np.ndarray) -> np.ndarray:
    """``(1 - s) a1 + s a2``."""
    return (1 - s) * a1 + s * a2


def _gap_peak(w1: np.ndarray, w2: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Where ``|t - s|`` peaks, and its height: ``sqrt(w2) / (sqrt(w1) + sqrt(w2))`` and
    ``|sqrt(w2) - sqrt(w1)| / (sqrt(w1) + sqrt(w2))``."""
    r1, r2 = np.sqrt(w1), np.sqrt(w2)
    return r2 / (r1 + r2), np.abs(r2 - r1) / (r1 + r2)


def s_from_t(t: object, w1: object, w2: object) -> np.ndarray | float:
    """Screen parameter s of the point at object parameter t: ``t w2 / ((1 - t) w1 + t w2)``.

    Parameters
    ----------
    t : array_like
        Object-space parameter(s); 0 at A, 1 at B. Values outside [0, 1] extrapolate along the
        line, as long as the point stays in front of the camera.
    w1, w2 : array_like
        View depths (clip-space w) of A and B, in [1e-12, 1e12]. All three broadcast
        together.

    Returns
    -------
    float or ndarray
        s, broadcast to the common shape (a float for scalar input).

    Examples
    --------
    >>> s_from_t(0.5, 1.0, 3.0)      # the midpoint of AB is 3/4 of the way along the image
    0.75
    >>> s_from_t([0, 1], 2.0, 5.0)   # the endpoints stay put
    array([0., 1.])
    """
    t = _fraction(t, "t")
    w1, w2 = _depths(w1, w2)
    t, w1, w2 = _checks.broadcast(t=t, w1=w1, w2=w2)
    if np.any(_lerp(w1, w2, t) <= 0):  # the depth of P(t)
        raise ValueError("t must keep the point in front of the camera: (1-t) w1 + t w2 > 0")
    return _result(_s_from_t(t, w1, w2))


def t_from_s(s: object, w1: object, w2: object) -> np.ndarray | float:
    """Object parameter t of the point seen at screen parameter s: ``s w1 / (s w1 + (1 - s) w2)``.

    The inverse of :func:`s_from_t`.

    Parameters
    ----------
    s : array_like
        Screen-space parameter(s); 0 at the image a of A, 1 at the image b of B.
    w1, w2 : array_like
        View depths (clip-space w) of A and B, in [1e-12, 1e12]. All three broadcast
        together.

    Returns
    -------
    float or ndarray
        t, broadcast to the common shape.

    Examples
    --------
    >>> t_from_s(0.75, 1.0, 3.0)
    0.5
    >>> t_from_s(0.5, 1.0, 3.0)      # the middle of the image shows a point 1/4 along AB
    0.25
    """
    s = _fraction(s, "s")
    w1, w2 = _depths(w1, w2)
    s, w1, w2 = _checks.broadcast(s=s, w1=w1, w2=w2)
    if np.any(_lerp(w2, w1, s) <= 0):
        raise ValueError("s must be where the line is visible: s w1 + (1-s) w2 > 0")
    return _result(_t_from_s(s, w1, w2))


def project_to_image_plane(points: object, d: float = 1.0) -> np.ndarray | float:
    """Image coordinate of 2D view-space points on the image plane ``z = -d``.

    Parameters
    ----------
    points : (2,) or (N, 2) array_like
        Points ``(x, z)`` in view space, in front of the camera: ``z <= -1e-12``.
    d : float
        Distance from the eye to the image plane, in [1e-12, 1e12].

    Returns
    -------
    float or (N,) array
        ``d * x / w`` with ``w = -z``: the perspective divide.

    Examples
    --------
    >>> project_to_image_plane([2.0, -4.0], d=1.0)
    0.5
    >>> project_to_image_plane([[1, -1], [1, -2]], d=2.0)   # further away: closer to the axis
    array([2., 1.])
    """
    points = _checks.number_array(points, "points")
    if points.ndim not in (1, 2) or points.shape[-1] != 2:
        raise ValueError(f"points must have shape (2,) or (N, 2), got {points.shape}")
    d = _checks.scale(d, "d")
    w = -points[..., 1]
    if np.any(w < _checks.MIN_POSITIVE):
        raise ValueError(
            f"points must be in front of the camera: z <= -{_checks.MIN_POSITIVE:g}, got z = "
            f"{-w.min():g}"
        )
    return _result(d * points[..., 0] / w)


def lerp_affine(a1: object, a2: object, s: object) -> np.ndarray | float:
    """Screen-space linear interpolation ``(1 - s) a1 + s a2``: what ``noperspective`` does.

    Examples
    --------
    >>> lerp_affine(0.0, 1.0, 0.75)
    0.75
    """
    a1, a2 = _fraction(a1, "a1"), _fraction(a2, "a2")
    s = _fraction(s, "s")
    a1, a2, s = _checks.broadcast(a1=a1, a2=a2, s=s)
    return _result(_lerp(a1, a2, s))


def lerp_inverse_w(w1: object, w2: object, s: object) -> np.ndarray | float:
    """``1/w`` at screen parameter s: linear in s, ``(1 - s)/w1 + s/w2`` (Low, eq. 12).

    Examples
    --------
    >>> 1 / lerp_inverse_w(1.0, 3.0, 0.5)   # the depth seen in the middle of the image
    1.5
    """
    w1, w2 = _depths(w1, w2)
    s = _fraction(s, "s")
    w1, w2, s = _checks.broadcast(w1=w1, w2=w2, s=s)
    return _result(_lerp(1 / w1, 1 / w2, s))


def lerp_perspective(
    a1: object, a2: object, w1: object, w2: object, s: object
) -> np.ndarray | float:
    """Perspective-correct interpolation at screen parameter s: what ``smooth`` does.

    ``a/w`` and ``1/w`` are both linear in s (Low, eq. 16), so interpolate them linearly and
    divide per point:

        a(s) = ((1 - s) a1/w1 + s a2/w2) / ((1 - s)/w1 + s/w2)

    which equals ``(1 - t) a1 + t a2`` with ``t = t_from_s(s, w1, w2)``.

    Parameters
    ----------
    a1, a2 : array_like
        The attribute at A and B.
    w1, w2 : array_like
        View depths of A and B, in [1e-12, 1e12].
    s : array_like
        Screen parameter(s). All five broadcast together.

    Examples
    --------
    >>> lerp_perspective(0.0, 1.0, 1.0, 3.0, 0.5)   # half-way on screen is only 1/4 along AB
    0.25
    """
    a1, a2 = _fraction(a1, "a1"), _fraction(a2, "a2")
    w1, w2 = _depths(w1, w2)
    s = _fraction(s, "s")
    a1, a2, w1, w2, s = _checks.broadcast(a1=a1, a2=a2, w1=w1, w2=w2, s=s)
    if np.any(_lerp(1 / w1, 1 / w2, s) <= 0):
        raise ValueError("s must be where the line is visible: (1-s)/w1 + s/w2 > 0")
    return _result(_lerp_perspective(a1, a2, w1, w2, s))


def _lerp_perspective(
    a1: np.ndarray, a2: np.ndarray, w1: np.ndarray, w2: np.ndarray, s: np.ndarray
) -> np.ndarray:
    """``lerp(a/w) / lerp(1/w)``: the perspective-correct attribute at screen parameter s."""
    return _lerp(a1 / w1, a2 / w2, s) / _lerp(1 / w1, 1 / w2, s)


def gap_peak(w1: object, w2: object) -> tuple[np.ndarray | float, np.ndarray | float]:
    """Where the gap ``|t - s|`` between object and screen parameter peaks, and how large it gets.

    Lesson 3 derives it: ``dt/ds = w1 w2 / (s w1 + (1 - s) w2)**2`` equals 1 where
    ``s w1 + (1 - s) w2 = sqrt(w1 w2)``, so the peak is at ``s* = sqrt(w2) / (sqrt(w1) +
    sqrt(w2))`` and the gap there is ``|sqrt(w2) - sqrt(w1)| / (sqrt(w1) + sqrt(w2))``.

    Parameters
    ----------
    w1, w2 : array_like
        View depths of A and B, in [1e-12, 1e12]; they broadcast together.

    Returns
    -------
    s_star, gap : float or ndarray
        Where the gap peaks, and its height there.

    Examples
    --------
    >>> gap_peak(1.0, 9.0)
    (0.75, 0.5)
    """
    w1, w2 = _depths(w1, w2)
    w1, w2 = _checks.broadcast(w1=w1, w2=w2)
    s_star, gap = _gap_peak(w1, w2)
    return _result(s_star), _result(gap)
